"""Find a variable by id or name, and a PDI error by number or code name.

The indexes are built once, at import; a lookup is one dictionary access.
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType

from veronte4x.variables.bits import BIT_VARIABLES
from veronte4x.variables.model import Kind, PdiError, Variable
from veronte4x.variables.pdi_errors import PDI_ERRORS
from veronte4x.variables.rvars import REAL_VARIABLES
from veronte4x.variables.uvars import INTEGER_VARIABLES

VARIABLES: Mapping[Kind, tuple[Variable, ...]] = MappingProxyType(
    {Kind.BIT: BIT_VARIABLES, Kind.RVAR: REAL_VARIABLES, Kind.UVAR: INTEGER_VARIABLES}
)
"""Every variable of the manual, per kind, in the manual's order."""


def _name_key(name: str) -> str:
    return " ".join(name.split()).casefold()


_BY_ID: dict[Kind, dict[int, Variable]] = {
    kind: {number: var for var in rows for number in var.ids} for kind, rows in VARIABLES.items()
}
_BY_NAME: dict[Kind, dict[str, Variable]] = {
    kind: {_name_key(var.name): var for var in rows} for kind, rows in VARIABLES.items()
}
_PDI_BY_NUMBER: dict[int, PdiError] = {error.number: error for error in PDI_ERRORS}
_PDI_BY_CODE: dict[str, PdiError] = {error.code.casefold(): error for error in PDI_ERRORS}


def by_id(kind: Kind, number: int) -> Variable | None:
    """The variable of ``kind`` with id ``number``, or ``None`` if the manual lists none.

    An id inside a range row (e.g. bit 803 in 800-805) finds that row.
    """
    return _BY_ID[kind].get(number)


def by_name(kind: Kind, name: str) -> Variable | None:
    """The variable of ``kind`` named ``name`` (case and extra spaces ignored), or ``None``."""
    return _BY_NAME[kind].get(_name_key(name))


def pdi_error(key: int | str) -> PdiError | None:
    """The PDI error with this number (e.g. ``10005``) or code name (e.g. ``"pdi_arb_cfg2"``).

    Code names are matched case-insensitively. Returns ``None`` for an unknown key.
    """
    if isinstance(key, int):
        return _PDI_BY_NUMBER.get(key)
    return _PDI_BY_CODE.get(key.strip().casefold())
