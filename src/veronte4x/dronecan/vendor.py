"""Every type of the vendor DSDL namespaces shipped with the package (ardupilot, com, cuav, dronecan, mppt).

GENERATED from the DSDL files shipped in ``veronte4x/dronecan/dsdl`` by
``python -m veronte4x.dronecan.generate``: do not edit (a test regenerates and compares).
Named as `veronte4x.dronecan.load_dsdl` names vendor types added to the standard set
(`veronte4x.dronecan.generate`).
"""

from __future__ import annotations

import enum
from dataclasses import dataclass
from typing import Any, ClassVar, TypeAlias

from veronte4x.display import HtmlDisplay
from veronte4x.dronecan.standard import (
    Timestamp,
)


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


@dataclass(frozen=True, slots=True)
class BatteryInfoAux(HtmlDisplay):
    """``ardupilot.equipment.power.BatteryInfoAux``, message 20004 (``equipment/power/20004.BatteryInfoAux.uavcan``).

    Auxilary Single battery info.

    This message is to be used in conjunction with uavcan/equipment/power/1092.BatteryInfo.uavcan
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"max_current", "nominal_voltage", "voltage_cell"})

    timestamp: Timestamp = Timestamp()
    voltage_cell: tuple[float, ...] = ()
    """[Volt]"""
    cycle_count: int = 0
    over_discharge_count: int = 0
    max_current: float = 0.0
    """[Ampere]"""
    nominal_voltage: float = 0.0
    """[Volt]"""
    is_powering_off: bool = False
    """Power off event imminent indication, false if unknown"""
    battery_id: int = 0
    """Identifies the battery within this vehicle, e.g. 0 - primary battery"""


@dataclass(frozen=True, slots=True)
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

    temperature_cells: float = 0.0
    """[C]  : Pack mounted thermistor (preferably installed between cells), NAN: field not provided"""
    temperature_pcb: float = 0.0
    """[C]  : Battery PCB temperature (likely output FET(s) or current sense resistor), NAN: field not provided"""
    temperature_other: float = 0.0
    """[C]  : Application dependent, NAN: field not provided"""
    current: float = 0.0
    """[A]  : Positive: defined as a discharge current. Negative: defined as a charging current, NAN: field not provided"""
    voltage: float = 0.0
    """[V]  : Battery voltage"""
    state_of_charge: float = 0.0
    """[%]  : The estimated state of charge, in percent remaining (0 - 100)."""
    slot_id: int = 0
    """: The physical location of the battery on the aircraft. 0: field not provided"""
    capacity_consumed: float = 0.0
    """[Ah] : This is either the consumption since power-on or since the battery was full, depending on the value of STATUS_FLAG_CAPACITY_RELATIVE_TO_FULL, NAN: field not provided"""
    status_flags: int = 0
    """: Fault, health, readiness, and other status indications"""


@dataclass(frozen=True, slots=True)
class BatteryPeriodic(HtmlDisplay):
    """``ardupilot.equipment.power.BatteryPeriodic``, message 20011 (``equipment/power/20011.BatteryPeriodic.uavcan``).

    Battery data to be sent statically upon request or periodically at a low rate
    Recommend that this message is sent at a maximum of 1Hz and nominally 0.2 Hz (IE: once every 5 seconds.)
    """

    _TEXT_FIELDS_: ClassVar[frozenset[str]] = frozenset({"manufacture_date", "name", "serial_number"})
    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"charging_maximum_voltage", "charging_minimum_voltage", "discharge_minimum_voltage", "nominal_voltage"})
    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"charging_maximum_current", "design_capacity", "discharge_maximum_burst_current", "discharge_maximum_current", "full_charge_capacity"})

    name: bytes = b""
    """: Formatted as manufacturer_product, 0 terminated"""
    serial_number: bytes = b""
    """: Serial number in ASCII characters, 0 terminated"""
    manufacture_date: bytes = b""
    """: Manufacture date (DDMMYYYY) in ASCII characters, 0 terminated"""
    design_capacity: float = 0.0
    """[Ah] : Fully charged design capacity. 0: field not provided."""
    cells_in_series: int = 0
    """: Number of battery cells in series. 0: field not provided."""
    nominal_voltage: float = 0.0
    """[V]  : Battery nominal voltage. Used for conversion between Wh and Ah. 0: field not provided."""
    discharge_minimum_voltage: float = 0.0
    """[V]  : Minimum per-cell voltage when discharging. 0: field not provided."""
    charging_minimum_voltage: float = 0.0
    """[V]  : Minimum per-cell voltage when charging. 0: field not provided."""
    charging_maximum_voltage: float = 0.0
    """[V]  : Maximum per-cell voltage when charged. 0: field not provided."""
    charging_maximum_current: float = 0.0
    """[A]  : Maximum pack continuous charge current. 0: field not provided."""
    discharge_maximum_current: float = 0.0
    """[A]  : Maximum pack continuous discharge current. 0: field not provided."""
    discharge_maximum_burst_current: float = 0.0
    """[A]  : Maximum pack discharge burst current for 30 seconds. 0: field not provided"""
    full_charge_capacity: float = 0.0
    """[Ah] : Predicted battery capacity when fully charged (accounting for battery degradation), NAN: field not provided"""
    cycle_count: int = 0
    """: Lifetime count of the number of charge/discharge cycles (https://en.wikipedia.org/wiki/Charge_cycle). UINT16_MAX: field not provided."""
    state_of_health: int = 0
    """[%]  : State of Health (SOH) estimate, in percent (0 - 100). UINT8_MAX: field not provided."""


@dataclass(frozen=True, slots=True)
class BatteryCells(HtmlDisplay):
    """``ardupilot.equipment.power.BatteryCells``, message 20012 (``equipment/power/20012.BatteryCells.uavcan``).

    Battery cell voltages
    Rate: set by parameter on smart battery (default off)
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"voltages"})

    voltages: tuple[float, ...] = ()
    """[Volt]"""
    index: int = 0
    """Index of the first cell in the array, index 0 is cells at array indices 0 - 23, index 24 is cells at array indices 24 - 47, etc."""


@dataclass(frozen=True, slots=True)
class BatteryTag(HtmlDisplay):
    """``ardupilot.equipment.power.BatteryTag``, message 20500 (``equipment/power/20500.BatteryTag.uavcan``).

    Battery tag information. This is broadcast by a battery tag device
    permanently attached to a battery to record the lifecycle of the battery
    """

    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"armed_hours"})

    serial_number: int = 0
    num_cycles: int = 0
    armed_hours: float = 0.0
    battery_capacity_mAh: int = 0
    first_use_mins: int = 0
    last_arm_time_mins: int = 0


@dataclass(frozen=True, slots=True)
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

    sensor_id: int = 0
    """Sensor ID"""
    reading_type: ProximityReadingType | int = 0
    """Sensor Status"""
    flags: int = 0
    """Reserved"""
    yaw: float = 0.0
    """Degrees in body frame"""
    pitch: float = 0.0
    """Degrees in body frame"""
    distance: float = 0.0
    """Meters"""


@dataclass(frozen=True, slots=True)
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

    timestamp: Timestamp = Timestamp()
    icao_address: int = 0
    tslc: int = 0
    latitude_deg_1e7: int = 0
    longitude_deg_1e7: int = 0
    alt_m: float = 0.0
    heading: float = 0.0
    velocity: tuple[float, ...] = (0.0,) * 3
    squawk: int = 0
    callsign: bytes = bytes(9)
    source: TrafficReportSource | int = 0
    traffic_type: TrafficType | int = 0
    alt_type: AltType | int = 0
    lat_lon_valid: bool = False
    heading_valid: bool = False
    velocity_valid: bool = False
    callsign_valid: bool = False
    ident_valid: bool = False
    simulated_report: bool = False
    vertical_velocity_valid: bool = False
    baro_valid: bool = False


@dataclass(frozen=True, slots=True)
class Heading(HtmlDisplay):
    """``ardupilot.gnss.Heading``, message 20002 (``gnss/20002.Heading.uavcan``)."""

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"heading_accuracy_rad", "heading_rad"})

    heading_valid: bool = False
    heading_accuracy_valid: bool = False
    heading_rad: float = 0.0
    heading_accuracy_rad: float = 0.0


@dataclass(frozen=True, slots=True)
class ArdupilotGnssStatus(HtmlDisplay):
    """``ardupilot.gnss.Status``, message 20003 (``gnss/20003.Status.uavcan``).

    Node specific GNSS error codes, primarily available for logging and diagnostics
    """

    STATUS_LOGGING: ClassVar[int] = 1
    """GNSS system is doing any onboard logging"""
    STATUS_ARMABLE: ClassVar[int] = 2
    """GNSS system is in a reasonable state to allow the system to arm"""

    error_codes: int = 0
    healthy: bool = False
    status: ArdupilotGnssStatusStatus | int = 0


@dataclass(frozen=True, slots=True)
class MovingBaselineData(HtmlDisplay):
    """``ardupilot.gnss.MovingBaselineData``, message 20005 (``gnss/20005.MovingBaselineData.uavcan``).

    length of data is set per the number of bytes for pkt in
    libraries/AP_GPS/RTCM3_Parser.h
    """

    data: bytes = b""


@dataclass(frozen=True, slots=True)
class RelPosHeading(HtmlDisplay):
    """``ardupilot.gnss.RelPosHeading``, message 20006 (``gnss/20006.RelPosHeading.uavcan``).

    timestamp on the gps message
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"relative_distance_m", "relative_down_pos_m"})
    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"reported_heading_acc_deg", "reported_heading_deg"})

    timestamp: Timestamp = Timestamp()
    reported_heading_acc_available: bool = False
    reported_heading_deg: float = 0.0
    reported_heading_acc_deg: float = 0.0
    relative_distance_m: float = 0.0
    relative_down_pos_m: float = 0.0


