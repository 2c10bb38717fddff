"""Integer variables (UVar, 16-bit) of the Veronte Autopilot 4x.

Source: 4x Software Manual, section 2.2.3 "Integer Variables (UVar) - 16 Bits".
The table has no unit column. Rows printed with a stray number underneath (a garbled second
copy of the row, e.g. "55", "405", "720") are read once. "Line N" in a correction note counts
lines of the manual's text (release 6.12) as veronte4x read it. UVar 71 and 497 are not in the
manual and are not listed.
"""

from __future__ import annotations

from veronte4x.variables.model import Kind, Variable, entry

_U = Kind.UVAR

INTEGER_VARIABLES: tuple[Variable, ...] = (
    entry(_U, 2, "Internal ADC 0", "Internal ADC pin. Note: Variable for internal use"),
    entry(_U, (3, 7), "ADC 0-4", "Direct reading of ADC pins"),
    entry(
        _U,
        (8, 17),
        "Internal ADC 1-10",
        "Internal ADC pins. Note: Variables for internal use",
        correction='name and description run together: "Internal ADC 1-10 Internal ADC pins" '
        "(line 309)",
    ),
    entry(
        _U,
        53,
        "4XV Veronte ID",
        "ID of the Autopilot 1x for the redundant configuration (0, 3)",
        correction='"AXV Varante ID", "$(0, 3)$", stray "55" (lines 311-312)',
    ),
    entry(
        _U,
        54,
        "4XV Veronte CAP",
        "Current Autopilot 1x selected - If the Autopilot has version 4.7 or higher, it is "
        "obtained from MUX readings, otherwise it is copied from UVar 55 (in this table)",
        correction='"copied from RVar 55 (in this table)" (line 316): the table is the UVar '
        "table and UVar 55 is 4XV Veronte selected",
    ),
    entry(_U, 55, "4XV Veronte selected", "Autopilot 1x selected", stored_in_1x=True),
    entry(
        _U,
        56,
        "4XV Config manager status (flash / sd / safe mode)",
        "Configuration manager state (flash, sd or safe)",
        stored_in_1x=True,
    ),
    entry(
        _U,
        57,
        "4XV File system status",
        "State error for DFS2 file system",
        stored_in_1x=True,
    ),
    entry(
        _U,
        58,
        "4XV CAN to Serial 0 frames dropped",
        "Lost messages during transformations CAN to Serial 0",
        stored_in_1x=True,
        correction='stray "5 0.1" (line 324)',
    ),
    entry(
        _U,
        59,
        "4XV CAN to Serial 1 frames dropped",
        "Lost messages during transformations CAN to Serial 1",
        stored_in_1x=True,
        correction='"CAN to Serial I" (line 325)',
    ),
    entry(
        _U,
        (60, 69),
        "4XV Internal ADC 0-9",
        "4XV Internal ADC pins 0-9",
        stored_in_1x=True,
        correction='"60.60* AVV Internel ADC 0.0 | 1 AVV Internal ADC pind 0.0" (line 327); the '
        'name "4XV Internal ADC 0-9" is legible on line 328; 10 pins up to the next row, 70',
    ),
    entry(
        _U,
        70,
        "4XV VCC for arbiter",
        "4XV VCC for arbiter",
        stored_in_1x=True,
        correction='"70* 4XV Internal ADC 0-9 | 4XV VCC for arbitr" (line 328): the name cell '
        "repeats the row above; name taken from the description, as rows 72-75 print the "
        "same text in both cells",
    ),
    entry(_U, 72, "4XV VCC B", "4XV VCC B", stored_in_1x=True),
    entry(
        _U,
        73,
        "4XV VCC 0",
        "4XV VCC 0",
        stored_in_1x=True,
        correction='"72* | (blank) | 4XV VCC 0" (line 331): id 73 between 72 and 74, name from '
        "the description",
    ),
    entry(_U, 74, "4XV VCC 1", "4XV VCC 1", stored_in_1x=True),
    entry(_U, 75, "4XV VCC 2", "4XV VCC 2", stored_in_1x=True),
    entry(_U, 90, "Version Major", "Major software version"),
    entry(_U, 91, "Version Minor", "Minor software version"),
    entry(_U, 92, "Version Revision", "Revision software version"),
    entry(_U, 95, "UAV address", "UAV address"),
    entry(_U, 450, "CAN-A Tx errors", "CAN A communication errors in transmission"),
    entry(_U, 451, "CAN-A Rx errors", "CAN A communication errors in reception"),
    entry(_U, 452, "CAN-B Tx errors", "CAN B communication errors in transmission"),
    entry(_U, 453, "CAN-B Rx errors", "CAN B communication errors in reception"),
    entry(
        _U,
        (454, 455),
        "CAN to Serial 0-1 frames dropped",
        "Lost messages during CAN to Serial transformations",
        correction='stray "405" (line 347)',
    ),
    entry(
        _U,
        496,
        "Global configuration state (crc) of memory (Higher 16 bits)",
        "Global configuration state (crc) of memory",
        uncertain=True,
        correction='two garbled copies "490 ... (crc) of" and "496 ... (are) of", then '
        '"720 memory (Higher 16 bits) | memory" (lines 348-350); read as 496, next to 498 '
        "and 499",
    ),
    entry(
        _U,
        498,
        "Global configuration state (crc) of files",
        "Global configuration state (crc) of files",
        correction='"(cro) of files | (cre) of files" (lines 351-352)',
    ),
    entry(
        _U,
        499,
        "Global configuration state (crc) of memory",
        "Global configuration state (crc) of memory",
    ),
)
