"""Errors of the arbiter model, in the library's one hierarchy."""

from __future__ import annotations

from veronte4x.errors import Veronte4xError


class ConfigError(Veronte4xError, ValueError):
    """An arbiter configuration that the manuals do not allow.

    Attributes:
        field: The offending field of `ArbiterConfig` or `VariableConfig`.
        value: The offending value.
        allowed: The allowed range or kind, in words.
    """

    def __init__(self, field: str, value: object, allowed: str) -> None:
        self.field = field
        self.value = value
        self.allowed = allowed
        super().__init__(f"ArbiterConfig.{field} = {value!r}: expected {allowed}")


class InputError(Veronte4xError, ValueError):
    """An input the model cannot take: a timestamp going backwards, an unknown autopilot.

    Attributes:
        what: The input, in words.
        value: The offending value.
        allowed: What the model accepts, in words.
    """

    def __init__(self, what: str, value: object, allowed: str) -> None:
        self.what = what
        self.value = value
        self.allowed = allowed
        super().__init__(f"{what} = {value!r}: expected {allowed}")
