"""`codec.decode`, the most-used function, is documented where users look (issue 37, item 8):
``help()`` and Jupyter's ``?`` (both read ``__doc__`` through `inspect`), its import path
(``__module__``, ``__qualname__``), and the API page (mkdocstrings reads the source with
griffe, as ``docs/api/codec.md`` asks)."""

from __future__ import annotations

import inspect
import pickle
import pydoc
from pathlib import Path

import pytest

from veronte4x import codec
from veronte4x.codec.core import Codec

ROOT = Path(__file__).resolve().parents[2]


def test_help_shows_the_signature_and_the_docstring() -> None:
    text = pydoc.plain(pydoc.render_doc(codec.decode))
    assert "decode(data, *, sender, allow_excess=False)" in text
    assert "Decode one Veronte frame's data bytes." in text
    doc = inspect.getdoc(codec.decode)
    assert doc == inspect.getdoc(Codec.decode)
    assert doc is not None and doc.startswith("Decode one Veronte frame's data bytes.\n")
    for section in ("Args:", "Returns:", "Raises:", "UnknownCommandError"):
        assert section in doc


def test_it_names_where_it_imports_from() -> None:
    assert (codec.decode.__module__, codec.decode.__qualname__) == ("veronte4x.codec", "decode")
    assert pickle.loads(pickle.dumps(codec.decode)) is codec.decode


def test_the_decoders_of_any_codec_carry_their_methods_docs() -> None:
    own = Codec()
    assert (own.decode.__module__, own.decode.__qualname__) == (
        "veronte4x.codec.core",
        "Codec.decode",
    )
    assert inspect.getdoc(own.decode) == inspect.getdoc(Codec.decode)
    decoder = own.decoder(codec.Sender.AUTOPILOT)
    assert (decoder.__module__, decoder.__qualname__) == ("veronte4x.codec.core", "Codec.decoder")
    assert inspect.getdoc(decoder) == inspect.getdoc(Codec.decoder)
    assert decoder(b"\x00\xff\x01", False) == codec.Ready(ready=True)


def test_the_api_page_documents_it() -> None:
    griffe = pytest.importorskip("griffe")
    assert "::: veronte4x.codec\n" in (ROOT / "docs" / "api" / "codec.md").read_text()
    module = griffe.load("veronte4x.codec", search_paths=[str(ROOT / "src")])
    decode = module.members["decode"]
    assert decode.docstring is not None  # mkdocstrings leaves out a member without one
    sections = decode.docstring.parse("google")
    text = sections[0].value
    assert text.startswith("Decode one Veronte frame's data bytes with `DEFAULT_CODEC`:")
    assert "``decode(data, *, sender, allow_excess=False)``" in text
    assert "`Codec.decode`" in text
