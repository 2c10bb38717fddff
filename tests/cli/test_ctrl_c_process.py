"""Ctrl-C at any moment of a ``veronte4x`` process: one line, exit code 130, no traceback,
no partial output visible.

Every test waits for what it needs (the CLI's output, its open of a FIFO), never for time.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from veronte4x import __main__ as entry
from veronte4x.cli.exit_codes import EXIT_INTERRUPTED

LINES = "".join(f"({i}.0) can0 009#00FF01\n" for i in range(2000))


def _python(code: str, *args: str) -> subprocess.CompletedProcess[bytes]:
    return subprocess.run(
        [sys.executable, "-c", code, *args], capture_output=True, check=False, timeout=600
    )


def test_the_entry_point_knows_the_documented_code() -> None:
    assert entry.EXIT_INTERRUPTED == EXIT_INTERRUPTED == 130


def test_ctrl_c_while_the_command_line_loads() -> None:
    """The handler is in place before the command line's modules load."""
    code = (
        "import signal, sys\n"
        "import veronte4x.__main__ as entry\n"
        "class Loading:\n"
        "    def find_spec(self, name, path, target=None):\n"
        "        if name == 'veronte4x.cli':\n"
        "            signal.raise_signal(signal.SIGINT)\n"
        "sys.meta_path.insert(0, Loading())\n"
        "sys.argv = ['veronte4x', 'decode', 'examples/capture.log']\n"
        "entry.script()\n"
    )
    result = _python(code)
    assert result.returncode == 130
    assert result.stderr == b"veronte4x: interrupted\n"
    assert result.stdout == b""


def test_ctrl_c_once_the_command_has_returned(tmp_path: Path) -> None:
    """A Ctrl-C that lands after the work (a thread raises it while the process exits) still
    ends it with 130 and one line; the output written is all there."""
    capture = tmp_path / "flight.log"
    capture.write_text(LINES)
    code = (
        "import signal, sys, threading\n"
        "import veronte4x.__main__ as entry, veronte4x.cli as cli\n"
        "command = cli.main\n"
        "def main():\n"
        "    code = command()\n"
        "    threading.Thread(target=signal.raise_signal, args=(signal.SIGINT,)).start()\n"
        "    return code\n"
        "cli.main = main\n"
        "sys.argv = ['veronte4x', *sys.argv[1:]]\n"
        "entry.script()\n"
    )
    result = _python(code, "decode", str(capture))
    assert result.returncode == 130
    assert result.stderr.decode().splitlines() == [
        "veronte4x: 2000 records, 0 undecoded, 0 bad (skip)",
        "veronte4x: interrupted",
    ]
    assert len(result.stdout.splitlines()) == 2000


def test_a_finished_command_exits_with_its_own_code(tmp_path: Path) -> None:
    result = subprocess.run(
        [sys.executable, "-m", "veronte4x", "stats", str(tmp_path / "none.log")],
        capture_output=True,
        check=False,
    )
    assert result.returncode == 2
    assert b"Traceback" not in result.stderr


def test_coverage_measures_a_command_line_started_by_a_measured_process(tmp_path: Path) -> None:
    """The process ends with ``os._exit`` (no slow unloading), after saving the data of
    coverage.py if it measures the process (as ``make coverage`` does in the command lines
    the tests start, through its subprocess patch)."""
    coverage = pytest.importorskip("coverage")
    example = Path(__file__).resolve().parents[2] / "examples" / "capture.log"
    (tmp_path / ".coveragerc").write_text(
        "[run]\nparallel = true\npatch = subprocess\nsource_pkgs = veronte4x\n"
        f"data_file = {tmp_path / 'data'}\n"
    )
    (tmp_path / "parent.py").write_text(
        "import subprocess, sys\n"
        f"command = [sys.executable, '-m', 'veronte4x', 'stats', {str(example)!r}]\n"
        "subprocess.run(command, check=True)\n"
    )
    environment = {k: v for k, v in os.environ.items() if not k.startswith("COVERAGE_")}
    result = subprocess.run(
        [sys.executable, "-m", "coverage", "run", "parent.py"],
        capture_output=True,
        check=False,
        env=environment,
        cwd=tmp_path,
    )
    assert result.returncode == 0, result.stderr
    combined = subprocess.run(
        [sys.executable, "-m", "coverage", "combine", "--quiet"],
        capture_output=True,
        check=False,
        env=environment,
        cwd=tmp_path,
    )
    assert combined.returncode == 0, combined.stderr
    measured = coverage.CoverageData(str(tmp_path / "data"))
    measured.read()
    stats = next(f for f in measured.measured_files() if f.endswith("veronte4x/cli/stats.py"))
    lines = Path(stats).read_text().splitlines()
    report = next(i for i, line in enumerate(lines, 1) if "print(capture.stats(" in line)
    assert report in (measured.lines(stats) or ())  # the command's own line, not an import


