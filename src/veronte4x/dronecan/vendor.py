"""Every type of the vendor DSDL namespaces shipped with the package (ardupilot, com, cuav, dronecan, mppt).

GENERATED from the DSDL files shipped in ``veronte4x/dronecan/dsdl`` by
``python -m veronte4x.dronecan.generate``: do not edit (a test regenerates and compares).
Named as `veronte4x.dronecan.load_dsdl` names vendor types added to the standard set
(`veronte4x.dronecan.generate`).
"""

from __future__ import annotations

import enum
from typing import Any, ClassVar, TypeAlias

from veronte4x.display import HtmlDisplay
from veronte4x.dronecan.written import frozen_dataclass
from veronte4x.dronecan.standard import (
    Timestamp,
)

_setattr = object.__setattr__
"""How each ``__init__`` sets a frozen field."""


class BatteryContinuousStatusFlag(enum.IntFlag):
    """DSDL constants ``STATUS_FLAG_*``."""

    READY_TO_USE = 1
    CHARGING = 2
    CELL_BALANCING = 4
    FAULT_CELL_IMBALANCE = 8
    AUTO_DISCHARGING = 16
    REQUIRES_SERVICE = 32
    BAD_BATTERY = 64
    PROTECTIONS_ENABLED = 128
    FAULT_PROTECTION_SYSTEM = 256
    FAULT_OVER_VOLT = 512
    FAULT_UNDER_VOLT = 1024
    FAULT_OVER_TEMP = 2048
    FAULT_UNDER_TEMP = 4096
    FAULT_OVER_CURRENT = 8192
    FAULT_SHORT_CIRCUIT = 16384
    FAULT_INCOMPATIBLE_VOLTAGE = 32768
    FAULT_INCOMPATIBLE_FIRMWARE = 65536
    FAULT_INCOMPATIBLE_CELLS_CONFIGURATION = 131072
    CAPACITY_RELATIVE_TO_FULL = 262144


class ProximityReadingType(enum.IntEnum):
    """DSDL constants ``READING_TYPE_*``."""

    NO_DATA = 0
    """Distance is unknown"""
    NOT_CONNECTED = 1
    """Distance field contains valid distance"""
    GOOD = 2
    """Distance field contains valid reading for the sensor"""


class TrafficReportSource(enum.IntEnum):
    """DSDL constants ``SOURCE_*``."""

    ADSB = 0
    ADSB_UAT = 1
    FLARM = 2


class TrafficType(enum.IntEnum):
    """DSDL constants ``TRAFFIC_TYPE_*``."""

    UNKNOWN = 0
    LIGHT = 1
    SMALL = 2
    LARGE = 3
    HIGH_VORTEX_LARGE = 4
    HEAVY = 5
    HIGHLY_MANUV = 6
    ROTOCRAFT = 7
    GLIDER = 9
    LIGHTER_THAN_AIR = 10
    PARACHUTE = 11
    ULTRA_LIGHT = 12
    UAV = 14
    SPACE = 15
    EMERGENCY_SURFACE = 17
    SERVICE_SURFACE = 18
    POINT_OBSTACLE = 19


class AltType(enum.IntEnum):
    """DSDL constants ``ALT_TYPE_*``."""

    ALT_UNKNOWN = 0
    PRESSURE_AMSL = 1
    WGS84 = 2


class ArdupilotGnssStatusStatus(enum.IntEnum):
    """DSDL constants ``STATUS_*``."""

    LOGGING = 1
    """GNSS system is doing any onboard logging"""
    ARMABLE = 2
    """GNSS system is in a reasonable state to allow the system to arm"""


class SafetyStateStatus(enum.IntEnum):
    """DSDL constants ``STATUS_*``."""

    SAFETY_ON = 0
    SAFETY_OFF = 255


class ErrorStatus(enum.IntEnum):
    """DSDL constants ``ERROR_STATUS_*``."""

    NO_ERROR = 0
    DATA_ERROR = 1


class Baud(enum.IntEnum):
    """DSDL constants ``BAUD_*``."""

    BAUD_1MBPS = 0
    BAUD_500KBPS = 1
    BAUD_250KBPS = 2
    BAUD_200KBPS = 3
    BAUD_100KBPS = 4
    BAUD_50KBPS = 5


class Color(enum.IntEnum):
    """DSDL constants ``COLOR_*``."""

    R = 4
    G = 2
    B = 1


class Blink(enum.IntEnum):
    """DSDL constants ``BLINK_*``."""

    BLINK_OFF = 0
    BLINK_1HZ = 1
    BLINK_2HZ = 2
    BLINK_5HZ = 5


class Direction(enum.IntEnum):
    """DSDL constants ``DIRECTION_*``."""

    CLOCKWISE = 0
    COUNTER_CLOCKWISE = 1
    QUERY = 255


class Option(enum.IntEnum):
    """DSDL constants ``OPTION_*``."""

    READ = 0
    WRITE = 1


class Rate(enum.IntEnum):
    """DSDL constants ``RATE_*``."""

    RATE_500HZ = 1
    RATE_250HZ = 2
    RATE_200HZ = 3
    RATE_100HZ = 4
    RATE_50HZ = 5
    RATE_20HZ = 6
    RATE_10HZ = 7
    RATE_1HZ = 8
    RATE_0HZ = 9


class SetThrottleSourceRequestSource(enum.IntEnum):
    """DSDL constants ``SOURCE_*``."""

    CAN_DIGITAL = 0
    PWM = 1


class SelfTestResponseStatus(enum.IntEnum):
    """DSDL constants ``STATUS_*``."""

    PASS = 0
    FAIL = 1


class CBATStatusFlag(enum.IntFlag):
    """DSDL constants ``STATUS_FLAG_*``."""

    IN_USE = 1
    """The battery is currently used as a power supply"""
    CHARGING = 2
    """Charger is active"""
    CHARGED = 4
    """Charging complete, but the charger is still active"""
    TEMP_HOT = 8
    """Battery temperature is above normal"""
    TEMP_COLD = 16
    """Battery temperature is below normal"""
    OVERLOAD = 32
    """Safe operating area violation"""
    BAD_BATTERY = 64
    """This battery should not be used anymore (e.g. low SOH)"""
    NEED_SERVICE = 128
    """This battery requires maintenance (e.g. balancing, full recharge)"""
    BMS_ERROR = 256
    """Battery management system/controller error, smart battery interface error"""
    RESERVED_A = 512
    """Keep zero"""
    RESERVED_B = 1024
    """Keep zero"""


class Result(enum.IntEnum):
    """DSDL constants ``RESULT_*``."""

    ACCEPTED = 0
    TEMPORARILY_REJECTED = 1
    DENIED = 2
    UNSUPPORTED = 3
    FAILED = 4


class Quality(enum.IntEnum):
    """DSDL constants ``QUALITY_*``."""

    TYPE_RSSI = 0
    """quality field represents RSSI in scaled units, 0 is no signal, 255 is "full" signal"""
    TYPE_LQ_ACTIVE_ANTENNA = 4
    """quality field represents LQ in percent in bits 1-7 (0 is no signal, 100 is 100% link quality) and active antenna in bit 8"""
    TYPE_RSSI_DBM = 8
    """quality field represents RSSI in inverted dBm, 0 is no signal, 1 = -1 dBm, 255 = -255 dBm"""
    TYPE_SNR = 12
    """quality field represents SNR in device dependent units, shifted by 128"""
    TYPE_TX_POWER = 16
    """quality field represents uplink power in units of 5 mW"""


@frozen_dataclass
class BatteryInfoAux(HtmlDisplay):
    """``ardupilot.equipment.power.BatteryInfoAux``, message 20004 (``equipment/power/20004.BatteryInfoAux.uavcan``).

    Auxilary Single battery info.

    This message is to be used in conjunction with uavcan/equipment/power/1092.BatteryInfo.uavcan
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"max_current", "nominal_voltage", "voltage_cell"})

    __slots__ = ("timestamp", "voltage_cell", "cycle_count", "over_discharge_count", "max_current", "nominal_voltage", "is_powering_off", "battery_id",)

    timestamp: Timestamp
    voltage_cell: tuple[float, ...]
    """[Volt]"""
    cycle_count: int
    over_discharge_count: int
    max_current: float
    """[Ampere]"""
    nominal_voltage: float
    """[Volt]"""
    is_powering_off: bool
    """Power off event imminent indication, false if unknown"""
    battery_id: int
    """Identifies the battery within this vehicle, e.g. 0 - primary battery"""

    def __init__(
        self,
        timestamp: Timestamp = Timestamp(),
        voltage_cell: tuple[float, ...] = (),
        cycle_count: int = 0,
        over_discharge_count: int = 0,
        max_current: float = 0.0,
        nominal_voltage: float = 0.0,
        is_powering_off: bool = False,
        battery_id: int = 0,
    ) -> None:
        _setattr(self, "timestamp", timestamp)
        _setattr(self, "voltage_cell", voltage_cell)
        _setattr(self, "cycle_count", cycle_count)
        _setattr(self, "over_discharge_count", over_discharge_count)
        _setattr(self, "max_current", max_current)
        _setattr(self, "nominal_voltage", nominal_voltage)
        _setattr(self, "is_powering_off", is_powering_off)
        _setattr(self, "battery_id", battery_id)


@frozen_dataclass
class BatteryContinuous(HtmlDisplay):
    """``ardupilot.equipment.power.BatteryContinuous``, message 20010 (``equipment/power/20010.BatteryContinuous.uavcan``).

    Battery data to be sent continuously
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"state_of_charge", "temperature_cells", "temperature_other", "temperature_pcb"})
    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"capacity_consumed", "current", "voltage"})
    STATUS_FLAG_READY_TO_USE: ClassVar[int] = 1
    STATUS_FLAG_CHARGING: ClassVar[int] = 2
    STATUS_FLAG_CELL_BALANCING: ClassVar[int] = 4
    STATUS_FLAG_FAULT_CELL_IMBALANCE: ClassVar[int] = 8
    STATUS_FLAG_AUTO_DISCHARGING: ClassVar[int] = 16
    STATUS_FLAG_REQUIRES_SERVICE: ClassVar[int] = 32
    STATUS_FLAG_BAD_BATTERY: ClassVar[int] = 64
    STATUS_FLAG_PROTECTIONS_ENABLED: ClassVar[int] = 128
    STATUS_FLAG_FAULT_PROTECTION_SYSTEM: ClassVar[int] = 256
    STATUS_FLAG_FAULT_OVER_VOLT: ClassVar[int] = 512
    STATUS_FLAG_FAULT_UNDER_VOLT: ClassVar[int] = 1024
    STATUS_FLAG_FAULT_OVER_TEMP: ClassVar[int] = 2048
    STATUS_FLAG_FAULT_UNDER_TEMP: ClassVar[int] = 4096
    STATUS_FLAG_FAULT_OVER_CURRENT: ClassVar[int] = 8192
    STATUS_FLAG_FAULT_SHORT_CIRCUIT: ClassVar[int] = 16384
    STATUS_FLAG_FAULT_INCOMPATIBLE_VOLTAGE: ClassVar[int] = 32768
    STATUS_FLAG_FAULT_INCOMPATIBLE_FIRMWARE: ClassVar[int] = 65536
    STATUS_FLAG_FAULT_INCOMPATIBLE_CELLS_CONFIGURATION: ClassVar[int] = 131072
    STATUS_FLAG_CAPACITY_RELATIVE_TO_FULL: ClassVar[int] = 262144

    __slots__ = ("temperature_cells", "temperature_pcb", "temperature_other", "current", "voltage", "state_of_charge", "slot_id", "capacity_consumed", "status_flags",)

    temperature_cells: float
    """[C]  : Pack mounted thermistor (preferably installed between cells), NAN: field not provided"""
    temperature_pcb: float
    """[C]  : Battery PCB temperature (likely output FET(s) or current sense resistor), NAN: field not provided"""
    temperature_other: float
    """[C]  : Application dependent, NAN: field not provided"""
    current: float
    """[A]  : Positive: defined as a discharge current. Negative: defined as a charging current, NAN: field not provided"""
    voltage: float
    """[V]  : Battery voltage"""
    state_of_charge: float
    """[%]  : The estimated state of charge, in percent remaining (0 - 100)."""
    slot_id: int
    """: The physical location of the battery on the aircraft. 0: field not provided"""
    capacity_consumed: float
    """[Ah] : This is either the consumption since power-on or since the battery was full, depending on the value of STATUS_FLAG_CAPACITY_RELATIVE_TO_FULL, NAN: field not provided"""
    status_flags: int
    """: Fault, health, readiness, and other status indications"""

    def __init__(
        self,
        temperature_cells: float = 0.0,
        temperature_pcb: float = 0.0,
        temperature_other: float = 0.0,
        current: float = 0.0,
        voltage: float = 0.0,
        state_of_charge: float = 0.0,
        slot_id: int = 0,
        capacity_consumed: float = 0.0,
        status_flags: int = 0,
    ) -> None:
        _setattr(self, "temperature_cells", temperature_cells)
        _setattr(self, "temperature_pcb", temperature_pcb)
        _setattr(self, "temperature_other", temperature_other)
        _setattr(self, "current", current)
        _setattr(self, "voltage", voltage)
        _setattr(self, "state_of_charge", state_of_charge)
        _setattr(self, "slot_id", slot_id)
        _setattr(self, "capacity_consumed", capacity_consumed)
        _setattr(self, "status_flags", status_flags)