@dataclass(frozen=True, slots=True)
class SafetyState(HtmlDisplay):
    """``ardupilot.indication.SafetyState``, message 20000 (``indication/20000.SafetyState.uavcan``).

    support for Safety LED on UAVCAN
    """

    STATUS_SAFETY_ON: ClassVar[int] = 0
    STATUS_SAFETY_OFF: ClassVar[int] = 255

    status: SafetyStateStatus | int = 0


@dataclass(frozen=True, slots=True)
class Button(HtmlDisplay):
    """``ardupilot.indication.Button``, message 20001 (``indication/20001.Button.uavcan``).

    support for buttons on UAVCAN
    while a button is being pressed this message should be sent at 10Hz
    """

    BUTTON_SAFETY: ClassVar[int] = 1

    button: int = 0
    press_time: int = 0


@dataclass(frozen=True, slots=True)
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

    aux_data_type: int = 0
    aux_data: bytes = b""
    vehicle_state: int = 0


@dataclass(frozen=True, slots=True)
class FlowMeasurement(HtmlDisplay):
    """``com.hex.equipment.flow.Measurement``, message 20200 (``hex/equipment/flow/20200.Measurement.uavcan``)."""

    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"flow_integral", "integration_interval", "rate_gyro_integral"})

    integration_interval: float = 0.0
    """Integration Interval in seconds"""
    rate_gyro_integral: tuple[float, ...] = (0.0,) * 2
    """Integrated Gyro Data in radians"""
    flow_integral: tuple[float, ...] = (0.0,) * 2
    """Integrated LOS Data in radians"""
    quality: int = 0
    """Flow Data Quality Lowest(0)-Highest(255) Unitless"""


