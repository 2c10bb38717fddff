"""The default codec is built on first use, not at import, and is then a plain attribute."""

from __future__ import annotations

import subprocess
import sys

import pytest


def test_import_does_not_build_the_default_codec() -> None:
    script = (
        "import veronte4x.codec as c\n"
        "print('DEFAULT_CODEC' in vars(c))\n"
        "decode = c.decode\n"
        "print(vars(c)['decode'] is decode is c.DEFAULT_CODEC.decode)\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", script], capture_output=True, text=True, check=True
    )
    assert done.stdout.split() == ["False", "True"]


def test_from_import_and_unknown_names() -> None:
    from veronte4x.codec import DEFAULT_CODEC, decode, encode

    assert decode is DEFAULT_CODEC.decode and encode == DEFAULT_CODEC.encode
    import veronte4x.codec as codec

    with pytest.raises(AttributeError, match="has no attribute 'nothing'"):
        codec.nothing  # noqa: B018