@frozen_dataclass
class BatteryPeriodic(HtmlDisplay):
    """``ardupilot.equipment.power.BatteryPeriodic``, message 20011 (``equipment/power/20011.BatteryPeriodic.uavcan``).

    Battery data to be sent statically upon request or periodically at a low rate
    Recommend that this message is sent at a maximum of 1Hz and nominally 0.2 Hz (IE: once every 5 seconds.)
    """

    _TEXT_FIELDS_: ClassVar[frozenset[str]] = frozenset({"manufacture_date", "name", "serial_number"})
    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"charging_maximum_voltage", "charging_minimum_voltage", "discharge_minimum_voltage", "nominal_voltage"})
    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"charging_maximum_current", "design_capacity", "discharge_maximum_burst_current", "discharge_maximum_current", "full_charge_capacity"})

    __slots__ = ("name", "serial_number", "manufacture_date", "design_capacity", "cells_in_series", "nominal_voltage", "discharge_minimum_voltage", "charging_minimum_voltage", "charging_maximum_voltage", "charging_maximum_current", "discharge_maximum_current", "discharge_maximum_burst_current", "full_charge_capacity", "cycle_count", "state_of_health",)

    name: bytes
    """: Formatted as manufacturer_product, 0 terminated"""
    serial_number: bytes
    """: Serial number in ASCII characters, 0 terminated"""
    manufacture_date: bytes
    """: Manufacture date (DDMMYYYY) in ASCII characters, 0 terminated"""
    design_capacity: float
    """[Ah] : Fully charged design capacity. 0: field not provided."""
    cells_in_series: int
    """: Number of battery cells in series. 0: field not provided."""
    nominal_voltage: float
    """[V]  : Battery nominal voltage. Used for conversion between Wh and Ah. 0: field not provided."""
    discharge_minimum_voltage: float
    """[V]  : Minimum per-cell voltage when discharging. 0: field not provided."""
    charging_minimum_voltage: float
    """[V]  : Minimum per-cell voltage when charging. 0: field not provided."""
    charging_maximum_voltage: float
    """[V]  : Maximum per-cell voltage when charged. 0: field not provided."""
    charging_maximum_current: float
    """[A]  : Maximum pack continuous charge current. 0: field not provided."""
    discharge_maximum_current: float
    """[A]  : Maximum pack continuous discharge current. 0: field not provided."""
    discharge_maximum_burst_current: float
    """[A]  : Maximum pack discharge burst current for 30 seconds. 0: field not provided"""
    full_charge_capacity: float
    """[Ah] : Predicted battery capacity when fully charged (accounting for battery degradation), NAN: field not provided"""
    cycle_count: int
    """: Lifetime count of the number of charge/discharge cycles (https://en.wikipedia.org/wiki/Charge_cycle). UINT16_MAX: field not provided."""
    state_of_health: int
    """[%]  : State of Health (SOH) estimate, in percent (0 - 100). UINT8_MAX: field not provided."""

    def __init__(
        self,
        name: bytes = b"",
        serial_number: bytes = b"",
        manufacture_date: bytes = b"",
        design_capacity: float = 0.0,
        cells_in_series: int = 0,
        nominal_voltage: float = 0.0,
        discharge_minimum_voltage: float = 0.0,
        charging_minimum_voltage: float = 0.0,
        charging_maximum_voltage: float = 0.0,
        charging_maximum_current: float = 0.0,
        discharge_maximum_current: float = 0.0,
        discharge_maximum_burst_current: float = 0.0,
        full_charge_capacity: float = 0.0,
        cycle_count: int = 0,
        state_of_health: int = 0,
    ) -> None:
        _setattr(self, "name", name)
        _setattr(self, "serial_number", serial_number)
        _setattr(self, "manufacture_date", manufacture_date)
        _setattr(self, "design_capacity", design_capacity)
        _setattr(self, "cells_in_series", cells_in_series)
        _setattr(self, "nominal_voltage", nominal_voltage)
        _setattr(self, "discharge_minimum_voltage", discharge_minimum_voltage)
        _setattr(self, "charging_minimum_voltage", charging_minimum_voltage)
        _setattr(self, "charging_maximum_voltage", charging_maximum_voltage)
        _setattr(self, "charging_maximum_current", charging_maximum_current)
        _setattr(self, "discharge_maximum_current", discharge_maximum_current)
        _setattr(self, "discharge_maximum_burst_current", discharge_maximum_burst_current)
        _setattr(self, "full_charge_capacity", full_charge_capacity)
        _setattr(self, "cycle_count", cycle_count)
        _setattr(self, "state_of_health", state_of_health)


@frozen_dataclass
class BatteryCells(HtmlDisplay):
    """``ardupilot.equipment.power.BatteryCells``, message 20012 (``equipment/power/20012.BatteryCells.uavcan``).

    Battery cell voltages
    Rate: set by parameter on smart battery (default off)
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"voltages"})

    __slots__ = ("voltages", "index",)

    voltages: tuple[float, ...]
    """[Volt]"""
    index: int
    """Index of the first cell in the array, index 0 is cells at array indices 0 - 23, index 24 is cells at array indices 24 - 47, etc."""

    def __init__(
        self,
        voltages: tuple[float, ...] = (),
        index: int = 0,
    ) -> None:
        _setattr(self, "voltages", voltages)
        _setattr(self, "index", index)


@frozen_dataclass
class BatteryTag(HtmlDisplay):
    """``ardupilot.equipment.power.BatteryTag``, message 20500 (``equipment/power/20500.BatteryTag.uavcan``).

    Battery tag information. This is broadcast by a battery tag device
    permanently attached to a battery to record the lifecycle of the battery
    """

    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"armed_hours"})

    __slots__ = ("serial_number", "num_cycles", "armed_hours", "battery_capacity_mAh", "first_use_mins", "last_arm_time_mins",)

    serial_number: int
    num_cycles: int
    armed_hours: float
    battery_capacity_mAh: int
    first_use_mins: int
    last_arm_time_mins: int

    def __init__(
        self,
        serial_number: int = 0,
        num_cycles: int = 0,
        armed_hours: float = 0.0,
        battery_capacity_mAh: int = 0,
        first_use_mins: int = 0,
        last_arm_time_mins: int = 0,
    ) -> None:
        _setattr(self, "serial_number", serial_number)
        _setattr(self, "num_cycles", num_cycles)
        _setattr(self, "armed_hours", armed_hours)
        _setattr(self, "battery_capacity_mAh", battery_capacity_mAh)
        _setattr(self, "first_use_mins", first_use_mins)
        _setattr(self, "last_arm_time_mins", last_arm_time_mins)


@frozen_dataclass
class Proximity(HtmlDisplay):
    """``ardupilot.equipment.proximity_sensor.Proximity``, message 21910 (``equipment/proximity_sensor/21910.Proximity.uavcan``).

    Proximity data
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"distance", "pitch", "yaw"})
    READING_TYPE_NO_DATA: ClassVar[int] = 0
    """Distance is unknown"""
    READING_TYPE_NOT_CONNECTED: ClassVar[int] = 1
    """Distance field contains valid distance"""
    READING_TYPE_GOOD: ClassVar[int] = 2
    """Distance field contains valid reading for the sensor"""
    FLAGS_NONE: ClassVar[int] = 0

    __slots__ = ("sensor_id", "reading_type", "flags", "yaw", "pitch", "distance",)

    sensor_id: int
    """Sensor ID"""
    reading_type: ProximityReadingType | int
    """Sensor Status"""
    flags: int
    """Reserved"""
    yaw: float
    """Degrees in body frame"""
    pitch: float
    """Degrees in body frame"""
    distance: float
    """Meters"""

    def __init__(
        self,
        sensor_id: int = 0,
        reading_type: ProximityReadingType | int = 0,
        flags: int = 0,
        yaw: float = 0.0,
        pitch: float = 0.0,
        distance: float = 0.0,
    ) -> None:
        _setattr(self, "sensor_id", sensor_id)
        _setattr(self, "reading_type", reading_type)
        _setattr(self, "flags", flags)
        _setattr(self, "yaw", yaw)
        _setattr(self, "pitch", pitch)
        _setattr(self, "distance", distance)


@frozen_dataclass
class TrafficReport(HtmlDisplay):
    """``ardupilot.equipment.trafficmonitor.TrafficReport``, message 20790 (``equipment/trafficmonitor/20790.TrafficReport.uavcan``).

    Network-synchronized timestamp, 0 if not available. Note: not necessarily a UTC time.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"heading", "velocity"})
    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"alt_m"})
    SOURCE_ADSB: ClassVar[int] = 0
    SOURCE_ADSB_UAT: ClassVar[int] = 1
    SOURCE_FLARM: ClassVar[int] = 2
    TRAFFIC_TYPE_UNKNOWN: ClassVar[int] = 0
    TRAFFIC_TYPE_LIGHT: ClassVar[int] = 1
    TRAFFIC_TYPE_SMALL: ClassVar[int] = 2
    TRAFFIC_TYPE_LARGE: ClassVar[int] = 3
    TRAFFIC_TYPE_HIGH_VORTEX_LARGE: ClassVar[int] = 4
    TRAFFIC_TYPE_HEAVY: ClassVar[int] = 5
    TRAFFIC_TYPE_HIGHLY_MANUV: ClassVar[int] = 6
    TRAFFIC_TYPE_ROTOCRAFT: ClassVar[int] = 7
    TRAFFIC_TYPE_GLIDER: ClassVar[int] = 9
    TRAFFIC_TYPE_LIGHTER_THAN_AIR: ClassVar[int] = 10
    TRAFFIC_TYPE_PARACHUTE: ClassVar[int] = 11
    TRAFFIC_TYPE_ULTRA_LIGHT: ClassVar[int] = 12
    TRAFFIC_TYPE_UAV: ClassVar[int] = 14
    TRAFFIC_TYPE_SPACE: ClassVar[int] = 15
    TRAFFIC_TYPE_EMERGENCY_SURFACE: ClassVar[int] = 17
    TRAFFIC_TYPE_SERVICE_SURFACE: ClassVar[int] = 18
    TRAFFIC_TYPE_POINT_OBSTACLE: ClassVar[int] = 19
    ALT_TYPE_ALT_UNKNOWN: ClassVar[int] = 0
    ALT_TYPE_PRESSURE_AMSL: ClassVar[int] = 1
    ALT_TYPE_WGS84: ClassVar[int] = 2

    __slots__ = ("timestamp", "icao_address", "tslc", "latitude_deg_1e7", "longitude_deg_1e7", "alt_m", "heading", "velocity", "squawk", "callsign", "source", "traffic_type", "alt_type", "lat_lon_valid", "heading_valid", "velocity_valid", "callsign_valid", "ident_valid", "simulated_report", "vertical_velocity_valid", "baro_valid",)

    timestamp: Timestamp
    icao_address: int
    tslc: int
    latitude_deg_1e7: int
    longitude_deg_1e7: int
    alt_m: float
    heading: float
    velocity: tuple[float, ...]
    squawk: int
    callsign: bytes
    source: TrafficReportSource | int
    traffic_type: TrafficType | int
    alt_type: AltType | int
    lat_lon_valid: bool
    heading_valid: bool
    velocity_valid: bool
    callsign_valid: bool
    ident_valid: bool
    simulated_report: bool
    vertical_velocity_valid: bool
    baro_valid: bool

    def __init__(
        self,
        timestamp: Timestamp = Timestamp(),
        icao_address: int = 0,
        tslc: int = 0,
        latitude_deg_1e7: int = 0,
        longitude_deg_1e7: int = 0,
        alt_m: float = 0.0,
        heading: float = 0.0,
        velocity: tuple[float, ...] = (0.0,) * 3,
        squawk: int = 0,
        callsign: bytes = bytes(9),
        source: TrafficReportSource | int = 0,
        traffic_type: TrafficType | int = 0,
        alt_type: AltType | int = 0,
        lat_lon_valid: bool = False,
        heading_valid: bool = False,
        velocity_valid: bool = False,
        callsign_valid: bool = False,
        ident_valid: bool = False,
        simulated_report: bool = False,
        vertical_velocity_valid: bool = False,
        baro_valid: bool = False,
    ) -> None:
        _setattr(self, "timestamp", timestamp)
        _setattr(self, "icao_address", icao_address)
        _setattr(self, "tslc", tslc)
        _setattr(self, "latitude_deg_1e7", latitude_deg_1e7)
        _setattr(self, "longitude_deg_1e7", longitude_deg_1e7)
        _setattr(self, "alt_m", alt_m)
        _setattr(self, "heading", heading)
        _setattr(self, "velocity", velocity)
        _setattr(self, "squawk", squawk)
        _setattr(self, "callsign", callsign)
        _setattr(self, "source", source)
        _setattr(self, "traffic_type", traffic_type)
        _setattr(self, "alt_type", alt_type)
        _setattr(self, "lat_lon_valid", lat_lon_valid)
        _setattr(self, "heading_valid", heading_valid)
        _setattr(self, "velocity_valid", velocity_valid)
        _setattr(self, "callsign_valid", callsign_valid)
        _setattr(self, "ident_valid", ident_valid)
        _setattr(self, "simulated_report", simulated_report)
        _setattr(self, "vertical_velocity_valid", vertical_velocity_valid)
        _setattr(self, "baro_valid", baro_valid)


@frozen_dataclass
class Heading(HtmlDisplay):
    """``ardupilot.gnss.Heading``, message 20002 (``gnss/20002.Heading.uavcan``)."""

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"heading_accuracy_rad", "heading_rad"})

    __slots__ = ("heading_valid", "heading_accuracy_valid", "heading_rad", "heading_accuracy_rad",)

    heading_valid: bool
    heading_accuracy_valid: bool
    heading_rad: float
    heading_accuracy_rad: float

    def __init__(
        self,
        heading_valid: bool = False,
        heading_accuracy_valid: bool = False,
        heading_rad: float = 0.0,
        heading_accuracy_rad: float = 0.0,
    ) -> None:
        _setattr(self, "heading_valid", heading_valid)
        _setattr(self, "heading_accuracy_valid", heading_accuracy_valid)
        _setattr(self, "heading_rad", heading_rad)
        _setattr(self, "heading_accuracy_rad", heading_accuracy_rad)


@frozen_dataclass
class ArdupilotGnssStatus(HtmlDisplay):
    """``ardupilot.gnss.Status``, message 20003 (``gnss/20003.Status.uavcan``).

    Node specific GNSS error codes, primarily available for logging and diagnostics
    """

    STATUS_LOGGING: ClassVar[int] = 1
    """GNSS system is doing any onboard logging"""
    STATUS_ARMABLE: ClassVar[int] = 2
    """GNSS system is in a reasonable state to allow the system to arm"""

    __slots__ = ("error_codes", "healthy", "status",)

    error_codes: int
    healthy: bool
    status: ArdupilotGnssStatusStatus | int

    def __init__(
        self,
        error_codes: int = 0,
        healthy: bool = False,
        status: ArdupilotGnssStatusStatus | int = 0,
    ) -> None:
        _setattr(self, "error_codes", error_codes)
        _setattr(self, "healthy", healthy)
        _setattr(self, "status", status)


@frozen_dataclass
class MovingBaselineData(HtmlDisplay):
    """``ardupilot.gnss.MovingBaselineData``, message 20005 (``gnss/20005.MovingBaselineData.uavcan``).

    length of data is set per the number of bytes for pkt in
    libraries/AP_GPS/RTCM3_Parser.h
    """

    __slots__ = ("data",)

    data: bytes

    def __init__(
        self,
        data: bytes = b"",
    ) -> None:
        _setattr(self, "data", data)


@frozen_dataclass
class RelPosHeading(HtmlDisplay):
    """``ardupilot.gnss.RelPosHeading``, message 20006 (``gnss/20006.RelPosHeading.uavcan``).

    timestamp on the gps message
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"relative_distance_m", "relative_down_pos_m"})
    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"reported_heading_acc_deg", "reported_heading_deg"})

    __slots__ = ("timestamp", "reported_heading_acc_available", "reported_heading_deg", "reported_heading_acc_deg", "relative_distance_m", "relative_down_pos_m",)

    timestamp: Timestamp
    reported_heading_acc_available: bool
    reported_heading_deg: float
    reported_heading_acc_deg: float
    relative_distance_m: float
    relative_down_pos_m: float

    def __init__(
        self,
        timestamp: Timestamp = Timestamp(),
        reported_heading_acc_available: bool = False,
        reported_heading_deg: float = 0.0,
        reported_heading_acc_deg: float = 0.0,
        relative_distance_m: float = 0.0,
        relative_down_pos_m: float = 0.0,
    ) -> None:
        _setattr(self, "timestamp", timestamp)
        _setattr(self, "reported_heading_acc_available", reported_heading_acc_available)
        _setattr(self, "reported_heading_deg", reported_heading_deg)
        _setattr(self, "reported_heading_acc_deg", reported_heading_acc_deg)
        _setattr(self, "relative_distance_m", relative_distance_m)
        _setattr(self, "relative_down_pos_m", relative_down_pos_m)