@dataclass(frozen=True, slots=True)
class ServoCmd(HtmlDisplay):
    """``com.himark.servo.ServoCmd``, message 2018 (``himark/servo/2018.ServoCmd.uavcan``).

    Himark servo commands
    it is not recommended that anyone implement this message. It is here as a placeholder
    for existing Himark servos
    """

    cmd: tuple[int, ...] = ()


@dataclass(frozen=True, slots=True)
class ServoInfo(HtmlDisplay):
    """``com.himark.servo.ServoInfo``, message 2019 (``himark/servo/2019.ServoInfo.uavcan``).

    Himark servo feedback information
    it is not recommended that anyone implement this message. It is here as a placeholder
    for existing Himark servos
    """

    ERROR_STATUS_NO_ERROR: ClassVar[int] = 0
    ERROR_STATUS_DATA_ERROR: ClassVar[int] = 1

    servo_id: int = 0
    pwm_input: int = 0
    pos_cmd: int = 0
    pos_sensor: int = 0
    voltage: int = 0
    current: int = 0
    pcb_temp: int = 0
    motor_temp: int = 0
    error_status: ErrorStatus | int = 0


@dataclass(frozen=True, slots=True)
class GetEscID(HtmlDisplay):
    """``com.hobbywing.esc.GetEscID``, message 20013 (``hobbywing/esc/20013.GetEscID.uavcan``).

    signature from original file location
    """

    payload: bytes = b""


@dataclass(frozen=True, slots=True)
class StatusMsg1(HtmlDisplay):
    """``com.hobbywing.esc.StatusMsg1``, message 20050 (``hobbywing/esc/20050.StatusMsg1.uavcan``)."""

    rpm: int = 0
    pwm: int = 0
    status: int = 0


@dataclass(frozen=True, slots=True)
class StatusMsg2(HtmlDisplay):
    """``com.hobbywing.esc.StatusMsg2``, message 20051 (``hobbywing/esc/20051.StatusMsg2.uavcan``)."""

    input_voltage: int = 0
    """0.1V"""
    current: int = 0
    """0.1A"""
    temperature: int = 0
    """degC"""


@dataclass(frozen=True, slots=True)
class StatusMsg3(HtmlDisplay):
    """``com.hobbywing.esc.StatusMsg3``, message 20052 (``hobbywing/esc/20052.StatusMsg3.uavcan``)."""

    MOS_T: int = 0
    CAP_T: int = 0
    Motor_T: int = 0


@dataclass(frozen=True, slots=True)
class EscRawCommand(HtmlDisplay):
    """``com.hobbywing.esc.RawCommand``, message 20100 (``hobbywing/esc/20100.RawCommand.uavcan``)."""

    command: tuple[int, ...] = ()


@dataclass(frozen=True, slots=True)
class SetIDRequest(HtmlDisplay):
    """``com.hobbywing.esc.SetID`` request, service 210 (``hobbywing/esc/210.SetID.uavcan``)."""

    node_id: int = 0
    throttle_channel: int = 0


@dataclass(frozen=True, slots=True)
class SetIDResponse(HtmlDisplay):
    """``com.hobbywing.esc.SetID`` response, service 210 (``hobbywing/esc/210.SetID.uavcan``)."""

    node_id: int = 0
    throttle_channel: int = 0