def _interrupt_on_fifo(tmp_path: Path, args: list[str]) -> subprocess.CompletedProcess[bytes]:
    """Run the CLI on a FIFO, feed it some lines, Ctrl-C it while it waits for more."""
    fifo = tmp_path / "live.log"
    os.mkfifo(fifo)
    process = subprocess.Popen(
        [sys.executable, "-m", "veronte4x", *[str(fifo) if a == "FIFO" else a for a in args]],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    with fifo.open("wb") as writer:  # returns once the CLI has opened the capture
        writer.write(LINES.encode())
        writer.flush()
        process.send_signal(signal.SIGINT)
    out, err = process.communicate(timeout=600)  # a hang guard, not a timed assertion
    return subprocess.CompletedProcess(args, process.returncode, out, err)


def test_ctrl_c_during_convert_leaves_no_part_of_the_dataset(tmp_path: Path) -> None:
    pytest.importorskip("pyarrow.parquet")
    out = tmp_path / "dataset"
    result = _interrupt_on_fifo(tmp_path, ["convert", "FIFO", "--to", "parquet", str(out)])
    assert result.returncode == 130
    assert result.stderr == b"veronte4x: interrupted\n"
    assert list(out.iterdir()) == []  # no capture directory, no run's hidden directory


def test_ctrl_c_during_convert_to_csv_leaves_no_part_of_the_file(tmp_path: Path) -> None:
    pytest.importorskip("pyarrow")
    out = tmp_path / "aligned.csv"
    result = _interrupt_on_fifo(
        tmp_path, ["convert", "FIFO", "--to", "csv", str(out), "--every", "1s"]
    )
    assert result.returncode == 130
    assert result.stderr == b"veronte4x: interrupted\n"
    assert sorted(path.name for path in tmp_path.iterdir()) == ["live.log"]


def _interrupt_after_first_line(args: list[str]) -> subprocess.CompletedProcess[bytes]:
    """Run the CLI, Ctrl-C it once it has written its first line on standard error."""
    process = subprocess.Popen(
        [sys.executable, "-m", "veronte4x", *args],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        stdin=subprocess.DEVNULL,
    )
    assert process.stderr is not None
    first = process.stderr.readline()
    process.send_signal(signal.SIGINT)
    _, rest = process.communicate(timeout=600)  # a hang guard, not a timed assertion
    return subprocess.CompletedProcess(args, process.returncode, b"", first + rest)


def test_ctrl_c_stops_the_simulator_with_the_interrupt_code() -> None:
    """Ctrl-C is 130 as for every command (SIGTERM stays a clean stop, 0), without waiting
    for --duration, and the bus is shut down."""
    pytest.importorskip("can")
    args = ["simulate", "esc", "--interface", "virtual", "--channel", "ctrl-c", "--duration", "600"]
    result = _interrupt_after_first_line(args)
    assert result.returncode == 130
    assert result.stderr.decode().splitlines() == [
        "veronte4x: simulating Vertiq ESC nodes 21 (esc_index 0); Ctrl-C stops",
        "veronte4x: interrupted",
    ]
