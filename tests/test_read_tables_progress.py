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


def test_one_large_file_moves_the_bar_batch_by_batch(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The bar follows the batches through one file, up to its size, never back."""
    from veronte4x import progress
    from veronte4x.capture.columnar import batches

    path = tmp_path / "long.log"
    path.write_bytes(CAPTURE.read_bytes() * 40)
    steps: list[int] = []

    class Recorder(progress.Bar):
        def update(self, amount: int) -> None:
            steps.append(amount)

    whole = capture.read_tables(path)
    monkeypatch.setattr("veronte4x.capture.columnar.Bar", Recorder)
    monkeypatch.setattr(batches, "BATCH_BYTES", 4096)
    assert capture.read_tables(path, progress=False) == whole
    assert len(steps) > 10
    assert all(step > 0 for step in steps)
    assert sum(steps) == path.stat().st_size