@frozen_dataclass
class SafetyState(HtmlDisplay):
    """``ardupilot.indication.SafetyState``, message 20000 (``indication/20000.SafetyState.uavcan``).

    support for Safety LED on UAVCAN
    """

    STATUS_SAFETY_ON: ClassVar[int] = 0
    STATUS_SAFETY_OFF: ClassVar[int] = 255

    __slots__ = ("status",)

    status: SafetyStateStatus | int

    def __init__(
        self,
        status: SafetyStateStatus | int = 0,
    ) -> None:
        _setattr(self, "status", status)


@frozen_dataclass
class Button(HtmlDisplay):
    """``ardupilot.indication.Button``, message 20001 (``indication/20001.Button.uavcan``).

    support for buttons on UAVCAN
    while a button is being pressed this message should be sent at 10Hz
    """

    BUTTON_SAFETY: ClassVar[int] = 1

    __slots__ = ("button", "press_time",)

    button: int
    press_time: int

    def __init__(
        self,
        button: int = 0,
        press_time: int = 0,
    ) -> None:
        _setattr(self, "button", button)
        _setattr(self, "press_time", press_time)


@frozen_dataclass
class NotifyState(HtmlDisplay):
    """``ardupilot.indication.NotifyState``, message 20007 (``indication/20007.NotifyState.uavcan``)."""

    VEHICLE_STATE_INITIALISING: ClassVar[int] = 0
    VEHICLE_STATE_ARMED: ClassVar[int] = 1
    VEHICLE_STATE_FLYING: ClassVar[int] = 2
    VEHICLE_STATE_PREARM: ClassVar[int] = 3
    VEHICLE_STATE_PREARM_GPS: ClassVar[int] = 4
    VEHICLE_STATE_SAVE_TRIM: ClassVar[int] = 5
    VEHICLE_STATE_ESC_CALIBRATION: ClassVar[int] = 6
    VEHICLE_STATE_FAILSAFE_RADIO: ClassVar[int] = 7
    VEHICLE_STATE_FAILSAFE_BATT: ClassVar[int] = 8
    VEHICLE_STATE_FAILSAFE_GCS: ClassVar[int] = 9
    VEHICLE_STATE_CHUTE_RELEASED: ClassVar[int] = 10
    VEHICLE_STATE_EKF_BAD: ClassVar[int] = 11
    VEHICLE_STATE_FW_UPDATE: ClassVar[int] = 12
    VEHICLE_STATE_MAGCAL_RUN: ClassVar[int] = 13
    VEHICLE_STATE_LEAK_DET: ClassVar[int] = 14
    VEHICLE_STATE_GPS_FUSION: ClassVar[int] = 15
    VEHICLE_STATE_GPS_GLITCH: ClassVar[int] = 16
    VEHICLE_STATE_POS_ABS_AVAIL: ClassVar[int] = 17
    VEHICLE_STATE_LOST: ClassVar[int] = 18
    VEHICLE_STATE_THROW_READY: ClassVar[int] = 19
    VEHICLE_STATE_POWERING_OFF: ClassVar[int] = 20
    VEHICLE_STATE_VIDEO_RECORDING: ClassVar[int] = 21
    VEHICLE_STATE_IS_LANDING: ClassVar[int] = 22
    VEHICLE_STATE_IS_TAKING_OFF: ClassVar[int] = 23
    VEHICLE_YAW_EARTH_CENTIDEGREES: ClassVar[int] = 0

    __slots__ = ("aux_data_type", "aux_data", "vehicle_state",)

    aux_data_type: int
    aux_data: bytes
    vehicle_state: int

    def __init__(
        self,
        aux_data_type: int = 0,
        aux_data: bytes = b"",
        vehicle_state: int = 0,
    ) -> None:
        _setattr(self, "aux_data_type", aux_data_type)
        _setattr(self, "aux_data", aux_data)
        _setattr(self, "vehicle_state", vehicle_state)


@frozen_dataclass
class FlowMeasurement(HtmlDisplay):
    """``com.hex.equipment.flow.Measurement``, message 20200 (``hex/equipment/flow/20200.Measurement.uavcan``)."""

    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"flow_integral", "integration_interval", "rate_gyro_integral"})

    __slots__ = ("integration_interval", "rate_gyro_integral", "flow_integral", "quality",)

    integration_interval: float
    """Integration Interval in seconds"""
    rate_gyro_integral: tuple[float, ...]
    """Integrated Gyro Data in radians"""
    flow_integral: tuple[float, ...]
    """Integrated LOS Data in radians"""
    quality: int
    """Flow Data Quality Lowest(0)-Highest(255) Unitless"""

    def __init__(
        self,
        integration_interval: float = 0.0,
        rate_gyro_integral: tuple[float, ...] = (0.0,) * 2,
        flow_integral: tuple[float, ...] = (0.0,) * 2,
        quality: int = 0,
    ) -> None:
        _setattr(self, "integration_interval", integration_interval)
        _setattr(self, "rate_gyro_integral", rate_gyro_integral)
        _setattr(self, "flow_integral", flow_integral)
        _setattr(self, "quality", quality)


@frozen_dataclass
class ServoCmd(HtmlDisplay):
    """``com.himark.servo.ServoCmd``, message 2018 (``himark/servo/2018.ServoCmd.uavcan``).

    Himark servo commands
    it is not recommended that anyone implement this message. It is here as a placeholder
    for existing Himark servos
    """

    __slots__ = ("cmd",)

    cmd: tuple[int, ...]

    def __init__(
        self,
        cmd: tuple[int, ...] = (),
    ) -> None:
        _setattr(self, "cmd", cmd)


@frozen_dataclass
class ServoInfo(HtmlDisplay):
    """``com.himark.servo.ServoInfo``, message 2019 (``himark/servo/2019.ServoInfo.uavcan``).

    Himark servo feedback information
    it is not recommended that anyone implement this message. It is here as a placeholder
    for existing Himark servos
    """

    ERROR_STATUS_NO_ERROR: ClassVar[int] = 0
    ERROR_STATUS_DATA_ERROR: ClassVar[int] = 1

    __slots__ = ("servo_id", "pwm_input", "pos_cmd", "pos_sensor", "voltage", "current", "pcb_temp", "motor_temp", "error_status",)

    servo_id: int
    pwm_input: int
    pos_cmd: int
    pos_sensor: int
    voltage: int
    current: int
    pcb_temp: int
    motor_temp: int
    error_status: ErrorStatus | int

    def __init__(
        self,
        servo_id: int = 0,
        pwm_input: int = 0,
        pos_cmd: int = 0,
        pos_sensor: int = 0,
        voltage: int = 0,
        current: int = 0,
        pcb_temp: int = 0,
        motor_temp: int = 0,
        error_status: ErrorStatus | int = 0,
    ) -> None:
        _setattr(self, "servo_id", servo_id)
        _setattr(self, "pwm_input", pwm_input)
        _setattr(self, "pos_cmd", pos_cmd)
        _setattr(self, "pos_sensor", pos_sensor)
        _setattr(self, "voltage", voltage)
        _setattr(self, "current", current)
        _setattr(self, "pcb_temp", pcb_temp)
        _setattr(self, "motor_temp", motor_temp)
        _setattr(self, "error_status", error_status)


@frozen_dataclass
class GetEscID(HtmlDisplay):
    """``com.hobbywing.esc.GetEscID``, message 20013 (``hobbywing/esc/20013.GetEscID.uavcan``).

    signature from original file location
    """

    __slots__ = ("payload",)

    payload: bytes

    def __init__(
        self,
        payload: bytes = b"",
    ) -> None:
        _setattr(self, "payload", payload)


@frozen_dataclass
class StatusMsg1(HtmlDisplay):
    """``com.hobbywing.esc.StatusMsg1``, message 20050 (``hobbywing/esc/20050.StatusMsg1.uavcan``)."""

    __slots__ = ("rpm", "pwm", "status",)

    rpm: int
    pwm: int
    status: int

    def __init__(
        self,
        rpm: int = 0,
        pwm: int = 0,
        status: int = 0,
    ) -> None:
        _setattr(self, "rpm", rpm)
        _setattr(self, "pwm", pwm)
        _setattr(self, "status", status)


@frozen_dataclass
class StatusMsg2(HtmlDisplay):
    """``com.hobbywing.esc.StatusMsg2``, message 20051 (``hobbywing/esc/20051.StatusMsg2.uavcan``)."""

    __slots__ = ("input_voltage", "current", "temperature",)

    input_voltage: int
    """0.1V"""
    current: int
    """0.1A"""
    temperature: int
    """degC"""

    def __init__(
        self,
        input_voltage: int = 0,
        current: int = 0,
        temperature: int = 0,
    ) -> None:
        _setattr(self, "input_voltage", input_voltage)
        _setattr(self, "current", current)
        _setattr(self, "temperature", temperature)


@frozen_dataclass
class StatusMsg3(HtmlDisplay):
    """``com.hobbywing.esc.StatusMsg3``, message 20052 (``hobbywing/esc/20052.StatusMsg3.uavcan``)."""

    __slots__ = ("MOS_T", "CAP_T", "Motor_T",)

    MOS_T: int
    CAP_T: int
    Motor_T: int

    def __init__(
        self,
        MOS_T: int = 0,
        CAP_T: int = 0,
        Motor_T: int = 0,
    ) -> None:
        _setattr(self, "MOS_T", MOS_T)
        _setattr(self, "CAP_T", CAP_T)
        _setattr(self, "Motor_T", Motor_T)


@frozen_dataclass
class EscRawCommand(HtmlDisplay):
    """``com.hobbywing.esc.RawCommand``, message 20100 (``hobbywing/esc/20100.RawCommand.uavcan``)."""

    __slots__ = ("command",)

    command: tuple[int, ...]

    def __init__(
        self,
        command: tuple[int, ...] = (),
    ) -> None:
        _setattr(self, "command", command)


@frozen_dataclass
class SetIDRequest(HtmlDisplay):
    """``com.hobbywing.esc.SetID`` request, service 210 (``hobbywing/esc/210.SetID.uavcan``)."""

    __slots__ = ("node_id", "throttle_channel",)

    node_id: int
    throttle_channel: int

    def __init__(
        self,
        node_id: int = 0,
        throttle_channel: int = 0,
    ) -> None:
        _setattr(self, "node_id", node_id)
        _setattr(self, "throttle_channel", throttle_channel)


@frozen_dataclass
class SetIDResponse(HtmlDisplay):
    """``com.hobbywing.esc.SetID`` response, service 210 (``hobbywing/esc/210.SetID.uavcan``)."""

    __slots__ = ("node_id", "throttle_channel",)

    node_id: int
    throttle_channel: int

    def __init__(
        self,
        node_id: int = 0,
        throttle_channel: int = 0,
    ) -> None:
        _setattr(self, "node_id", node_id)
        _setattr(self, "throttle_channel", throttle_channel)


@frozen_dataclass
class SetBaudRequest(HtmlDisplay):
    """``com.hobbywing.esc.SetBaud`` request, service 211 (``hobbywing/esc/211.SetBaud.uavcan``)."""

    BAUD_1MBPS: ClassVar[int] = 0
    BAUD_500KBPS: ClassVar[int] = 1
    BAUD_250KBPS: ClassVar[int] = 2
    BAUD_200KBPS: ClassVar[int] = 3
    BAUD_100KBPS: ClassVar[int] = 4
    BAUD_50KBPS: ClassVar[int] = 5

    __slots__ = ("baud",)

    baud: Baud | int

    def __init__(
        self,
        baud: Baud | int = 0,
    ) -> None:
        _setattr(self, "baud", baud)


@frozen_dataclass
class SetBaudResponse(HtmlDisplay):
    """``com.hobbywing.esc.SetBaud`` response, service 211 (``hobbywing/esc/211.SetBaud.uavcan``)."""

    __slots__ = ()


    def __init__(
        self,
    ) -> None:
        pass


@frozen_dataclass
class SetLEDRequest(HtmlDisplay):
    """``com.hobbywing.esc.SetLED`` request, service 212 (``hobbywing/esc/212.SetLED.uavcan``)."""

    OPTION_SAVE: ClassVar[int] = 1
    COLOR_R: ClassVar[int] = 4
    COLOR_G: ClassVar[int] = 2
    COLOR_B: ClassVar[int] = 1
    BLINK_OFF: ClassVar[int] = 0
    BLINK_1HZ: ClassVar[int] = 1
    BLINK_2HZ: ClassVar[int] = 2
    BLINK_5HZ: ClassVar[int] = 5

    __slots__ = ("option", "color", "blink",)

    option: int
    color: Color | int
    blink: Blink | int

    def __init__(
        self,
        option: int = 0,
        color: Color | int = 0,
        blink: Blink | int = 0,
    ) -> None:
        _setattr(self, "option", option)
        _setattr(self, "color", color)
        _setattr(self, "blink", blink)


@frozen_dataclass
class SetLEDResponse(HtmlDisplay):
    """``com.hobbywing.esc.SetLED`` response, service 212 (``hobbywing/esc/212.SetLED.uavcan``)."""

    __slots__ = ("option", "color", "blink",)

    option: int
    color: int
    blink: int

    def __init__(
        self,
        option: int = 0,
        color: int = 0,
        blink: int = 0,
    ) -> None:
        _setattr(self, "option", option)
        _setattr(self, "color", color)
        _setattr(self, "blink", blink)


@frozen_dataclass
class SetDirectionRequest(HtmlDisplay):
    """``com.hobbywing.esc.SetDirection`` request, service 213 (``hobbywing/esc/213.SetDirection.uavcan``)."""

    DIRECTION_CLOCKWISE: ClassVar[int] = 0
    DIRECTION_COUNTER_CLOCKWISE: ClassVar[int] = 1
    DIRECTION_QUERY: ClassVar[int] = 255

    __slots__ = ("direction",)

    direction: Direction | int

    def __init__(
        self,
        direction: Direction | int = 0,
    ) -> None:
        _setattr(self, "direction", direction)


@frozen_dataclass
class SetDirectionResponse(HtmlDisplay):
    """``com.hobbywing.esc.SetDirection`` response, service 213 (``hobbywing/esc/213.SetDirection.uavcan``)."""

    __slots__ = ("direction",)

    direction: int

    def __init__(
        self,
        direction: int = 0,
    ) -> None:
        _setattr(self, "direction", direction)


