"""The Veronte Autopilot 4x manual's variable lists and PDI errors, as clean data.

Source: the Veronte Autopilot 4x Software Manual, section 2 "Lists of interest": bit
variables, real variables (RVar, 32-bit), integer variables (UVar, 16-bit) and PDI errors.
The manual's lists are hard to read in places; every entry here has its typos fixed, and an entry
whose reading
departs from what the manual printed says so in ``Variable.correction`` (PDI errors keep the
printed row in ``PdiError.seed_text``).

``BIT_VARIABLES``, ``REAL_VARIABLES`` and ``INTEGER_VARIABLES`` (also ``VARIABLES[kind]``)
and ``PDI_ERRORS`` are tuples in the manual's order; a row may cover an id range.

Examples:
    >>> from veronte4x import variables
    >>> variables.by_id(variables.Kind.BIT, 803).name
    'PWM 0-5 GPIO Off'
    >>> variables.by_name(variables.Kind.RVAR, "4xv vcc for arbiter").first
    1360
    >>> variables.pdi_error("pdi_arb_cfg2").number
    10005
"""

from __future__ import annotations

from veronte4x.variables.bits import BIT_VARIABLES
from veronte4x.variables.lookup import VARIABLES, by_id, by_name, pdi_error
from veronte4x.variables.model import Kind, PdiError, Variable
from veronte4x.variables.pdi_errors import PDI_ERRORS
from veronte4x.variables.rvars import REAL_VARIABLES
from veronte4x.variables.status_links import STATUS_FLAG_BITS, STATUS_STATE_BITS
from veronte4x.variables.uvars import INTEGER_VARIABLES

__all__ = [
    "BIT_VARIABLES",
    "INTEGER_VARIABLES",
    "PDI_ERRORS",
    "REAL_VARIABLES",
    "STATUS_FLAG_BITS",
    "STATUS_STATE_BITS",
    "VARIABLES",
    "Kind",
    "PdiError",
    "Variable",
    "by_id",
    "by_name",
    "pdi_error",
]
