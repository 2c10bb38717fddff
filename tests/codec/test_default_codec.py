"""The default codec is a plain module attribute, built at import."""

from __future__ import annotations

import pytest

import veronte4x.codec as codec


def test_decode_and_encode_are_the_default_codecs_own() -> None:
    from veronte4x.codec import DEFAULT_CODEC, decode, encode

    assert decode is DEFAULT_CODEC.decode is vars(codec)["decode"]
    assert encode == DEFAULT_CODEC.encode


def test_the_module_has_no_getattr_hook() -> None:
    # CPython does not specialise attribute lookups on a module with __getattr__, which
    # would slow every ``codec.decode`` call down.
    assert "__getattr__" not in vars(codec)
    with pytest.raises(AttributeError, match="has no attribute 'nothing'"):
        codec.nothing  # type: ignore[attr-defined]  # noqa: B018