@frozen_dataclass
class SetReportingFrequencyRequest(HtmlDisplay):
    """``com.hobbywing.esc.SetReportingFrequency`` request, service 214 (``hobbywing/esc/214.SetReportingFrequency.uavcan``)."""

    OPTION_READ: ClassVar[int] = 0
    OPTION_WRITE: ClassVar[int] = 1
    RATE_500HZ: ClassVar[int] = 1
    RATE_250HZ: ClassVar[int] = 2
    RATE_200HZ: ClassVar[int] = 3
    RATE_100HZ: ClassVar[int] = 4
    RATE_50HZ: ClassVar[int] = 5
    RATE_20HZ: ClassVar[int] = 6
    RATE_10HZ: ClassVar[int] = 7
    RATE_1HZ: ClassVar[int] = 8
    RATE_0HZ: ClassVar[int] = 9

    __slots__ = ("option", "MSG_ID", "rate",)

    option: Option | int
    MSG_ID: int
    rate: Rate | int

    def __init__(
        self,
        option: Option | int = 0,
        MSG_ID: int = 0,
        rate: Rate | int = 0,
    ) -> None:
        _setattr(self, "option", option)
        _setattr(self, "MSG_ID", MSG_ID)
        _setattr(self, "rate", rate)


@frozen_dataclass
class SetReportingFrequencyResponse(HtmlDisplay):
    """``com.hobbywing.esc.SetReportingFrequency`` response, service 214 (``hobbywing/esc/214.SetReportingFrequency.uavcan``)."""

    __slots__ = ("option", "MSG_ID", "rate",)

    option: int
    MSG_ID: int
    rate: int

    def __init__(
        self,
        option: int = 0,
        MSG_ID: int = 0,
        rate: int = 0,
    ) -> None:
        _setattr(self, "option", option)
        _setattr(self, "MSG_ID", MSG_ID)
        _setattr(self, "rate", rate)


@frozen_dataclass
class SetThrottleSourceRequest(HtmlDisplay):
    """``com.hobbywing.esc.SetThrottleSource`` request, service 215 (``hobbywing/esc/215.SetThrottleSource.uavcan``)."""

    SOURCE_CAN_DIGITAL: ClassVar[int] = 0
    SOURCE_PWM: ClassVar[int] = 1

    __slots__ = ("source",)

    source: SetThrottleSourceRequestSource | int

    def __init__(
        self,
        source: SetThrottleSourceRequestSource | int = 0,
    ) -> None:
        _setattr(self, "source", source)


@frozen_dataclass
class SetThrottleSourceResponse(HtmlDisplay):
    """``com.hobbywing.esc.SetThrottleSource`` response, service 215 (``hobbywing/esc/215.SetThrottleSource.uavcan``)."""

    __slots__ = ("source",)

    source: int

    def __init__(
        self,
        source: int = 0,
    ) -> None:
        _setattr(self, "source", source)


@frozen_dataclass
class SelfTestRequest(HtmlDisplay):
    """``com.hobbywing.esc.SelfTest`` request, service 216 (``hobbywing/esc/216.SelfTest.uavcan``)."""

    __slots__ = ()


    def __init__(
        self,
    ) -> None:
        pass


@frozen_dataclass
class SelfTestResponse(HtmlDisplay):
    """``com.hobbywing.esc.SelfTest`` response, service 216 (``hobbywing/esc/216.SelfTest.uavcan``)."""

    STATUS_PASS: ClassVar[int] = 0
    STATUS_FAIL: ClassVar[int] = 1

    __slots__ = ("status",)

    status: SelfTestResponseStatus | int

    def __init__(
        self,
        status: SelfTestResponseStatus | int = 0,
    ) -> None:
        _setattr(self, "status", status)


@frozen_dataclass
class SetAngleRequest(HtmlDisplay):
    """``com.hobbywing.esc.SetAngle`` request, service 217 (``hobbywing/esc/217.SetAngle.uavcan``)."""

    __slots__ = ("option", "angle",)

    option: int
    angle: int

    def __init__(
        self,
        option: int = 0,
        angle: int = 0,
    ) -> None:
        _setattr(self, "option", option)
        _setattr(self, "angle", angle)


@frozen_dataclass
class SetAngleResponse(HtmlDisplay):
    """``com.hobbywing.esc.SetAngle`` response, service 217 (``hobbywing/esc/217.SetAngle.uavcan``)."""

    __slots__ = ("option", "angle",)

    option: int
    angle: tuple[int, ...]

    def __init__(
        self,
        option: int = 0,
        angle: tuple[int, ...] = (),
    ) -> None:
        _setattr(self, "option", option)
        _setattr(self, "angle", angle)


@frozen_dataclass
class GetMaintenanceInformationRequest(HtmlDisplay):
    """``com.hobbywing.esc.GetMaintenanceInformation`` request, service 241 (``hobbywing/esc/241.GetMaintenanceInformation.uavcan``)."""

    OPTION_CLEAR: ClassVar[int] = 1

    __slots__ = ("option",)

    option: int

    def __init__(
        self,
        option: int = 0,
    ) -> None:
        _setattr(self, "option", option)


@frozen_dataclass
class GetMaintenanceInformationResponse(HtmlDisplay):
    """``com.hobbywing.esc.GetMaintenanceInformation`` response, service 241 (``hobbywing/esc/241.GetMaintenanceInformation.uavcan``)."""

    __slots__ = ("total_rotation_time_min", "time_since_maintainence_min",)

    total_rotation_time_min: int
    time_since_maintainence_min: int

    def __init__(
        self,
        total_rotation_time_min: int = 0,
        time_since_maintainence_min: int = 0,
    ) -> None:
        _setattr(self, "total_rotation_time_min", total_rotation_time_min)
        _setattr(self, "time_since_maintainence_min", time_since_maintainence_min)


@frozen_dataclass
class GetMajorConfigRequest(HtmlDisplay):
    """``com.hobbywing.esc.GetMajorConfig`` request, service 242 (``hobbywing/esc/242.GetMajorConfig.uavcan``)."""

    __slots__ = ("option",)

    option: int

    def __init__(
        self,
        option: int = 0,
    ) -> None:
        _setattr(self, "option", option)


@frozen_dataclass
class GetMajorConfigResponse(HtmlDisplay):
    """``com.hobbywing.esc.GetMajorConfig`` response, service 242 (``hobbywing/esc/242.GetMajorConfig.uavcan``)."""

    __slots__ = ("direction", "throttle_source", "throttle_channel", "led_status", "led_color", "MSG2_rate", "MSG1_rate", "positioning_angle", "reserved",)

    direction: bool
    throttle_source: bool
    throttle_channel: int
    led_status: int
    led_color: int
    MSG2_rate: int
    MSG1_rate: int
    positioning_angle: int
    reserved: bytes

    def __init__(
        self,
        direction: bool = False,
        throttle_source: bool = False,
        throttle_channel: int = 0,
        led_status: int = 0,
        led_color: int = 0,
        MSG2_rate: int = 0,
        MSG1_rate: int = 0,
        positioning_angle: int = 0,
        reserved: bytes = bytes(2),
    ) -> None:
        _setattr(self, "direction", direction)
        _setattr(self, "throttle_source", throttle_source)
        _setattr(self, "throttle_channel", throttle_channel)
        _setattr(self, "led_status", led_status)
        _setattr(self, "led_color", led_color)
        _setattr(self, "MSG2_rate", MSG2_rate)
        _setattr(self, "MSG1_rate", MSG1_rate)
        _setattr(self, "positioning_angle", positioning_angle)
        _setattr(self, "reserved", reserved)


@frozen_dataclass
class ParamCfg(HtmlDisplay):
    """``com.tmotor.esc.ParamCfg``, message 1033 (``tmotor/esc/1033.ParamCfg.uavcan``).

    1033.ParamCfg.uavcan parameter setting
    """

    __slots__ = ("esc_index", "esc_uuid", "esc_id_set", "esc_ov_threshold", "esc_oc_threshold", "esc_ot_threshold", "esc_acc_threshold", "esc_dacc_threshold", "esc_rotate_dir", "esc_timing", "esc_signal_priority", "esc_led_mode", "esc_can_rate", "esc_fdb_rate", "esc_save_option",)

    esc_index: int
    esc_uuid: int
    esc_id_set: int
    esc_ov_threshold: int
    esc_oc_threshold: int
    esc_ot_threshold: int
    esc_acc_threshold: int
    esc_dacc_threshold: int
    esc_rotate_dir: int
    esc_timing: int
    esc_signal_priority: int
    esc_led_mode: int
    esc_can_rate: int
    esc_fdb_rate: int
    esc_save_option: int

    def __init__(
        self,
        esc_index: int = 0,
        esc_uuid: int = 0,
        esc_id_set: int = 0,
        esc_ov_threshold: int = 0,
        esc_oc_threshold: int = 0,
        esc_ot_threshold: int = 0,
        esc_acc_threshold: int = 0,
        esc_dacc_threshold: int = 0,
        esc_rotate_dir: int = 0,
        esc_timing: int = 0,
        esc_signal_priority: int = 0,
        esc_led_mode: int = 0,
        esc_can_rate: int = 0,
        esc_fdb_rate: int = 0,
        esc_save_option: int = 0,
    ) -> None:
        _setattr(self, "esc_index", esc_index)
        _setattr(self, "esc_uuid", esc_uuid)
        _setattr(self, "esc_id_set", esc_id_set)
        _setattr(self, "esc_ov_threshold", esc_ov_threshold)
        _setattr(self, "esc_oc_threshold", esc_oc_threshold)
        _setattr(self, "esc_ot_threshold", esc_ot_threshold)
        _setattr(self, "esc_acc_threshold", esc_acc_threshold)
        _setattr(self, "esc_dacc_threshold", esc_dacc_threshold)
        _setattr(self, "esc_rotate_dir", esc_rotate_dir)
        _setattr(self, "esc_timing", esc_timing)
        _setattr(self, "esc_signal_priority", esc_signal_priority)
        _setattr(self, "esc_led_mode", esc_led_mode)
        _setattr(self, "esc_can_rate", esc_can_rate)
        _setattr(self, "esc_fdb_rate", esc_fdb_rate)
        _setattr(self, "esc_save_option", esc_save_option)


@frozen_dataclass
class FocCtrl(HtmlDisplay):
    """``com.tmotor.esc.FocCtrl``, message 1035 (``tmotor/esc/1035.FocCtrl.uavcan``).

    Generic ESC status.
    """

    __slots__ = ("esc_index", "esc_mode", "esc_fdb_rate", "esc_cmd", "esc_cmd_val",)

    esc_index: int
    esc_mode: int
    esc_fdb_rate: int
    esc_cmd: int
    esc_cmd_val: int

    def __init__(
        self,
        esc_index: int = 0,
        esc_mode: int = 0,
        esc_fdb_rate: int = 0,
        esc_cmd: int = 0,
        esc_cmd_val: int = 0,
    ) -> None:
        _setattr(self, "esc_index", esc_index)
        _setattr(self, "esc_mode", esc_mode)
        _setattr(self, "esc_fdb_rate", esc_fdb_rate)
        _setattr(self, "esc_cmd", esc_cmd)
        _setattr(self, "esc_cmd_val", esc_cmd_val)


@frozen_dataclass
class PUSHSCI(HtmlDisplay):
    """``com.tmotor.esc.PUSHSCI``, message 1038 (``tmotor/esc/1038.PUSHSCI.uavcan``).

    Generic ESC SCI DATA.
    """

    __slots__ = ("data_sequence", "data",)

    data_sequence: int
    """data sequence"""
    data: bytes

    def __init__(
        self,
        data_sequence: int = 0,
        data: bytes = b"",
    ) -> None:
        _setattr(self, "data_sequence", data_sequence)
        _setattr(self, "data", data)


@frozen_dataclass
class PUSHCAN(HtmlDisplay):
    """``com.tmotor.esc.PUSHCAN``, message 1039 (``tmotor/esc/1039.PUSHCAN.uavcan``).

    Generic ESC status.
    """

    __slots__ = ("data_sequence", "data",)

    data_sequence: int
    """data sequence"""
    data: bytes

    def __init__(
        self,
        data_sequence: int = 0,
        data: bytes = b"",
    ) -> None:
        _setattr(self, "data_sequence", data_sequence)
        _setattr(self, "data", data)


@frozen_dataclass
class ParamGet(HtmlDisplay):
    """``com.tmotor.esc.ParamGet``, message 1332 (``tmotor/esc/1332.ParamGet.uavcan``).

    1033.ParamGet.uavcan param get pack
    """

    __slots__ = ("esc_index", "esc_uuid", "esc_id_req", "esc_ov_threshold", "esc_oc_threshold", "esc_ot_threshold", "esc_acc_threshold", "esc_dacc_threshold", "esc_rotate_dir", "esc_timing", "esc_startup_times", "esc_startup_duration", "esc_product_date", "esc_error_count", "esc_signal_priority", "esc_led_mode", "esc_can_rate", "esc_fdb_rate", "esc_save_option", "rsvd",)

    esc_index: int
    esc_uuid: int
    esc_id_req: int
    esc_ov_threshold: int
    esc_oc_threshold: int
    esc_ot_threshold: int
    esc_acc_threshold: int
    esc_dacc_threshold: int
    esc_rotate_dir: int
    esc_timing: int
    esc_startup_times: int
    esc_startup_duration: int
    esc_product_date: int
    esc_error_count: int
    esc_signal_priority: int
    esc_led_mode: int
    esc_can_rate: int
    esc_fdb_rate: int
    esc_save_option: int
    rsvd: bytes

    def __init__(
        self,
        esc_index: int = 0,
        esc_uuid: int = 0,
        esc_id_req: int = 0,
        esc_ov_threshold: int = 0,
        esc_oc_threshold: int = 0,
        esc_ot_threshold: int = 0,
        esc_acc_threshold: int = 0,
        esc_dacc_threshold: int = 0,
        esc_rotate_dir: int = 0,
        esc_timing: int = 0,
        esc_startup_times: int = 0,
        esc_startup_duration: int = 0,
        esc_product_date: int = 0,
        esc_error_count: int = 0,
        esc_signal_priority: int = 0,
        esc_led_mode: int = 0,
        esc_can_rate: int = 0,
        esc_fdb_rate: int = 0,
        esc_save_option: int = 0,
        rsvd: bytes = b"",
    ) -> None:
        _setattr(self, "esc_index", esc_index)
        _setattr(self, "esc_uuid", esc_uuid)
        _setattr(self, "esc_id_req", esc_id_req)
        _setattr(self, "esc_ov_threshold", esc_ov_threshold)
        _setattr(self, "esc_oc_threshold", esc_oc_threshold)
        _setattr(self, "esc_ot_threshold", esc_ot_threshold)
        _setattr(self, "esc_acc_threshold", esc_acc_threshold)
        _setattr(self, "esc_dacc_threshold", esc_dacc_threshold)
        _setattr(self, "esc_rotate_dir", esc_rotate_dir)
        _setattr(self, "esc_timing", esc_timing)
        _setattr(self, "esc_startup_times", esc_startup_times)
        _setattr(self, "esc_startup_duration", esc_startup_duration)
        _setattr(self, "esc_product_date", esc_product_date)
        _setattr(self, "esc_error_count", esc_error_count)
        _setattr(self, "esc_signal_priority", esc_signal_priority)
        _setattr(self, "esc_led_mode", esc_led_mode)
        _setattr(self, "esc_can_rate", esc_can_rate)
        _setattr(self, "esc_fdb_rate", esc_fdb_rate)
        _setattr(self, "esc_save_option", esc_save_option)
        _setattr(self, "rsvd", rsvd)