@dataclass(frozen=True, slots=True)
class SetBaudRequest(HtmlDisplay):
    """``com.hobbywing.esc.SetBaud`` request, service 211 (``hobbywing/esc/211.SetBaud.uavcan``)."""

    BAUD_1MBPS: ClassVar[int] = 0
    BAUD_500KBPS: ClassVar[int] = 1
    BAUD_250KBPS: ClassVar[int] = 2
    BAUD_200KBPS: ClassVar[int] = 3
    BAUD_100KBPS: ClassVar[int] = 4
    BAUD_50KBPS: ClassVar[int] = 5

    baud: Baud | int = 0


@dataclass(frozen=True, slots=True)
class SetBaudResponse(HtmlDisplay):
    """``com.hobbywing.esc.SetBaud`` response, service 211 (``hobbywing/esc/211.SetBaud.uavcan``)."""


@dataclass(frozen=True, slots=True)
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

    option: int = 0
    color: Color | int = 0
    blink: Blink | int = 0


@dataclass(frozen=True, slots=True)
class SetLEDResponse(HtmlDisplay):
    """``com.hobbywing.esc.SetLED`` response, service 212 (``hobbywing/esc/212.SetLED.uavcan``)."""

    option: int = 0
    color: int = 0
    blink: int = 0


@dataclass(frozen=True, slots=True)
class SetDirectionRequest(HtmlDisplay):
    """``com.hobbywing.esc.SetDirection`` request, service 213 (``hobbywing/esc/213.SetDirection.uavcan``)."""

    DIRECTION_CLOCKWISE: ClassVar[int] = 0
    DIRECTION_COUNTER_CLOCKWISE: ClassVar[int] = 1
    DIRECTION_QUERY: ClassVar[int] = 255

    direction: Direction | int = 0


@dataclass(frozen=True, slots=True)
class SetDirectionResponse(HtmlDisplay):
    """``com.hobbywing.esc.SetDirection`` response, service 213 (``hobbywing/esc/213.SetDirection.uavcan``)."""

    direction: int = 0


@dataclass(frozen=True, slots=True)
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

    option: Option | int = 0
    MSG_ID: int = 0
    rate: Rate | int = 0


@dataclass(frozen=True, slots=True)
class SetReportingFrequencyResponse(HtmlDisplay):
    """``com.hobbywing.esc.SetReportingFrequency`` response, service 214 (``hobbywing/esc/214.SetReportingFrequency.uavcan``)."""

    option: int = 0
    MSG_ID: int = 0
    rate: int = 0


@dataclass(frozen=True, slots=True)
class SetThrottleSourceRequest(HtmlDisplay):
    """``com.hobbywing.esc.SetThrottleSource`` request, service 215 (``hobbywing/esc/215.SetThrottleSource.uavcan``)."""

    SOURCE_CAN_DIGITAL: ClassVar[int] = 0
    SOURCE_PWM: ClassVar[int] = 1

    source: SetThrottleSourceRequestSource | int = 0


@dataclass(frozen=True, slots=True)
class SetThrottleSourceResponse(HtmlDisplay):
    """``com.hobbywing.esc.SetThrottleSource`` response, service 215 (``hobbywing/esc/215.SetThrottleSource.uavcan``)."""

    source: int = 0


@dataclass(frozen=True, slots=True)
class SelfTestRequest(HtmlDisplay):
    """``com.hobbywing.esc.SelfTest`` request, service 216 (``hobbywing/esc/216.SelfTest.uavcan``)."""


@dataclass(frozen=True, slots=True)
class SelfTestResponse(HtmlDisplay):
    """``com.hobbywing.esc.SelfTest`` response, service 216 (``hobbywing/esc/216.SelfTest.uavcan``)."""

    STATUS_PASS: ClassVar[int] = 0
    STATUS_FAIL: ClassVar[int] = 1

    status: SelfTestResponseStatus | int = 0


@dataclass(frozen=True, slots=True)
class SetAngleRequest(HtmlDisplay):
    """``com.hobbywing.esc.SetAngle`` request, service 217 (``hobbywing/esc/217.SetAngle.uavcan``)."""

    option: int = 0
    angle: int = 0


@dataclass(frozen=True, slots=True)
class SetAngleResponse(HtmlDisplay):
    """``com.hobbywing.esc.SetAngle`` response, service 217 (``hobbywing/esc/217.SetAngle.uavcan``)."""

    option: int = 0
    angle: tuple[int, ...] = ()


@dataclass(frozen=True, slots=True)
class GetMaintenanceInformationRequest(HtmlDisplay):
    """``com.hobbywing.esc.GetMaintenanceInformation`` request, service 241 (``hobbywing/esc/241.GetMaintenanceInformation.uavcan``)."""

    OPTION_CLEAR: ClassVar[int] = 1

    option: int = 0


@dataclass(frozen=True, slots=True)
class GetMaintenanceInformationResponse(HtmlDisplay):
    """``com.hobbywing.esc.GetMaintenanceInformation`` response, service 241 (``hobbywing/esc/241.GetMaintenanceInformation.uavcan``)."""

    total_rotation_time_min: int = 0
    time_since_maintainence_min: int = 0


