"""Files written whole: a reader sees the old file or the new one, never a part."""

from __future__ import annotations

import contextlib
import os
import secrets
import stat
from collections.abc import Iterator
from typing import BinaryIO


@contextlib.contextmanager
def whole_file(path: str | os.PathLike[str]) -> Iterator[BinaryIO]:
    """Open ``path`` for writing bytes under a hidden name beside it, and put it in place by
    one rename when the block ends without an error; on an error (Ctrl-C included) the
    hidden file is removed and ``path`` stays as it was. A path that is not a regular file
    (``/dev/stdout``, a pipe) is written directly.

    Examples:
        >>> import pathlib, tempfile
        >>> target = pathlib.Path(tempfile.mkdtemp()) / "out.csv"
        >>> with whole_file(target) as file:
        ...     _ = file.write(b"time\\n")
        >>> target.read_bytes()
        b'time\\n'
    """
    target = os.fspath(path)
    with contextlib.suppress(FileNotFoundError):
        if not stat.S_ISREG(os.stat(target).st_mode):
            with open(target, "wb") as file:
                yield file
            return
    head, name = os.path.split(target)
    hidden = os.path.join(head, f".{name}.{os.getpid()}-{secrets.token_hex(4)}")
    try:
        with open(hidden, "wb") as file:
            yield file
        os.replace(hidden, target)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(hidden)
        raise
