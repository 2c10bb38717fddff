"""Decode the public captures of ``tests/dronecan/data/`` with the ``dronecan`` package, to
rewrite their ``pydronecan.json``; from the repository root (the ``dev`` extra installed)::

    python tests/dronecan/make_public_capture_vectors.py

Each capture's frames go, in order, through the package's own receive path
(``dronecan.transport.TransferManager.receive_frame``, then ``Transfer.from_frames``), as
its ``Node`` feeds them; every transfer it completes is written with the fields it decodes.
"""

from __future__ import annotations

import json
from importlib.metadata import version
from pathlib import Path
from typing import Any

from dronecan_oracle import reference_builtin

import dronecan
from dronecan import transport

DATA = Path(__file__).parent / "data"
CAPTURES = ("lpatiny",)


def _kind(t: transport.Transfer) -> str:
    if not t.service_not_message:
        return "message"
    return "request" if t.request_not_response else "response"


def _transfers(log: Path) -> list[dict[str, Any]]:
    manager = transport.TransferManager()
    out = []
    for line in log.read_text().splitlines():
        stamp, _channel, frame = line.split()
        can_id, data = frame.split("#")
        seconds = float(stamp.strip("()"))
        frames = manager.receive_frame(
            transport.Frame(int(can_id, 16), bytes.fromhex(data), seconds, seconds)
        )
        if not frames:
            continue
        t = transport.Transfer()
        t.from_frames(frames)
        out.append({
            "timestamp": seconds,
            "can_id": frames[-1].message_id,
            "source": t.source_node_id,
            "destination": t.dest_node_id,
            "transfer_id": t.transfer_id,
            "type": dronecan.get_dronecan_data_type(t.payload).full_name,
            "kind": _kind(t),
            "fields": reference_builtin(t.payload),
        })  # fmt: skip
    return out


if __name__ == "__main__":
    for name in CAPTURES:
        vectors = {
            "made_by": f"dronecan {version('dronecan')}",
            "transfers": _transfers(DATA / name / "frames.log"),
        }
        (DATA / name / "pydronecan.json").write_text(json.dumps(vectors, indent=1) + "\n")
