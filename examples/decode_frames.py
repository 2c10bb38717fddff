"""Decode a candump -L capture of Veronte 4x traffic and print one line per frame.

Usage: python examples/decode_frames.py examples/capture.log

Lines look like ``(1700000000.000000) can0 0FF#00FF8177FFFF`` (read with
`veronte4x.capture.open_frames`). CAN IDs follow Embention's
defaults: AP1, AP2, AP3 and the external autopilot send on 8, 9, 10, 11; the arbiter sends
on 255. A frame that does not decode is printed with its error and counted, never fatal.
"""

from __future__ import annotations

import sys
from pathlib import Path

from veronte4x import codec
from veronte4x.capture import open_frames
from veronte4x.capture.frames import BadLine

ARBITER_ID = 255
AUTOPILOT_IDS = {8: "AP1", 9: "AP2", 10: "AP3", 11: "external AP"}


def main(path: str) -> int:
    """Decode every frame of the capture at `path`; return the number of bad frames."""
    bad = 0
    for frame in open_frames(path):
        if isinstance(frame, BadLine):
            print(f"line {frame.line_number}: {frame.reason}")
            bad += 1
            continue
        timestamp, can_id, data = frame.timestamp or 0.0, frame.can_id, frame.data
        if can_id == ARBITER_ID:
            sender, who = codec.Sender.ARBITER, "arbiter"
        elif can_id in AUTOPILOT_IDS:
            sender, who = codec.Sender.AUTOPILOT, AUTOPILOT_IDS[can_id]
        else:
            print(f"{timestamp:.6f} {can_id:03X} unknown sender: {data.hex(' ')}")
            bad += 1
            continue
        try:
            message = codec.decode(data, sender=sender)
        except codec.DecodeError as error:
            print(f"{timestamp:.6f} {can_id:03X} {who:<11} ERROR {error}")
            bad += 1
            continue
        print(f"{timestamp:.6f} {can_id:03X} {who:<11} {message}")
    print(f"{bad} frame(s) could not be decoded", file=sys.stderr)
    return bad


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(Path(__file__).with_name("capture.log")))
