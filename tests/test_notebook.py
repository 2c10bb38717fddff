"""examples/flight.ipynb runs top to bottom on the demo flight, as a user opens it after
`make demo`, and is kept in git without outputs."""

from __future__ import annotations

import os
import runpy
import shutil
from pathlib import Path
from typing import Any

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"
NOTEBOOK = EXAMPLES / "flight.ipynb"
VEHICLE_BUS = EXAMPLES / "vehicle_bus.ipynb"


@pytest.mark.parametrize("path", [NOTEBOOK, VEHICLE_BUS], ids=lambda path: path.name)
def test_the_notebook_is_kept_without_outputs(path: Path) -> None:
    notebook = nbformat.read(path, as_version=4)
    nbformat.validate(notebook)
    code = [cell for cell in notebook.cells if cell.cell_type == "code"]
    assert code
    assert [cell.outputs for cell in code if cell.outputs] == []
    assert [cell.execution_count for cell in code if cell.execution_count] == []


@pytest.mark.parametrize("path", [NOTEBOOK, VEHICLE_BUS], ids=lambda path: path.name)
def test_the_docs_show_the_notebook(path: Path) -> None:
    link = EXAMPLES.parent / "docs" / path.name
    assert link.resolve() == path
    assert path.name in (EXAMPLES.parent / "mkdocs.yml").read_text()


def _execute(path: Path, folder: Path, variable: str) -> Any:
    """Run a notebook top to bottom in ``folder`` (the capture named by the environment
    ``variable`` unset); any error in a cell fails the run."""
    notebook = nbformat.read(path, as_version=4)
    saved = os.environ.pop(variable, None)
    try:
        nbclient.NotebookClient(
            notebook,
            timeout=None,
            kernel_name="python3",
            resources={"metadata": {"path": str(folder)}},
        ).execute()
    finally:
        if saved is not None:
            os.environ[variable] = saved
    return notebook


@pytest.fixture(scope="module")
def executed(tmp_path_factory: pytest.TempPathFactory) -> Any:
    """The notebook run top to bottom next to the demo flight, as `make demo` leaves it;
    any error in a cell fails the run."""
    folder = tmp_path_factory.mktemp("examples")
    generate = runpy.run_path(str(EXAMPLES / "make_capture.py"))["generate"]
    generate(2.0, 60.0, 4).write(folder / "flight.log")
    shutil.copy(EXAMPLES / "arbiter.toml", folder)
    return _execute(NOTEBOOK, folder, "VERONTE4X_FLIGHT")


def _outputs(notebook: Any, mime: str) -> list[str]:
    return [
        output["data"][mime]
        for cell in notebook.cells
        if cell.cell_type == "code"
        for output in cell.outputs
        if output.get("output_type") in ("execute_result", "display_data")
        and mime in output["data"]
    ]


def test_the_notebook_runs_and_shows_its_results(executed: Any) -> None:
    errors = [
        output
        for cell in executed.cells
        if cell.cell_type == "code"
        for output in cell.outputs
        if output.get("output_type") == "error" or output.get("name") == "stderr"
    ]
    assert errors == []
    html = "\n".join(_outputs(executed, "text/html"))
    assert "Record: EscStatus" in html  # the record's rich view
    assert "<td>V</td>" in html  # units
    assert "OPERATIONAL" in html  # the node table, enums by name
    assert "by message type" in html  # Stats
    assert "2025-11-21 15:01:00.262115+00:00" in html  # the switch to AP3, time as time
    assert "AP2 dead" in html  # the replay's reason
    assert len(_outputs(executed, "image/png")) == 2  # the two plots, inline
    if not os.environ.get("TQDM_DISABLE"):  # read_tables' and to_parquet's progress bars
        assert len(_outputs(executed, "application/vnd.jupyter.widget-view+json")) == 2


def test_the_vehicle_bus_notebook_decodes_every_type(tmp_path: Path) -> None:
    """The notebook run next to the bus `make demo` writes."""
    runpy.run_path(str(EXAMPLES / "make_vehicle_bus.py"))["write"](tmp_path / "vehicle.log")
    notebook = _execute(VEHICLE_BUS, tmp_path, "VERONTE4X_VEHICLE_BUS")
    errors = [
        output
        for cell in notebook.cells
        if cell.cell_type == "code"
        for output in cell.outputs
        if output.get("output_type") == "error" or output.get("name") == "stderr"
    ]
    assert errors == []
    text = "\n".join(
        output.get("text", "")
        for cell in notebook.cells
        if cell.cell_type == "code"
        for output in cell.outputs
    )
    assert "in 15 tables: 0 unknown, 0 errors" in text
    html = "\n".join(_outputs(notebook, "text/html"))
    for shown in ("BatteryInfo", "Fix2", "STATUS_3D_FIX", "FULLY_ARMED", "OPERATIONAL"):
        assert shown in html
    assert "2023-11-14 22:13:20" in html  # time as time
    assert "Tattu 6S 10000mAh" in html and "b'Tattu" not in html  # text as text
    assert "max_temp_c" in html  # the DuckDB query
    assert "shape: (6, 3)" in "\n".join(_outputs(notebook, "text/plain"))  # the Polars one
    assert len(_outputs(notebook, "image/png")) == 1  # the plot, inline
