"""Make the golden vectors of the ``mcast:`` datagram and of pydronecan's capture file with
pydronecan's own drivers (``dronecan.driver.mcast``, ``dronecan.driver.file``), to rewrite
``tests/dronecan/data/pydronecan_mcast.json``; from the repository root, as root::

    tests/on_loopback python tests/dronecan/make_mcast_vectors.py \
        > tests/dronecan/data/pydronecan_mcast.json

Sent: each frame through a pydronecan mcast driver, the datagram it puts on the group.
Received: each datagram sent to the group, then a sentinel frame, and what the driver
hands on before the sentinel (None: it dropped the datagram). File: the frames written by
the ``fileout:`` driver, its bytes, and what ``filein:`` reads back.
"""

import json
import os
import socket
import struct
import sys
import tempfile
import time
from importlib.metadata import version
from pathlib import Path
from typing import Any

from dronecan.driver.common import CANFrame

import dronecan

BUS = 7
GROUP = f"239.65.82.{BUS}"
PORT = 57732

frames = [
    (0x1001557F, "00000000000000c0", True, False),
    (0x18040A7D, "c0", True, False),
    (0x00000000, "", True, False),
    (0x1FFFFFFF, "ffffffffffffffff", True, False),
    (0x123, "0102", False, False),
    (0x7FF, "", False, False),
    (0x0C04207D, "00112233445566778899aabb", True, True),
    (0x0C04207D, bytes(range(64)).hex(), True, True),
    (0x0C04207D, "0011223344", True, True),
]

listener = socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP)
listener.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
listener.bind((GROUP, PORT))
listener.setsockopt(
    socket.IPPROTO_IP,
    socket.IP_ADD_MEMBERSHIP,
    struct.pack("4sl", socket.inet_aton(GROUP), socket.INADDR_ANY),
)
listener.settimeout(10)

driver = dronecan.driver.make_driver(f"mcast:{BUS}")
time.sleep(1.0)  # its io process connects after 0.1 s
sent: list[dict[str, Any]] = []
for can_id, data, ext, fd in frames:
    driver.send_frame(CANFrame(can_id, bytearray.fromhex(data), ext, canfd=fd))
    datagram, _ = listener.recvfrom(200)
    sent.append(
        {"can_id": can_id, "data": data, "extended": ext, "fd": fd, "datagram": datagram.hex()}
    )

# decoding: datagrams from another socket, each then a sentinel frame
out = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
out.connect((GROUP, PORT))


def crc(data: bytes) -> int:
    """pydronecan's CRC-16-CCITT."""
    from dronecan.dsdl.common import crc16_from_bytes

    value: int = crc16_from_bytes(data)
    return value


def pkt(flags: int, mid: int, data: bytes, magic: int = 0x2934, bad_crc: bool = False) -> bytes:
    """A datagram made by hand (a wrong magic or CRC if asked)."""
    body = struct.pack("<HI", flags, mid) + data
    c = crc(body) ^ (1 if bad_crc else 0)
    return struct.pack("<HH", magic, c) + body


SENTINEL = pkt(0, (1 << 31) | 0x1ABCDEF, b"\x5a")
cases = [v["datagram"] for v in sent] + [
    pkt(0, 0x1001557F | (1 << 31), b"\x01\x02", magic=0x2935).hex(),
    pkt(0, 0x1001557F | (1 << 31), b"\x01\x02", bad_crc=True).hex(),
    pkt(0, 0x1001557F | (1 << 31), b"")[:9].hex(),
    pkt(0x0002, 0x1001557F | (1 << 31), b"\x01").hex(),  # unknown flag bit
    pkt(0, 0x1001557F | (1 << 31) | (1 << 30), b"").hex(),  # ArduPilot's remote bit
    pkt(0, 0x1001557F | (1 << 31) | (1 << 29), b"\x01").hex(),  # ArduPilot's error bit
    pkt(0, 0x1001557F | (1 << 31), bytes(9)).hex(),  # 9 bytes, classic
    pkt(1, 0x1001557F | (1 << 31), bytes(10)).hex(),  # 10 bytes, FD
    pkt(0, 0x0800, b"").hex(),  # standard id past 11 bits
    "",
]
received = []
for hexed in cases:
    out.send(bytes.fromhex(hexed))
    out.send(SENTINEL)
    got = []
    while True:
        f = driver.receive(10)
        assert f is not None, "no sentinel"
        if f.id == 0x1ABCDEF and bytes(f.data) == b"\x5a":
            break
        got.append(
            {"can_id": f.id, "data": bytes(f.data).hex(), "extended": f.extended, "fd": f.canfd}
        )
    received.append({"datagram": hexed, "pydronecan": got[0] if got else None})

# the capture file: written by fileout:, then read back by filein:
tmp = tempfile.mkdtemp()
path = os.path.join(tmp, "frames.bin")
writer = dronecan.driver.make_driver(f"fileout:{path}")
file_frames = []
for i, (can_id, data, ext, fd) in enumerate(frames):
    f = CANFrame(
        can_id,
        bytearray.fromhex(data),
        ext,
        ts_monotonic=1000.0 + i * 0.25 + 0.000001 * i,
        canfd=fd,
    )
    writer.send_frame(f)
    file_frames.append(
        {"can_id": can_id, "data": data, "extended": ext, "fd": fd, "ts_monotonic": f.ts_monotonic}
    )
writer.close()
writer.file = None  # its __del__ would flush the closed file
raw = Path(path).read_bytes()
reader = dronecan.driver.make_driver(f"filein:{path}")
back = []
while True:
    fr, ts = reader._read_frame()
    if fr is None:
        break
    back.append(
        {
            "can_id": fr.id,
            "data": bytes(fr.data).hex(),
            "extended": fr.extended,
            "fd": fr.canfd,
            "timestamp": ts,
        }
    )

json.dump(
    {
        "source": "made by tests/dronecan/make_mcast_vectors.py with pydronecan (the dronecan "
        f"package) {version('dronecan')}, Python {sys.version.split()[0]}: its mcast and "
        "file drivers",
        "send": sent,
        "receive": received,
        "file": {"frames": file_frames, "bytes": raw.hex(), "read_back": back},
    },
    sys.stdout,
    indent=1,
)
print()