@dataclass(frozen=True, slots=True)
class GetMajorConfigRequest(HtmlDisplay):
    """``com.hobbywing.esc.GetMajorConfig`` request, service 242 (``hobbywing/esc/242.GetMajorConfig.uavcan``)."""

    option: int = 0


@dataclass(frozen=True, slots=True)
class GetMajorConfigResponse(HtmlDisplay):
    """``com.hobbywing.esc.GetMajorConfig`` response, service 242 (``hobbywing/esc/242.GetMajorConfig.uavcan``)."""

    direction: bool = False
    throttle_source: bool = False
    throttle_channel: int = 0
    led_status: int = 0
    led_color: int = 0
    MSG2_rate: int = 0
    MSG1_rate: int = 0
    positioning_angle: int = 0
    reserved: bytes = bytes(2)


@dataclass(frozen=True, slots=True)
class ParamCfg(HtmlDisplay):
    """``com.tmotor.esc.ParamCfg``, message 1033 (``tmotor/esc/1033.ParamCfg.uavcan``).

    1033.ParamCfg.uavcan parameter setting
    """

    esc_index: int = 0
    esc_uuid: int = 0
    esc_id_set: int = 0
    esc_ov_threshold: int = 0
    esc_oc_threshold: int = 0
    esc_ot_threshold: int = 0
    esc_acc_threshold: int = 0
    esc_dacc_threshold: int = 0
    esc_rotate_dir: int = 0
    esc_timing: int = 0
    esc_signal_priority: int = 0
    esc_led_mode: int = 0
    esc_can_rate: int = 0
    esc_fdb_rate: int = 0
    esc_save_option: int = 0


@dataclass(frozen=True, slots=True)
class FocCtrl(HtmlDisplay):
    """``com.tmotor.esc.FocCtrl``, message 1035 (``tmotor/esc/1035.FocCtrl.uavcan``).

    Generic ESC status.
    """

    esc_index: int = 0
    esc_mode: int = 0
    esc_fdb_rate: int = 0
    esc_cmd: int = 0
    esc_cmd_val: int = 0


@dataclass(frozen=True, slots=True)
class PUSHSCI(HtmlDisplay):
    """``com.tmotor.esc.PUSHSCI``, message 1038 (``tmotor/esc/1038.PUSHSCI.uavcan``).

    Generic ESC SCI DATA.
    """

    data_sequence: int = 0
    """data sequence"""
    data: bytes = b""


@dataclass(frozen=True, slots=True)
class PUSHCAN(HtmlDisplay):
    """``com.tmotor.esc.PUSHCAN``, message 1039 (``tmotor/esc/1039.PUSHCAN.uavcan``).

    Generic ESC status.
    """

    data_sequence: int = 0
    """data sequence"""
    data: bytes = b""


@dataclass(frozen=True, slots=True)
class ParamGet(HtmlDisplay):
    """``com.tmotor.esc.ParamGet``, message 1332 (``tmotor/esc/1332.ParamGet.uavcan``).

    1033.ParamGet.uavcan param get pack
    """

    esc_index: int = 0
    esc_uuid: int = 0
    esc_id_req: int = 0
    esc_ov_threshold: int = 0
    esc_oc_threshold: int = 0
    esc_ot_threshold: int = 0
    esc_acc_threshold: int = 0
    esc_dacc_threshold: int = 0
    esc_rotate_dir: int = 0
    esc_timing: int = 0
    esc_startup_times: int = 0
    esc_startup_duration: int = 0
    esc_product_date: int = 0
    esc_error_count: int = 0
    esc_signal_priority: int = 0
    esc_led_mode: int = 0
    esc_can_rate: int = 0
    esc_fdb_rate: int = 0
    esc_save_option: int = 0
    rsvd: bytes = b""


