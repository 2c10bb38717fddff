"""The shape of one entry of the manual's variable lists and of its PDI error list.

Source: the Veronte Autopilot 4x Software Manual, section 2 "Lists of interest".
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum


class Kind(str, Enum):
    """Which of the manual's three variable lists an entry belongs to.

    Attributes:
        BIT: Bit variables (4x Software Manual, section 2.2.1).
        RVAR: Real variables, 32-bit float (section 2.2.2).
        UVAR: Integer variables, 16-bit (section 2.2.3).
    """

    BIT = "bit"
    RVAR = "rvar"
    UVAR = "uvar"


@dataclass(frozen=True, slots=True)
class Variable:
    """One row of a variable table: a single id or an id range sharing one name.

    Attributes:
        kind: The table the row comes from.
        first: First id of the row.
        last: Last id of the row (equal to ``first`` for a single variable).
        name: Name as printed in the manual, typos fixed.
        description: Description as printed in the manual, typos fixed.
        unit: The "Units/Value" column (real variables only), ``None`` where blank.
        stored_in_1x: The manual's "*" marker: the variable is stored in the Autopilot 1x
            and, if communication is configured accordingly, carries information sent by
            the Arbiter.
        deprecated: The manual marks the variable "Warning: Deprecated variable".
        uncertain: Part of the row is illegible in the manual and the reading given here
            is the most plausible one, not a certain one (see ``correction``).
        correction: What the manual printed where this entry departs from it, so that every
            correction can be checked against the manual; ``None`` for rows taken as printed.
    """

    kind: Kind
    first: int
    last: int
    name: str
    description: str
    unit: str | None = None
    stored_in_1x: bool = False
    deprecated: bool = False
    uncertain: bool = False
    correction: str | None = None

    @property
    def ids(self) -> range:
        """Every id the row covers."""
        return range(self.first, self.last + 1)

    @property
    def id_text(self) -> str:
        """The id or id range as the manual writes it, e.g. ``"20"`` or ``"800-805"``."""
        return str(self.first) if self.first == self.last else f"{self.first}-{self.last}"


def entry(
    kind: Kind,
    ids: int | tuple[int, int],
    name: str,
    description: str,
    *,
    unit: str | None = None,
    stored_in_1x: bool = False,
    deprecated: bool = False,
    uncertain: bool = False,
    correction: str | None = None,
) -> Variable:
    """Build a :class:`Variable` from a single id or a ``(first, last)`` range."""
    first, last = (ids, ids) if isinstance(ids, int) else ids
    return Variable(
        kind, first, last, name, description, unit, stored_in_1x, deprecated, uncertain, correction
    )


@dataclass(frozen=True, slots=True)
class PdiError:
    """One PDI error the Arbiter can report (4x Software Manual, section 2.3).

    Attributes:
        code: The error's code name, e.g. ``"pdi_arb_cfg2"``.
        number: The error number.
        explanation: The manual's explanation, typos fixed.
        inferred: The number is illegible in the manual and was inferred from the legible
            ones (consecutive numbering).
        seed_text: The manual's row exactly as printed, to check the reading against.
    """

    code: str
    number: int
    explanation: str
    inferred: bool
    seed_text: str
