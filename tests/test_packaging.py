"""What ships: a license, no docs generators in the package, a fast `import veronte4x.codec`."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def test_the_license_is_there_and_declared() -> None:
    assert (ROOT / "LICENSE").read_text().startswith("MIT License\n")
    assert 'license-files = ["LICENSE"]' in (ROOT / "pyproject.toml").read_text()


def test_no_docs_generator_in_the_package() -> None:
    """The docs' table generators live in docs/_hooks/docgen, outside the wheel."""
    assert sorted(p.name for p in (ROOT / "src" / "veronte4x").rglob("docs.py")) == []


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
    assert result.stdout.strip() == "0.1.0"
