"""Messages about the input itself, printed on standard error as a command meets them."""

from __future__ import annotations

import sys
from collections.abc import Iterable, Iterator

from veronte4x.capture.records import Record


def tell_truncation(records: Iterable[Record]) -> Iterator[Record]:
    """Pass records through; print the detail of one that says the input ends early.

    Such a record (error ``truncated``) is about the file, not a frame: a person is told
    whatever ``--on-error`` does with bad frames.
    """
    for record in records:
        if record.error == "truncated":
            sys.stdout.flush()
            print(f"veronte4x: {record.detail}", file=sys.stderr)
        yield record
