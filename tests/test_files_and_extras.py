"""`veronte4x.files.whole_file` (a file is replaced whole or not at all, a pipe is written
directly) and `veronte4x.extras.require` (a missing extra is named, a broken one is not
hidden)."""

from __future__ import annotations

import os
import sys
import threading
from pathlib import Path

import pytest

from veronte4x.errors import MissingExtraError
from veronte4x.extras import require
from veronte4x.files import whole_file


def test_a_file_is_replaced_whole_and_no_hidden_file_stays(tmp_path: Path) -> None:
    target = tmp_path / "out.csv"
    target.write_bytes(b"old\n")
    with whole_file(target) as file:
        file.write(b"new\n")
        assert target.read_bytes() == b"old\n"  # a reader still sees the old file
        [hidden] = [p for p in tmp_path.iterdir() if p != target]
        assert hidden.name.startswith(".out.csv.")
    assert target.read_bytes() == b"new\n"
    assert [p.name for p in tmp_path.iterdir()] == ["out.csv"]


@pytest.mark.parametrize("error", [OSError("disk full"), KeyboardInterrupt()])
def test_an_error_while_writing_leaves_the_old_file(tmp_path: Path, error: BaseException) -> None:
    target = tmp_path / "out.csv"
    target.write_bytes(b"old\n")
    with pytest.raises(type(error)), whole_file(target) as file:
        file.write(b"half of the ne")
        raise error
    assert target.read_bytes() == b"old\n"
    assert [p.name for p in tmp_path.iterdir()] == ["out.csv"]


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="named pipes are POSIX")
def test_a_pipe_is_written_directly(tmp_path: Path) -> None:
    """A path that is no regular file (``<(...)``, ``/dev/stdout``) is opened as it is: a
    hidden file beside a pipe could never be renamed onto it."""
    pipe = tmp_path / "pipe"
    os.mkfifo(pipe)
    read: list[bytes] = []
    reader = threading.Thread(target=lambda: read.append(pipe.read_bytes()))
    reader.start()
    try:
        with whole_file(pipe) as file:
            file.write(b"time\n1.5\n")
    finally:
        reader.join()
    assert read == [b"time\n1.5\n"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["pipe"]


def test_a_missing_package_names_the_extra_to_install() -> None:
    with pytest.raises(MissingExtraError) as caught:
        require("no_such_package_v4x.figure", "plot", "plotting")
    assert str(caught.value) == (
        "plotting needs the 'no_such_package_v4x.figure' package: pip install 'veronte4x[plot]'"
    )
    assert caught.value.extra == "plot"


def test_a_package_whose_own_import_fails_is_not_called_missing(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The package is installed but broken (one of its own dependencies is missing): the
    user sees that module's name, not an advice to install the extra they already have."""
    (tmp_path / "broken_v4x_extra.py").write_text("import no_such_dependency_v4x\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    try:
        with pytest.raises(ModuleNotFoundError) as caught:
            require("broken_v4x_extra", "can", "reading x.blf")
    finally:
        sys.modules.pop("broken_v4x_extra", None)
    assert not isinstance(caught.value, MissingExtraError)
    assert caught.value.name == "no_such_dependency_v4x"