@frozen_dataclass
class ServoActuatorStatus(HtmlDisplay):
    """``com.volz.servo.ActuatorStatus``, message 20020 (``volz/servo/20020.ActuatorStatus.uavcan``).

    Volz servo feedback.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"actual_position"})

    __slots__ = ("actuator_id", "actual_position", "current", "voltage", "motor_pwm", "motor_temperature",)

    actuator_id: int
    """Unique actuator ID (1..15)"""
    actual_position: float
    """Actual servo position in radians"""
    current: int
    """Current: unsigned, 8-bit value, one count = 0.025 A"""
    voltage: int
    """Supply voltage: unsigned, 8-bit value, one count = 0.2 V"""
    motor_pwm: int
    """Motor PWM: unsigned, 8-bit value, 0 = 0% Motor power, 255 = 100% Motor Power"""
    motor_temperature: int
    """Motor temperature: unsigned 8-bit value, 0 = -50C, 255 = sensor error, one count = one degree"""

    def __init__(
        self,
        actuator_id: int = 0,
        actual_position: float = 0.0,
        current: int = 0,
        voltage: int = 0,
        motor_pwm: int = 0,
        motor_temperature: int = 0,
    ) -> None:
        _setattr(self, "actuator_id", actuator_id)
        _setattr(self, "actual_position", actual_position)
        _setattr(self, "current", current)
        _setattr(self, "voltage", voltage)
        _setattr(self, "motor_pwm", motor_pwm)
        _setattr(self, "motor_temperature", motor_temperature)


@frozen_dataclass
class XactiGnssStatus(HtmlDisplay):
    """``com.xacti.GnssStatus``, message 20305 (``xacti/20305.GnssStatus.uavcan``).

    Xacti GNSS status
    """

    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"altitude", "utc_seconds"})

    __slots__ = ("gps_status", "order", "remain_buffer", "utc_year", "utc_month", "utc_day", "utc_hour", "utc_minute", "utc_seconds", "latitude", "longitude", "altitude",)

    gps_status: int
    order: int
    remain_buffer: int
    utc_year: int
    """2023 ~"""
    utc_month: int
    """1 ~ 12"""
    utc_day: int
    """1 ~ 31"""
    utc_hour: int
    """0 ~ 23"""
    utc_minute: int
    """0 ~ 59"""
    utc_seconds: float
    """0 ~ below 60"""
    latitude: float
    """degrees -90 ~ +90"""
    longitude: float
    """degrees -180 ~ +180"""
    altitude: float
    """meters above sea level, AMSL"""

    def __init__(
        self,
        gps_status: int = 0,
        order: int = 0,
        remain_buffer: int = 0,
        utc_year: int = 0,
        utc_month: int = 0,
        utc_day: int = 0,
        utc_hour: int = 0,
        utc_minute: int = 0,
        utc_seconds: float = 0.0,
        latitude: float = 0.0,
        longitude: float = 0.0,
        altitude: float = 0.0,
    ) -> None:
        _setattr(self, "gps_status", gps_status)
        _setattr(self, "order", order)
        _setattr(self, "remain_buffer", remain_buffer)
        _setattr(self, "utc_year", utc_year)
        _setattr(self, "utc_month", utc_month)
        _setattr(self, "utc_day", utc_day)
        _setattr(self, "utc_hour", utc_hour)
        _setattr(self, "utc_minute", utc_minute)
        _setattr(self, "utc_seconds", utc_seconds)
        _setattr(self, "latitude", latitude)
        _setattr(self, "longitude", longitude)
        _setattr(self, "altitude", altitude)


@frozen_dataclass
class GnssStatusReq(HtmlDisplay):
    """``com.xacti.GnssStatusReq``, message 20306 (``xacti/20306.GnssStatusReq.uavcan``).

    Xacti GNSS status request
    """

    __slots__ = ("requirement",)

    requirement: int

    def __init__(
        self,
        requirement: int = 0,
    ) -> None:
        _setattr(self, "requirement", requirement)


@frozen_dataclass
class GimbalAttitudeStatus(HtmlDisplay):
    """``com.xacti.GimbalAttitudeStatus``, message 20402 (``xacti/20402.GimbalAttitudeStatus.uavcan``).

    Xacti camera gimbal attitude status
    """

    __slots__ = ("gimbal_roll", "gimbal_pitch", "gimbal_yaw", "magneticencoder_roll", "magneticencoder_pitch", "magneticencoder_yaw",)

    gimbal_roll: int
    gimbal_pitch: int
    gimbal_yaw: int
    magneticencoder_roll: int
    magneticencoder_pitch: int
    magneticencoder_yaw: int

    def __init__(
        self,
        gimbal_roll: int = 0,
        gimbal_pitch: int = 0,
        gimbal_yaw: int = 0,
        magneticencoder_roll: int = 0,
        magneticencoder_pitch: int = 0,
        magneticencoder_yaw: int = 0,
    ) -> None:
        _setattr(self, "gimbal_roll", gimbal_roll)
        _setattr(self, "gimbal_pitch", gimbal_pitch)
        _setattr(self, "gimbal_yaw", gimbal_yaw)
        _setattr(self, "magneticencoder_roll", magneticencoder_roll)
        _setattr(self, "magneticencoder_pitch", magneticencoder_pitch)
        _setattr(self, "magneticencoder_yaw", magneticencoder_yaw)


@frozen_dataclass
class CopterAttStatus(HtmlDisplay):
    '``com.xacti.CopterAttStatus``, message 20407 (``xacti/20407.CopterAttStatus.uavcan``).\n\nXacti specific vehicle attitude provided to camera gimbal\nsend periodically 5~10Hz.\n\nquaternion_wxyz_e4[0] = q.w\t(or q.q0) * 1e4f\nquaternion_wxyz_e4[1] = q.x\t(or q.q1) * 1e4f\nquaternion_wxyz_e4[2] = q.y\t(or q.q2) * 1e4f\nquaternion_wxyz_e4[3] = q.z\t(or q.q3) * 1e4f'

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"reserved"})

    __slots__ = ("quaternion_wxyz_e4", "reserved",)

    quaternion_wxyz_e4: tuple[int, ...]
    reserved: tuple[float, ...]

    def __init__(
        self,
        quaternion_wxyz_e4: tuple[int, ...] = (0,) * 4,
        reserved: tuple[float, ...] = (),
    ) -> None:
        _setattr(self, "quaternion_wxyz_e4", quaternion_wxyz_e4)
        _setattr(self, "reserved", reserved)


@frozen_dataclass
class GimbalControlData(HtmlDisplay):
    """``com.xacti.GimbalControlData``, message 20554 (``xacti/20554.GimbalControlData.uavcan``).

    Xacti camera gimbal control
    """

    __slots__ = ("pitch_cmd_type", "yaw_cmd_type", "pitch_cmd_value", "yaw_cmd_value",)

    pitch_cmd_type: int
    yaw_cmd_type: int
    pitch_cmd_value: int
    yaw_cmd_value: int

    def __init__(
        self,
        pitch_cmd_type: int = 0,
        yaw_cmd_type: int = 0,
        pitch_cmd_value: int = 0,
        yaw_cmd_value: int = 0,
    ) -> None:
        _setattr(self, "pitch_cmd_type", pitch_cmd_type)
        _setattr(self, "yaw_cmd_type", yaw_cmd_type)
        _setattr(self, "pitch_cmd_value", pitch_cmd_value)
        _setattr(self, "yaw_cmd_value", yaw_cmd_value)


@frozen_dataclass
class CBAT(HtmlDisplay):
    """``cuav.equipment.power.CBAT``, message 20300 (``equipment/power/20300.CBAT.uavcan``).

    support for CUAV Smart Battery on UAVCAN
    """

    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"available_energy", "average_current", "average_power", "current", "design_capacity", "full_charge_capacity", "nominal_voltage", "passed_charge", "remaining_capacity", "temperature", "voltage", "voltage_cell"})
    STATUS_FLAG_IN_USE: ClassVar[int] = 1
    """The battery is currently used as a power supply"""
    STATUS_FLAG_CHARGING: ClassVar[int] = 2
    """Charger is active"""
    STATUS_FLAG_CHARGED: ClassVar[int] = 4
    """Charging complete, but the charger is still active"""
    STATUS_FLAG_TEMP_HOT: ClassVar[int] = 8
    """Battery temperature is above normal"""
    STATUS_FLAG_TEMP_COLD: ClassVar[int] = 16
    """Battery temperature is below normal"""
    STATUS_FLAG_OVERLOAD: ClassVar[int] = 32
    """Safe operating area violation"""
    STATUS_FLAG_BAD_BATTERY: ClassVar[int] = 64
    """This battery should not be used anymore (e.g. low SOH)"""
    STATUS_FLAG_NEED_SERVICE: ClassVar[int] = 128
    """This battery requires maintenance (e.g. balancing, full recharge)"""
    STATUS_FLAG_BMS_ERROR: ClassVar[int] = 256
    """Battery management system/controller error, smart battery interface error"""
    STATUS_FLAG_RESERVED_A: ClassVar[int] = 512
    """Keep zero"""
    STATUS_FLAG_RESERVED_B: ClassVar[int] = 1024
    """Keep zero"""

    __slots__ = ("temperature", "voltage", "voltage_cell", "cell_count", "current", "average_current", "average_power", "available_energy", "remaining_capacity", "full_charge_capacity", "design_capacity", "average_time_to_empty", "average_time_to_full", "state_of_health", "state_of_charge", "max_error", "serial_number", "manufacture_date", "cycle_count", "over_discharge_count", "passed_charge", "nominal_voltage", "is_powering_off", "interface_error", "status_flags",)

    temperature: float
    """The surface temperature of the battery"""
    voltage: float
    """The total voltage of the battery"""
    voltage_cell: tuple[float, ...]
    """Battery individual cell voltages"""
    cell_count: int
    """Number of cells"""
    current: float
    """The current flowing through the sense resistor"""
    average_current: float
    """The average current flowing through the sense resistor"""
    average_power: float
    """The average power of the current discharge"""
    available_energy: float
    """The predicted charge or energy remaining in the battery"""
    remaining_capacity: float
    """The compensated battery capacity remaining"""
    full_charge_capacity: float
    """The compensated capacity of the battery when fully charged"""
    design_capacity: float
    """The design capacity of the battery"""
    average_time_to_empty: int
    """The predicted remaining battery life at the present rate of discharge, in minutes"""
    average_time_to_full: int
    """The predicted remaining time until the battery reaches full charge, in minutes"""
    state_of_health: int
    """Health of the battery"""
    state_of_charge: int
    """Percent of the full charge [0, 100]"""
    max_error: int
    """max error, expected margin of error in % in the state-of-charge calculation with a range of 1 to 100%"""
    serial_number: int
    """serial number of the battery pack"""
    manufacture_date: int
    """manufacture date, part of serial number of the battery pack"""
    cycle_count: int
    """number of discharge cycles the battery has experienced"""
    over_discharge_count: int
    """Number of battery overdischarge"""
    passed_charge: float
    """The amount of charge passing through the sense resistor"""
    nominal_voltage: float
    """Nominal voltage of the battery pack"""
    is_powering_off: bool
    """Power off event imminent indication, false if unknown"""
    interface_error: int
    """interface error counter"""
    status_flags: int

    def __init__(
        self,
        temperature: float = 0.0,
        voltage: float = 0.0,
        voltage_cell: tuple[float, ...] = (),
        cell_count: int = 0,
        current: float = 0.0,
        average_current: float = 0.0,
        average_power: float = 0.0,
        available_energy: float = 0.0,
        remaining_capacity: float = 0.0,
        full_charge_capacity: float = 0.0,
        design_capacity: float = 0.0,
        average_time_to_empty: int = 0,
        average_time_to_full: int = 0,
        state_of_health: int = 0,
        state_of_charge: int = 0,
        max_error: int = 0,
        serial_number: int = 0,
        manufacture_date: int = 0,
        cycle_count: int = 0,
        over_discharge_count: int = 0,
        passed_charge: float = 0.0,
        nominal_voltage: float = 0.0,
        is_powering_off: bool = False,
        interface_error: int = 0,
        status_flags: int = 0,
    ) -> None:
        _setattr(self, "temperature", temperature)
        _setattr(self, "voltage", voltage)
        _setattr(self, "voltage_cell", voltage_cell)
        _setattr(self, "cell_count", cell_count)
        _setattr(self, "current", current)
        _setattr(self, "average_current", average_current)
        _setattr(self, "average_power", average_power)
        _setattr(self, "available_energy", available_energy)
        _setattr(self, "remaining_capacity", remaining_capacity)
        _setattr(self, "full_charge_capacity", full_charge_capacity)
        _setattr(self, "design_capacity", design_capacity)
        _setattr(self, "average_time_to_empty", average_time_to_empty)
        _setattr(self, "average_time_to_full", average_time_to_full)
        _setattr(self, "state_of_health", state_of_health)
        _setattr(self, "state_of_charge", state_of_charge)
        _setattr(self, "max_error", max_error)
        _setattr(self, "serial_number", serial_number)
        _setattr(self, "manufacture_date", manufacture_date)
        _setattr(self, "cycle_count", cycle_count)
        _setattr(self, "over_discharge_count", over_discharge_count)
        _setattr(self, "passed_charge", passed_charge)
        _setattr(self, "nominal_voltage", nominal_voltage)
        _setattr(self, "is_powering_off", is_powering_off)
        _setattr(self, "interface_error", interface_error)
        _setattr(self, "status_flags", status_flags)


@frozen_dataclass
class FlexDebug(HtmlDisplay):
    """``dronecan.protocol.FlexDebug``, message 16371 (``protocol/16371.FlexDebug.uavcan``).

    flexible debug message for development purposes

    vendors can reserve a range of IDs for their products, reservation are in blocks of 10
    """

    RESERVATION_SIZE: ClassVar[int] = 10
    AM32_RESERVE_START: ClassVar[int] = 100
    MLRS_RESERVE_START: ClassVar[int] = 110

    __slots__ = ("id", "u8",)

    id: int
    u8: bytes

    def __init__(
        self,
        id: int = 0,
        u8: bytes = b"",
    ) -> None:
        _setattr(self, "id", id)
        _setattr(self, "u8", u8)


@frozen_dataclass
class Stats(HtmlDisplay):
    """``dronecan.protocol.Stats``, message 342 (``protocol/342.Stats.uavcan``).

    monitor the status of the DroneCAN Protocol decoder on the node
    """

    __slots__ = ("tx_frames", "tx_errors", "rx_frames", "rx_error_oom", "rx_error_internal", "rx_error_missed_start", "rx_error_wrong_toggle", "rx_error_short_frame", "rx_error_bad_crc", "rx_ignored_wrong_address", "rx_ignored_not_wanted", "rx_ignored_unexpected_tid",)

    tx_frames: int
    """Number of transmitted frames"""
    tx_errors: int
    """Number of errors during transmission"""
    rx_frames: int
    """Number of received frames"""
    rx_error_oom: int
    """Number of out-of-memory errors"""
    rx_error_internal: int
    """Number of internal errors"""
    rx_error_missed_start: int
    """Number of missed start bits"""
    rx_error_wrong_toggle: int
    """Number of wrong toggle bits"""
    rx_error_short_frame: int
    """Number of frames that were too short"""
    rx_error_bad_crc: int
    """Number of frames with bad CRC"""
    rx_ignored_wrong_address: int
    """Number of frames with wrong address"""
    rx_ignored_not_wanted: int
    """Number of frames that were not wanted"""
    rx_ignored_unexpected_tid: int
    """Number of frames with unexpected TID"""

    def __init__(
        self,
        tx_frames: int = 0,
        tx_errors: int = 0,
        rx_frames: int = 0,
        rx_error_oom: int = 0,
        rx_error_internal: int = 0,
        rx_error_missed_start: int = 0,
        rx_error_wrong_toggle: int = 0,
        rx_error_short_frame: int = 0,
        rx_error_bad_crc: int = 0,
        rx_ignored_wrong_address: int = 0,
        rx_ignored_not_wanted: int = 0,
        rx_ignored_unexpected_tid: int = 0,
    ) -> None:
        _setattr(self, "tx_frames", tx_frames)
        _setattr(self, "tx_errors", tx_errors)
        _setattr(self, "rx_frames", rx_frames)
        _setattr(self, "rx_error_oom", rx_error_oom)
        _setattr(self, "rx_error_internal", rx_error_internal)
        _setattr(self, "rx_error_missed_start", rx_error_missed_start)
        _setattr(self, "rx_error_wrong_toggle", rx_error_wrong_toggle)
        _setattr(self, "rx_error_short_frame", rx_error_short_frame)
        _setattr(self, "rx_error_bad_crc", rx_error_bad_crc)
        _setattr(self, "rx_ignored_wrong_address", rx_ignored_wrong_address)
        _setattr(self, "rx_ignored_not_wanted", rx_ignored_not_wanted)
        _setattr(self, "rx_ignored_unexpected_tid", rx_ignored_unexpected_tid)


@frozen_dataclass
class CanStats(HtmlDisplay):
    """``dronecan.protocol.CanStats``, message 343 (``protocol/343.CanStats.uavcan``).

    Monitor the stats of physical layer on the node
    """

    __slots__ = ("interface", "tx_requests", "tx_rejected", "tx_overflow", "tx_success", "tx_timedout", "tx_abort", "rx_received", "rx_overflow", "rx_errors", "busoff_errors",)

    interface: int
    """interface number"""
    tx_requests: int
    """number of tx requests"""
    tx_rejected: int
    """number of tx requests rejected"""
    tx_overflow: int
    """number of tx requests overflow"""
    tx_success: int
    """number of tx requests success"""
    tx_timedout: int
    """number of tx requests timedout"""
    tx_abort: int
    """number of tx requests aborted"""
    rx_received: int
    """number of rx received"""
    rx_overflow: int
    """number of rx overflow"""
    rx_errors: int
    """number of rx errors"""
    busoff_errors: int
    """number of busoff errors"""

    def __init__(
        self,
        interface: int = 0,
        tx_requests: int = 0,
        tx_rejected: int = 0,
        tx_overflow: int = 0,
        tx_success: int = 0,
        tx_timedout: int = 0,
        tx_abort: int = 0,
        rx_received: int = 0,
        rx_overflow: int = 0,
        rx_errors: int = 0,
        busoff_errors: int = 0,
    ) -> None:
        _setattr(self, "interface", interface)
        _setattr(self, "tx_requests", tx_requests)
        _setattr(self, "tx_rejected", tx_rejected)
        _setattr(self, "tx_overflow", tx_overflow)
        _setattr(self, "tx_success", tx_success)
        _setattr(self, "tx_timedout", tx_timedout)
        _setattr(self, "tx_abort", tx_abort)
        _setattr(self, "rx_received", rx_received)
        _setattr(self, "rx_overflow", rx_overflow)
        _setattr(self, "rx_errors", rx_errors)
        _setattr(self, "busoff_errors", busoff_errors)


@frozen_dataclass
class GlobalTime(HtmlDisplay):
    """``dronecan.protocol.GlobalTime``, message 344 (``protocol/344.GlobalTime.uavcan``).

    provide global timestamp, time since 1/1/1970 in microseconds
    should only be broadcast once a reliable time base (GPS or equivalent) is known
    """

    __slots__ = ("timestamp",)

    timestamp: Timestamp

    def __init__(
        self,
        timestamp: Timestamp = Timestamp(),
    ) -> None:
        _setattr(self, "timestamp", timestamp)


@frozen_dataclass
class BasicID(HtmlDisplay):
    """``dronecan.remoteid.BasicID``, message 20030 (``remoteid/20030.BasicID.uavcan``).

    DroneCAN version of MAVLink OPEN_DRONE_ID_BASIC_ID
    see MAVLink XML for detailed description
    """

    ODID_ID_TYPE_NONE: ClassVar[int] = 0
    ODID_ID_TYPE_SERIAL_NUMBER: ClassVar[int] = 1
    ODID_ID_TYPE_CAA_REGISTRATION_ID: ClassVar[int] = 2
    ODID_ID_TYPE_UTM_ASSIGNED_UUID: ClassVar[int] = 3
    ODID_ID_TYPE_SPECIFIC_SESSION_ID: ClassVar[int] = 4
    ODID_UA_TYPE_NONE: ClassVar[int] = 0
    """No UA (Unmanned Aircraft) type defined"""
    ODID_UA_TYPE_AEROPLANE: ClassVar[int] = 1
    """Aeroplane/Airplane. Fixed wing"""
    ODID_UA_TYPE_HELICOPTER_OR_MULTIROTOR: ClassVar[int] = 2
    """Helicopter or multirotor"""
    ODID_UA_TYPE_GYROPLANE: ClassVar[int] = 3
    """Gyroplane"""
    ODID_UA_TYPE_HYBRID_LIFT: ClassVar[int] = 4
    """VTOL (Vertical Take-Off and Landing). Fixed wing aircraft that can take off vertically"""
    ODID_UA_TYPE_ORNITHOPTER: ClassVar[int] = 5
    """Ornithopter"""
    ODID_UA_TYPE_GLIDER: ClassVar[int] = 6
    """Glider"""
    ODID_UA_TYPE_KITE: ClassVar[int] = 7
    """Kite"""
    ODID_UA_TYPE_FREE_BALLOON: ClassVar[int] = 8
    """Free Balloon"""
    ODID_UA_TYPE_CAPTIVE_BALLOON: ClassVar[int] = 9
    """Captive Balloon"""
    ODID_UA_TYPE_AIRSHIP: ClassVar[int] = 10
    """Airship. E.g. a blimp"""
    ODID_UA_TYPE_FREE_FALL_PARACHUTE: ClassVar[int] = 11
    """Free Fall/Parachute (unpowered)"""
    ODID_UA_TYPE_ROCKET: ClassVar[int] = 12
    """Rocket"""
    ODID_UA_TYPE_TETHERED_POWERED_AIRCRAFT: ClassVar[int] = 13
    """Tethered powered aircraft"""
    ODID_UA_TYPE_GROUND_OBSTACLE: ClassVar[int] = 14
    """Ground Obstacle"""
    ODID_UA_TYPE_OTHER: ClassVar[int] = 15
    """Other type of aircraft not listed earlier"""

    __slots__ = ("id_or_mac", "id_type", "ua_type", "uas_id",)

    id_or_mac: bytes
    id_type: int
    ua_type: int
    uas_id: bytes

    def __init__(
        self,
        id_or_mac: bytes = b"",
        id_type: int = 0,
        ua_type: int = 0,
        uas_id: bytes = b"",
    ) -> None:
        _setattr(self, "id_or_mac", id_or_mac)
        _setattr(self, "id_type", id_type)
        _setattr(self, "ua_type", ua_type)
        _setattr(self, "uas_id", uas_id)


@frozen_dataclass
class Location(HtmlDisplay):
    """``dronecan.remoteid.Location``, message 20031 (``remoteid/20031.Location.uavcan``).

    DroneCAN version of MAVLink OPEN_DRONE_ID_LOCATION
    see MAVLink XML for detailed description
    """

    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"altitude_barometric", "altitude_geodetic", "height", "timestamp"})
    ODID_STATUS_UNDECLARED: ClassVar[int] = 0
    """The status of the (UA) Unmanned Aircraft is undefined"""
    ODID_STATUS_GROUND: ClassVar[int] = 1
    """The UA is on the ground"""
    ODID_STATUS_AIRBORNE: ClassVar[int] = 2
    """The UA is in the air"""
    ODID_STATUS_EMERGENCY: ClassVar[int] = 3
    """The UA is having an emergency"""
    ODID_HEIGHT_REF_OVER_TAKEOFF: ClassVar[int] = 0
    """The height field is relative to the take-off location"""
    ODID_HEIGHT_REF_OVER_GROUND: ClassVar[int] = 1
    """The height field is relative to ground"""
    ODID_HOR_ACC_UNKNOWN: ClassVar[int] = 0
    """The horizontal accuracy is unknown"""
    ODID_HOR_ACC_10NM: ClassVar[int] = 1
    """The horizontal accuracy is smaller than 10 Nautical Miles. 18.52 km"""
    ODID_HOR_ACC_4NM: ClassVar[int] = 2
    """The horizontal accuracy is smaller than 4 Nautical Miles. 7.408 km"""
    ODID_HOR_ACC_2NM: ClassVar[int] = 3
    """The horizontal accuracy is smaller than 2 Nautical Miles. 3.704 km"""
    ODID_HOR_ACC_1NM: ClassVar[int] = 4
    """The horizontal accuracy is smaller than 1 Nautical Miles. 1.852 km"""
    ODID_HOR_ACC_0_5NM: ClassVar[int] = 5
    """The horizontal accuracy is smaller than 0.5 Nautical Miles. 926 m"""
    ODID_HOR_ACC_0_3NM: ClassVar[int] = 6
    """The horizontal accuracy is smaller than 0.3 Nautical Miles. 555.6 m"""
    ODID_HOR_ACC_0_1NM: ClassVar[int] = 7
    """The horizontal accuracy is smaller than 0.1 Nautical Miles. 185.2 m"""
    ODID_HOR_ACC_0_05NM: ClassVar[int] = 8
    """The horizontal accuracy is smaller than 0.05 Nautical Miles. 92.6 m"""
    ODID_HOR_ACC_30_METER: ClassVar[int] = 9
    """The horizontal accuracy is smaller than 30 meter"""
    ODID_HOR_ACC_10_METER: ClassVar[int] = 10
    """The horizontal accuracy is smaller than 10 meter"""
    ODID_HOR_ACC_3_METER: ClassVar[int] = 11
    """The horizontal accuracy is smaller than 3 meter"""
    ODID_HOR_ACC_1_METER: ClassVar[int] = 12
    """The horizontal accuracy is smaller than 1 meter"""
    ODID_VER_ACC_UNKNOWN: ClassVar[int] = 0
    """The vertical accuracy is unknown"""
    ODID_VER_ACC_150_METER: ClassVar[int] = 1
    """The vertical accuracy is smaller than 150 meter"""
    ODID_VER_ACC_45_METER: ClassVar[int] = 2
    """The vertical accuracy is smaller than 45 meter"""
    ODID_VER_ACC_25_METER: ClassVar[int] = 3
    """The vertical accuracy is smaller than 25 meter"""
    ODID_VER_ACC_10_METER: ClassVar[int] = 4
    """The vertical accuracy is smaller than 10 meter"""
    ODID_VER_ACC_3_METER: ClassVar[int] = 5
    """The vertical accuracy is smaller than 3 meter"""
    ODID_VER_ACC_1_METER: ClassVar[int] = 6
    """The vertical accuracy is smaller than 1 meter"""
    ODID_SPEED_ACC_UNKNOWN: ClassVar[int] = 0
    """The speed accuracy is unknown"""
    ODID_SPEED_ACC_10_METERS_PER_SECOND: ClassVar[int] = 1
    """The speed accuracy is smaller than 10 meters per second"""
    ODID_SPEED_ACC_3_METERS_PER_SECOND: ClassVar[int] = 2
    """The speed accuracy is smaller than 3 meters per second"""
    ODID_SPEED_ACC_1_METERS_PER_SECOND: ClassVar[int] = 3
    """The speed accuracy is smaller than 1 meters per second"""
    ODID_SPEED_ACC_0_3_METERS_PER_SECOND: ClassVar[int] = 4
    """The speed accuracy is smaller than 0.3 meters per second"""
    ODID_TIME_ACC_0_1_SECOND: ClassVar[int] = 1
    """The timestamp accuracy is smaller than or equal to 0.1 second"""
    ODID_TIME_ACC_0_2_SECOND: ClassVar[int] = 2
    """The timestamp accuracy is smaller than or equal to 0.2 second"""
    ODID_TIME_ACC_0_3_SECOND: ClassVar[int] = 3
    """The timestamp accuracy is smaller than or equal to 0.3 second"""
    ODID_TIME_ACC_0_4_SECOND: ClassVar[int] = 4
    """The timestamp accuracy is smaller than or equal to 0.4 second"""
    ODID_TIME_ACC_0_5_SECOND: ClassVar[int] = 5
    """The timestamp accuracy is smaller than or equal to 0.5 second"""
    ODID_TIME_ACC_0_6_SECOND: ClassVar[int] = 6
    """The timestamp accuracy is smaller than or equal to 0.6 second"""
    ODID_TIME_ACC_0_7_SECOND: ClassVar[int] = 7
    """The timestamp accuracy is smaller than or equal to 0.7 second"""
    ODID_TIME_ACC_0_8_SECOND: ClassVar[int] = 8
    """The timestamp accuracy is smaller than or equal to 0.8 second"""
    ODID_TIME_ACC_0_9_SECOND: ClassVar[int] = 9
    """The timestamp accuracy is smaller than or equal to 0.9 second"""
    ODID_TIME_ACC_1_0_SECOND: ClassVar[int] = 10
    """The timestamp accuracy is smaller than or equal to 1.0 second"""
    ODID_TIME_ACC_1_1_SECOND: ClassVar[int] = 11
    """The timestamp accuracy is smaller than or equal to 1.1 second"""
    ODID_TIME_ACC_1_2_SECOND: ClassVar[int] = 12
    """The timestamp accuracy is smaller than or equal to 1.2 second"""
    ODID_TIME_ACC_1_3_SECOND: ClassVar[int] = 13
    """The timestamp accuracy is smaller than or equal to 1.3 second"""
    ODID_TIME_ACC_1_4_SECOND: ClassVar[int] = 14
    """The timestamp accuracy is smaller than or equal to 1.4 second"""
    ODID_TIME_ACC_1_5_SECOND: ClassVar[int] = 15
    """The timestamp accuracy is smaller than or equal to 1.5 second"""

    __slots__ = ("id_or_mac", "status", "direction", "speed_horizontal", "speed_vertical", "latitude", "longitude", "altitude_barometric", "altitude_geodetic", "height_reference", "height", "horizontal_accuracy", "vertical_accuracy", "barometer_accuracy", "speed_accuracy", "timestamp", "timestamp_accuracy",)

    id_or_mac: bytes
    status: int
    direction: int
    """centi-deg, 0-35999"""
    speed_horizontal: int
    """cm/s, max 25425, if unknown use 25500"""
    speed_vertical: int
    """positive up, max +/-6200, if unknown use 6300"""
    latitude: int
    """degE7"""
    longitude: int
    """degE7"""
    altitude_barometric: float
    """meters, for unknown use -1000, ref is 29.92inHg or 1013.2mb"""
    altitude_geodetic: float
    """meters, for unknown use -1000, WGS84"""
    height_reference: int
    height: float
    """meters, for unknown use -1000"""
    horizontal_accuracy: int
    vertical_accuracy: int
    barometer_accuracy: int
    speed_accuracy: int
    timestamp: float
    """seconds after the full hour with reference to UTC time. Use 0xFFFF if unknown"""
    timestamp_accuracy: int

    def __init__(
        self,
        id_or_mac: bytes = b"",
        status: int = 0,
        direction: int = 0,
        speed_horizontal: int = 0,
        speed_vertical: int = 0,
        latitude: int = 0,
        longitude: int = 0,
        altitude_barometric: float = 0.0,
        altitude_geodetic: float = 0.0,
        height_reference: int = 0,
        height: float = 0.0,
        horizontal_accuracy: int = 0,
        vertical_accuracy: int = 0,
        barometer_accuracy: int = 0,
        speed_accuracy: int = 0,
        timestamp: float = 0.0,
        timestamp_accuracy: int = 0,
    ) -> None:
        _setattr(self, "id_or_mac", id_or_mac)
        _setattr(self, "status", status)
        _setattr(self, "direction", direction)
        _setattr(self, "speed_horizontal", speed_horizontal)
        _setattr(self, "speed_vertical", speed_vertical)
        _setattr(self, "latitude", latitude)
        _setattr(self, "longitude", longitude)
        _setattr(self, "altitude_barometric", altitude_barometric)
        _setattr(self, "altitude_geodetic", altitude_geodetic)
        _setattr(self, "height_reference", height_reference)
        _setattr(self, "height", height)
        _setattr(self, "horizontal_accuracy", horizontal_accuracy)
        _setattr(self, "vertical_accuracy", vertical_accuracy)
        _setattr(self, "barometer_accuracy", barometer_accuracy)
        _setattr(self, "speed_accuracy", speed_accuracy)
        _setattr(self, "timestamp", timestamp)
        _setattr(self, "timestamp_accuracy", timestamp_accuracy)


@frozen_dataclass
class SelfID(HtmlDisplay):
    """``dronecan.remoteid.SelfID``, message 20032 (``remoteid/20032.SelfID.uavcan``).

    DroneCAN version of MAVLink OPEN_DRONE_ID_SELF_ID
    see MAVLink XML for detailed description
    """

    _TEXT_FIELDS_: ClassVar[frozenset[str]] = frozenset({"description"})
    ODID_DESC_TYPE_TEXT: ClassVar[int] = 0
    """Free-form text description of the purpose of the flight"""

    __slots__ = ("id_or_mac", "description_type", "description",)

    id_or_mac: bytes
    description_type: int
    description: bytes

    def __init__(
        self,
        id_or_mac: bytes = b"",
        description_type: int = 0,
        description: bytes = b"",
    ) -> None:
        _setattr(self, "id_or_mac", id_or_mac)
        _setattr(self, "description_type", description_type)
        _setattr(self, "description", description)


@frozen_dataclass
class System(HtmlDisplay):
    """``dronecan.remoteid.System``, message 20033 (``remoteid/20033.System.uavcan``).

    DroneCAN version of MAVLink OPEN_DRONE_ID_SYSTEM
    see MAVLink XML for detailed description
    """

    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"area_ceiling", "area_floor", "operator_altitude_geo"})
    ODID_OPERATOR_LOCATION_TYPE_TAKEOFF: ClassVar[int] = 0
    """The location of the operator is the same as the take-off location"""
    ODID_OPERATOR_LOCATION_TYPE_LIVE_GNSS: ClassVar[int] = 1
    """The location of the operator is based on live GNSS data"""
    ODID_OPERATOR_LOCATION_TYPE_FIXED: ClassVar[int] = 2
    """The location of the operator is a fixed location"""
    ODID_CLASSIFICATION_TYPE_EU: ClassVar[int] = 0
    ODID_CATEGORY_EU_UNDECLARED: ClassVar[int] = 0
    """The category for the UA, according to the EU specification, is undeclared"""
    ODID_CATEGORY_EU_OPEN: ClassVar[int] = 1
    """The category for the UA, according to the EU specification, is the Open category"""
    ODID_CATEGORY_EU_SPECIFIC: ClassVar[int] = 2
    """The category for the UA, according to the EU specification, is the Specific category"""
    ODID_CATEGORY_EU_CERTIFIED: ClassVar[int] = 3
    """The category for the UA, according to the EU specification, is the Certified category"""
    ODID_CLASS_EU_UNDECLARED: ClassVar[int] = 0
    """The class for the UA, according to the EU specification, is undeclared"""
    ODID_CLASS_EU_CLASS_0: ClassVar[int] = 1
    """The class for the UA, according to the EU specification, is Class 0"""
    ODID_CLASS_EU_CLASS_1: ClassVar[int] = 2
    """The class for the UA, according to the EU specification, is Class 1"""
    ODID_CLASS_EU_CLASS_2: ClassVar[int] = 3
    """The class for the UA, according to the EU specification, is Class 2"""
    ODID_CLASS_EU_CLASS_3: ClassVar[int] = 4
    """The class for the UA, according to the EU specification, is Class 3"""
    ODID_CLASS_EU_CLASS_4: ClassVar[int] = 5
    """The class for the UA, according to the EU specification, is Class 4"""
    ODID_CLASS_EU_CLASS_5: ClassVar[int] = 6
    """The class for the UA, according to the EU specification, is Class 5"""
    ODID_CLASS_EU_CLASS_6: ClassVar[int] = 7
    """The class for the UA, according to the EU specification, is Class 6"""

    __slots__ = ("id_or_mac", "operator_location_type", "classification_type", "operator_latitude", "operator_longitude", "area_count", "area_radius", "area_ceiling", "area_floor", "category_eu", "class_eu", "operator_altitude_geo", "timestamp",)

    id_or_mac: bytes
    operator_location_type: int
    classification_type: int
    operator_latitude: int
    """degE7"""
    operator_longitude: int
    """degE7"""
    area_count: int
    """default 1"""
    area_radius: int
    """meters"""
    area_ceiling: float
    """meters, use -1000 if unknown, WGS84"""
    area_floor: float
    """meters, use -1000 if unknown, WGS84"""
    category_eu: int
    class_eu: int
    operator_altitude_geo: float
    """meters, use -1000 if unknown, WGS84"""
    timestamp: int
    """Unix seconds since 00:00:00 01/01/2019"""

    def __init__(
        self,
        id_or_mac: bytes = b"",
        operator_location_type: int = 0,
        classification_type: int = 0,
        operator_latitude: int = 0,
        operator_longitude: int = 0,
        area_count: int = 0,
        area_radius: int = 0,
        area_ceiling: float = 0.0,
        area_floor: float = 0.0,
        category_eu: int = 0,
        class_eu: int = 0,
        operator_altitude_geo: float = 0.0,
        timestamp: int = 0,
    ) -> None:
        _setattr(self, "id_or_mac", id_or_mac)
        _setattr(self, "operator_location_type", operator_location_type)
        _setattr(self, "classification_type", classification_type)
        _setattr(self, "operator_latitude", operator_latitude)
        _setattr(self, "operator_longitude", operator_longitude)
        _setattr(self, "area_count", area_count)
        _setattr(self, "area_radius", area_radius)
        _setattr(self, "area_ceiling", area_ceiling)
        _setattr(self, "area_floor", area_floor)
        _setattr(self, "category_eu", category_eu)
        _setattr(self, "class_eu", class_eu)
        _setattr(self, "operator_altitude_geo", operator_altitude_geo)
        _setattr(self, "timestamp", timestamp)


@frozen_dataclass
class OperatorID(HtmlDisplay):
    """``dronecan.remoteid.OperatorID``, message 20034 (``remoteid/20034.OperatorID.uavcan``).

    DroneCAN version of MAVLink OPEN_DRONE_ID_OPERATOR_ID
    see MAVLink XML for detailed description
    """

    ODID_OPERATOR_ID_TYPE_CAA: ClassVar[int] = 0
    """CAA (Civil Aviation Authority) registered operator ID"""

    __slots__ = ("id_or_mac", "operator_id_type", "operator_id",)

    id_or_mac: bytes
    operator_id_type: int
    operator_id: bytes

    def __init__(
        self,
        id_or_mac: bytes = b"",
        operator_id_type: int = 0,
        operator_id: bytes = b"",
    ) -> None:
        _setattr(self, "id_or_mac", id_or_mac)
        _setattr(self, "operator_id_type", operator_id_type)
        _setattr(self, "operator_id", operator_id)


@frozen_dataclass
class ArmStatus(HtmlDisplay):
    """``dronecan.remoteid.ArmStatus``, message 20035 (``remoteid/20035.ArmStatus.uavcan``).

    DroneCAN version of MAVLink OPEN_DRONE_ID_ARM_STATUS
    see MAVLink XML for detailed description
    """

    ODID_ARM_STATUS_GOOD_TO_ARM: ClassVar[int] = 0
    ODID_ARM_STATUS_FAIL_GENERIC: ClassVar[int] = 1

    __slots__ = ("status", "error",)

    status: int
    error: bytes

    def __init__(
        self,
        status: int = 0,
        error: bytes = b"",
    ) -> None:
        _setattr(self, "status", status)
        _setattr(self, "error", error)


@frozen_dataclass
class SecureCommandRequest(HtmlDisplay):
    """``dronecan.remoteid.SecureCommand`` request, service 64 (``remoteid/64.SecureCommand.uavcan``).

    DroneCAN version of MAVLink2 SECURE_COMMAND. Please see MAVLink2 spec for more details
    """

    SECURE_COMMAND_GET_SESSION_KEY: ClassVar[int] = 0
    SECURE_COMMAND_GET_REMOTEID_SESSION_KEY: ClassVar[int] = 1
    SECURE_COMMAND_REMOVE_PUBLIC_KEYS: ClassVar[int] = 2
    SECURE_COMMAND_GET_PUBLIC_KEYS: ClassVar[int] = 3
    SECURE_COMMAND_SET_PUBLIC_KEYS: ClassVar[int] = 4
    SECURE_COMMAND_GET_REMOTEID_CONFIG: ClassVar[int] = 5
    SECURE_COMMAND_SET_REMOTEID_CONFIG: ClassVar[int] = 6

    __slots__ = ("sequence", "operation", "sig_length", "data",)

    sequence: int
    operation: int
    sig_length: int
    data: bytes

    def __init__(
        self,
        sequence: int = 0,
        operation: int = 0,
        sig_length: int = 0,
        data: bytes = b"",
    ) -> None:
        _setattr(self, "sequence", sequence)
        _setattr(self, "operation", operation)
        _setattr(self, "sig_length", sig_length)
        _setattr(self, "data", data)


@frozen_dataclass
class SecureCommandResponse(HtmlDisplay):
    """``dronecan.remoteid.SecureCommand`` response, service 64 (``remoteid/64.SecureCommand.uavcan``)."""

    RESULT_ACCEPTED: ClassVar[int] = 0
    RESULT_TEMPORARILY_REJECTED: ClassVar[int] = 1
    RESULT_DENIED: ClassVar[int] = 2
    RESULT_UNSUPPORTED: ClassVar[int] = 3
    RESULT_FAILED: ClassVar[int] = 4

    __slots__ = ("sequence", "operation", "result", "data",)

    sequence: int
    operation: int
    result: Result | int
    data: bytes

    def __init__(
        self,
        sequence: int = 0,
        operation: int = 0,
        result: Result | int = 0,
        data: bytes = b"",
    ) -> None:
        _setattr(self, "sequence", sequence)
        _setattr(self, "operation", operation)
        _setattr(self, "result", result)
        _setattr(self, "data", data)


@frozen_dataclass
class Hygrometer(HtmlDisplay):
    """``dronecan.sensors.hygrometer.Hygrometer``, message 1032 (``sensors/hygrometer/1032.Hygrometer.uavcan``).

    support for hygrometer sensors
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"humidity", "temperature"})

    __slots__ = ("temperature", "humidity", "id",)

    temperature: float
    humidity: float
    id: int

    def __init__(
        self,
        temperature: float = 0.0,
        humidity: float = 0.0,
        id: int = 0,
    ) -> None:
        _setattr(self, "temperature", temperature)
        _setattr(self, "humidity", humidity)
        _setattr(self, "id", id)


