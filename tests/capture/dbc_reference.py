"""What cantools itself decodes, by the fields of veronte4x's DBC message classes."""

from __future__ import annotations

from typing import Any

from cantools.database.namedsignalvalue import NamedSignalValue


def cantools_fields(message: Any, data: bytes) -> dict[str, Any]:
    """cantools' values of a frame, named as a message class whose fields keep the DBC's
    signal names (the test DBCs' names need no renaming): each signal's number as
    ``decode_choices=False`` gives it, and for a value table ``<signal>_name``, the name
    ``decode_choices=True`` gives (None where it gives a number); None for a signal the
    frame does not carry.

    Raises:
        Exception: What cantools raises for a frame it refuses.
    """
    numbers = message.decode(data, decode_choices=False)
    names = message.decode(data, decode_choices=True)
    out: dict[str, Any] = {}
    for signal in message.signals:
        out[signal.name] = numbers.get(signal.name)
        if signal.choices:
            name = names.get(signal.name)
            out[f"{signal.name}_name"] = str(name) if isinstance(name, NamedSignalValue) else None
    return out
