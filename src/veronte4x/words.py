"""Words in the lines a person reads: a count with its noun in the right number."""

from __future__ import annotations


def counted(count: int, noun: str, plural: str | None = None) -> str:
    """``count`` and ``noun``, singular for exactly one, else ``plural`` (``noun + "s"``).

    Examples:
        >>> counted(1, "file"), counted(0, "file"), counted(2, "bad frame")
        ('1 file', '0 files', '2 bad frames')
        >>> counted(3, "entry", "entries")
        '3 entries'
    """
    return f"{count} {noun if count == 1 else plural or noun + 's'}"
