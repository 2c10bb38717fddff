"""Readers: turn captures into `Frame` (and `BadLine`) streams. No decoding happens here."""

from veronte4x.capture.readers.candump import parse_candump, parse_line

__all__ = ["parse_candump", "parse_line"]
