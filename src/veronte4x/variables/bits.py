"""Bit variables of the Veronte Autopilot 4x (4x Software Manual, section 2.2.1, "Bit Variables").

The manual prints rows 6-27 many times over in garbled, overlapping forms; each of those
rows below is the reading that the legible copies share. Rows 28 on are printed once, some
with a second, garbled copy of the row underneath. "Line N" in a correction note counts lines of the
manual's text (release 6.12) as veronte4x read it.
"""

from __future__ import annotations

from veronte4x.variables.model import Kind, Variable, entry

_B = Kind.BIT

BIT_VARIABLES: tuple[Variable, ...] = (
    entry(_B, 6, "File System Error", "System file manager - 0 for error, 1 for running"),
    entry(
        _B,
        7,
        "System Error",
        "This bit checks whether the system is running properly. "
        "0 for system error, 1 for system OK",
    ),
    entry(
        _B,
        8,
        "Memory allocation",
        "RAM allocation - 0 for trying to use more than available memory, 1 for running",
    ),
    entry(_B, 9, "PDI Error", "PDI files - 0 for wrong PDI configuration, 1 for running OK"),
    entry(
        _B,
        10,
        "CIO Low or C2 Error",
        "CIO low or C2 failed. Bits 400 and 401 are recommended instead",
    ),
    entry(
        _B,
        11,
        "4X CAN failed",
        "Fail of CAN communication between 1x and Arbiter - 0 for fail, 1 for communication "
        "OK. This bit is initialized with 1. When it is set as 0, it cannot recover until 1x "
        "is restarted",
        deprecated=True,
        correction='the name cell also reads "Warning: Deprecated variable" (printed "Varning", '
        '"Vyriable"), kept as deprecated=True; name printed variously as "114X CAN failed", '
        '"AY CAN foiled", "4A CAN lalled" (lines 131-143)',
    ),
    entry(_B, 12, "System Power up BIT Error", "Power up - 0 for error, 1 for OK"),
    entry(
        _B,
        16,
        "Stack C1 usage FAIL",
        "0 for stack overflow of core 1, 1 for OK",
        correction='one copy (line 125) numbers this row "14"; every other copy reads 16',
    ),
    entry(_B, 20, "4XV System", "System Error bit (bit 7) from the Arbiter", stored_in_1x=True),
    entry(
        _B,
        21,
        "4XV System Power up BIT",
        "Autopilot 4x power up - 0 for fail, 1 for running OK",
        stored_in_1x=True,
    ),
    entry(
        _B,
        22,
        "4XV PDI",
        "PDI files for Autopilot 4x - 0 for wrong PDI configuration, 1 for OK",
        stored_in_1x=True,
    ),
    entry(
        _B,
        23,
        "4XV Memory allocation",
        "RAM allocation - 0 for trying to use more than available memory, 1 for OK",
        stored_in_1x=True,
    ),
    entry(
        _B,
        24,
        "4XV CAN-A BUS OFF",
        "Autopilot 4x CAN A bus - 0 for error, 1 for running OK",
        stored_in_1x=True,
    ),
    entry(
        _B,
        25,
        "4XV CAN-B BUS OFF",
        "Autopilot 4x CAN B bus - 0 for error, 1 for running OK",
        stored_in_1x=True,
    ),
    entry(
        _B,
        26,
        "4XV C1 arbiter",
        "Main Task of CP1 in Autopilot 4x - 0 for error, 1 for running OK",
        stored_in_1x=True,
    ),
    entry(
        _B,
        27,
        "4XV Acquisition arbiter",
        "Autopilot 4x acquisition task in real time - 0 for error, 1 for OK",
        stored_in_1x=True,
    ),
    entry(
        _B,
        28,
        "4XV Power A",
        "State of power supply for Autopilot 4x - 0 for error, 1 for OK",
        stored_in_1x=True,
    ),
    entry(
        _B,
        29,
        "4XV not in maintenance mode",
        "1 for NOT in maintenance mode - 0 for maintenance mode",
        stored_in_1x=True,
        correction='"mantenance" (line 173)',
    ),
    entry(
        _B,
        30,
        "4XV Alive 0",
        "Indicates whether Autopilot 1x number 0 is sending status messages or not - "
        "0 for dead, 1 for alive",
        stored_in_1x=True,
    ),
    entry(
        _B,
        31,
        "4XV Alive 1",
        "Indicates whether Autopilot 1x number 1 is sending status messages or not - "
        "0 for dead, 1 for alive",
        stored_in_1x=True,
    ),
    entry(
        _B,
        32,
        "4XV Alive 2",
        "Indicates whether Autopilot 1x number 2 is sending status messages or not - "
        "0 for dead, 1 for alive",
        stored_in_1x=True,
        correction='"0 for dead. 1 for alive" (line 183)',
    ),
    entry(
        _B,
        33,
        "4XV Alive 3 external",
        "Indicates whether external Autopilot is sending status messages or not - "
        "0 for dead, 1 for alive",
        stored_in_1x=True,
        correction='"for dead 1 for alive" (line 186)',
    ),
    entry(
        _B,
        34,
        "4XV Ready 0",
        "Inner Autopilot 1x number 0 state - 0 for not ready, 1 for ready",
        stored_in_1x=True,
        correction='id "3.4*", "number () state"; garbled copy "54 +X V Ready 0" (lines 187-188)',
    ),
    entry(
        _B,
        35,
        "4XV Ready 1",
        "Inner Autopilot 1x number 1 state - 0 for not ready, 1 for ready",
        stored_in_1x=True,
    ),
    entry(
        _B,
        36,
        "4XV Ready 2",
        "Inner Autopilot 1x number 2 state - 0 for not ready, 1 for ready",
        stored_in_1x=True,
        correction='"AVV Pandy 2"; garbled copy "50. 4X V Ready 2" (lines 191-192)',
    ),
    entry(
        _B,
        37,
        "4XV Ready 3 external",
        "External Autopilot 1x state - 0 for not ready, 1 for ready",
        stored_in_1x=True,
        correction='"4VV Deedy 2 systemed" / "4A V Ready 5 external", "Euternel Autorilet 1v" '
        '/ "External Autophot IX" (lines 193-195); 3 as in "4XV Alive 3 external" (bit 33)',
    ),
    entry(
        _B,
        38,
        "4XV Arbitrating",
        "Arbiter state - 0 for not ready, 1 for ready",
        stored_in_1x=True,
        correction='"4X V Arburating" (line 196)',
    ),
    entry(
        _B,
        39,
        "4XV File Open Error",
        "System file manager state - 0 for error, 1 for running OK",
        stored_in_1x=True,
    ),
    entry(
        _B,
        40,
        "4XV PDI version not compatible",
        "PDI files state - 0 for not compatible with current version, 1 for compatible",
        stored_in_1x=True,
        correction='"I for compatible" (line 201)',
    ),
    entry(
        _B,
        41,
        "4XV Stack usage FAIL",
        "0 for memory overflow allocated for local variables, 1 for OK",
        stored_in_1x=True,
    ),
    entry(
        _B,
        42,
        "4XV PWM1 GPIO Off",
        "GPIO/PWM 1 Value to read - 0 for OFF, 1 for ON",
        stored_in_1x=True,
    ),
    entry(
        _B,
        43,
        "4XV PWM2 GPIO Off",
        "GPIO/PWM 2 Value to read - 0 for OFF, 1 for ON",
        stored_in_1x=True,
    ),
    entry(
        _B,
        44,
        "4XV PWM3 GPIO Off",
        "GPIO/PWM 3 Value to read - 0 for OFF, 1 for ON",
        stored_in_1x=True,
    ),
    entry(
        _B,
        45,
        "4XV PWM4 GPIO Off",
        "GPIO/PWM 4 Value to read - 0 for OFF, 1 for ON",
        stored_in_1x=True,
    ),
    entry(
        _B,
        46,
        "4XV PWM5 GPIO Off",
        "GPIO/PWM 5 Value to read - 0 for OFF, 1 for ON",
        stored_in_1x=True,
    ),
    entry(
        _B,
        47,
        "4XV Watchdog Error (v4.7+)",
        "For version 4.7 or higher - 0 for watchdog signal is not read correctly, 1 for OK",
        correction='"4XV Watchdog Error. (v4.7+)" (line 215); printed without "*"',
    ),
    entry(_B, 73, "CAN-A Error", "CAN A state - 0 for error, 1 for OK"),
    entry(_B, 74, "CAN-B Error", "CAN B state - 0 for error, 1 for OK"),
    entry(_B, 75, "CAN-A Warning", "CAN A state - 0 for warning, 1 for OK"),
    entry(_B, 76, "CAN-B Warning", "CAN B state - 0 for warning, 1 for OK"),
    entry(
        _B,
        117,
        "Main Power Error",
        "Main power supply A. It will be 0 for indicating error state",
        correction='"0 fot indicating" (line 230)',
    ),
    entry(
        _B,
        124,
        "4XV Vcc for Arbiter CPU Error",
        "Power state of CPU Arbiter (Based on RVar 1360) - 0 for error, 1 for OK",
    ),
    entry(
        _B,
        125,
        "4XV Vcc-A Error",
        "State of redundant power supply A (Based on RVar 1361) - 0 for error, 1 for OK",
    ),
    entry(
        _B,
        126,
        "4XV Vcc-B Error",
        "State of redundant power supply B (Based on RVar 1362) - 0 for error, 1 for OK",
    ),
    entry(
        _B,
        127,
        "4XV Vcc-0 Error",
        "Power supply for inner Autopilot 1x number 0 (Based on RVar 1363) - 0 for error, 1 for OK",
        correction='"$RVar 1363$"; stray "120" (lines 241-242)',
    ),
    entry(
        _B,
        128,
        "4XV Vcc-1 Error",
        "Power supply for inner Autopilot 1x number 1 (Based on RVar 1364) - 0 for error, 1 for OK",
        correction='"Autopilot Ix", "$RVar 1364$", "1 for UK" (lines 243-245)',
    ),
    entry(
        _B,
        129,
        "4XV Vcc-2 Error",
        "Power supply for inner Autopilot 1x number 2 (Based on RVar 1365) - 0 for error, 1 for OK",
        correction='"Autopilot Ix", "$RVar 1303$", "1 for UK" (lines 246-248); RVar 1365 is '
        '"4XV Vcc-2", following 127 -> 1363 and 128 -> 1364',
    ),
    entry(
        _B,
        183,
        "4X Selected",
        "4x veronte Autopilot selected - 0 when this AP is not the selected AP, "
        "1 when this AP is the selected one",
        correction='"I when this AF is the selected one" (line 251)',
    ),
    entry(
        _B,
        (230, 293),
        "4XV Custom msg 0-63 Rx Error",
        "Custom messages 0-63 reception timeout - 1 for OK",
        uncertain=True,
        correction='two garbled copies: "220,202 AVV Custom mag 0.62 By Error" and '
        '"230-293 4X V Custom msg 0-03 KX Error | timeout 1 for OK" (lines 251-252); '
        "read as 230-293 (64 ids = messages 0-63); of the description only "
        '"timeout 1 for OK" is legible',
    ),
    entry(
        _B,
        400,
        "C1 Low Frequency",
        "Low priority tasks frequency - 0 for error -> running frequency < 10 Hz, "
        "1 for OK -> running frequency > 10 Hz",
        correction='garbled copy "100 CT Low Trequency" (line 254)',
    ),
    entry(
        _B,
        402,
        "Acquisition step missed",
        "0 for acquisition step missed -> C1 hi frequency fluctuation is higher than "
        "permitted (1%), 1 for acquisition step OK -> C1 hi frequency fluctuation is under "
        "set limits (1%)",
        correction='"permited" (line 262)',
    ),
    entry(
        _B,
        (800, 805),
        "PWM 0-5 GPIO Off",
        "PWM GPIO 0-5 communication state - 0 for Off, 1 for On",
        correction='"Sate" (line 267)',
    ),
    entry(_B, (1200, 1209), "User BIT 00-09 Error", "User bit 0 to 9 - 0 for error, 1 for OK"),
)
