"""Readers: turn captures into `Frame` (and `BadLine`) streams. No decoding happens here."""

from veronte4x.readers.candump import parse_candump, read_candump
from veronte4x.readers.open import open_frames

__all__ = ["open_frames", "parse_candump", "read_candump"]
