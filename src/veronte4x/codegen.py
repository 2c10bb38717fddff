"""The one home of generated code: compile it under a readable name, and build slotted objects.

Every function the package generates at run time (the Veronte decoders and encoders of
`veronte4x.codec`, the DroneCAN fast paths) is compiled by `compile_source`. What comes
from data reaches the source as a quoted literal (`repr`) or, where it must be a name, held
to `attribute`; never as raw text. As attrs does
for its generated methods, the source is registered with `linecache` under a unique file
name such as ``<veronte4x generated decode Codec fast #3>``: a traceback through generated
code shows the generated line, and `inspect.getsource` returns the function's text.
"""

from __future__ import annotations

import itertools
import keyword
import linecache
from typing import Any

_COUNTER = itertools.count(1)


def attribute(name: str) -> str:
    """``name``, where generated code writes ``obj.<name>``: an ASCII Python identifier that
    is not a keyword (the DSDL and DBC parsers hold names to that grammar).

    Raises:
        ValueError: Any other text, which must not reach the source.
    """
    if not (name.isascii() and name.isidentifier()) or keyword.iskeyword(name):
        raise ValueError(f"{name!r} cannot be an attribute of generated code")
    return name


def compile_source(source: str, namespace: dict[str, Any], title: str) -> dict[str, Any]:
    """Run generated ``source`` in ``namespace`` under a unique, readable file name.

    Args:
        source: Python source of one or more functions (a module body).
        namespace: The globals of the generated code; the definitions land here.
        title: What the code is, e.g. ``decode Codec fast``; part of the file name.

    Returns:
        ``namespace``, with the names the source defines.
    """
    if not source.endswith("\n"):
        source += "\n"
    filename = f"<veronte4x generated {title} #{next(_COUNTER)}>"
    # (size, mtime, lines, name): a None mtime keeps `linecache.checkcache` from dropping it.
    linecache.cache[filename] = (len(source), None, source.splitlines(True), filename)
    exec(compile(source, filename, "exec"), namespace)
    return namespace


def slot_builder(cls: type) -> type | None:
    """A plain class with the same slots as ``cls``, or None if none fits.

    An instance of it is filled by plain slot stores (no frozen ``__setattr__``, no call)
    and then given the class ``cls`` by ``__class__`` assignment, which Python allows
    between classes of identical layout. The result is an ordinary instance of ``cls``,
    built several times faster than through the slots' setters or a frozen ``__init__``.
    The builder derives from the base under the class that declares the slots, which must
    be a plain slotted class (``object``, `veronte4x.codec.Message`, a slotted dataclass);
    otherwise None (callers then use the slots' setters or the constructor).
    """
    declaring: type = cls
    while not declaring.__dict__.get("__slots__") and declaring.__base__ not in (None, object):
        declaring = declaring.__base__
    base: Any = declaring.__base__
    if base is None or base.__setattr__ is not object.__setattr__:
        return None
    slots = declaring.__dict__.get("__slots__", ())
    made = type(f"_{cls.__name__}Builder", (base,), {"__slots__": tuple(slots)})
    try:
        probe: Any = object.__new__(made)
        probe.__class__ = cls
    except TypeError:
        return None
    return made