@frozen_dataclass
class MagneticFieldStrengthHiRes(HtmlDisplay):
    """``dronecan.sensors.magnetometer.MagneticFieldStrengthHiRes``, message 1043 (``sensors/magnetometer/1043.MagneticFieldStrengthHiRes.uavcan``).

    Magnetic field readings, in Gauss, in body frame, high resolution version
    """

    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"magnetic_field_ga"})

    __slots__ = ("sensor_id", "magnetic_field_ga",)

    sensor_id: int
    magnetic_field_ga: tuple[float, ...]

    def __init__(
        self,
        sensor_id: int = 0,
        magnetic_field_ga: tuple[float, ...] = (0.0,) * 3,
    ) -> None:
        _setattr(self, "sensor_id", sensor_id)
        _setattr(self, "magnetic_field_ga", magnetic_field_ga)


@frozen_dataclass
class RCInput(HtmlDisplay):
    """``dronecan.sensors.rc.RCInput``, message 1140 (``sensors/rc/1140.RCInput.uavcan``).

    RC channels and basic link statistics
    """

    STATUS_QUALITY_VALID: ClassVar[int] = 1
    """quality field is valid"""
    STATUS_FAILSAFE: ClassVar[int] = 2
    """receiver has lost contact with transmitter"""
    STATUS_QUALITY_TYPE: ClassVar[int] = 28
    """mask of 3 bits (4+8+16) to indicate the type of data carried in the quality field, see QUALITY_TYPE enum"""
    QUALITY_TYPE_RSSI: ClassVar[int] = 0
    """quality field represents RSSI in scaled units, 0 is no signal, 255 is "full" signal"""
    QUALITY_TYPE_LQ_ACTIVE_ANTENNA: ClassVar[int] = 4
    """quality field represents LQ in percent in bits 1-7 (0 is no signal, 100 is 100% link quality) and active antenna in bit 8"""
    QUALITY_TYPE_RSSI_DBM: ClassVar[int] = 8
    """quality field represents RSSI in inverted dBm, 0 is no signal, 1 = -1 dBm, 255 = -255 dBm"""
    QUALITY_TYPE_SNR: ClassVar[int] = 12
    """quality field represents SNR in device dependent units, shifted by 128"""
    QUALITY_TYPE_TX_POWER: ClassVar[int] = 16
    """quality field represents uplink power in units of 5 mW"""

    __slots__ = ("status", "quality", "id", "rcin",)

    status: int
    """bitmask of status bits, enumerated above with STATUS_*"""
    quality: Quality | int
    """see descriptions for status bits STATUS_QUALITY_VALID, STATUS_QUALITY_LQ, STATUS_QUALITY_SNR"""
    id: int
    """ID of this RC input device"""
    rcin: tuple[int, ...]
    """RC channel values between 0 and 4095, values are in PWM microseconds, 1500 represents the mid position"""

    def __init__(
        self,
        status: int = 0,
        quality: Quality | int = 0,
        id: int = 0,
        rcin: tuple[int, ...] = (),
    ) -> None:
        _setattr(self, "status", status)
        _setattr(self, "quality", quality)
        _setattr(self, "id", id)
        _setattr(self, "rcin", rcin)


