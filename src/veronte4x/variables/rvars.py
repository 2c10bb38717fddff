"""Real variables (RVar, 32-bit float) of the Veronte Autopilot 4x.

Source: 4x Software Manual, section 2.2.2 "Real Variables (RVar) - 32 Bits". The
unit is the table's "Units/Value" column; it is blank for RVars 1361-1365 and left ``None``
there. "Line N" in a correction note counts lines of the manual's text (release 6.12) as
veronte4x read it.
"""

from __future__ import annotations

from veronte4x.variables.model import Kind, Variable, entry

_R = Kind.RVAR

REAL_VARIABLES: tuple[Variable, ...] = (
    entry(_R, 50, "CAN-A Tx Rate", "CAN-A transmission packet rate", unit="pkts/s"),
    entry(_R, 51, "CAN-B Tx Rate", "CAN-B transmission packet rate", unit="pkts/s"),
    entry(
        _R,
        52,
        "CAN-A Tx Skip Rate",
        "CAN-A messages delayed because no mailbox is available for sending",
        unit="pkts/s",
    ),
    entry(
        _R,
        53,
        "CAN-B Tx Skip Rate",
        "CAN-B messages delayed because no mailbox is available for sending",
        unit="pkts/s",
    ),
    entry(
        _R,
        300,
        "Relative Timestamp",
        "Relative timestamp",
        unit="s",
        uncertain=True,
        correction='unit "S"; the description printed is that of RVar 52 ("CAN-A messages '
        'delayed because no mailbox is available for sending", line 282), a copy error in '
        "the manual: replaced by the name",
    ),
    entry(
        _R,
        (1350, 1356),
        "4XV ADC0-6 Converted Value",
        "4XV ADC0-6 Converted Values",
        unit="V",
        correction='id "1350- 1356" (line 283)',
    ),
    entry(
        _R,
        (1357, 1358),
        "4XV Internal ADC7-8 Converted Value",
        "4XV Internal ADC7-8 Converted Values",
        unit="V",
        correction='id and name split over two lines: "1357-" / "1358 Converted Value" '
        "(lines 284-285)",
    ),
    entry(
        _R,
        1359,
        "4XV Internal ADC 9 Converted Value",
        "4XV Internal Arbiter identifier (A or B)",
        unit="V",
    ),
    entry(_R, 1360, "4XV Vcc for arbiter", "Vcc for arbiter", unit="V"),
    entry(_R, 1361, "4XV Vcc-A 3.3V", "Vcc-A 3.3V"),
    entry(_R, 1362, "4XV Vcc-B 3.3V", "Vcc-B 3.3V"),
    entry(_R, 1363, "4XV Vcc-0", "Vcc-0"),
    entry(_R, 1364, "4XV Vcc-1", "Vcc-1"),
    entry(_R, 1365, "4XV Vcc-2", "Vcc-2"),
    entry(
        _R,
        1366,
        "4XV Autopilot 0 Score",
        "Score of Autopilot 1x number 0",
        unit="customType",
        stored_in_1x=True,
    ),
    entry(
        _R,
        1367,
        "4XV Autopilot 1 Score",
        "Score of Autopilot 1x number 1",
        unit="customType",
        stored_in_1x=True,
    ),
    entry(
        _R,
        1368,
        "4XV Autopilot 2 Score",
        "Score of Autopilot 1x number 2",
        unit="customType",
        stored_in_1x=True,
    ),
    entry(
        _R,
        1369,
        "4XV Autopilot External Score",
        "Score of external Autopilot 1x",
        unit="Decimal",
        stored_in_1x=True,
    ),
)