@dataclass(frozen=True, slots=True)
class ServoActuatorStatus(HtmlDisplay):
    """``com.volz.servo.ActuatorStatus``, message 20020 (``volz/servo/20020.ActuatorStatus.uavcan``).

    Volz servo feedback.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"actual_position"})

    actuator_id: int = 0
    """Unique actuator ID (1..15)"""
    actual_position: float = 0.0
    """Actual servo position in radians"""
    current: int = 0
    """Current: unsigned, 8-bit value, one count = 0.025 A"""
    voltage: int = 0
    """Supply voltage: unsigned, 8-bit value, one count = 0.2 V"""
    motor_pwm: int = 0
    """Motor PWM: unsigned, 8-bit value, 0 = 0% Motor power, 255 = 100% Motor Power"""
    motor_temperature: int = 0
    """Motor temperature: unsigned 8-bit value, 0 = -50C, 255 = sensor error, one count = one degree"""


@dataclass(frozen=True, slots=True)
class XactiGnssStatus(HtmlDisplay):
    """``com.xacti.GnssStatus``, message 20305 (``xacti/20305.GnssStatus.uavcan``).

    Xacti GNSS status
    """

    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"altitude", "utc_seconds"})

    gps_status: int = 0
    order: int = 0
    remain_buffer: int = 0
    utc_year: int = 0
    """2023 ~"""
    utc_month: int = 0
    """1 ~ 12"""
    utc_day: int = 0
    """1 ~ 31"""
    utc_hour: int = 0
    """0 ~ 23"""
    utc_minute: int = 0
    """0 ~ 59"""
    utc_seconds: float = 0.0
    """0 ~ below 60"""
    latitude: float = 0.0
    """degrees -90 ~ +90"""
    longitude: float = 0.0
    """degrees -180 ~ +180"""
    altitude: float = 0.0
    """meters above sea level, AMSL"""


@dataclass(frozen=True, slots=True)
class GnssStatusReq(HtmlDisplay):
    """``com.xacti.GnssStatusReq``, message 20306 (``xacti/20306.GnssStatusReq.uavcan``).

    Xacti GNSS status request
    """

    requirement: int = 0


@dataclass(frozen=True, slots=True)
class GimbalAttitudeStatus(HtmlDisplay):
    """``com.xacti.GimbalAttitudeStatus``, message 20402 (``xacti/20402.GimbalAttitudeStatus.uavcan``).

    Xacti camera gimbal attitude status
    """

    gimbal_roll: int = 0
    gimbal_pitch: int = 0
    gimbal_yaw: int = 0
    magneticencoder_roll: int = 0
    magneticencoder_pitch: int = 0
    magneticencoder_yaw: int = 0


@dataclass(frozen=True, slots=True)
class CopterAttStatus(HtmlDisplay):
    '``com.xacti.CopterAttStatus``, message 20407 (``xacti/20407.CopterAttStatus.uavcan``).\n\nXacti specific vehicle attitude provided to camera gimbal\nsend periodically 5~10Hz.\n\nquaternion_wxyz_e4[0] = q.w\t(or q.q0) * 1e4f\nquaternion_wxyz_e4[1] = q.x\t(or q.q1) * 1e4f\nquaternion_wxyz_e4[2] = q.y\t(or q.q2) * 1e4f\nquaternion_wxyz_e4[3] = q.z\t(or q.q3) * 1e4f'

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"reserved"})

    quaternion_wxyz_e4: tuple[int, ...] = (0,) * 4
    reserved: tuple[float, ...] = ()


@dataclass(frozen=True, slots=True)
class GimbalControlData(HtmlDisplay):
    """``com.xacti.GimbalControlData``, message 20554 (``xacti/20554.GimbalControlData.uavcan``).

    Xacti camera gimbal control
    """

    pitch_cmd_type: int = 0
    yaw_cmd_type: int = 0
    pitch_cmd_value: int = 0
    yaw_cmd_value: int = 0


@dataclass(frozen=True, slots=True)
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

    temperature: float = 0.0
    """The surface temperature of the battery"""
    voltage: float = 0.0
    """The total voltage of the battery"""
    voltage_cell: tuple[float, ...] = ()
    """Battery individual cell voltages"""
    cell_count: int = 0
    """Number of cells"""
    current: float = 0.0
    """The current flowing through the sense resistor"""
    average_current: float = 0.0
    """The average current flowing through the sense resistor"""
    average_power: float = 0.0
    """The average power of the current discharge"""
    available_energy: float = 0.0
    """The predicted charge or energy remaining in the battery"""
    remaining_capacity: float = 0.0
    """The compensated battery capacity remaining"""
    full_charge_capacity: float = 0.0
    """The compensated capacity of the battery when fully charged"""
    design_capacity: float = 0.0
    """The design capacity of the battery"""
    average_time_to_empty: int = 0
    """The predicted remaining battery life at the present rate of discharge, in minutes"""
    average_time_to_full: int = 0
    """The predicted remaining time until the battery reaches full charge, in minutes"""
    state_of_health: int = 0
    """Health of the battery"""
    state_of_charge: int = 0
    """Percent of the full charge [0, 100]"""
    max_error: int = 0
    """max error, expected margin of error in % in the state-of-charge calculation with a range of 1 to 100%"""
    serial_number: int = 0
    """serial number of the battery pack"""
    manufacture_date: int = 0
    """manufacture date, part of serial number of the battery pack"""
    cycle_count: int = 0
    """number of discharge cycles the battery has experienced"""
    over_discharge_count: int = 0
    """Number of battery overdischarge"""
    passed_charge: float = 0.0
    """The amount of charge passing through the sense resistor"""
    nominal_voltage: float = 0.0
    """Nominal voltage of the battery pack"""
    is_powering_off: bool = False
    """Power off event imminent indication, false if unknown"""
    interface_error: int = 0
    """interface error counter"""
    status_flags: int = 0


@dataclass(frozen=True, slots=True)
class FlexDebug(HtmlDisplay):
    """``dronecan.protocol.FlexDebug``, message 16371 (``protocol/16371.FlexDebug.uavcan``).

    flexible debug message for development purposes

    vendors can reserve a range of IDs for their products, reservation are in blocks of 10
    """

    RESERVATION_SIZE: ClassVar[int] = 10
    AM32_RESERVE_START: ClassVar[int] = 100
    MLRS_RESERVE_START: ClassVar[int] = 110

    id: int = 0
    u8: bytes = b""


@dataclass(frozen=True, slots=True)
class Stats(HtmlDisplay):
    """``dronecan.protocol.Stats``, message 342 (``protocol/342.Stats.uavcan``).

    monitor the status of the DroneCAN Protocol decoder on the node
    """

    tx_frames: int = 0
    """Number of transmitted frames"""
    tx_errors: int = 0
    """Number of errors during transmission"""
    rx_frames: int = 0
    """Number of received frames"""
    rx_error_oom: int = 0
    """Number of out-of-memory errors"""
    rx_error_internal: int = 0
    """Number of internal errors"""
    rx_error_missed_start: int = 0
    """Number of missed start bits"""
    rx_error_wrong_toggle: int = 0
    """Number of wrong toggle bits"""
    rx_error_short_frame: int = 0
    """Number of frames that were too short"""
    rx_error_bad_crc: int = 0
    """Number of frames with bad CRC"""
    rx_ignored_wrong_address: int = 0
    """Number of frames with wrong address"""
    rx_ignored_not_wanted: int = 0
    """Number of frames that were not wanted"""
    rx_ignored_unexpected_tid: int = 0
    """Number of frames with unexpected TID"""


@dataclass(frozen=True, slots=True)
class CanStats(HtmlDisplay):
    """``dronecan.protocol.CanStats``, message 343 (``protocol/343.CanStats.uavcan``).

    Monitor the stats of physical layer on the node
    """

    interface: int = 0
    """interface number"""
    tx_requests: int = 0
    """number of tx requests"""
    tx_rejected: int = 0
    """number of tx requests rejected"""
    tx_overflow: int = 0
    """number of tx requests overflow"""
    tx_success: int = 0
    """number of tx requests success"""
    tx_timedout: int = 0
    """number of tx requests timedout"""
    tx_abort: int = 0
    """number of tx requests aborted"""
    rx_received: int = 0
    """number of rx received"""
    rx_overflow: int = 0
    """number of rx overflow"""
    rx_errors: int = 0
    """number of rx errors"""
    busoff_errors: int = 0
    """number of busoff errors"""


@dataclass(frozen=True, slots=True)
class GlobalTime(HtmlDisplay):
    """``dronecan.protocol.GlobalTime``, message 344 (``protocol/344.GlobalTime.uavcan``).

    provide global timestamp, time since 1/1/1970 in microseconds
    should only be broadcast once a reliable time base (GPS or equivalent) is known
    """

    timestamp: Timestamp = Timestamp()


@dataclass(frozen=True, slots=True)
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

    id_or_mac: bytes = b""
    id_type: int = 0
    ua_type: int = 0
    uas_id: bytes = b""


@dataclass(frozen=True, slots=True)
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

    id_or_mac: bytes = b""
    status: int = 0
    direction: int = 0
    """centi-deg, 0-35999"""
    speed_horizontal: int = 0
    """cm/s, max 25425, if unknown use 25500"""
    speed_vertical: int = 0
    """positive up, max +/-6200, if unknown use 6300"""
    latitude: int = 0
    """degE7"""
    longitude: int = 0
    """degE7"""
    altitude_barometric: float = 0.0
    """meters, for unknown use -1000, ref is 29.92inHg or 1013.2mb"""
    altitude_geodetic: float = 0.0
    """meters, for unknown use -1000, WGS84"""
    height_reference: int = 0
    height: float = 0.0
    """meters, for unknown use -1000"""
    horizontal_accuracy: int = 0
    vertical_accuracy: int = 0
    barometer_accuracy: int = 0
    speed_accuracy: int = 0
    timestamp: float = 0.0
    """seconds after the full hour with reference to UTC time. Use 0xFFFF if unknown"""
    timestamp_accuracy: int = 0


@dataclass(frozen=True, slots=True)
class SelfID(HtmlDisplay):
    """``dronecan.remoteid.SelfID``, message 20032 (``remoteid/20032.SelfID.uavcan``).

    DroneCAN version of MAVLink OPEN_DRONE_ID_SELF_ID
    see MAVLink XML for detailed description
    """

    _TEXT_FIELDS_: ClassVar[frozenset[str]] = frozenset({"description"})
    ODID_DESC_TYPE_TEXT: ClassVar[int] = 0
    """Free-form text description of the purpose of the flight"""

    id_or_mac: bytes = b""
    description_type: int = 0
    description: bytes = b""


@dataclass(frozen=True, slots=True)
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

    id_or_mac: bytes = b""
    operator_location_type: int = 0
    classification_type: int = 0
    operator_latitude: int = 0
    """degE7"""
    operator_longitude: int = 0
    """degE7"""
    area_count: int = 0
    """default 1"""
    area_radius: int = 0
    """meters"""
    area_ceiling: float = 0.0
    """meters, use -1000 if unknown, WGS84"""
    area_floor: float = 0.0
    """meters, use -1000 if unknown, WGS84"""
    category_eu: int = 0
    class_eu: int = 0
    operator_altitude_geo: float = 0.0
    """meters, use -1000 if unknown, WGS84"""
    timestamp: int = 0
    """Unix seconds since 00:00:00 01/01/2019"""


@dataclass(frozen=True, slots=True)
class OperatorID(HtmlDisplay):
    """``dronecan.remoteid.OperatorID``, message 20034 (``remoteid/20034.OperatorID.uavcan``).

    DroneCAN version of MAVLink OPEN_DRONE_ID_OPERATOR_ID
    see MAVLink XML for detailed description
    """

    ODID_OPERATOR_ID_TYPE_CAA: ClassVar[int] = 0
    """CAA (Civil Aviation Authority) registered operator ID"""

    id_or_mac: bytes = b""
    operator_id_type: int = 0
    operator_id: bytes = b""


@dataclass(frozen=True, slots=True)
class ArmStatus(HtmlDisplay):
    """``dronecan.remoteid.ArmStatus``, message 20035 (``remoteid/20035.ArmStatus.uavcan``).

    DroneCAN version of MAVLink OPEN_DRONE_ID_ARM_STATUS
    see MAVLink XML for detailed description
    """

    ODID_ARM_STATUS_GOOD_TO_ARM: ClassVar[int] = 0
    ODID_ARM_STATUS_FAIL_GENERIC: ClassVar[int] = 1

    status: int = 0
    error: bytes = b""


@dataclass(frozen=True, slots=True)
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

    sequence: int = 0
    operation: int = 0
    sig_length: int = 0
    data: bytes = b""


@dataclass(frozen=True, slots=True)
class SecureCommandResponse(HtmlDisplay):
    """``dronecan.remoteid.SecureCommand`` response, service 64 (``remoteid/64.SecureCommand.uavcan``)."""

    RESULT_ACCEPTED: ClassVar[int] = 0
    RESULT_TEMPORARILY_REJECTED: ClassVar[int] = 1
    RESULT_DENIED: ClassVar[int] = 2
    RESULT_UNSUPPORTED: ClassVar[int] = 3
    RESULT_FAILED: ClassVar[int] = 4

    sequence: int = 0
    operation: int = 0
    result: Result | int = 0
    data: bytes = b""


@dataclass(frozen=True, slots=True)
class Hygrometer(HtmlDisplay):
    """``dronecan.sensors.hygrometer.Hygrometer``, message 1032 (``sensors/hygrometer/1032.Hygrometer.uavcan``).

    support for hygrometer sensors
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"humidity", "temperature"})

    temperature: float = 0.0
    humidity: float = 0.0
    id: int = 0


