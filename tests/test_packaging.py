"""What ships: a license, no docs generators in the package, a fast `import veronte4x.codec`,
and a wheel that installs on its own and carries every data file the library reads."""

from __future__ import annotations

import subprocess
import sys
import zipfile
from pathlib import Path

import pytest
import tomli

ROOT = Path(__file__).resolve().parent.parent
VERSION = tomli.loads((ROOT / "pyproject.toml").read_text())["project"]["version"]


def test_the_license_is_there_and_declared() -> None:
    assert (ROOT / "LICENSE").read_text().startswith("MIT License\n")
    assert 'license-files = ["LICENSE"]' in (ROOT / "pyproject.toml").read_text()


def test_no_docs_generator_in_the_package() -> None:
    """The docs' table generators live in docs/_hooks/docgen, outside the wheel."""
    assert sorted(p.name for p in (ROOT / "src" / "veronte4x").rglob("docs.py")) == []


def test_the_version_has_one_source() -> None:
    """pyproject.toml's version; the package reads it from the installed metadata."""
    sources = [
        path.relative_to(ROOT).as_posix()
        for path in (ROOT / "src").rglob("*.py")
        if f'"{VERSION}"' in path.read_text()
    ]
    assert sources == []


def test_import_codec_does_not_read_package_metadata() -> None:
    """``__version__`` is looked up on first use: the lookup cost as much as the codec."""
    probe = "import sys, veronte4x.codec; print('importlib.metadata' in sys.modules)"
    result = subprocess.run(
        [sys.executable, "-c", probe], capture_output=True, text=True, check=True
    )
    assert result.stdout == "False\n"
    version = "import veronte4x; print(veronte4x.__version__)"
    result = subprocess.run(
        [sys.executable, "-c", version], capture_output=True, text=True, check=True
    )
    assert result.stdout.strip() == VERSION


def _tracked_data_files() -> list[str]:
    """Every file under src/veronte4x that git tracks and that is not Python source."""
    listed = subprocess.run(
        ["git", "ls-files", "src/veronte4x"], cwd=ROOT, capture_output=True, text=True
    )
    if listed.returncode != 0:
        pytest.skip("not a git checkout: the tracked files are unknown")
    names = [line.removeprefix("src/") for line in listed.stdout.splitlines()]
    return sorted(name for name in names if not name.endswith(".py"))


@pytest.fixture(scope="module")
def dist(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """An sdist and a wheel built as ``python -m build`` builds them (the wheel from the
    sdist), with this environment's setuptools: no package index needed."""
    out = tmp_path_factory.mktemp("dist")
    subprocess.run(
        [sys.executable, "-m", "build", "--no-isolation", "--outdir", str(out), str(ROOT)],
        capture_output=True,
        text=True,
        check=True,
    )
    return out


def test_build_makes_an_sdist_and_a_wheel_that_twine_accepts(dist: Path) -> None:
    names = sorted(path.name for path in dist.iterdir())
    assert names == [f"veronte4x-{VERSION}-py3-none-any.whl", f"veronte4x-{VERSION}.tar.gz"]
    check = subprocess.run(
        [sys.executable, "-m", "twine", "check", "--strict", *map(str, dist.iterdir())],
        capture_output=True,
        text=True,
    )
    assert check.returncode == 0, check.stdout + check.stderr


def test_the_wheel_carries_the_data_files_and_the_license(dist: Path) -> None:
    [wheel] = dist.glob("*.whl")
    shipped = set(zipfile.ZipFile(wheel).namelist())
    data = _tracked_data_files()
    assert "veronte4x/py.typed" in data
    assert [name for name in data if name not in shipped] == []
    assert f"veronte4x-{VERSION}.dist-info/licenses/LICENSE" in shipped
    assert [name for name in shipped if "__pycache__" in name or name.endswith(".pyc")] == []
    assert [name for name in shipped if name.startswith(("tests/", "docs/", "benchmarks/"))] == []


def test_the_wheel_installs_alone_and_imports(dist: Path, tmp_path: Path) -> None:
    """Into a fresh virtual environment, without a package index and with no extra."""
    [wheel] = dist.glob("*.whl")
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True, capture_output=True)
    python = venv / "bin" / "python"
    subprocess.run(
        [str(python), "-m", "pip", "install", "--quiet", "--no-index", str(wheel)],
        check=True,
        capture_output=True,
    )
    probe = (
        "import veronte4x, veronte4x.codec as c\n"
        "m = c.decode(b'\\x00\\xff\\x01', sender=c.Sender.AUTOPILOT)\n"
        "print(veronte4x.__version__, m, c.encode(m).hex(), veronte4x.__file__)\n"
    )
    result = subprocess.run(
        [str(python), "-c", probe], cwd=tmp_path, capture_output=True, text=True, check=True
    )
    version, message, data, location = result.stdout.split()
    assert (version, message, data) == (VERSION, "Ready(ready=True)", "00ff01")
    assert Path(location).is_relative_to(venv)
    cli = subprocess.run(
        [str(venv / "bin" / "veronte4x"), "--help"], capture_output=True, text=True
    )
    assert cli.returncode == 0, cli.stderr
