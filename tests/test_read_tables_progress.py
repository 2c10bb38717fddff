"""`capture.read_tables` shows a progress bar when asked, or when interactive; else nothing."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

pytest.importorskip("pyarrow")
pytest.importorskip("tqdm")

from veronte4x import capture

CAPTURE = Path(__file__).resolve().parent.parent / "examples" / "capture.log"


def test_a_bar_on_request_and_none_otherwise(capsys: Any) -> None:
    shown = capture.read_tables([CAPTURE, CAPTURE], progress=True)
    assert "decoding" in capsys.readouterr().err
    assert capture.read_tables([CAPTURE, CAPTURE], progress=False) == shown
    assert capsys.readouterr().err == ""
    capture.read_tables(CAPTURE)  # standard error is no terminal here, and no notebook
    assert capsys.readouterr().err == ""


def test_standard_input_and_missing_files_still_say_what_is_wrong(tmp_path: Path) -> None:
    with pytest.raises(FileNotFoundError, match=r"nothing\.log"):
        capture.read_tables([CAPTURE, tmp_path / "nothing.log"], progress=True)


def test_importing_a_kernel_is_not_being_in_a_notebook(capsys: Any) -> None:
    """A test runner or a script that imports ipykernel runs no notebook: no bar."""
    pytest.importorskip("ipykernel")
    import ipykernel.kernelapp  # noqa: F401

    capture.read_tables(CAPTURE)
    assert capsys.readouterr().err == ""