@dataclass(frozen=True, slots=True)
class MagneticFieldStrengthHiRes(HtmlDisplay):
    """``dronecan.sensors.magnetometer.MagneticFieldStrengthHiRes``, message 1043 (``sensors/magnetometer/1043.MagneticFieldStrengthHiRes.uavcan``).

    Magnetic field readings, in Gauss, in body frame, high resolution version
    """

    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"magnetic_field_ga"})

    sensor_id: int = 0
    magnetic_field_ga: tuple[float, ...] = (0.0,) * 3


@dataclass(frozen=True, slots=True)
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

    status: int = 0
    """bitmask of status bits, enumerated above with STATUS_*"""
    quality: Quality | int = 0
    """see descriptions for status bits STATUS_QUALITY_VALID, STATUS_QUALITY_LQ, STATUS_QUALITY_SNR"""
    id: int = 0
    """ID of this RC input device"""
    rcin: tuple[int, ...] = ()
    """RC channel values between 0 and 4095, values are in PWM microseconds, 1500 represents the mid position"""


@dataclass(frozen=True, slots=True)
class RPM(HtmlDisplay):
    """``dronecan.sensors.rpm.RPM``, message 1045 (``sensors/rpm/1045.RPM.uavcan``).

    RPM reading in revolutions per minute
    """

    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"rpm"})
    FLAGS_UNHEALTHY: ClassVar[int] = 1
    """Sensor is not healthy"""

    sensor_id: int = 0
    flags: int = 0
    rpm: float = 0.0


@dataclass(frozen=True, slots=True)
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

    fault_flags: int = 0
    temperature: int = 0
    """[Celsius]"""
    input_voltage: float = 0.0
    """[Volt]"""
    input_current: float = 0.0
    """[Amp]"""
    input_power: float = 0.0
    """[Watt]"""
    output_voltage: float = 0.0
    """[Volt]"""
    output_current: float = 0.0
    """[Amp]"""
    output_power: float = 0.0
    """[Watt]"""


@dataclass(frozen=True, slots=True)
class OutputEnableRequest(HtmlDisplay):
    """``mppt.OutputEnable`` request, service 240 (``240.OutputEnable.uavcan``).

    Service to enable or disable the mppt output.
    """

    enable: bool = False
    disable: bool = False


@dataclass(frozen=True, slots=True)
class OutputEnableResponse(HtmlDisplay):
    """``mppt.OutputEnable`` response, service 240 (``240.OutputEnable.uavcan``)."""

    enabled: bool = False


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