@frozen_dataclass
class RPM(HtmlDisplay):
    """``dronecan.sensors.rpm.RPM``, message 1045 (``sensors/rpm/1045.RPM.uavcan``).

    RPM reading in revolutions per minute
    """

    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"rpm"})
    FLAGS_UNHEALTHY: ClassVar[int] = 1
    """Sensor is not healthy"""

    __slots__ = ("sensor_id", "flags", "rpm",)

    sensor_id: int
    flags: int
    rpm: float

    def __init__(
        self,
        sensor_id: int = 0,
        flags: int = 0,
        rpm: float = 0.0,
    ) -> None:
        _setattr(self, "sensor_id", sensor_id)
        _setattr(self, "flags", flags)
        _setattr(self, "rpm", rpm)


@frozen_dataclass
class Stream(HtmlDisplay):
    """``mppt.Stream``, message 20009 (``20009.Stream.uavcan``).

    MPPT streaming data, transmitted at 1Hz
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"input_current", "input_power", "input_voltage", "output_current", "output_power", "output_voltage"})
    OV_FAULT: ClassVar[int] = 1
    """over-voltage"""
    UV_FAULT: ClassVar[int] = 2
    """under-voltage"""
    OC_FAULT: ClassVar[int] = 4
    """over-current"""
    OT_FAULT: ClassVar[int] = 8
    """over-temperature"""

    __slots__ = ("fault_flags", "temperature", "input_voltage", "input_current", "input_power", "output_voltage", "output_current", "output_power",)

    fault_flags: int
    temperature: int
    """[Celsius]"""
    input_voltage: float
    """[Volt]"""
    input_current: float
    """[Amp]"""
    input_power: float
    """[Watt]"""
    output_voltage: float
    """[Volt]"""
    output_current: float
    """[Amp]"""
    output_power: float
    """[Watt]"""

    def __init__(
        self,
        fault_flags: int = 0,
        temperature: int = 0,
        input_voltage: float = 0.0,
        input_current: float = 0.0,
        input_power: float = 0.0,
        output_voltage: float = 0.0,
        output_current: float = 0.0,
        output_power: float = 0.0,
    ) -> None:
        _setattr(self, "fault_flags", fault_flags)
        _setattr(self, "temperature", temperature)
        _setattr(self, "input_voltage", input_voltage)
        _setattr(self, "input_current", input_current)
        _setattr(self, "input_power", input_power)
        _setattr(self, "output_voltage", output_voltage)
        _setattr(self, "output_current", output_current)
        _setattr(self, "output_power", output_power)


@frozen_dataclass
class OutputEnableRequest(HtmlDisplay):
    """``mppt.OutputEnable`` request, service 240 (``240.OutputEnable.uavcan``).

    Service to enable or disable the mppt output.
    """

    __slots__ = ("enable", "disable",)

    enable: bool
    disable: bool

    def __init__(
        self,
        enable: bool = False,
        disable: bool = False,
    ) -> None:
        _setattr(self, "enable", enable)
        _setattr(self, "disable", disable)


@frozen_dataclass
class OutputEnableResponse(HtmlDisplay):
    """``mppt.OutputEnable`` response, service 240 (``240.OutputEnable.uavcan``)."""

    __slots__ = ("enabled",)

    enabled: bool

    def __init__(
        self,
        enabled: bool = False,
    ) -> None:
        _setattr(self, "enabled", enabled)


__all__ = [
    'AltType',
    'ArdupilotGnssStatus',
    'ArdupilotGnssStatusStatus',
    'ArmStatus',
    'BasicID',
    'BatteryCells',
    'BatteryContinuous',
    'BatteryContinuousStatusFlag',
    'BatteryInfoAux',
    'BatteryPeriodic',
    'BatteryTag',
    'Baud',
    'Blink',
    'Button',
    'CBAT',
    'CBATStatusFlag',
    'CanStats',
    'Color',
    'CopterAttStatus',
    'Direction',
    'ErrorStatus',
    'EscRawCommand',
    'FlexDebug',
    'FlowMeasurement',
    'FocCtrl',
    'GetEscID',
    'GetMaintenanceInformationRequest',
    'GetMaintenanceInformationResponse',
    'GetMajorConfigRequest',
    'GetMajorConfigResponse',
    'GimbalAttitudeStatus',
    'GimbalControlData',
    'GlobalTime',
    'GnssStatusReq',
    'Heading',
    'Hygrometer',
    'Location',
    'MagneticFieldStrengthHiRes',
    'MovingBaselineData',
    'NotifyState',
    'OperatorID',
    'Option',
    'OutputEnableRequest',
    'OutputEnableResponse',
    'PUSHCAN',
    'PUSHSCI',
    'ParamCfg',
    'ParamGet',
    'Proximity',
    'ProximityReadingType',
    'Quality',
    'RCInput',
    'RPM',
    'Rate',
    'RelPosHeading',
    'Result',
    'SafetyState',
    'SafetyStateStatus',
    'SecureCommandRequest',
    'SecureCommandResponse',
    'SelfID',
    'SelfTestRequest',
    'SelfTestResponse',
    'SelfTestResponseStatus',
    'ServoActuatorStatus',
    'ServoCmd',
    'ServoInfo',
    'SetAngleRequest',
    'SetAngleResponse',
    'SetBaudRequest',
    'SetBaudResponse',
    'SetDirectionRequest',
    'SetDirectionResponse',
    'SetIDRequest',
    'SetIDResponse',
    'SetLEDRequest',
    'SetLEDResponse',
    'SetReportingFrequencyRequest',
    'SetReportingFrequencyResponse',
    'SetThrottleSourceRequest',
    'SetThrottleSourceRequestSource',
    'SetThrottleSourceResponse',
    'Stats',
    'StatusMsg1',
    'StatusMsg2',
    'StatusMsg3',
    'Stream',
    'System',
    'TrafficReport',
    'TrafficReportSource',
    'TrafficType',
    'XactiGnssStatus',
]

CLASSES: dict[str, Any] = {
    'ardupilot.equipment.power.BatteryInfoAux': BatteryInfoAux,
    'ardupilot.equipment.power.BatteryContinuous': BatteryContinuous,
    'ardupilot.equipment.power.BatteryPeriodic': BatteryPeriodic,
    'ardupilot.equipment.power.BatteryCells': BatteryCells,
    'ardupilot.equipment.power.BatteryTag': BatteryTag,
    'ardupilot.equipment.proximity_sensor.Proximity': Proximity,
    'ardupilot.equipment.trafficmonitor.TrafficReport': TrafficReport,
    'ardupilot.gnss.Heading': Heading,
    'ardupilot.gnss.Status': ArdupilotGnssStatus,
    'ardupilot.gnss.MovingBaselineData': MovingBaselineData,
    'ardupilot.gnss.RelPosHeading': RelPosHeading,
    'ardupilot.indication.SafetyState': SafetyState,
    'ardupilot.indication.Button': Button,
    'ardupilot.indication.NotifyState': NotifyState,
    'com.hex.equipment.flow.Measurement': FlowMeasurement,
    'com.himark.servo.ServoCmd': ServoCmd,
    'com.himark.servo.ServoInfo': ServoInfo,
    'com.hobbywing.esc.GetEscID': GetEscID,
    'com.hobbywing.esc.StatusMsg1': StatusMsg1,
    'com.hobbywing.esc.StatusMsg2': StatusMsg2,
    'com.hobbywing.esc.StatusMsg3': StatusMsg3,
    'com.hobbywing.esc.RawCommand': EscRawCommand,
    'com.hobbywing.esc.SetID.Request': SetIDRequest,
    'com.hobbywing.esc.SetID.Response': SetIDResponse,
    'com.hobbywing.esc.SetBaud.Request': SetBaudRequest,
    'com.hobbywing.esc.SetBaud.Response': SetBaudResponse,
    'com.hobbywing.esc.SetLED.Request': SetLEDRequest,
    'com.hobbywing.esc.SetLED.Response': SetLEDResponse,
    'com.hobbywing.esc.SetDirection.Request': SetDirectionRequest,
    'com.hobbywing.esc.SetDirection.Response': SetDirectionResponse,
    'com.hobbywing.esc.SetReportingFrequency.Request': SetReportingFrequencyRequest,
    'com.hobbywing.esc.SetReportingFrequency.Response': SetReportingFrequencyResponse,
    'com.hobbywing.esc.SetThrottleSource.Request': SetThrottleSourceRequest,
    'com.hobbywing.esc.SetThrottleSource.Response': SetThrottleSourceResponse,
    'com.hobbywing.esc.SelfTest.Request': SelfTestRequest,
    'com.hobbywing.esc.SelfTest.Response': SelfTestResponse,
    'com.hobbywing.esc.SetAngle.Request': SetAngleRequest,
    'com.hobbywing.esc.SetAngle.Response': SetAngleResponse,
    'com.hobbywing.esc.GetMaintenanceInformation.Request': GetMaintenanceInformationRequest,
    'com.hobbywing.esc.GetMaintenanceInformation.Response': GetMaintenanceInformationResponse,
    'com.hobbywing.esc.GetMajorConfig.Request': GetMajorConfigRequest,
    'com.hobbywing.esc.GetMajorConfig.Response': GetMajorConfigResponse,
    'com.tmotor.esc.ParamCfg': ParamCfg,
    'com.tmotor.esc.FocCtrl': FocCtrl,
    'com.tmotor.esc.PUSHSCI': PUSHSCI,
    'com.tmotor.esc.PUSHCAN': PUSHCAN,
    'com.tmotor.esc.ParamGet': ParamGet,
    'com.volz.servo.ActuatorStatus': ServoActuatorStatus,
    'com.xacti.GnssStatus': XactiGnssStatus,
    'com.xacti.GnssStatusReq': GnssStatusReq,
    'com.xacti.GimbalAttitudeStatus': GimbalAttitudeStatus,
    'com.xacti.CopterAttStatus': CopterAttStatus,
    'com.xacti.GimbalControlData': GimbalControlData,
    'cuav.equipment.power.CBAT': CBAT,
    'dronecan.protocol.FlexDebug': FlexDebug,
    'dronecan.protocol.Stats': Stats,
    'dronecan.protocol.CanStats': CanStats,
    'dronecan.protocol.GlobalTime': GlobalTime,
    'dronecan.remoteid.BasicID': BasicID,
    'dronecan.remoteid.Location': Location,
    'dronecan.remoteid.SelfID': SelfID,
    'dronecan.remoteid.System': System,
    'dronecan.remoteid.OperatorID': OperatorID,
    'dronecan.remoteid.ArmStatus': ArmStatus,
    'dronecan.remoteid.SecureCommand.Request': SecureCommandRequest,
    'dronecan.remoteid.SecureCommand.Response': SecureCommandResponse,
    'dronecan.sensors.hygrometer.Hygrometer': Hygrometer,
    'dronecan.sensors.magnetometer.MagneticFieldStrengthHiRes': MagneticFieldStrengthHiRes,
    'dronecan.sensors.rc.RCInput': RCInput,
    'dronecan.sensors.rpm.RPM': RPM,
    'mppt.Stream': Stream,
    'mppt.OutputEnable.Request': OutputEnableRequest,
    'mppt.OutputEnable.Response': OutputEnableResponse,
}
"""The class of each key (full name, with ``.Request``/``.Response``)."""

ENUMS: dict[tuple[str, str], type] = {
    ('ardupilot.equipment.proximity_sensor.Proximity', 'reading_type'): ProximityReadingType,
    ('ardupilot.equipment.trafficmonitor.TrafficReport', 'source'): TrafficReportSource,
    ('ardupilot.equipment.trafficmonitor.TrafficReport', 'traffic_type'): TrafficType,
    ('ardupilot.equipment.trafficmonitor.TrafficReport', 'alt_type'): AltType,
    ('ardupilot.gnss.Status', 'status'): ArdupilotGnssStatusStatus,
    ('ardupilot.indication.SafetyState', 'status'): SafetyStateStatus,
    ('com.himark.servo.ServoInfo', 'error_status'): ErrorStatus,
    ('com.hobbywing.esc.SetBaud.Request', 'baud'): Baud,
    ('com.hobbywing.esc.SetLED.Request', 'color'): Color,
    ('com.hobbywing.esc.SetLED.Request', 'blink'): Blink,
    ('com.hobbywing.esc.SetDirection.Request', 'direction'): Direction,
    ('com.hobbywing.esc.SetReportingFrequency.Request', 'option'): Option,
    ('com.hobbywing.esc.SetReportingFrequency.Request', 'rate'): Rate,
    ('com.hobbywing.esc.SetThrottleSource.Request', 'source'): SetThrottleSourceRequestSource,
    ('com.hobbywing.esc.SelfTest.Response', 'status'): SelfTestResponseStatus,
    ('dronecan.remoteid.SecureCommand.Response', 'result'): Result,
    ('dronecan.sensors.rc.RCInput', 'quality'): Quality,
}
"""The enum a field decodes to, by (key, field name)."""

UNION_MEMBERS: dict[str, tuple[type, ...]] = {
}
"""The member classes of each union, in member order."""
