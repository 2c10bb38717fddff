"""Which bit variables the flags of the Status message summarise, where the manual says so.

Status bytes 4-5 (4x Software Manual, section 3.1.1, "Status Message") carry sixteen OK flags; the
codec names them ``cbit_ok`` ... ``normal_mode``. Each flag is linked below to the Arbiter's
own bit variable and to its "4XV" copy stored in the Autopilot 1x (marked "*" in the 4x Software
Manual
section 2.2.1), only where a sentence or row of the manual ties them; the justifying text is
quoted above each link ("2.1" is section "Activation System Error bits", "Status" the
Status message table, "bit N" the row of the bit variable table). A flag's bits and the flag
say the same thing with the same polarity: 1 (True) is OK.
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType

STATUS_FLAG_BITS: Mapping[str, tuple[int, ...]] = MappingProxyType(
    {
        # Status byte 4 bit 0: "CBIT. System error. Will fail if any of the below items fail."
        # 2.1: "The System Error variable is indicated by bit number 7."
        # bit 20*: "4XV System | System Error bit (bit 7) from the Arbiter".
        "cbit_ok": (7, 20),
        # Status byte 4 bit 1: "PBIT. System Boot Ok."
        # 2.1: "An error occurred with System power up according to bit 12."
        # bit 12: "System Power up BIT Error | Power up - 0 for error, 1 for OK".
        # bit 21*: "4XV System Power up BIT | Autopilot 4x power up - 0 for fail, 1 for
        # running OK".
        "pbit_ok": (12, 21),
        # Status byte 4 bit 2: "PDI Ok. Will fail if there is an error in configuration files."
        # bit 9: "PDI Error | PDI files - 0 for wrong PDI configuration, 1 for running OK".
        # bit 22*: "4XV PDI | PDI files for Autopilot 4x - 0 for wrong PDI configuration, 1
        # for OK".
        "pdi_ok": (9, 22),
        # Status byte 4 bit 3: "Memory Allocation OK".
        # 2.1: "RAM allocation is in error state ... this is indicated with a 0 on bit 8."
        # bit 23*: "4XV Memory allocation | RAM allocation - 0 for trying to use more than
        # available memory, 1 for OK".
        "memory_ok": (8, 23),
        # Status byte 4 bit 4: "CAN A Ok".
        # 2.1: "CAN A bus is not working, hence bit 73 is set as 0."
        # bit 24*: "4XV CAN-A BUS OFF | Autopilot 4x CAN A bus - 0 for error, 1 for running OK".
        "can_a_ok": (73, 24),
        # Status byte 4 bit 5: "CAN B Ok".
        # 2.1: "CAN B bus is not working, hence bit 74 is set as 0."
        # bit 25*: "4XV CAN-B BUS OFF | Autopilot 4x CAN B bus - 0 for error, 1 for running OK".
        "can_b_ok": (74, 25),
        # Status byte 4 bit 6: "CIO Low Task Ok".
        # 2.1: "Low priority task frequency is not correct, i.e. bit 400 is set as 0."
        # bit 400: "C1 Low Frequency | Low priority tasks frequency". No 1x copy is named.
        "cio_low_ok": (400,),
        # Status byte 4 bit 7: "CIO High Task Ok".
        # 2.1: "Acquisition task frequency is not correct, i.e. bit 402 is set as 0."
        # bit 402: "Acquisition step missed | ... C1 hi frequency fluctuation ...".
        # bit 27*: "4XV Acquisition arbiter | Autopilot 4x acquisition task in real time - 0
        # for error, 1 for OK".
        "cio_high_ok": (402, 27),
        # Status byte 5 bit 0: "Power OK. All power indicators are OK."
        # bit 28*: "4XV Power A | State of power supply for Autopilot 4x - 0 for error, 1 for
        # OK". The manual names no Arbiter-side bit for it.
        "power_ok": (28,),
        # Status byte 5 bit 1: "A Bus Voltage Ok".
        # bit 125: "4XV Vcc-A Error | State of redundant power supply A (Based on RVar 1361)".
        "bus_a_voltage_ok": (125,),
        # Status byte 5 bit 2: "B Bus Voltage Ok".
        # bit 126: "4XV Vcc-B Error | State of redundant power supply B (Based on RVar 1362)".
        "bus_b_voltage_ok": (126,),
        # Status byte 5 bit 3: "Arbiter Voltage Ok".
        # bit 124: "4XV Vcc for Arbiter CPU Error | Power state of CPU Arbiter (Based on RVar
        # 1360)".
        "arbiter_voltage_ok": (124,),
        # Status byte 5 bits 4-6: "AP1 Voltage Ok" ... "AP3 Voltage Ok"; AP1 is autopilot 0
        # (Status byte 2: "0 = AP1, 1 = AP2, 2 = AP3").
        # bits 127-129: "4XV Vcc-0/1/2 Error | Power supply for inner Autopilot 1x number
        # 0/1/2 (Based on RVar 1363/1364/1365)".
        "ap1_voltage_ok": (127,),
        "ap2_voltage_ok": (128,),
        "ap3_voltage_ok": (129,),
        # Status byte 5 bit 7: "Arbiter Mode. 1 = Normal, 0 = Maintenance".
        # bit 29*: "4XV not in maintenance mode | 1 for NOT in maintenance mode - 0 for
        # maintenance mode".
        "normal_mode": (29,),
    }
)
"""Status flag name -> the bit variables it summarises (Arbiter bit first, then 1x copy)."""

STATUS_STATE_BITS: Mapping[str, tuple[int, ...]] = MappingProxyType(
    {
        # Status byte 3 bits 0-3: "AP1 Alive" ... "External AP Alive".
        # bits 30*-33*: "4XV Alive 0/1/2 | Indicates whether Autopilot 1x number 0/1/2 is
        # sending status messages", "4XV Alive 3 external".
        "alive": (30, 31, 32, 33),
        # Status byte 3 bits 4-7: "AP1 Ready" ... "External AP Ready".
        # bits 34*-37*: "4XV Ready 0/1/2 | Inner Autopilot 1x number 0/1/2 state - 0 for not
        # ready, 1 for ready", "4XV Ready 3 external".
        "ready": (34, 35, 36, 37),
        # Status byte 2 bit 7: "Arbitration OFF/ON".
        # bit 38*: "4XV Arbitrating | Arbiter state - 0 for not ready, 1 for ready".
        "arbitrating": (38,),
    }
)
"""Status field -> its 1x-stored bit variables, one per element.

``alive`` and ``ready`` are 4-tuples (AP1, AP2, AP3, external): element ``i`` of the field is
bit ``STATUS_STATE_BITS[field][i]``. ``arbitrating`` is a single flag: bit 38.
"""
