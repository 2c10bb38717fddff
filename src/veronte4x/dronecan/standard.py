"""Every type of the standard ``uavcan`` DSDL namespace, as frozen dataclasses.

GENERATED from the DSDL files shipped in ``veronte4x/dronecan/dsdl`` by
``python -m veronte4x.dronecan.generate``: do not edit (a test regenerates and compares).
The naming rules are those of `veronte4x.dronecan.generate`; `veronte4x.dronecan.messages`
re-exports the classes veronte4x had before the DSDL compiler.
"""

from __future__ import annotations

import enum
from typing import Any, ClassVar, TypeAlias

from veronte4x.display import HtmlDisplay
from veronte4x.dronecan.written import frozen_dataclass

_setattr = object.__setattr__
"""How each ``__init__`` sets a frozen field."""


class TemperatureErrorFlag(enum.IntFlag):
    """DSDL constants ``ERROR_FLAG_*``."""

    OVERHEATING = 1
    OVERCOOLING = 2


class Health(enum.IntEnum):
    """DSDL constants ``HEALTH_*``."""

    OK = 0
    """The node is functioning properly."""
    WARNING = 1
    """A critical parameter went out of range or the node encountered a minor failure."""
    ERROR = 2
    """The node encountered a major failure."""
    CRITICAL = 3
    """The node suffered a fatal malfunction."""


class Mode(enum.IntEnum):
    """DSDL constants ``MODE_*``."""

    OPERATIONAL = 0
    """Normal operating mode."""
    INITIALIZATION = 1
    """Initialization is in progress; this mode is entered immediately after startup."""
    MAINTENANCE = 2
    """E.g. calibration, the bootloader is running, etc."""
    SOFTWARE_UPDATE = 3
    """New software/firmware is being loaded."""
    OFFLINE = 7
    """The node is no longer available."""


class SoftwareVersionFlag(enum.IntFlag):
    """DSDL constants ``OPTIONAL_FIELD_FLAG_*``."""

    VCS_COMMIT = 1
    IMAGE_CRC = 2


class FirmwareUpdateError(enum.IntEnum):
    """DSDL constants ``ERROR_*``."""

    OK = 0
    INVALID_MODE = 1
    """Cannot perform the update in the current operating mode or state."""
    IN_PROGRESS = 2
    """Firmware update is already in progress, and the slave doesn't want to restart."""
    UNKNOWN = 255


class EntryTypeFlag(enum.IntFlag):
    """DSDL constants ``FLAG_*``."""

    FILE = 1
    """Excludes FLAG_DIRECTORY"""
    DIRECTORY = 2
    """Excludes FLAG_FILE"""
    SYMLINK = 4
    """Link target is either FLAG_FILE or FLAG_DIRECTORY"""
    READABLE = 8
    WRITEABLE = 16


class Opcode(enum.IntEnum):
    """DSDL constants ``OPCODE_*``."""

    SAVE = 0
    """Save all parameters to non-volatile storage."""
    ERASE = 1
    """Clear the non-volatile storage; some changes may take effect only after reboot."""


class CommandType(enum.IntEnum):
    """DSDL constants ``COMMAND_TYPE_*``."""

    UNITLESS = 0
    """[-1, 1]"""
    POSITION = 1
    """meter or radian"""
    FORCE = 2
    """Newton or Newton metre"""
    SPEED = 3
    """meter per second or radian per second"""
    PWM = 4
    """PWM microsecond signal"""


class SensorId(enum.IntEnum):
    """DSDL constants ``SENSOR_ID_*``."""

    LEFT = 254
    RIGHT = 255


class RawAirDataFlag(enum.IntFlag):
    """DSDL constants ``FLAG_*``."""

    HEATER_AVAILABLE = 1
    HEATER_WORKING = 2
    HEATER_OVERCURRENT = 4
    HEATER_OPENCIRCUIT = 8


class HeightReference(enum.IntEnum):
    """DSDL constants ``HEIGHT_REFERENCE_*``."""

    ELLIPSOID = 0
    MEAN_SEA_LEVEL = 1


class CommandMode(enum.IntEnum):
    """DSDL constants ``COMMAND_MODE_*``."""

    ANGULAR_VELOCITY = 0
    ORIENTATION_FIXED_FRAME = 1
    ORIENTATION_BODY_FRAME = 2
    GEO_POI = 3


class FixGnssTimeStandard(enum.IntEnum):
    """DSDL constants ``GNSS_TIME_STANDARD_*``."""

    NONE = 0
    """Time is unknown"""
    TAI = 1
    UTC = 2
    GPS = 3


class FixStatus(enum.IntEnum):
    """DSDL constants ``STATUS_*``."""

    STATUS_NO_FIX = 0
    STATUS_TIME_ONLY = 1
    STATUS_2D_FIX = 2
    STATUS_3D_FIX = 3


class ProtocolId(enum.IntEnum):
    """DSDL constants ``PROTOCOL_ID_*``."""

    UNKNOWN = 0
    RTCM2 = 2
    RTCM3 = 3


class Fix2GnssTimeStandard(enum.IntEnum):
    """DSDL constants ``GNSS_TIME_STANDARD_*``."""

    NONE = 0
    """Time is unknown"""
    TAI = 1
    UTC = 2
    GPS = 3


class Fix2Status(enum.IntEnum):
    """DSDL constants ``STATUS_*``."""

    STATUS_NO_FIX = 0
    STATUS_TIME_ONLY = 1
    STATUS_2D_FIX = 2
    STATUS_3D_FIX = 3


class Fix2Mode(enum.IntEnum):
    """DSDL constants ``MODE_*``."""

    SINGLE = 0
    DGPS = 1
    RTK = 2
    PPP = 3


class State(enum.IntEnum):
    """DSDL constants ``STATE_*``."""

    STOPPED = 0
    STARTING = 1
    RUNNING = 2
    FAULT = 3


class ReciprocatingStatusFlag(enum.IntFlag):
    """DSDL constants ``FLAG_*``."""

    GENERAL_ERROR = 1
    CRANKSHAFT_SENSOR_ERROR_SUPPORTED = 2
    CRANKSHAFT_SENSOR_ERROR = 4
    TEMPERATURE_SUPPORTED = 8
    TEMPERATURE_BELOW_NOMINAL = 16
    """Under-temperature warning"""
    TEMPERATURE_ABOVE_NOMINAL = 32
    """Over-temperature warning"""
    TEMPERATURE_OVERHEATING = 64
    """Critical overheating"""
    TEMPERATURE_EGT_ABOVE_NOMINAL = 128
    """Exhaust gas over-temperature warning"""
    FUEL_PRESSURE_SUPPORTED = 256
    FUEL_PRESSURE_BELOW_NOMINAL = 512
    """Under-pressure warning"""
    FUEL_PRESSURE_ABOVE_NOMINAL = 1024
    """Over-pressure warning"""
    DETONATION_SUPPORTED = 2048
    DETONATION_OBSERVED = 4096
    """Detonation condition observed warning"""
    MISFIRE_SUPPORTED = 8192
    MISFIRE_OBSERVED = 16384
    """Misfire condition observed warning"""
    OIL_PRESSURE_SUPPORTED = 32768
    OIL_PRESSURE_BELOW_NOMINAL = 65536
    """Under-pressure warning"""
    OIL_PRESSURE_ABOVE_NOMINAL = 131072
    """Over-pressure warning"""
    DEBRIS_SUPPORTED = 262144
    DEBRIS_DETECTED = 524288
    """Detection of debris warning"""


class LightId(enum.IntEnum):
    """DSDL constants ``LIGHT_ID_*``."""

    ANTI_COLLISION = 246
    RIGHT_OF_WAY = 247
    STROBE = 248
    WING = 249
    LOGO = 250
    TAXI = 251
    TURN_OFF = 252
    TAKE_OFF = 253
    LANDING = 254
    FORMATION = 255


class ErrorFlag(enum.IntFlag):
    """DSDL constants ``ERROR_FLAG_*``."""

    OVERVOLTAGE = 1
    UNDERVOLTAGE = 2
    OVERCURRENT = 4
    UNDERCURRENT = 8


class StatusFlag(enum.IntFlag):
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


class SensorType(enum.IntEnum):
    """DSDL constants ``SENSOR_TYPE_*``."""

    UNDEFINED = 0
    SONAR = 1
    LIDAR = 2
    RADAR = 3


class ReadingType(enum.IntEnum):
    """DSDL constants ``READING_TYPE_*``."""

    UNDEFINED = 0
    """Range is unknown"""
    VALID_RANGE = 1
    """Range field contains valid distance"""
    TOO_CLOSE = 2
    """Range field contains min range for the sensor"""
    TOO_FAR = 3
    """Range field contains max range for the sensor"""


class ArmingStatusStatus(enum.IntEnum):
    """DSDL constants ``STATUS_*``."""

    DISARMED = 0
    FULLY_ARMED = 255


class GetDataTypeInfoResponseFlag(enum.IntFlag):
    """DSDL constants ``FLAG_*``."""

    KNOWN = 1
    """This data type is defined"""
    SUBSCRIBED = 2
    """Subscribed to messages of this type"""
    PUBLISHING = 4
    """Publishing messages of this type"""
    SERVING = 8
    """Providing service of this type"""


class AccessCommandShellRequestFlag(enum.IntFlag):
    """DSDL constants ``FLAG_*``."""

    RESET_SHELL = 1
    """Restarts the shell instance anew; may or may not imply CLEAR_OUTPUT_BUFFERS"""
    CLEAR_OUTPUT_BUFFERS = 2
    """Makes stdout and stderr buffers empty"""
    READ_STDOUT = 64
    """Output will contain stdout"""
    READ_STDERR = 128
    """Output will be extended with stderr"""


class AccessCommandShellResponseFlag(enum.IntFlag):
    """DSDL constants ``FLAG_*``."""

    RUNNING = 1
    """The shell is currently running a process; stdin/out/err are piped to it"""
    SHELL_ERROR = 2
    """Exit status contains error code, output contains text (e.g. no such command)"""
    HAS_PENDING_STDOUT = 64
    """There is more stdout to read"""
    HAS_PENDING_STDERR = 128
    """There is more stderr to read"""


class DataTypeKindValue(enum.IntEnum):
    """DSDL constants of ``uavcan.protocol.DataTypeKind``."""

    SERVICE = 0
    MESSAGE = 1


class LogLevelValue(enum.IntEnum):
    """DSDL constants of ``uavcan.protocol.debug.LogLevel``."""

    DEBUG = 0
    INFO = 1
    WARNING = 2
    ERROR = 3


class Error(enum.IntEnum):
    """DSDL constants ``ERROR_*``."""

    OK = 0
    """Success"""
    INVALID_MODE = 1
    """The node cannot perform enumeration in its current operating mode"""
    INVALID_PARAMETER = 2
    """The node cannot enumerate on the requested parameter, or it doesn't exist"""
    UNSUPPORTED = 3
    """The node cannot perform enumeration in its current configuration"""
    UNKNOWN = 255
    """Generic error"""


class ProtocolProtocol(enum.IntEnum):
    """DSDL constants of ``uavcan.tunnel.Protocol``."""

    MAVLINK = 0
    """MAVLink"""
    MAVLINK2 = 1
    """MAVLink2"""
    GPS_GENERIC = 2
    """GPS in any protocol (e.g. UBX, NMEA, etc.)"""
    UNDEFINED = 255
    """Undefined"""


class FileError(enum.IntEnum):
    """DSDL constants of ``uavcan.protocol.file.Error``."""

    OK = 0
    UNKNOWN_ERROR = 32767
    NOT_FOUND = 2
    IO_ERROR = 5
    ACCESS_DENIED = 13
    IS_DIRECTORY = 21
    """I.e. attempt to read/write on a path that points to a directory"""
    INVALID_VALUE = 22
    """E.g. file name is not valid for the target file system"""
    FILE_TOO_LARGE = 27
    OUT_OF_SPACE = 28
    NOT_IMPLEMENTED = 38


@frozen_dataclass
class CoarseOrientation(HtmlDisplay):
    """``uavcan.CoarseOrientation`` (nested; ``CoarseOrientation.uavcan``).

    Nested type.
    Coarse, low-resolution 3D orientation represented as fixed axes in 16 bit.

    Roll, pitch, yaw angles in radians should be multiplied by
    ANGLE_MULTIPLIER in order to convert them to the coarse representation.

    ANGLE_MULTIPLIER = NORM / PI

    Where NORM is 12, because it:
    - Fits the maximum range of a signed 5 bit integer
    - Allows to exactly represent the following angles:
    0, 15, 30, 45, 60, 75, 90, 105, 120, 135, 150, 165, 180, and negatives
    """

    ANGLE_MULTIPLIER: ClassVar[float] = 4.7746482927568605

    __slots__ = ("fixed_axis_roll_pitch_yaw", "orientation_defined",)

    fixed_axis_roll_pitch_yaw: tuple[int, ...]
    orientation_defined: bool
    """False if the orientation is actually not defined"""

    def __init__(
        self,
        fixed_axis_roll_pitch_yaw: tuple[int, ...] = (0,) * 3,
        orientation_defined: bool = False,
    ) -> None:
        _setattr(self, "fixed_axis_roll_pitch_yaw", fixed_axis_roll_pitch_yaw)
        _setattr(self, "orientation_defined", orientation_defined)


@frozen_dataclass
class Timestamp(HtmlDisplay):
    """``uavcan.Timestamp`` (nested; ``Timestamp.uavcan``).

    Global timestamp in microseconds, 7 bytes.

    Use this data type for timestamp fields in messages, like follows:
    uavcan.Timestamp timestamp
    """

    UNKNOWN: ClassVar[int] = 0

    __slots__ = ("usec",)

    usec: int
    """Microseconds"""

    def __init__(
        self,
        usec: int = 0,
    ) -> None:
        _setattr(self, "usec", usec)


@frozen_dataclass
class ActuatorCommand(HtmlDisplay):
    """``uavcan.equipment.actuator.Command`` (nested; ``equipment/actuator/Command.uavcan``).

    Nested type.
    Single actuator command.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"command_value"})
    COMMAND_TYPE_UNITLESS: ClassVar[int] = 0
    """[-1, 1]"""
    COMMAND_TYPE_POSITION: ClassVar[int] = 1
    """meter or radian"""
    COMMAND_TYPE_FORCE: ClassVar[int] = 2
    """Newton or Newton metre"""
    COMMAND_TYPE_SPEED: ClassVar[int] = 3
    """meter per second or radian per second"""
    COMMAND_TYPE_PWM: ClassVar[int] = 4
    """PWM microsecond signal"""

    __slots__ = ("actuator_id", "command_type", "command_value",)

    actuator_id: int
    command_type: CommandType | int
    command_value: float

    def __init__(
        self,
        actuator_id: int = 0,
        command_type: CommandType | int = 0,
        command_value: float = 0.0,
    ) -> None:
        _setattr(self, "actuator_id", actuator_id)
        _setattr(self, "command_type", command_type)
        _setattr(self, "command_value", command_value)


@frozen_dataclass
class ArrayCommand(HtmlDisplay):
    """``uavcan.equipment.actuator.ArrayCommand``, message 1010 (``equipment/actuator/1010.ArrayCommand.uavcan``).

    Actuator commands.
    The system supports up to 256 actuators; up to 15 of them can be commanded with one message.
    """

    __slots__ = ("commands",)

    commands: tuple[ActuatorCommand, ...]

    def __init__(
        self,
        commands: tuple[ActuatorCommand, ...] = (),
    ) -> None:
        _setattr(self, "commands", commands)


@frozen_dataclass
class ActuatorStatus(HtmlDisplay):
    """``uavcan.equipment.actuator.Status``, message 1011 (``equipment/actuator/1011.Status.uavcan``).

    Generic actuator feedback, if available.
    Unknown fields should be set to NAN.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"force", "position", "speed"})
    POWER_RATING_PCT_UNKNOWN: ClassVar[int] = 127

    __slots__ = ("actuator_id", "position", "force", "speed", "power_rating_pct",)

    actuator_id: int
    position: float
    """meter or radian"""
    force: float
    """Newton or Newton metre"""
    speed: float
    """meter per second or radian per second"""
    power_rating_pct: int
    """0 - unloaded, 100 - full load"""

    def __init__(
        self,
        actuator_id: int = 0,
        position: float = 0.0,
        force: float = 0.0,
        speed: float = 0.0,
        power_rating_pct: int = 0,
    ) -> None:
        _setattr(self, "actuator_id", actuator_id)
        _setattr(self, "position", position)
        _setattr(self, "force", force)
        _setattr(self, "speed", speed)
        _setattr(self, "power_rating_pct", power_rating_pct)


@frozen_dataclass
class Solution(HtmlDisplay):
    """``uavcan.equipment.ahrs.Solution``, message 1000 (``equipment/ahrs/1000.Solution.uavcan``).

    Inertial data and orientation in body frame.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"angular_velocity", "angular_velocity_covariance", "linear_acceleration", "linear_acceleration_covariance", "orientation_covariance", "orientation_xyzw"})

    __slots__ = ("timestamp", "orientation_xyzw", "orientation_covariance", "angular_velocity", "angular_velocity_covariance", "linear_acceleration", "linear_acceleration_covariance",)

    timestamp: Timestamp
    orientation_xyzw: tuple[float, ...]
    orientation_covariance: tuple[float, ...]
    angular_velocity: tuple[float, ...]
    angular_velocity_covariance: tuple[float, ...]
    linear_acceleration: tuple[float, ...]
    linear_acceleration_covariance: tuple[float, ...]

    def __init__(
        self,
        timestamp: Timestamp = Timestamp(),
        orientation_xyzw: tuple[float, ...] = (0.0,) * 4,
        orientation_covariance: tuple[float, ...] = (),
        angular_velocity: tuple[float, ...] = (0.0,) * 3,
        angular_velocity_covariance: tuple[float, ...] = (),
        linear_acceleration: tuple[float, ...] = (0.0,) * 3,
        linear_acceleration_covariance: tuple[float, ...] = (),
    ) -> None:
        _setattr(self, "timestamp", timestamp)
        _setattr(self, "orientation_xyzw", orientation_xyzw)
        _setattr(self, "orientation_covariance", orientation_covariance)
        _setattr(self, "angular_velocity", angular_velocity)
        _setattr(self, "angular_velocity_covariance", angular_velocity_covariance)
        _setattr(self, "linear_acceleration", linear_acceleration)
        _setattr(self, "linear_acceleration_covariance", linear_acceleration_covariance)


@frozen_dataclass
class MagneticFieldStrength(HtmlDisplay):
    """``uavcan.equipment.ahrs.MagneticFieldStrength``, message 1001 (``equipment/ahrs/1001.MagneticFieldStrength.uavcan``).

    Magnetic field readings, in Gauss, in body frame.
    SI units are avoided because of float16 range limitations.
    This message is deprecated. Use the newer 1002.MagneticFieldStrength2.uavcan message.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"magnetic_field_covariance", "magnetic_field_ga"})

    __slots__ = ("magnetic_field_ga", "magnetic_field_covariance",)

    magnetic_field_ga: tuple[float, ...]
    magnetic_field_covariance: tuple[float, ...]

    def __init__(
        self,
        magnetic_field_ga: tuple[float, ...] = (0.0,) * 3,
        magnetic_field_covariance: tuple[float, ...] = (),
    ) -> None:
        _setattr(self, "magnetic_field_ga", magnetic_field_ga)
        _setattr(self, "magnetic_field_covariance", magnetic_field_covariance)


@frozen_dataclass
class MagneticFieldStrength2(HtmlDisplay):
    """``uavcan.equipment.ahrs.MagneticFieldStrength2``, message 1002 (``equipment/ahrs/1002.MagneticFieldStrength2.uavcan``).

    Magnetic field readings, in Gauss, in body frame.
    SI units are avoided because of float16 range limitations.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"magnetic_field_covariance", "magnetic_field_ga"})

    __slots__ = ("sensor_id", "magnetic_field_ga", "magnetic_field_covariance",)

    sensor_id: int
    magnetic_field_ga: tuple[float, ...]
    magnetic_field_covariance: tuple[float, ...]

    def __init__(
        self,
        sensor_id: int = 0,
        magnetic_field_ga: tuple[float, ...] = (0.0,) * 3,
        magnetic_field_covariance: tuple[float, ...] = (),
    ) -> None:
        _setattr(self, "sensor_id", sensor_id)
        _setattr(self, "magnetic_field_ga", magnetic_field_ga)
        _setattr(self, "magnetic_field_covariance", magnetic_field_covariance)


@frozen_dataclass
class RawIMU(HtmlDisplay):
    """``uavcan.equipment.ahrs.RawIMU``, message 1003 (``equipment/ahrs/1003.RawIMU.uavcan``).

    Raw IMU data with timestamps.

    THIS DEFINITION MAY BE CHANGED IN A NON-BACKWARD-COMPATIBLE WAY IN THE FUTURE.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"accelerometer_latest", "covariance", "rate_gyro_latest"})
    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"accelerometer_integral", "integration_interval", "rate_gyro_integral"})

    __slots__ = ("timestamp", "integration_interval", "rate_gyro_latest", "rate_gyro_integral", "accelerometer_latest", "accelerometer_integral", "covariance",)

    timestamp: Timestamp
    integration_interval: float
    rate_gyro_latest: tuple[float, ...]
    """Latest sample, radian/second"""
    rate_gyro_integral: tuple[float, ...]
    """Integrated samples, radian"""
    accelerometer_latest: tuple[float, ...]
    """Latest sample, meter/(second^2)"""
    accelerometer_integral: tuple[float, ...]
    """Integrated samples, meter/second"""
    covariance: tuple[float, ...]

    def __init__(
        self,
        timestamp: Timestamp = Timestamp(),
        integration_interval: float = 0.0,
        rate_gyro_latest: tuple[float, ...] = (0.0,) * 3,
        rate_gyro_integral: tuple[float, ...] = (0.0,) * 3,
        accelerometer_latest: tuple[float, ...] = (0.0,) * 3,
        accelerometer_integral: tuple[float, ...] = (0.0,) * 3,
        covariance: tuple[float, ...] = (),
    ) -> None:
        _setattr(self, "timestamp", timestamp)
        _setattr(self, "integration_interval", integration_interval)
        _setattr(self, "rate_gyro_latest", rate_gyro_latest)
        _setattr(self, "rate_gyro_integral", rate_gyro_integral)
        _setattr(self, "accelerometer_latest", accelerometer_latest)
        _setattr(self, "accelerometer_integral", accelerometer_integral)
        _setattr(self, "covariance", covariance)


@frozen_dataclass
class TrueAirspeed(HtmlDisplay):
    """``uavcan.equipment.air_data.TrueAirspeed``, message 1020 (``equipment/air_data/1020.TrueAirspeed.uavcan``).

    TAS.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"true_airspeed", "true_airspeed_variance"})

    __slots__ = ("true_airspeed", "true_airspeed_variance",)

    true_airspeed: float
    """m/s"""
    true_airspeed_variance: float
    """(m/s)^2"""

    def __init__(
        self,
        true_airspeed: float = 0.0,
        true_airspeed_variance: float = 0.0,
    ) -> None:
        _setattr(self, "true_airspeed", true_airspeed)
        _setattr(self, "true_airspeed_variance", true_airspeed_variance)


@frozen_dataclass
class IndicatedAirspeed(HtmlDisplay):
    """``uavcan.equipment.air_data.IndicatedAirspeed``, message 1021 (``equipment/air_data/1021.IndicatedAirspeed.uavcan``).

    IAS.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"indicated_airspeed", "indicated_airspeed_variance"})

    __slots__ = ("indicated_airspeed", "indicated_airspeed_variance",)

    indicated_airspeed: float
    """m/s"""
    indicated_airspeed_variance: float
    """(m/s)^2"""

    def __init__(
        self,
        indicated_airspeed: float = 0.0,
        indicated_airspeed_variance: float = 0.0,
    ) -> None:
        _setattr(self, "indicated_airspeed", indicated_airspeed)
        _setattr(self, "indicated_airspeed_variance", indicated_airspeed_variance)


@frozen_dataclass
class AngleOfAttack(HtmlDisplay):
    """``uavcan.equipment.air_data.AngleOfAttack``, message 1025 (``equipment/air_data/1025.AngleOfAttack.uavcan``).

    Angle of attack.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"aoa", "aoa_variance"})
    SENSOR_ID_LEFT: ClassVar[int] = 254
    SENSOR_ID_RIGHT: ClassVar[int] = 255

    __slots__ = ("sensor_id", "aoa", "aoa_variance",)

    sensor_id: SensorId | int
    aoa: float
    """Radians"""
    aoa_variance: float
    """Radians^2"""

    def __init__(
        self,
        sensor_id: SensorId | int = 0,
        aoa: float = 0.0,
        aoa_variance: float = 0.0,
    ) -> None:
        _setattr(self, "sensor_id", sensor_id)
        _setattr(self, "aoa", aoa)
        _setattr(self, "aoa_variance", aoa_variance)


@frozen_dataclass
class Sideslip(HtmlDisplay):
    """``uavcan.equipment.air_data.Sideslip``, message 1026 (``equipment/air_data/1026.Sideslip.uavcan``).

    Body sideslip in radians.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"sideslip_angle", "sideslip_angle_variance"})

    __slots__ = ("sideslip_angle", "sideslip_angle_variance",)

    sideslip_angle: float
    """Radians"""
    sideslip_angle_variance: float
    """Radians^2"""

    def __init__(
        self,
        sideslip_angle: float = 0.0,
        sideslip_angle_variance: float = 0.0,
    ) -> None:
        _setattr(self, "sideslip_angle", sideslip_angle)
        _setattr(self, "sideslip_angle_variance", sideslip_angle_variance)


@frozen_dataclass
class RawAirData(HtmlDisplay):
    """``uavcan.equipment.air_data.RawAirData``, message 1027 (``equipment/air_data/1027.RawAirData.uavcan``).

    Raw Air Data.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"covariance", "differential_pressure_sensor_temperature", "pitot_temperature", "static_air_temperature", "static_pressure_sensor_temperature"})
    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"differential_pressure", "static_pressure"})
    FLAG_HEATER_AVAILABLE: ClassVar[int] = 1
    FLAG_HEATER_WORKING: ClassVar[int] = 2
    FLAG_HEATER_OVERCURRENT: ClassVar[int] = 4
    FLAG_HEATER_OPENCIRCUIT: ClassVar[int] = 8

    __slots__ = ("flags", "static_pressure", "differential_pressure", "static_pressure_sensor_temperature", "differential_pressure_sensor_temperature", "static_air_temperature", "pitot_temperature", "covariance",)

    flags: int
    static_pressure: float
    """Pascal"""
    differential_pressure: float
    """Pascal"""
    static_pressure_sensor_temperature: float
    """Kelvin"""
    differential_pressure_sensor_temperature: float
    """Kelvin"""
    static_air_temperature: float
    """Kelvin"""
    pitot_temperature: float
    """Kelvin"""
    covariance: tuple[float, ...]
    """order of diagonal elements :"""

    def __init__(
        self,
        flags: int = 0,
        static_pressure: float = 0.0,
        differential_pressure: float = 0.0,
        static_pressure_sensor_temperature: float = 0.0,
        differential_pressure_sensor_temperature: float = 0.0,
        static_air_temperature: float = 0.0,
        pitot_temperature: float = 0.0,
        covariance: tuple[float, ...] = (),
    ) -> None:
        _setattr(self, "flags", flags)
        _setattr(self, "static_pressure", static_pressure)
        _setattr(self, "differential_pressure", differential_pressure)
        _setattr(self, "static_pressure_sensor_temperature", static_pressure_sensor_temperature)
        _setattr(self, "differential_pressure_sensor_temperature", differential_pressure_sensor_temperature)
        _setattr(self, "static_air_temperature", static_air_temperature)
        _setattr(self, "pitot_temperature", pitot_temperature)
        _setattr(self, "covariance", covariance)


@frozen_dataclass
class StaticPressure(HtmlDisplay):
    """``uavcan.equipment.air_data.StaticPressure``, message 1028 (``equipment/air_data/1028.StaticPressure.uavcan``).

    Static pressure.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"static_pressure_variance"})
    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"static_pressure"})

    __slots__ = ("static_pressure", "static_pressure_variance",)

    static_pressure: float
    """Pascal"""
    static_pressure_variance: float
    """Pascal^2"""

    def __init__(
        self,
        static_pressure: float = 0.0,
        static_pressure_variance: float = 0.0,
    ) -> None:
        _setattr(self, "static_pressure", static_pressure)
        _setattr(self, "static_pressure_variance", static_pressure_variance)


@frozen_dataclass
class StaticTemperature(HtmlDisplay):
    """``uavcan.equipment.air_data.StaticTemperature``, message 1029 (``equipment/air_data/1029.StaticTemperature.uavcan``).

    Static temperature.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"static_temperature", "static_temperature_variance"})

    __slots__ = ("static_temperature", "static_temperature_variance",)

    static_temperature: float
    """Kelvin"""
    static_temperature_variance: float
    """Kelvin^2"""

    def __init__(
        self,
        static_temperature: float = 0.0,
        static_temperature_variance: float = 0.0,
    ) -> None:
        _setattr(self, "static_temperature", static_temperature)
        _setattr(self, "static_temperature_variance", static_temperature_variance)


@frozen_dataclass
class CameraGimbalMode(HtmlDisplay):
    """``uavcan.equipment.camera_gimbal.Mode`` (nested; ``equipment/camera_gimbal/Mode.uavcan``).

    Gimbal operating mode
    """

    COMMAND_MODE_ANGULAR_VELOCITY: ClassVar[int] = 0
    COMMAND_MODE_ORIENTATION_FIXED_FRAME: ClassVar[int] = 1
    COMMAND_MODE_ORIENTATION_BODY_FRAME: ClassVar[int] = 2
    COMMAND_MODE_GEO_POI: ClassVar[int] = 3

    __slots__ = ("command_mode",)

    command_mode: CommandMode | int

    def __init__(
        self,
        command_mode: CommandMode | int = 0,
    ) -> None:
        _setattr(self, "command_mode", command_mode)


@frozen_dataclass
class AngularCommand(HtmlDisplay):
    """``uavcan.equipment.camera_gimbal.AngularCommand``, message 1040 (``equipment/camera_gimbal/1040.AngularCommand.uavcan``).

    Generic camera gimbal control.

    This message can only be used in the following modes:
    - COMMAND_MODE_ANGULAR_VELOCITY
    - COMMAND_MODE_ORIENTATION_FIXED_FRAME
    - COMMAND_MODE_ORIENTATION_BODY_FRAME
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"quaternion_xyzw"})

    __slots__ = ("gimbal_id", "mode", "quaternion_xyzw",)

    gimbal_id: int
    mode: CameraGimbalMode
    quaternion_xyzw: tuple[float, ...]

    def __init__(
        self,
        gimbal_id: int = 0,
        mode: CameraGimbalMode = CameraGimbalMode(),
        quaternion_xyzw: tuple[float, ...] = (0.0,) * 4,
    ) -> None:
        _setattr(self, "gimbal_id", gimbal_id)
        _setattr(self, "mode", mode)
        _setattr(self, "quaternion_xyzw", quaternion_xyzw)


@frozen_dataclass
class GEOPOICommand(HtmlDisplay):
    """``uavcan.equipment.camera_gimbal.GEOPOICommand``, message 1041 (``equipment/camera_gimbal/1041.GEOPOICommand.uavcan``).

    Generic camera gimbal control.

    This message can only be used in the following modes:
    - COMMAND_MODE_GEO_POI
    """

    HEIGHT_REFERENCE_ELLIPSOID: ClassVar[int] = 0
    HEIGHT_REFERENCE_MEAN_SEA_LEVEL: ClassVar[int] = 1

    __slots__ = ("gimbal_id", "mode", "longitude_deg_1e7", "latitude_deg_1e7", "height_cm", "height_reference",)

    gimbal_id: int
    mode: CameraGimbalMode
    longitude_deg_1e7: int
    """1 LSB = 1e-7 deg"""
    latitude_deg_1e7: int
    height_cm: int
    """1 LSB = 10 mm"""
    height_reference: HeightReference | int

    def __init__(
        self,
        gimbal_id: int = 0,
        mode: CameraGimbalMode = CameraGimbalMode(),
        longitude_deg_1e7: int = 0,
        latitude_deg_1e7: int = 0,
        height_cm: int = 0,
        height_reference: HeightReference | int = 0,
    ) -> None:
        _setattr(self, "gimbal_id", gimbal_id)
        _setattr(self, "mode", mode)
        _setattr(self, "longitude_deg_1e7", longitude_deg_1e7)
        _setattr(self, "latitude_deg_1e7", latitude_deg_1e7)
        _setattr(self, "height_cm", height_cm)
        _setattr(self, "height_reference", height_reference)


@frozen_dataclass
class CameraGimbalStatus(HtmlDisplay):
    """``uavcan.equipment.camera_gimbal.Status``, message 1044 (``equipment/camera_gimbal/1044.Status.uavcan``).

    Generic gimbal status.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"camera_orientation_in_body_frame_covariance", "camera_orientation_in_body_frame_xyzw"})

    __slots__ = ("gimbal_id", "mode", "camera_orientation_in_body_frame_xyzw", "camera_orientation_in_body_frame_covariance",)

    gimbal_id: int
    mode: CameraGimbalMode
    camera_orientation_in_body_frame_xyzw: tuple[float, ...]
    camera_orientation_in_body_frame_covariance: tuple[float, ...]
    """+inf for non-existent axes"""

    def __init__(
        self,
        gimbal_id: int = 0,
        mode: CameraGimbalMode = CameraGimbalMode(),
        camera_orientation_in_body_frame_xyzw: tuple[float, ...] = (0.0,) * 4,
        camera_orientation_in_body_frame_covariance: tuple[float, ...] = (),
    ) -> None:
        _setattr(self, "gimbal_id", gimbal_id)
        _setattr(self, "mode", mode)
        _setattr(self, "camera_orientation_in_body_frame_xyzw", camera_orientation_in_body_frame_xyzw)
        _setattr(self, "camera_orientation_in_body_frame_covariance", camera_orientation_in_body_frame_covariance)


@frozen_dataclass
class Temperature(HtmlDisplay):
    """``uavcan.equipment.device.Temperature``, message 1110 (``equipment/device/1110.Temperature.uavcan``).

    Generic device temperature
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"temperature"})
    ERROR_FLAG_OVERHEATING: ClassVar[int] = 1
    ERROR_FLAG_OVERCOOLING: ClassVar[int] = 2

    __slots__ = ("device_id", "temperature", "error_flags",)

    device_id: int
    temperature: float
    """in kelvin"""
    error_flags: int

    def __init__(
        self,
        device_id: int = 0,
        temperature: float = 0.0,
        error_flags: int = 0,
    ) -> None:
        _setattr(self, "device_id", device_id)
        _setattr(self, "temperature", temperature)
        _setattr(self, "error_flags", error_flags)


@frozen_dataclass
class RawCommand(HtmlDisplay):
    """``uavcan.equipment.esc.RawCommand``, message 1030 (``equipment/esc/1030.RawCommand.uavcan``).

    Raw ESC command normalized into [-8192, 8191]. The ESC should normalize the setpoint into its effective input range.
    Non-zero setpoint value below minimum should be interpreted as min valid setpoint for the given motor. Positive
    values indicate forward rotation, negative values indicate reverse rotation, and zero indicates no rotation. For example,
    a typical quadcopter always commands non-negative values for all four motors, independent of ESC configuration,
    motor wiring, or propeller direction. ESCs which do not allow reverse rotation shall clamp negative commands to zero.
    """

    __slots__ = ("cmd",)

    cmd: tuple[int, ...]

    def __init__(
        self,
        cmd: tuple[int, ...] = (),
    ) -> None:
        _setattr(self, "cmd", cmd)


@frozen_dataclass
class RPMCommand(HtmlDisplay):
    """``uavcan.equipment.esc.RPMCommand``, message 1031 (``equipment/esc/1031.RPMCommand.uavcan``).

    Simple RPM setpoint.
    The ESC should automatically clamp the setpoint according to the minimum and maximum supported RPM;
    for example, given a ESC that operates in the range 100 to 10000 RPM, a setpoint of 1 RPM will be clamped to 100 RPM.
    Positive values indicate forward rotation, negative values indicate reverse rotation, and zero indicates no rotation.
    For example, a typical quadcopter always commands non-negative values for all four motors, independent of ESC configuration,
    motor wiring, or propeller direction. ESCs which do not allow reverse rotation shall clamp negative RPMs to zero.
    """

    __slots__ = ("rpm",)

    rpm: tuple[int, ...]

    def __init__(
        self,
        rpm: tuple[int, ...] = (),
    ) -> None:
        _setattr(self, "rpm", rpm)


@frozen_dataclass
class EscStatus(HtmlDisplay):
    """``uavcan.equipment.esc.Status``, message 1034 (``equipment/esc/1034.Status.uavcan``).

    Generic ESC status.
    Unknown fields should be set to NAN.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"current", "temperature", "voltage"})

    __slots__ = ("error_count", "voltage", "current", "temperature", "rpm", "power_rating_pct", "esc_index",)

    error_count: int
    """Resets when the motor restarts"""
    voltage: float
    """Volt"""
    current: float
    """Ampere. Can be negative in case of a regenerative braking."""
    temperature: float
    """Kelvin"""
    rpm: int
    """Current value, with the same sign convention as RPMCommand. For example, a typical"""
    power_rating_pct: int
    """Instant demand factor in percent (percent of maximum power); range 0% to 127%."""
    esc_index: int
    """zero is first ESC. This should match the index into the cmd[] array in RawCommand"""

    def __init__(
        self,
        error_count: int = 0,
        voltage: float = 0.0,
        current: float = 0.0,
        temperature: float = 0.0,
        rpm: int = 0,
        power_rating_pct: int = 0,
        esc_index: int = 0,
    ) -> None:
        _setattr(self, "error_count", error_count)
        _setattr(self, "voltage", voltage)
        _setattr(self, "current", current)
        _setattr(self, "temperature", temperature)
        _setattr(self, "rpm", rpm)
        _setattr(self, "power_rating_pct", power_rating_pct)
        _setattr(self, "esc_index", esc_index)


@frozen_dataclass
class StatusExtended(HtmlDisplay):
    """``uavcan.equipment.esc.StatusExtended``, message 1036 (``equipment/esc/1036.StatusExtended.uavcan``).

    Extended Generic ESC status.
    Additional fields on top of the generic ESC status message.
    Transmitted at a lower rate.
    """

    __slots__ = ("input_pct", "output_pct", "motor_temperature_degC", "motor_angle", "status_flags", "esc_index",)

    input_pct: int
    """Absolute input command to ESC, in percent, which is commanded using the setpoint messages. Range 0% to 100%."""
    output_pct: int
    """Absolute output command from ESC to motor, in percent. Range 0% to 100%."""
    motor_temperature_degC: int
    """Temperature of connected motor, in Celsius. Range is -256 to +255 C."""
    motor_angle: int
    """Measured angle of connected angle sensor, in degrees. Range is 0 to 360. The angle increases as the"""
    status_flags: int
    """Manufacturer-specific status flags currently active."""
    esc_index: int
    """Index of currently reporting ESC."""

    def __init__(
        self,
        input_pct: int = 0,
        output_pct: int = 0,
        motor_temperature_degC: int = 0,
        motor_angle: int = 0,
        status_flags: int = 0,
        esc_index: int = 0,
    ) -> None:
        _setattr(self, "input_pct", input_pct)
        _setattr(self, "output_pct", output_pct)
        _setattr(self, "motor_temperature_degC", motor_temperature_degC)
        _setattr(self, "motor_angle", motor_angle)
        _setattr(self, "status_flags", status_flags)
        _setattr(self, "esc_index", esc_index)


@frozen_dataclass
class Fix(HtmlDisplay):
    """``uavcan.equipment.gnss.Fix``, message 1060 (``equipment/gnss/1060.Fix.uavcan``).

    GNSS navigation solution with uncertainty.
    This message is deprecated. Use the newer 1063.Fix2.uavcan message.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"ned_velocity", "pdop", "position_covariance", "velocity_covariance"})
    GNSS_TIME_STANDARD_NONE: ClassVar[int] = 0
    """Time is unknown"""
    GNSS_TIME_STANDARD_TAI: ClassVar[int] = 1
    GNSS_TIME_STANDARD_UTC: ClassVar[int] = 2
    GNSS_TIME_STANDARD_GPS: ClassVar[int] = 3
    NUM_LEAP_SECONDS_UNKNOWN: ClassVar[int] = 0
    STATUS_NO_FIX: ClassVar[int] = 0
    STATUS_TIME_ONLY: ClassVar[int] = 1
    STATUS_2D_FIX: ClassVar[int] = 2
    STATUS_3D_FIX: ClassVar[int] = 3

    __slots__ = ("timestamp", "gnss_timestamp", "gnss_time_standard", "num_leap_seconds", "longitude_deg_1e8", "latitude_deg_1e8", "height_ellipsoid_mm", "height_msl_mm", "ned_velocity", "sats_used", "status", "pdop", "position_covariance", "velocity_covariance",)

    timestamp: Timestamp
    """Global network-synchronized time, if available, otherwise zero"""
    gnss_timestamp: Timestamp
    gnss_time_standard: FixGnssTimeStandard | int
    num_leap_seconds: int
    longitude_deg_1e8: int
    """Longitude degrees multiplied by 1e8 (approx. 1 mm per LSB)"""
    latitude_deg_1e8: int
    """Latitude degrees multiplied by 1e8 (approx. 1 mm per LSB on equator)"""
    height_ellipsoid_mm: int
    """Height above ellipsoid in millimeters"""
    height_msl_mm: int
    """Height above mean sea level in millimeters"""
    ned_velocity: tuple[float, ...]
    """NED frame (north-east-down) in meters per second"""
    sats_used: int
    status: FixStatus
    pdop: float
    position_covariance: tuple[float, ...]
    """m^2"""
    velocity_covariance: tuple[float, ...]
    """(m/s)^2"""

    def __init__(
        self,
        timestamp: Timestamp = Timestamp(),
        gnss_timestamp: Timestamp = Timestamp(),
        gnss_time_standard: FixGnssTimeStandard | int = 0,
        num_leap_seconds: int = 0,
        longitude_deg_1e8: int = 0,
        latitude_deg_1e8: int = 0,
        height_ellipsoid_mm: int = 0,
        height_msl_mm: int = 0,
        ned_velocity: tuple[float, ...] = (0.0,) * 3,
        sats_used: int = 0,
        status: FixStatus = FixStatus(0),
        pdop: float = 0.0,
        position_covariance: tuple[float, ...] = (),
        velocity_covariance: tuple[float, ...] = (),
    ) -> None:
        _setattr(self, "timestamp", timestamp)
        _setattr(self, "gnss_timestamp", gnss_timestamp)
        _setattr(self, "gnss_time_standard", gnss_time_standard)
        _setattr(self, "num_leap_seconds", num_leap_seconds)
        _setattr(self, "longitude_deg_1e8", longitude_deg_1e8)
        _setattr(self, "latitude_deg_1e8", latitude_deg_1e8)
        _setattr(self, "height_ellipsoid_mm", height_ellipsoid_mm)
        _setattr(self, "height_msl_mm", height_msl_mm)
        _setattr(self, "ned_velocity", ned_velocity)
        _setattr(self, "sats_used", sats_used)
        _setattr(self, "status", status)
        _setattr(self, "pdop", pdop)
        _setattr(self, "position_covariance", position_covariance)
        _setattr(self, "velocity_covariance", velocity_covariance)


@frozen_dataclass
class Auxiliary(HtmlDisplay):
    """``uavcan.equipment.gnss.Auxiliary``, message 1061 (``equipment/gnss/1061.Auxiliary.uavcan``).

    GNSS low priority auxiliary info.
    Unknown DOP parameters should be set to NAN.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"edop", "gdop", "hdop", "ndop", "pdop", "tdop", "vdop"})

    __slots__ = ("gdop", "pdop", "hdop", "vdop", "tdop", "ndop", "edop", "sats_visible", "sats_used",)

    gdop: float
    pdop: float
    hdop: float
    vdop: float
    tdop: float
    ndop: float
    edop: float
    sats_visible: int
    """All visible sats of all available GNSS (e.g. GPS, GLONASS, etc)"""
    sats_used: int
    """All used sats of all available GNSS"""

    def __init__(
        self,
        gdop: float = 0.0,
        pdop: float = 0.0,
        hdop: float = 0.0,
        vdop: float = 0.0,
        tdop: float = 0.0,
        ndop: float = 0.0,
        edop: float = 0.0,
        sats_visible: int = 0,
        sats_used: int = 0,
    ) -> None:
        _setattr(self, "gdop", gdop)
        _setattr(self, "pdop", pdop)
        _setattr(self, "hdop", hdop)
        _setattr(self, "vdop", vdop)
        _setattr(self, "tdop", tdop)
        _setattr(self, "ndop", ndop)
        _setattr(self, "edop", edop)
        _setattr(self, "sats_visible", sats_visible)
        _setattr(self, "sats_used", sats_used)


@frozen_dataclass
class RTCMStream(HtmlDisplay):
    """``uavcan.equipment.gnss.RTCMStream``, message 1062 (``equipment/gnss/1062.RTCMStream.uavcan``).

    GNSS RTCM SC-104 protocol raw stream container.
    RTCM messages that are longer than max data size can be split over multiple consecutive messages.
    """

    PROTOCOL_ID_UNKNOWN: ClassVar[int] = 0
    PROTOCOL_ID_RTCM2: ClassVar[int] = 2
    PROTOCOL_ID_RTCM3: ClassVar[int] = 3

    __slots__ = ("protocol_id", "data",)

    protocol_id: ProtocolId | int
    data: bytes

    def __init__(
        self,
        protocol_id: ProtocolId | int = 0,
        data: bytes = b"",
    ) -> None:
        _setattr(self, "protocol_id", protocol_id)
        _setattr(self, "data", data)


@frozen_dataclass
class ECEFPositionVelocity(HtmlDisplay):
    """``uavcan.equipment.gnss.ECEFPositionVelocity`` (nested; ``equipment/gnss/ECEFPositionVelocity.uavcan``).

    Nested type.
    GNSS ECEF high resolution position and velocity.

    ECEF is an acronym for Earth-Centered-Earth-Fixed, which is a cartesian
    coordinate system which rotates with the earth. The origin (0,0,0) is
    located at the center of the earth. The x-axis is a vector pointing from
    the origin with positive direction towards 0 degrees latitude and
    longitude (equator, at the prime meridian). The z-axis is a vector
    pointing from the origin towards the north-pole. The y-axis completes a
    right-handed coordinate system.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"covariance"})
    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"velocity_xyz"})

    __slots__ = ("velocity_xyz", "position_xyz_mm", "covariance",)

    velocity_xyz: tuple[float, ...]
    """XYZ velocity in m/s"""
    position_xyz_mm: tuple[int, ...]
    """XYZ-axis coordinates in mm"""
    covariance: tuple[float, ...]
    """Position and velocity covariance in the ECEF frame. Units are m^2 for position,"""

    def __init__(
        self,
        velocity_xyz: tuple[float, ...] = (0.0,) * 3,
        position_xyz_mm: tuple[int, ...] = (0,) * 3,
        covariance: tuple[float, ...] = (),
    ) -> None:
        _setattr(self, "velocity_xyz", velocity_xyz)
        _setattr(self, "position_xyz_mm", position_xyz_mm)
        _setattr(self, "covariance", covariance)


@frozen_dataclass
class Fix2(HtmlDisplay):
    """``uavcan.equipment.gnss.Fix2``, message 1063 (``equipment/gnss/1063.Fix2.uavcan``).

    GNSS ECEF and LLA navigation solution with uncertainty.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"covariance", "pdop"})
    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"ned_velocity"})
    GNSS_TIME_STANDARD_NONE: ClassVar[int] = 0
    """Time is unknown"""
    GNSS_TIME_STANDARD_TAI: ClassVar[int] = 1
    GNSS_TIME_STANDARD_UTC: ClassVar[int] = 2
    GNSS_TIME_STANDARD_GPS: ClassVar[int] = 3
    NUM_LEAP_SECONDS_UNKNOWN: ClassVar[int] = 0
    STATUS_NO_FIX: ClassVar[int] = 0
    STATUS_TIME_ONLY: ClassVar[int] = 1
    STATUS_2D_FIX: ClassVar[int] = 2
    STATUS_3D_FIX: ClassVar[int] = 3
    MODE_SINGLE: ClassVar[int] = 0
    MODE_DGPS: ClassVar[int] = 1
    MODE_RTK: ClassVar[int] = 2
    MODE_PPP: ClassVar[int] = 3
    SUB_MODE_DGPS_OTHER: ClassVar[int] = 0
    SUB_MODE_DGPS_SBAS: ClassVar[int] = 1
    SUB_MODE_RTK_FLOAT: ClassVar[int] = 0
    SUB_MODE_RTK_FIXED: ClassVar[int] = 1

    __slots__ = ("timestamp", "gnss_timestamp", "gnss_time_standard", "num_leap_seconds", "longitude_deg_1e8", "latitude_deg_1e8", "height_ellipsoid_mm", "height_msl_mm", "ned_velocity", "sats_used", "status", "mode", "sub_mode", "covariance", "pdop", "ecef_position_velocity",)

    timestamp: Timestamp
    gnss_timestamp: Timestamp
    gnss_time_standard: Fix2GnssTimeStandard | int
    num_leap_seconds: int
    longitude_deg_1e8: int
    """Longitude degrees multiplied by 1e8 (approx. 1 mm per LSB)"""
    latitude_deg_1e8: int
    """Latitude degrees multiplied by 1e8 (approx. 1 mm per LSB on equator)"""
    height_ellipsoid_mm: int
    """Height above ellipsoid in millimeters"""
    height_msl_mm: int
    """Height above mean sea level in millimeters"""
    ned_velocity: tuple[float, ...]
    """NED frame (north-east-down) in meters per second"""
    sats_used: int
    status: Fix2Status
    mode: Fix2Mode | int
    sub_mode: int
    covariance: tuple[float, ...]
    """Position and velocity covariance. Units are"""
    pdop: float
    ecef_position_velocity: tuple[ECEFPositionVelocity, ...]

    def __init__(
        self,
        timestamp: Timestamp = Timestamp(),
        gnss_timestamp: Timestamp = Timestamp(),
        gnss_time_standard: Fix2GnssTimeStandard | int = 0,
        num_leap_seconds: int = 0,
        longitude_deg_1e8: int = 0,
        latitude_deg_1e8: int = 0,
        height_ellipsoid_mm: int = 0,
        height_msl_mm: int = 0,
        ned_velocity: tuple[float, ...] = (0.0,) * 3,
        sats_used: int = 0,
        status: Fix2Status = Fix2Status(0),
        mode: Fix2Mode | int = 0,
        sub_mode: int = 0,
        covariance: tuple[float, ...] = (),
        pdop: float = 0.0,
        ecef_position_velocity: tuple[ECEFPositionVelocity, ...] = (),
    ) -> None:
        _setattr(self, "timestamp", timestamp)
        _setattr(self, "gnss_timestamp", gnss_timestamp)
        _setattr(self, "gnss_time_standard", gnss_time_standard)
        _setattr(self, "num_leap_seconds", num_leap_seconds)
        _setattr(self, "longitude_deg_1e8", longitude_deg_1e8)
        _setattr(self, "latitude_deg_1e8", latitude_deg_1e8)
        _setattr(self, "height_ellipsoid_mm", height_ellipsoid_mm)
        _setattr(self, "height_msl_mm", height_msl_mm)
        _setattr(self, "ned_velocity", ned_velocity)
        _setattr(self, "sats_used", sats_used)
        _setattr(self, "status", status)
        _setattr(self, "mode", mode)
        _setattr(self, "sub_mode", sub_mode)
        _setattr(self, "covariance", covariance)
        _setattr(self, "pdop", pdop)
        _setattr(self, "ecef_position_velocity", ecef_position_velocity)


@frozen_dataclass
class HardpointCommand(HtmlDisplay):
    """``uavcan.equipment.hardpoint.Command``, message 1070 (``equipment/hardpoint/1070.Command.uavcan``).

    Generic cargo holder/hardpoint command.
    """

    __slots__ = ("hardpoint_id", "command",)

    hardpoint_id: int
    command: int

    def __init__(
        self,
        hardpoint_id: int = 0,
        command: int = 0,
    ) -> None:
        _setattr(self, "hardpoint_id", hardpoint_id)
        _setattr(self, "command", command)


@frozen_dataclass
class HardpointStatus(HtmlDisplay):
    """``uavcan.equipment.hardpoint.Status``, message 1071 (``equipment/hardpoint/1071.Status.uavcan``).

    Generic cargo holder/hardpoint status.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"payload_weight", "payload_weight_variance"})

    __slots__ = ("hardpoint_id", "payload_weight", "payload_weight_variance", "status",)

    hardpoint_id: int
    payload_weight: float
    """Newton"""
    payload_weight_variance: float
    status: int

    def __init__(
        self,
        hardpoint_id: int = 0,
        payload_weight: float = 0.0,
        payload_weight_variance: float = 0.0,
        status: int = 0,
    ) -> None:
        _setattr(self, "hardpoint_id", hardpoint_id)
        _setattr(self, "payload_weight", payload_weight)
        _setattr(self, "payload_weight_variance", payload_weight_variance)
        _setattr(self, "status", status)


@frozen_dataclass
class FuelTankStatus(HtmlDisplay):
    """``uavcan.equipment.ice.FuelTankStatus``, message 1129 (``equipment/ice/1129.FuelTankStatus.uavcan``).

    Generic fuel tank status message.
    All fields are required unless stated otherwise. Unpopulated optional fields should be set to NaN.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"fuel_temperature"})
    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"available_fuel_volume_cm3", "fuel_consumption_rate_cm3pm"})

    __slots__ = ("available_fuel_volume_percent", "available_fuel_volume_cm3", "fuel_consumption_rate_cm3pm", "fuel_temperature", "fuel_tank_id",)

    available_fuel_volume_percent: int
    """Unit: percent, from 0% to 100%"""
    available_fuel_volume_cm3: float
    """Unit: centimeter^3"""
    fuel_consumption_rate_cm3pm: float
    fuel_temperature: float
    fuel_tank_id: int

    def __init__(
        self,
        available_fuel_volume_percent: int = 0,
        available_fuel_volume_cm3: float = 0.0,
        fuel_consumption_rate_cm3pm: float = 0.0,
        fuel_temperature: float = 0.0,
        fuel_tank_id: int = 0,
    ) -> None:
        _setattr(self, "available_fuel_volume_percent", available_fuel_volume_percent)
        _setattr(self, "available_fuel_volume_cm3", available_fuel_volume_cm3)
        _setattr(self, "fuel_consumption_rate_cm3pm", fuel_consumption_rate_cm3pm)
        _setattr(self, "fuel_temperature", fuel_temperature)
        _setattr(self, "fuel_tank_id", fuel_tank_id)


@frozen_dataclass
class CylinderStatus(HtmlDisplay):
    """``uavcan.equipment.ice.reciprocating.CylinderStatus`` (nested; ``equipment/ice/reciprocating/CylinderStatus.uavcan``).

    Cylinder state information.
    This is a nested data type.

    All unknown parameters should be set to NaN.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"cylinder_head_temperature", "exhaust_gas_temperature", "ignition_timing_deg", "injection_time_ms", "lambda_coefficient"})

    __slots__ = ("ignition_timing_deg", "injection_time_ms", "cylinder_head_temperature", "exhaust_gas_temperature", "lambda_coefficient",)

    ignition_timing_deg: float
    injection_time_ms: float
    cylinder_head_temperature: float
    exhaust_gas_temperature: float
    lambda_coefficient: float

    def __init__(
        self,
        ignition_timing_deg: float = 0.0,
        injection_time_ms: float = 0.0,
        cylinder_head_temperature: float = 0.0,
        exhaust_gas_temperature: float = 0.0,
        lambda_coefficient: float = 0.0,
    ) -> None:
        _setattr(self, "ignition_timing_deg", ignition_timing_deg)
        _setattr(self, "injection_time_ms", injection_time_ms)
        _setattr(self, "cylinder_head_temperature", cylinder_head_temperature)
        _setattr(self, "exhaust_gas_temperature", exhaust_gas_temperature)
        _setattr(self, "lambda_coefficient", lambda_coefficient)


@frozen_dataclass
class ReciprocatingStatus(HtmlDisplay):
    """``uavcan.equipment.ice.reciprocating.Status``, message 1120 (``equipment/ice/reciprocating/1120.Status.uavcan``).

    Generic status message of a piston engine control system.

    All integer fields are required unless stated otherwise.
    All floating point fields are optional unless stated otherwise; unknown/unapplicable fields should be set to NaN.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"atmospheric_pressure_kpa", "coolant_temperature", "fuel_pressure", "intake_manifold_pressure_kpa", "intake_manifold_temperature", "oil_pressure", "oil_temperature", "spark_dwell_time_ms"})
    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"estimated_consumed_fuel_volume_cm3", "fuel_consumption_rate_cm3pm"})
    STATE_STOPPED: ClassVar[int] = 0
    STATE_STARTING: ClassVar[int] = 1
    STATE_RUNNING: ClassVar[int] = 2
    STATE_FAULT: ClassVar[int] = 3
    FLAG_GENERAL_ERROR: ClassVar[int] = 1
    FLAG_CRANKSHAFT_SENSOR_ERROR_SUPPORTED: ClassVar[int] = 2
    FLAG_CRANKSHAFT_SENSOR_ERROR: ClassVar[int] = 4
    FLAG_TEMPERATURE_SUPPORTED: ClassVar[int] = 8
    FLAG_TEMPERATURE_BELOW_NOMINAL: ClassVar[int] = 16
    """Under-temperature warning"""
    FLAG_TEMPERATURE_ABOVE_NOMINAL: ClassVar[int] = 32
    """Over-temperature warning"""
    FLAG_TEMPERATURE_OVERHEATING: ClassVar[int] = 64
    """Critical overheating"""
    FLAG_TEMPERATURE_EGT_ABOVE_NOMINAL: ClassVar[int] = 128
    """Exhaust gas over-temperature warning"""
    FLAG_FUEL_PRESSURE_SUPPORTED: ClassVar[int] = 256
    FLAG_FUEL_PRESSURE_BELOW_NOMINAL: ClassVar[int] = 512
    """Under-pressure warning"""
    FLAG_FUEL_PRESSURE_ABOVE_NOMINAL: ClassVar[int] = 1024
    """Over-pressure warning"""
    FLAG_DETONATION_SUPPORTED: ClassVar[int] = 2048
    FLAG_DETONATION_OBSERVED: ClassVar[int] = 4096
    """Detonation condition observed warning"""
    FLAG_MISFIRE_SUPPORTED: ClassVar[int] = 8192
    FLAG_MISFIRE_OBSERVED: ClassVar[int] = 16384
    """Misfire condition observed warning"""
    FLAG_OIL_PRESSURE_SUPPORTED: ClassVar[int] = 32768
    FLAG_OIL_PRESSURE_BELOW_NOMINAL: ClassVar[int] = 65536
    """Under-pressure warning"""
    FLAG_OIL_PRESSURE_ABOVE_NOMINAL: ClassVar[int] = 131072
    """Over-pressure warning"""
    FLAG_DEBRIS_SUPPORTED: ClassVar[int] = 262144
    FLAG_DEBRIS_DETECTED: ClassVar[int] = 524288
    """Detection of debris warning"""
    SPARK_PLUG_SINGLE: ClassVar[int] = 0
    SPARK_PLUG_FIRST_ACTIVE: ClassVar[int] = 1
    SPARK_PLUG_SECOND_ACTIVE: ClassVar[int] = 2
    SPARK_PLUG_BOTH_ACTIVE: ClassVar[int] = 3

    __slots__ = ("state", "flags", "engine_load_percent", "engine_speed_rpm", "spark_dwell_time_ms", "atmospheric_pressure_kpa", "intake_manifold_pressure_kpa", "intake_manifold_temperature", "coolant_temperature", "oil_pressure", "oil_temperature", "fuel_pressure", "fuel_consumption_rate_cm3pm", "estimated_consumed_fuel_volume_cm3", "throttle_position_percent", "ecu_index", "spark_plug_usage", "cylinder_status",)

    state: State
    flags: int
    engine_load_percent: int
    engine_speed_rpm: int
    spark_dwell_time_ms: float
    atmospheric_pressure_kpa: float
    intake_manifold_pressure_kpa: float
    intake_manifold_temperature: float
    coolant_temperature: float
    oil_pressure: float
    oil_temperature: float
    fuel_pressure: float
    fuel_consumption_rate_cm3pm: float
    estimated_consumed_fuel_volume_cm3: float
    throttle_position_percent: int
    ecu_index: int
    spark_plug_usage: int
    cylinder_status: tuple[CylinderStatus, ...]

    def __init__(
        self,
        state: State = State(0),
        flags: int = 0,
        engine_load_percent: int = 0,
        engine_speed_rpm: int = 0,
        spark_dwell_time_ms: float = 0.0,
        atmospheric_pressure_kpa: float = 0.0,
        intake_manifold_pressure_kpa: float = 0.0,
        intake_manifold_temperature: float = 0.0,
        coolant_temperature: float = 0.0,
        oil_pressure: float = 0.0,
        oil_temperature: float = 0.0,
        fuel_pressure: float = 0.0,
        fuel_consumption_rate_cm3pm: float = 0.0,
        estimated_consumed_fuel_volume_cm3: float = 0.0,
        throttle_position_percent: int = 0,
        ecu_index: int = 0,
        spark_plug_usage: int = 0,
        cylinder_status: tuple[CylinderStatus, ...] = (),
    ) -> None:
        _setattr(self, "state", state)
        _setattr(self, "flags", flags)
        _setattr(self, "engine_load_percent", engine_load_percent)
        _setattr(self, "engine_speed_rpm", engine_speed_rpm)
        _setattr(self, "spark_dwell_time_ms", spark_dwell_time_ms)
        _setattr(self, "atmospheric_pressure_kpa", atmospheric_pressure_kpa)
        _setattr(self, "intake_manifold_pressure_kpa", intake_manifold_pressure_kpa)
        _setattr(self, "intake_manifold_temperature", intake_manifold_temperature)
        _setattr(self, "coolant_temperature", coolant_temperature)
        _setattr(self, "oil_pressure", oil_pressure)
        _setattr(self, "oil_temperature", oil_temperature)
        _setattr(self, "fuel_pressure", fuel_pressure)
        _setattr(self, "fuel_consumption_rate_cm3pm", fuel_consumption_rate_cm3pm)
        _setattr(self, "estimated_consumed_fuel_volume_cm3", estimated_consumed_fuel_volume_cm3)
        _setattr(self, "throttle_position_percent", throttle_position_percent)
        _setattr(self, "ecu_index", ecu_index)
        _setattr(self, "spark_plug_usage", spark_plug_usage)
        _setattr(self, "cylinder_status", cylinder_status)


@frozen_dataclass
class BeepCommand(HtmlDisplay):
    """``uavcan.equipment.indication.BeepCommand``, message 1080 (``equipment/indication/1080.BeepCommand.uavcan``).

    Nodes that are capable of producing sounds should obey.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"duration", "frequency"})

    __slots__ = ("frequency", "duration",)

    frequency: float
    """Hz"""
    duration: float
    """Sec"""

    def __init__(
        self,
        frequency: float = 0.0,
        duration: float = 0.0,
    ) -> None:
        _setattr(self, "frequency", frequency)
        _setattr(self, "duration", duration)


@frozen_dataclass
class RGB565(HtmlDisplay):
    """``uavcan.equipment.indication.RGB565`` (nested; ``equipment/indication/RGB565.uavcan``).

    Nested type.
    RGB color in the standard 5-6-5 16-bit palette.
    Monocolor lights should interpret this as brightness setpoint: from zero (0, 0, 0) to full brightness (31, 63, 31).
    """

    __slots__ = ("red", "green", "blue",)

    red: int
    green: int
    blue: int

    def __init__(
        self,
        red: int = 0,
        green: int = 0,
        blue: int = 0,
    ) -> None:
        _setattr(self, "red", red)
        _setattr(self, "green", green)
        _setattr(self, "blue", blue)


@frozen_dataclass
class SingleLightCommand(HtmlDisplay):
    """``uavcan.equipment.indication.SingleLightCommand`` (nested; ``equipment/indication/SingleLightCommand.uavcan``).

    Nested type.
    Controls single light source, color or monochrome.
    """

    LIGHT_ID_ANTI_COLLISION: ClassVar[int] = 246
    LIGHT_ID_RIGHT_OF_WAY: ClassVar[int] = 247
    LIGHT_ID_STROBE: ClassVar[int] = 248
    LIGHT_ID_WING: ClassVar[int] = 249
    LIGHT_ID_LOGO: ClassVar[int] = 250
    LIGHT_ID_TAXI: ClassVar[int] = 251
    LIGHT_ID_TURN_OFF: ClassVar[int] = 252
    LIGHT_ID_TAKE_OFF: ClassVar[int] = 253
    LIGHT_ID_LANDING: ClassVar[int] = 254
    LIGHT_ID_FORMATION: ClassVar[int] = 255

    __slots__ = ("light_id", "color",)

    light_id: LightId | int
    color: RGB565
    """Monocolor lights should interpret this as brightness"""

    def __init__(
        self,
        light_id: LightId | int = 0,
        color: RGB565 = RGB565(),
    ) -> None:
        _setattr(self, "light_id", light_id)
        _setattr(self, "color", color)


@frozen_dataclass
class LightsCommand(HtmlDisplay):
    """``uavcan.equipment.indication.LightsCommand``, message 1081 (``equipment/indication/1081.LightsCommand.uavcan``).

    Lights control command.
    """

    __slots__ = ("commands",)

    commands: tuple[SingleLightCommand, ...]

    def __init__(
        self,
        commands: tuple[SingleLightCommand, ...] = (),
    ) -> None:
        _setattr(self, "commands", commands)


@frozen_dataclass
class PrimaryPowerSupplyStatus(HtmlDisplay):
    """``uavcan.equipment.power.PrimaryPowerSupplyStatus``, message 1090 (``equipment/power/1090.PrimaryPowerSupplyStatus.uavcan``).

    Primary power supply status.
    Typical publishing rate should be around 1~2 Hz.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"hours_to_empty_at_10sec_avg_power", "hours_to_empty_at_10sec_avg_power_variance"})

    __slots__ = ("hours_to_empty_at_10sec_avg_power", "hours_to_empty_at_10sec_avg_power_variance", "external_power_available", "remaining_energy_pct", "remaining_energy_pct_stdev",)

    hours_to_empty_at_10sec_avg_power: float
    """[Hours]"""
    hours_to_empty_at_10sec_avg_power_variance: float
    """[Hours^2]"""
    external_power_available: bool
    remaining_energy_pct: int
    """[Percent]     Required"""
    remaining_energy_pct_stdev: int
    """[Percent]     Error standard deviation. Use best guess if unknown."""

    def __init__(
        self,
        hours_to_empty_at_10sec_avg_power: float = 0.0,
        hours_to_empty_at_10sec_avg_power_variance: float = 0.0,
        external_power_available: bool = False,
        remaining_energy_pct: int = 0,
        remaining_energy_pct_stdev: int = 0,
    ) -> None:
        _setattr(self, "hours_to_empty_at_10sec_avg_power", hours_to_empty_at_10sec_avg_power)
        _setattr(self, "hours_to_empty_at_10sec_avg_power_variance", hours_to_empty_at_10sec_avg_power_variance)
        _setattr(self, "external_power_available", external_power_available)
        _setattr(self, "remaining_energy_pct", remaining_energy_pct)
        _setattr(self, "remaining_energy_pct_stdev", remaining_energy_pct_stdev)


@frozen_dataclass
class CircuitStatus(HtmlDisplay):
    """``uavcan.equipment.power.CircuitStatus``, message 1091 (``equipment/power/1091.CircuitStatus.uavcan``).

    Generic electrical circuit info.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"current", "voltage"})
    ERROR_FLAG_OVERVOLTAGE: ClassVar[int] = 1
    ERROR_FLAG_UNDERVOLTAGE: ClassVar[int] = 2
    ERROR_FLAG_OVERCURRENT: ClassVar[int] = 4
    ERROR_FLAG_UNDERCURRENT: ClassVar[int] = 8

    __slots__ = ("circuit_id", "voltage", "current", "error_flags",)

    circuit_id: int
    voltage: float
    current: float
    error_flags: int

    def __init__(
        self,
        circuit_id: int = 0,
        voltage: float = 0.0,
        current: float = 0.0,
        error_flags: int = 0,
    ) -> None:
        _setattr(self, "circuit_id", circuit_id)
        _setattr(self, "voltage", voltage)
        _setattr(self, "current", current)
        _setattr(self, "error_flags", error_flags)


@frozen_dataclass
class BatteryInfo(HtmlDisplay):
    """``uavcan.equipment.power.BatteryInfo``, message 1092 (``equipment/power/1092.BatteryInfo.uavcan``).

    Single battery info.

    Typical publishing rate should be around 0.2~1 Hz.

    Please refer to the Smart Battery data specification for some elaboration.
    """

    _TEXT_FIELDS_: ClassVar[frozenset[str]] = frozenset({"model_name"})
    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"average_power_10sec", "current", "full_charge_capacity_wh", "hours_to_full_charge", "remaining_capacity_wh", "temperature", "voltage"})
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
    STATE_OF_HEALTH_UNKNOWN: ClassVar[int] = 127
    """Use this constant if SOH cannot be estimated"""
    STATE_OF_CHARGE_UNKNOWN: ClassVar[int] = 127
    """Use this constant if SoC cannot be estimated"""

    __slots__ = ("temperature", "voltage", "current", "average_power_10sec", "remaining_capacity_wh", "full_charge_capacity_wh", "hours_to_full_charge", "status_flags", "state_of_health_pct", "state_of_charge_pct", "state_of_charge_pct_stdev", "battery_id", "model_instance_id", "model_name",)

    temperature: float
    """[Kelvin]"""
    voltage: float
    """[Volt]"""
    current: float
    """[Ampere]"""
    average_power_10sec: float
    """[Watt]        Average power consumption over the last 10 seconds"""
    remaining_capacity_wh: float
    """[Watt hours]  Will be increasing during charging"""
    full_charge_capacity_wh: float
    """[Watt hours]  Predicted battery capacity when it is fully charged. Falls with aging"""
    hours_to_full_charge: float
    """[Hours]       Charging is expected to complete in this time; zero if not charging"""
    status_flags: int
    state_of_health_pct: int
    """Health of the battery, in percent, optional"""
    state_of_charge_pct: int
    """Percent of the full charge [0, 100]. This field is required"""
    state_of_charge_pct_stdev: int
    """SOC error standard deviation; use best guess if unknown"""
    battery_id: int
    """Identifies the battery within this vehicle, e.g. 0 - primary battery"""
    model_instance_id: int
    """Set to zero if not applicable"""
    model_name: bytes
    """Battery model name"""

    def __init__(
        self,
        temperature: float = 0.0,
        voltage: float = 0.0,
        current: float = 0.0,
        average_power_10sec: float = 0.0,
        remaining_capacity_wh: float = 0.0,
        full_charge_capacity_wh: float = 0.0,
        hours_to_full_charge: float = 0.0,
        status_flags: int = 0,
        state_of_health_pct: int = 0,
        state_of_charge_pct: int = 0,
        state_of_charge_pct_stdev: int = 0,
        battery_id: int = 0,
        model_instance_id: int = 0,
        model_name: bytes = b"",
    ) -> None:
        _setattr(self, "temperature", temperature)
        _setattr(self, "voltage", voltage)
        _setattr(self, "current", current)
        _setattr(self, "average_power_10sec", average_power_10sec)
        _setattr(self, "remaining_capacity_wh", remaining_capacity_wh)
        _setattr(self, "full_charge_capacity_wh", full_charge_capacity_wh)
        _setattr(self, "hours_to_full_charge", hours_to_full_charge)
        _setattr(self, "status_flags", status_flags)
        _setattr(self, "state_of_health_pct", state_of_health_pct)
        _setattr(self, "state_of_charge_pct", state_of_charge_pct)
        _setattr(self, "state_of_charge_pct_stdev", state_of_charge_pct_stdev)
        _setattr(self, "battery_id", battery_id)
        _setattr(self, "model_instance_id", model_instance_id)
        _setattr(self, "model_name", model_name)


@frozen_dataclass
class Measurement(HtmlDisplay):
    """``uavcan.equipment.range_sensor.Measurement``, message 1050 (``equipment/range_sensor/1050.Measurement.uavcan``).

    Generic narrow-beam range sensor data.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"field_of_view", "range"})
    SENSOR_TYPE_UNDEFINED: ClassVar[int] = 0
    SENSOR_TYPE_SONAR: ClassVar[int] = 1
    SENSOR_TYPE_LIDAR: ClassVar[int] = 2
    SENSOR_TYPE_RADAR: ClassVar[int] = 3
    READING_TYPE_UNDEFINED: ClassVar[int] = 0
    """Range is unknown"""
    READING_TYPE_VALID_RANGE: ClassVar[int] = 1
    """Range field contains valid distance"""
    READING_TYPE_TOO_CLOSE: ClassVar[int] = 2
    """Range field contains min range for the sensor"""
    READING_TYPE_TOO_FAR: ClassVar[int] = 3
    """Range field contains max range for the sensor"""

    __slots__ = ("timestamp", "sensor_id", "beam_orientation_in_body_frame", "field_of_view", "sensor_type", "reading_type", "range",)

    timestamp: Timestamp
    sensor_id: int
    beam_orientation_in_body_frame: CoarseOrientation
    field_of_view: float
    """Radians"""
    sensor_type: SensorType | int
    reading_type: ReadingType | int
    range: float
    """Meters"""

    def __init__(
        self,
        timestamp: Timestamp = Timestamp(),
        sensor_id: int = 0,
        beam_orientation_in_body_frame: CoarseOrientation = CoarseOrientation(),
        field_of_view: float = 0.0,
        sensor_type: SensorType | int = 0,
        reading_type: ReadingType | int = 0,
        range: float = 0.0,
    ) -> None:
        _setattr(self, "timestamp", timestamp)
        _setattr(self, "sensor_id", sensor_id)
        _setattr(self, "beam_orientation_in_body_frame", beam_orientation_in_body_frame)
        _setattr(self, "field_of_view", field_of_view)
        _setattr(self, "sensor_type", sensor_type)
        _setattr(self, "reading_type", reading_type)
        _setattr(self, "range", range)


@frozen_dataclass
class ArmingStatus(HtmlDisplay):
    """``uavcan.equipment.safety.ArmingStatus``, message 1100 (``equipment/safety/1100.ArmingStatus.uavcan``).

    This message represents the system arming status.
    Some nodes may refuse to operate unless the system is fully armed.
    """

    STATUS_DISARMED: ClassVar[int] = 0
    STATUS_FULLY_ARMED: ClassVar[int] = 255

    __slots__ = ("status",)

    status: ArmingStatusStatus | int

    def __init__(
        self,
        status: ArmingStatusStatus | int = 0,
    ) -> None:
        _setattr(self, "status", status)


@frozen_dataclass
class GlobalNavigationSolution(HtmlDisplay):
    """``uavcan.navigation.GlobalNavigationSolution``, message 2000 (``navigation/2000.GlobalNavigationSolution.uavcan``).

    Inertial data and orientation in body frame with fused location.

    Fields marked as optional should be set to NaN if the corresponding value is unknown.
    """

    _FLOAT16_FIELDS_: ClassVar[frozenset[str]] = frozenset({"linear_acceleration_body", "pose_covariance", "qnh_hpa", "velocity_covariance"})
    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"angular_velocity_body", "height_agl", "height_baro", "height_ellipsoid", "height_msl", "linear_velocity_body", "orientation_xyzw"})

    __slots__ = ("timestamp", "longitude", "latitude", "height_ellipsoid", "height_msl", "height_agl", "height_baro", "qnh_hpa", "orientation_xyzw", "pose_covariance", "linear_velocity_body", "angular_velocity_body", "linear_acceleration_body", "velocity_covariance",)

    timestamp: Timestamp
    longitude: float
    """required"""
    latitude: float
    """required"""
    height_ellipsoid: float
    """Above ellipsoid (required)"""
    height_msl: float
    """Above the mean sea level (required)"""
    height_agl: float
    """Above ground level (provided by radar altimeter or LIDAR) (optional)"""
    height_baro: float
    """Barometric height (optional)"""
    qnh_hpa: float
    """optional"""
    orientation_xyzw: tuple[float, ...]
    pose_covariance: tuple[float, ...]
    linear_velocity_body: tuple[float, ...]
    angular_velocity_body: tuple[float, ...]
    linear_acceleration_body: tuple[float, ...]
    velocity_covariance: tuple[float, ...]

    def __init__(
        self,
        timestamp: Timestamp = Timestamp(),
        longitude: float = 0.0,
        latitude: float = 0.0,
        height_ellipsoid: float = 0.0,
        height_msl: float = 0.0,
        height_agl: float = 0.0,
        height_baro: float = 0.0,
        qnh_hpa: float = 0.0,
        orientation_xyzw: tuple[float, ...] = (0.0,) * 4,
        pose_covariance: tuple[float, ...] = (),
        linear_velocity_body: tuple[float, ...] = (0.0,) * 3,
        angular_velocity_body: tuple[float, ...] = (0.0,) * 3,
        linear_acceleration_body: tuple[float, ...] = (0.0,) * 3,
        velocity_covariance: tuple[float, ...] = (),
    ) -> None:
        _setattr(self, "timestamp", timestamp)
        _setattr(self, "longitude", longitude)
        _setattr(self, "latitude", latitude)
        _setattr(self, "height_ellipsoid", height_ellipsoid)
        _setattr(self, "height_msl", height_msl)
        _setattr(self, "height_agl", height_agl)
        _setattr(self, "height_baro", height_baro)
        _setattr(self, "qnh_hpa", qnh_hpa)
        _setattr(self, "orientation_xyzw", orientation_xyzw)
        _setattr(self, "pose_covariance", pose_covariance)
        _setattr(self, "linear_velocity_body", linear_velocity_body)
        _setattr(self, "angular_velocity_body", angular_velocity_body)
        _setattr(self, "linear_acceleration_body", linear_acceleration_body)
        _setattr(self, "velocity_covariance", velocity_covariance)


@frozen_dataclass
class GetNodeInfoRequest(HtmlDisplay):
    """``uavcan.protocol.GetNodeInfo`` request, service 1 (``protocol/1.GetNodeInfo.uavcan``).

    Full node info request.
    Note that all fields of the response section are byte-aligned.
    """

    __slots__ = ()


    def __init__(
        self,
    ) -> None:
        pass


@frozen_dataclass
class NodeStatus(HtmlDisplay):
    """``uavcan.protocol.NodeStatus``, message 341 (``protocol/341.NodeStatus.uavcan``).

    Abstract node status information.

    All UAVCAN nodes are required to publish this message periodically.
    """

    MAX_BROADCASTING_PERIOD_MS: ClassVar[int] = 1000
    MIN_BROADCASTING_PERIOD_MS: ClassVar[int] = 2
    OFFLINE_TIMEOUT_MS: ClassVar[int] = 3000
    HEALTH_OK: ClassVar[int] = 0
    """The node is functioning properly."""
    HEALTH_WARNING: ClassVar[int] = 1
    """A critical parameter went out of range or the node encountered a minor failure."""
    HEALTH_ERROR: ClassVar[int] = 2
    """The node encountered a major failure."""
    HEALTH_CRITICAL: ClassVar[int] = 3
    """The node suffered a fatal malfunction."""
    MODE_OPERATIONAL: ClassVar[int] = 0
    """Normal operating mode."""
    MODE_INITIALIZATION: ClassVar[int] = 1
    """Initialization is in progress; this mode is entered immediately after startup."""
    MODE_MAINTENANCE: ClassVar[int] = 2
    """E.g. calibration, the bootloader is running, etc."""
    MODE_SOFTWARE_UPDATE: ClassVar[int] = 3
    """New software/firmware is being loaded."""
    MODE_OFFLINE: ClassVar[int] = 7
    """The node is no longer available."""

    __slots__ = ("uptime_sec", "health", "mode", "sub_mode", "vendor_specific_status_code",)

    uptime_sec: int
    health: Health
    mode: Mode | int
    sub_mode: int
    vendor_specific_status_code: int

    def __init__(
        self,
        uptime_sec: int = 0,
        health: Health = Health(0),
        mode: Mode | int = 0,
        sub_mode: int = 0,
        vendor_specific_status_code: int = 0,
    ) -> None:
        _setattr(self, "uptime_sec", uptime_sec)
        _setattr(self, "health", health)
        _setattr(self, "mode", mode)
        _setattr(self, "sub_mode", sub_mode)
        _setattr(self, "vendor_specific_status_code", vendor_specific_status_code)


@frozen_dataclass
class SoftwareVersion(HtmlDisplay):
    """``uavcan.protocol.SoftwareVersion`` (nested; ``protocol/SoftwareVersion.uavcan``).

    Nested type.
    Generic software version information.
    """

    OPTIONAL_FIELD_FLAG_VCS_COMMIT: ClassVar[int] = 1
    OPTIONAL_FIELD_FLAG_IMAGE_CRC: ClassVar[int] = 2

    __slots__ = ("major", "minor", "optional_field_flags", "vcs_commit", "image_crc",)

    major: int
    minor: int
    optional_field_flags: int
    vcs_commit: int
    image_crc: int

    def __init__(
        self,
        major: int = 0,
        minor: int = 0,
        optional_field_flags: int = 0,
        vcs_commit: int = 0,
        image_crc: int = 0,
    ) -> None:
        _setattr(self, "major", major)
        _setattr(self, "minor", minor)
        _setattr(self, "optional_field_flags", optional_field_flags)
        _setattr(self, "vcs_commit", vcs_commit)
        _setattr(self, "image_crc", image_crc)


@frozen_dataclass
class HardwareVersion(HtmlDisplay):
    """``uavcan.protocol.HardwareVersion`` (nested; ``protocol/HardwareVersion.uavcan``).

    Nested type.
    Generic hardware version information.
    These values should remain unchanged for the device's lifetime.
    """

    __slots__ = ("major", "minor", "unique_id", "certificate_of_authenticity",)

    major: int
    minor: int
    unique_id: bytes
    certificate_of_authenticity: bytes

    def __init__(
        self,
        major: int = 0,
        minor: int = 0,
        unique_id: bytes = bytes(16),
        certificate_of_authenticity: bytes = b"",
    ) -> None:
        _setattr(self, "major", major)
        _setattr(self, "minor", minor)
        _setattr(self, "unique_id", unique_id)
        _setattr(self, "certificate_of_authenticity", certificate_of_authenticity)


@frozen_dataclass
class GetNodeInfoResponse(HtmlDisplay):
    """``uavcan.protocol.GetNodeInfo`` response, service 1 (``protocol/1.GetNodeInfo.uavcan``)."""

    _TEXT_FIELDS_: ClassVar[frozenset[str]] = frozenset({"name"})

    __slots__ = ("status", "software_version", "hardware_version", "name",)

    status: NodeStatus
    software_version: SoftwareVersion
    hardware_version: HardwareVersion
    name: bytes

    def __init__(
        self,
        status: NodeStatus = NodeStatus(),
        software_version: SoftwareVersion = SoftwareVersion(),
        hardware_version: HardwareVersion = HardwareVersion(),
        name: bytes = b"",
    ) -> None:
        _setattr(self, "status", status)
        _setattr(self, "software_version", software_version)
        _setattr(self, "hardware_version", hardware_version)
        _setattr(self, "name", name)


@frozen_dataclass
class DataTypeKind(HtmlDisplay):
    """``uavcan.protocol.DataTypeKind`` (nested; ``protocol/DataTypeKind.uavcan``).

    Data type kind (message or service).
    """

    SERVICE: ClassVar[int] = 0
    MESSAGE: ClassVar[int] = 1

    __slots__ = ("value",)

    value: DataTypeKindValue | int

    def __init__(
        self,
        value: DataTypeKindValue | int = 0,
    ) -> None:
        _setattr(self, "value", value)


@frozen_dataclass
class GetDataTypeInfoRequest(HtmlDisplay):
    """``uavcan.protocol.GetDataTypeInfo`` request, service 2 (``protocol/2.GetDataTypeInfo.uavcan``).

    Get the implementation details of a given data type.

    Request is interpreted as follows:
    - If the field 'name' is empty, the fields 'kind' and 'id' will be used to identify the data type.
    - If the field 'name' is non-empty, it will be used to identify the data type; the
    fields 'kind' and 'id' will be ignored.
    """

    _TEXT_FIELDS_: ClassVar[frozenset[str]] = frozenset({"name"})

    __slots__ = ("id", "kind", "name",)

    id: int
    """Ignored if 'name' is non-empty"""
    kind: DataTypeKind
    """Ignored if 'name' is non-empty"""
    name: bytes
    """Full data type name, e.g. "uavcan.protocol.GetDataTypeInfo" """

    def __init__(
        self,
        id: int = 0,
        kind: DataTypeKind = DataTypeKind(),
        name: bytes = b"",
    ) -> None:
        _setattr(self, "id", id)
        _setattr(self, "kind", kind)
        _setattr(self, "name", name)


@frozen_dataclass
class GetDataTypeInfoResponse(HtmlDisplay):
    """``uavcan.protocol.GetDataTypeInfo`` response, service 2 (``protocol/2.GetDataTypeInfo.uavcan``)."""

    _TEXT_FIELDS_: ClassVar[frozenset[str]] = frozenset({"name"})
    FLAG_KNOWN: ClassVar[int] = 1
    """This data type is defined"""
    FLAG_SUBSCRIBED: ClassVar[int] = 2
    """Subscribed to messages of this type"""
    FLAG_PUBLISHING: ClassVar[int] = 4
    """Publishing messages of this type"""
    FLAG_SERVING: ClassVar[int] = 8
    """Providing service of this type"""

    __slots__ = ("signature", "id", "kind", "flags", "name",)

    signature: int
    """Data type signature; valid only if the data type is known (see FLAG_KNOWN)"""
    id: int
    """Valid only if the data type is known (see FLAG_KNOWN)"""
    kind: DataTypeKind
    """Ditto"""
    flags: int
    name: bytes
    """Full data type name"""

    def __init__(
        self,
        signature: int = 0,
        id: int = 0,
        kind: DataTypeKind = DataTypeKind(),
        flags: int = 0,
        name: bytes = b"",
    ) -> None:
        _setattr(self, "signature", signature)
        _setattr(self, "id", id)
        _setattr(self, "kind", kind)
        _setattr(self, "flags", flags)
        _setattr(self, "name", name)


@frozen_dataclass
class GetTransportStatsRequest(HtmlDisplay):
    """``uavcan.protocol.GetTransportStats`` request, service 4 (``protocol/4.GetTransportStats.uavcan``).

    Get transport statistics.
    """

    __slots__ = ()


    def __init__(
        self,
    ) -> None:
        pass


@frozen_dataclass
class CANIfaceStats(HtmlDisplay):
    """``uavcan.protocol.CANIfaceStats`` (nested; ``protocol/CANIfaceStats.uavcan``).

    Single CAN iface statistics.
    """

    __slots__ = ("frames_tx", "frames_rx", "errors",)

    frames_tx: int
    """Number of transmitted CAN frames."""
    frames_rx: int
    """Number of received CAN frames."""
    errors: int
    """Number of errors in the CAN layer."""

    def __init__(
        self,
        frames_tx: int = 0,
        frames_rx: int = 0,
        errors: int = 0,
    ) -> None:
        _setattr(self, "frames_tx", frames_tx)
        _setattr(self, "frames_rx", frames_rx)
        _setattr(self, "errors", errors)


@frozen_dataclass
class GetTransportStatsResponse(HtmlDisplay):
    """``uavcan.protocol.GetTransportStats`` response, service 4 (``protocol/4.GetTransportStats.uavcan``)."""

    __slots__ = ("transfers_tx", "transfers_rx", "transfer_errors", "can_iface_stats",)

    transfers_tx: int
    """Number of transmitted transfers."""
    transfers_rx: int
    """Number of received transfers."""
    transfer_errors: int
    """Number of errors detected in the UAVCAN transport layer."""
    can_iface_stats: tuple[CANIfaceStats, ...]

    def __init__(
        self,
        transfers_tx: int = 0,
        transfers_rx: int = 0,
        transfer_errors: int = 0,
        can_iface_stats: tuple[CANIfaceStats, ...] = (),
    ) -> None:
        _setattr(self, "transfers_tx", transfers_tx)
        _setattr(self, "transfers_rx", transfers_rx)
        _setattr(self, "transfer_errors", transfer_errors)
        _setattr(self, "can_iface_stats", can_iface_stats)


@frozen_dataclass
class GlobalTimeSync(HtmlDisplay):
    """``uavcan.protocol.GlobalTimeSync``, message 4 (``protocol/4.GlobalTimeSync.uavcan``).

    Global time synchronization.
    Any node that publishes timestamped data must use this time reference.

    Please refer to the specification to learn about the synchronization algorithm.
    """

    MAX_BROADCASTING_PERIOD_MS: ClassVar[int] = 1100
    """Milliseconds"""
    MIN_BROADCASTING_PERIOD_MS: ClassVar[int] = 40
    """Milliseconds"""
    RECOMMENDED_BROADCASTER_TIMEOUT_MS: ClassVar[int] = 2200
    """Milliseconds"""

    __slots__ = ("previous_transmission_timestamp_usec",)

    previous_transmission_timestamp_usec: int
    """Microseconds"""

    def __init__(
        self,
        previous_transmission_timestamp_usec: int = 0,
    ) -> None:
        _setattr(self, "previous_transmission_timestamp_usec", previous_transmission_timestamp_usec)


@frozen_dataclass
class Panic(HtmlDisplay):
    """``uavcan.protocol.Panic``, message 5 (``protocol/5.Panic.uavcan``).

    This message may be published periodically to inform network participants that the system has encountered
    an unrecoverable fault and is not capable of further operation.

    Nodes that are expected to react to this message should wait for at least MIN_MESSAGES subsequent messages
    with any reason text from any sender published with the interval no higher than MAX_INTERVAL_MS before
    undertaking any emergency actions.
    """

    _TEXT_FIELDS_: ClassVar[frozenset[str]] = frozenset({"reason_text"})
    MIN_MESSAGES: ClassVar[int] = 3
    MAX_INTERVAL_MS: ClassVar[int] = 500

    __slots__ = ("reason_text",)

    reason_text: bytes

    def __init__(
        self,
        reason_text: bytes = b"",
    ) -> None:
        _setattr(self, "reason_text", reason_text)


@frozen_dataclass
class RestartNodeRequest(HtmlDisplay):
    """``uavcan.protocol.RestartNode`` request, service 5 (``protocol/5.RestartNode.uavcan``).

    Restart the node.

    Some nodes may require restart before the new configuration will be applied.

    The request should be rejected if magic_number does not equal MAGIC_NUMBER.
    """

    MAGIC_NUMBER: ClassVar[int] = 742196058910

    __slots__ = ("magic_number",)

    magic_number: int

    def __init__(
        self,
        magic_number: int = 0,
    ) -> None:
        _setattr(self, "magic_number", magic_number)


@frozen_dataclass
class RestartNodeResponse(HtmlDisplay):
    """``uavcan.protocol.RestartNode`` response, service 5 (``protocol/5.RestartNode.uavcan``)."""

    __slots__ = ("ok",)

    ok: bool

    def __init__(
        self,
        ok: bool = False,
    ) -> None:
        _setattr(self, "ok", ok)


@frozen_dataclass
class AccessCommandShellRequest(HtmlDisplay):
    """``uavcan.protocol.AccessCommandShell`` request, service 6 (``protocol/6.AccessCommandShell.uavcan``).

    THIS DEFINITION IS SUBJECT TO CHANGE.

    This service allows to execute arbitrary commands on the remote node's internal system shell.

    Essentially, this service mimics a typical terminal emulator, with one text input (stdin) and two text
    outputs (stdout and stderr). When there's no process running, the input is directed into the terminal
    handler itself, which interprets it. If there's a process running, the input will be directed into
    stdin of the running process. It is possible to forcefully return the terminal into a known state by
    means of setting the reset flag (see below), in which case the terminal will kill all of the child
    processes, if any, and return into the initial idle state.

    The server is assumed to allocate one independent terminal instance per client, so that different clients
    can execute commands without interfering with each other.
    """

    NEWLINE: ClassVar[int] = 10
    MIN_OUTPUT_LIFETIME_SEC: ClassVar[int] = 10
    FLAG_RESET_SHELL: ClassVar[int] = 1
    """Restarts the shell instance anew; may or may not imply CLEAR_OUTPUT_BUFFERS"""
    FLAG_CLEAR_OUTPUT_BUFFERS: ClassVar[int] = 2
    """Makes stdout and stderr buffers empty"""
    FLAG_READ_STDOUT: ClassVar[int] = 64
    """Output will contain stdout"""
    FLAG_READ_STDERR: ClassVar[int] = 128
    """Output will be extended with stderr"""

    __slots__ = ("flags", "input",)

    flags: int
    input: bytes

    def __init__(
        self,
        flags: int = 0,
        input: bytes = b"",
    ) -> None:
        _setattr(self, "flags", flags)
        _setattr(self, "input", input)


@frozen_dataclass
class AccessCommandShellResponse(HtmlDisplay):
    """``uavcan.protocol.AccessCommandShell`` response, service 6 (``protocol/6.AccessCommandShell.uavcan``)."""

    FLAG_RUNNING: ClassVar[int] = 1
    """The shell is currently running a process; stdin/out/err are piped to it"""
    FLAG_SHELL_ERROR: ClassVar[int] = 2
    """Exit status contains error code, output contains text (e.g. no such command)"""
    FLAG_HAS_PENDING_STDOUT: ClassVar[int] = 64
    """There is more stdout to read"""
    FLAG_HAS_PENDING_STDERR: ClassVar[int] = 128
    """There is more stderr to read"""

    __slots__ = ("last_exit_status", "flags", "output",)

    last_exit_status: int
    flags: int
    output: bytes

    def __init__(
        self,
        last_exit_status: int = 0,
        flags: int = 0,
        output: bytes = b"",
    ) -> None:
        _setattr(self, "last_exit_status", last_exit_status)
        _setattr(self, "flags", flags)
        _setattr(self, "output", output)


@frozen_dataclass
class KeyValue(HtmlDisplay):
    """``uavcan.protocol.debug.KeyValue``, message 16370 (``protocol/debug/16370.KeyValue.uavcan``).

    Generic named parameter (key/value pair).
    """

    _TEXT_FIELDS_: ClassVar[frozenset[str]] = frozenset({"key"})
    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"value"})

    __slots__ = ("value", "key",)

    value: float
    key: bytes

    def __init__(
        self,
        value: float = 0.0,
        key: bytes = b"",
    ) -> None:
        _setattr(self, "value", value)
        _setattr(self, "key", key)


@frozen_dataclass
class LogLevel(HtmlDisplay):
    """``uavcan.protocol.debug.LogLevel`` (nested; ``protocol/debug/LogLevel.uavcan``).

    Log message severity
    """

    DEBUG: ClassVar[int] = 0
    INFO: ClassVar[int] = 1
    WARNING: ClassVar[int] = 2
    ERROR: ClassVar[int] = 3

    __slots__ = ("value",)

    value: LogLevelValue | int

    def __init__(
        self,
        value: LogLevelValue | int = 0,
    ) -> None:
        _setattr(self, "value", value)


@frozen_dataclass
class LogMessage(HtmlDisplay):
    """``uavcan.protocol.debug.LogMessage``, message 16383 (``protocol/debug/16383.LogMessage.uavcan``).

    Generic log message.
    All items are byte aligned.
    """

    _TEXT_FIELDS_: ClassVar[frozenset[str]] = frozenset({"source", "text"})

    __slots__ = ("level", "source", "text",)

    level: LogLevel
    source: bytes
    text: bytes

    def __init__(
        self,
        level: LogLevel = LogLevel(),
        source: bytes = b"",
        text: bytes = b"",
    ) -> None:
        _setattr(self, "level", level)
        _setattr(self, "source", source)
        _setattr(self, "text", text)


@frozen_dataclass
class Allocation(HtmlDisplay):
    """``uavcan.protocol.dynamic_node_id.Allocation``, message 1 (``protocol/dynamic_node_id/1.Allocation.uavcan``).

    This message is used for dynamic Node ID allocation.

    When a node needs to request a node ID dynamically, it will transmit an anonymous message transfer of this type.
    In order to reduce probability of CAN ID collisions when multiple nodes are publishing this request, the CAN ID
    field of anonymous message transfer includes a Discriminator, which is a special field that has to be filled with
    random data by the transmitting node. Since Discriminator collisions are likely to happen (probability approx.
    0.006%), nodes that are requesting dynamic allocations need to be able to handle them correctly. Hence, a collision
    resolution protocol is defined (alike CSMA/CD). The collision resolution protocol is based on two randomized
    transmission intervals:

    - Request period - Trequest.
    - Follow up delay - Tfollowup.

    Recommended randomization ranges for these intervals are documented in the constants of this message type (see below).
    Random intervals must be chosen anew per transmission, whereas the Discriminator value is allowed to stay constant
    per node.

    In the below description the following terms are used:
    - Allocator - the node that serves allocation requests.
    - Allocatee - the node that requests an allocation from the Allocator.

    The response timeout is not explicitly defined for this protocol, as the Allocatee will request the allocation
    Trequest units of time later again, unless the allocation has been granted. Despite this, the implementation can
    consider the value of FOLLOWUP_TIMEOUT_MS as an allocation timeout, if necessary.

    On the allocatee's side the protocol is defined through the following set of rules:

    Rule A. On initialization:
    1. The allocatee subscribes to this message.
    2. The allocatee starts the Request Timer with a random interval of Trequest.

    Rule B. On expiration of Request Timer:
    1. Request Timer restarts with a random interval of Trequest.
    2. The allocatee broadcasts a first-stage Allocation request message, where the fields are assigned following values:
    node_id                 - preferred node ID, or zero if the allocatee doesn't have any preference
    first_part_of_unique_id - true
    unique_id               - first MAX_LENGTH_OF_UNIQUE_ID_IN_REQUEST bytes of unique ID

    Rule C. On any Allocation message, even if other rules also match:
    1. Request Timer restarts with a random interval of Trequest.

    Rule D. On an Allocation message WHERE (source node ID is non-anonymous) AND (allocatee's unique ID starts with the
    bytes available in the field unique_id) AND (unique_id is less than 16 bytes long):
    1. The allocatee waits for Tfollowup units of time, while listening for other Allocation messages. If an Allocation
    message is received during this time, the execution of this rule will be terminated. Also see rule C.
    2. The allocatee broadcasts a second-stage Allocation request message, where the fields are assigned following values:
    node_id                 - same value as in the first-stage
    first_part_of_unique_id - false
    unique_id               - at most MAX_LENGTH_OF_UNIQUE_ID_IN_REQUEST bytes of local unique ID with an offset
    equal to number of bytes in the received unique ID

    Rule E. On an Allocation message WHERE (source node ID is non-anonymous) AND (unique_id fully matches allocatee's
    unique ID) AND (node_id in the received message is not zero):
    1. Request Timer stops.
    2. The allocatee initializes its node_id with the received value.
    3. The allocatee terminates subscription to Allocation messages.
    4. Exit.
    """

    MAX_REQUEST_PERIOD_MS: ClassVar[int] = 1000
    """It is OK to exceed this value"""
    MIN_REQUEST_PERIOD_MS: ClassVar[int] = 600
    """It is OK to exceed this value"""
    MAX_FOLLOWUP_DELAY_MS: ClassVar[int] = 400
    MIN_FOLLOWUP_DELAY_MS: ClassVar[int] = 0
    """Defined only for regularity; will always be zero."""
    FOLLOWUP_TIMEOUT_MS: ClassVar[int] = 500
    MAX_LENGTH_OF_UNIQUE_ID_IN_REQUEST: ClassVar[int] = 6
    ANY_NODE_ID: ClassVar[int] = 0

    __slots__ = ("node_id", "first_part_of_unique_id", "unique_id",)

    node_id: int
    first_part_of_unique_id: bool
    unique_id: bytes

    def __init__(
        self,
        node_id: int = 0,
        first_part_of_unique_id: bool = False,
        unique_id: bytes = b"",
    ) -> None:
        _setattr(self, "node_id", node_id)
        _setattr(self, "first_part_of_unique_id", first_part_of_unique_id)
        _setattr(self, "unique_id", unique_id)


@frozen_dataclass
class Entry(HtmlDisplay):
    """``uavcan.protocol.dynamic_node_id.server.Entry`` (nested; ``protocol/dynamic_node_id/server/Entry.uavcan``).

    THIS DEFINITION IS SUBJECT TO CHANGE.

    One dynamic node ID allocation entry.
    This type is a part of the Raft consensus algorithm.
    Please refer to the specification for details.
    """

    __slots__ = ("term", "unique_id", "node_id",)

    term: int
    """Refer to the Raft paper for explanation."""
    unique_id: bytes
    """Unique ID of this allocation."""
    node_id: int
    """Node ID of this allocation."""

    def __init__(
        self,
        term: int = 0,
        unique_id: bytes = bytes(16),
        node_id: int = 0,
    ) -> None:
        _setattr(self, "term", term)
        _setattr(self, "unique_id", unique_id)
        _setattr(self, "node_id", node_id)


@frozen_dataclass
class AppendEntriesRequest(HtmlDisplay):
    """``uavcan.protocol.dynamic_node_id.server.AppendEntries`` request, service 30 (``protocol/dynamic_node_id/server/30.AppendEntries.uavcan``).

    THIS DEFINITION IS SUBJECT TO CHANGE.

    This type is a part of the Raft consensus algorithm.
    Please refer to the specification for details.
    """

    DEFAULT_MIN_ELECTION_TIMEOUT_MS: ClassVar[int] = 2000
    DEFAULT_MAX_ELECTION_TIMEOUT_MS: ClassVar[int] = 4000

    __slots__ = ("term", "prev_log_term", "prev_log_index", "leader_commit", "entries",)

    term: int
    prev_log_term: int
    prev_log_index: int
    leader_commit: int
    entries: tuple[Entry, ...]

    def __init__(
        self,
        term: int = 0,
        prev_log_term: int = 0,
        prev_log_index: int = 0,
        leader_commit: int = 0,
        entries: tuple[Entry, ...] = (),
    ) -> None:
        _setattr(self, "term", term)
        _setattr(self, "prev_log_term", prev_log_term)
        _setattr(self, "prev_log_index", prev_log_index)
        _setattr(self, "leader_commit", leader_commit)
        _setattr(self, "entries", entries)


@frozen_dataclass
class AppendEntriesResponse(HtmlDisplay):
    """``uavcan.protocol.dynamic_node_id.server.AppendEntries`` response, service 30 (``protocol/dynamic_node_id/server/30.AppendEntries.uavcan``)."""

    __slots__ = ("term", "success",)

    term: int
    success: bool

    def __init__(
        self,
        term: int = 0,
        success: bool = False,
    ) -> None:
        _setattr(self, "term", term)
        _setattr(self, "success", success)


@frozen_dataclass
class RequestVoteRequest(HtmlDisplay):
    """``uavcan.protocol.dynamic_node_id.server.RequestVote`` request, service 31 (``protocol/dynamic_node_id/server/31.RequestVote.uavcan``).

    THIS DEFINITION IS SUBJECT TO CHANGE.

    This type is a part of the Raft consensus algorithm.
    Please refer to the specification for details.
    """

    __slots__ = ("term", "last_log_term", "last_log_index",)

    term: int
    last_log_term: int
    last_log_index: int

    def __init__(
        self,
        term: int = 0,
        last_log_term: int = 0,
        last_log_index: int = 0,
    ) -> None:
        _setattr(self, "term", term)
        _setattr(self, "last_log_term", last_log_term)
        _setattr(self, "last_log_index", last_log_index)


@frozen_dataclass
class RequestVoteResponse(HtmlDisplay):
    """``uavcan.protocol.dynamic_node_id.server.RequestVote`` response, service 31 (``protocol/dynamic_node_id/server/31.RequestVote.uavcan``)."""

    __slots__ = ("term", "vote_granted",)

    term: int
    vote_granted: bool

    def __init__(
        self,
        term: int = 0,
        vote_granted: bool = False,
    ) -> None:
        _setattr(self, "term", term)
        _setattr(self, "vote_granted", vote_granted)


@frozen_dataclass
class Discovery(HtmlDisplay):
    """``uavcan.protocol.dynamic_node_id.server.Discovery``, message 390 (``protocol/dynamic_node_id/server/390.Discovery.uavcan``).

    THIS DEFINITION IS SUBJECT TO CHANGE.

    This message is used by allocation servers to find each other's node ID.
    Please refer to the specification for details.

    A server should stop publishing this message as soon as it has discovered all other nodes in the cluster.

    An exception applies: when a server receives a Discovery message from another server where the list
    of known nodes is incomplete (i.e. len(known_nodes) < configured_cluster_size), the server must
    publish a discovery message once. This condition allows other servers to quickly re-discover the cluster
    after restart.
    """

    BROADCASTING_PERIOD_MS: ClassVar[int] = 1000

    __slots__ = ("configured_cluster_size", "known_nodes",)

    configured_cluster_size: int
    known_nodes: bytes

    def __init__(
        self,
        configured_cluster_size: int = 0,
        known_nodes: bytes = b"",
    ) -> None:
        _setattr(self, "configured_cluster_size", configured_cluster_size)
        _setattr(self, "known_nodes", known_nodes)


@frozen_dataclass
class BeginRequest(HtmlDisplay):
    """``uavcan.protocol.enumeration.Begin`` request, service 15 (``protocol/enumeration/15.Begin.uavcan``).

    This service instructs the node to begin the process of automated enumeration.
    """

    _TEXT_FIELDS_: ClassVar[frozenset[str]] = frozenset({"parameter_name"})
    TIMEOUT_CANCEL: ClassVar[int] = 0
    """Stop enumeration immediately"""
    TIMEOUT_INFINITE: ClassVar[int] = 65535
    """Do not stop until explicitly requested"""

    __slots__ = ("timeout_sec", "parameter_name",)

    timeout_sec: int
    """[Seconds]"""
    parameter_name: bytes

    def __init__(
        self,
        timeout_sec: int = 0,
        parameter_name: bytes = b"",
    ) -> None:
        _setattr(self, "timeout_sec", timeout_sec)
        _setattr(self, "parameter_name", parameter_name)


@frozen_dataclass
class BeginResponse(HtmlDisplay):
    """``uavcan.protocol.enumeration.Begin`` response, service 15 (``protocol/enumeration/15.Begin.uavcan``)."""

    ERROR_OK: ClassVar[int] = 0
    """Success"""
    ERROR_INVALID_MODE: ClassVar[int] = 1
    """The node cannot perform enumeration in its current operating mode"""
    ERROR_INVALID_PARAMETER: ClassVar[int] = 2
    """The node cannot enumerate on the requested parameter, or it doesn't exist"""
    ERROR_UNSUPPORTED: ClassVar[int] = 3
    """The node cannot perform enumeration in its current configuration"""
    ERROR_UNKNOWN: ClassVar[int] = 255
    """Generic error"""

    __slots__ = ("error",)

    error: Error | int

    def __init__(
        self,
        error: Error | int = 0,
    ) -> None:
        _setattr(self, "error", error)


@frozen_dataclass
class Empty(HtmlDisplay):
    """``uavcan.protocol.param.Empty`` (nested; ``protocol/param/Empty.uavcan``).

    Ex nihilo nihil fit.
    """

    __slots__ = ()


    def __init__(
        self,
    ) -> None:
        pass


@frozen_dataclass
class IntegerValue(HtmlDisplay):
    """Member ``integer_value`` of the union ``uavcan.protocol.param.NumericValue``."""

    __slots__ = ("value",)

    value: int

    def __init__(
        self,
        value: int = 0,
    ) -> None:
        _setattr(self, "value", value)


@frozen_dataclass
class RealValue(HtmlDisplay):
    """Member ``real_value`` of the union ``uavcan.protocol.param.NumericValue``."""

    _FLOAT32_FIELDS_: ClassVar[frozenset[str]] = frozenset({"value"})

    __slots__ = ("value",)

    value: float

    def __init__(
        self,
        value: float = 0.0,
    ) -> None:
        _setattr(self, "value", value)


NumericValue: TypeAlias = Empty | IntegerValue | RealValue
"""``uavcan.protocol.param.NumericValue`` (nested; ``protocol/param/NumericValue.uavcan``).

Numeric-only value.

This is a union, which means that this structure can contain either one of the fields below.
The structure is prefixed with tag - a selector value that indicates which particular field is encoded.
"""


@frozen_dataclass
class Indication(HtmlDisplay):
    """``uavcan.protocol.enumeration.Indication``, message 380 (``protocol/enumeration/380.Indication.uavcan``).

    This message will be broadcasted when the node receives user input in the process of enumeration.
    """

    _TEXT_FIELDS_: ClassVar[frozenset[str]] = frozenset({"parameter_name"})

    __slots__ = ("value", "parameter_name",)

    value: NumericValue
    parameter_name: bytes

    def __init__(
        self,
        value: NumericValue = Empty(),
        parameter_name: bytes = b"",
    ) -> None:
        _setattr(self, "value", value)
        _setattr(self, "parameter_name", parameter_name)


@frozen_dataclass
class Path(HtmlDisplay):
    """``uavcan.protocol.file.Path`` (nested; ``protocol/file/Path.uavcan``).

    Nested type.

    File system path in UTF8.

    The only valid separator is forward slash.
    """

    _TEXT_FIELDS_: ClassVar[frozenset[str]] = frozenset({"path"})
    SEPARATOR: ClassVar[int] = 47

    __slots__ = ("path",)

    path: bytes

    def __init__(
        self,
        path: bytes = b"",
    ) -> None:
        _setattr(self, "path", path)


@frozen_dataclass
class BeginFirmwareUpdateRequest(HtmlDisplay):
    """``uavcan.protocol.file.BeginFirmwareUpdate`` request, service 40 (``protocol/file/40.BeginFirmwareUpdate.uavcan``).

    This service initiates firmware update on a remote node.

    The node that is being updated (slave) will retrieve the firmware image file 'image_file_remote_path' from the node
    'source_node_id' using the file read service, then it will update the firmware and reboot.

    The slave can explicitly reject this request if it is not possible to update the firmware at the moment
    (e.g. if the node is busy).

    If the slave node accepts this request, the initiator will get a response immediately, before the update process
    actually begins.

    While the firmware is being updated, the slave should set its mode (uavcan.protocol.NodeStatus.mode) to
    MODE_SOFTWARE_UPDATE.
    """

    __slots__ = ("source_node_id", "image_file_remote_path",)

    source_node_id: int
    """If this field is zero, the caller's Node ID will be used instead."""
    image_file_remote_path: Path

    def __init__(
        self,
        source_node_id: int = 0,
        image_file_remote_path: Path = Path(),
    ) -> None:
        _setattr(self, "source_node_id", source_node_id)
        _setattr(self, "image_file_remote_path", image_file_remote_path)


@frozen_dataclass
class BeginFirmwareUpdateResponse(HtmlDisplay):
    """``uavcan.protocol.file.BeginFirmwareUpdate`` response, service 40 (``protocol/file/40.BeginFirmwareUpdate.uavcan``)."""

    _TEXT_FIELDS_: ClassVar[frozenset[str]] = frozenset({"optional_error_message"})
    ERROR_OK: ClassVar[int] = 0
    ERROR_INVALID_MODE: ClassVar[int] = 1
    """Cannot perform the update in the current operating mode or state."""
    ERROR_IN_PROGRESS: ClassVar[int] = 2
    """Firmware update is already in progress, and the slave doesn't want to restart."""
    ERROR_UNKNOWN: ClassVar[int] = 255

    __slots__ = ("error", "optional_error_message",)

    error: FirmwareUpdateError | int
    optional_error_message: bytes
    """Detailed description of the error."""

    def __init__(
        self,
        error: FirmwareUpdateError | int = 0,
        optional_error_message: bytes = b"",
    ) -> None:
        _setattr(self, "error", error)
        _setattr(self, "optional_error_message", optional_error_message)


@frozen_dataclass
class FileGetInfoRequest(HtmlDisplay):
    """``uavcan.protocol.file.GetInfo`` request, service 45 (``protocol/file/45.GetInfo.uavcan``).

    Request info about a remote file system entry (file, directory, etc).
    """

    __slots__ = ("path",)

    path: Path

    def __init__(
        self,
        path: Path = Path(),
    ) -> None:
        _setattr(self, "path", path)


@frozen_dataclass
class FileErrorCode(HtmlDisplay):
    """``uavcan.protocol.file.Error`` (nested; ``protocol/file/Error.uavcan``).

    Nested type.
    File operation result code.
    """

    OK: ClassVar[int] = 0
    UNKNOWN_ERROR: ClassVar[int] = 32767
    NOT_FOUND: ClassVar[int] = 2
    IO_ERROR: ClassVar[int] = 5
    ACCESS_DENIED: ClassVar[int] = 13
    IS_DIRECTORY: ClassVar[int] = 21
    """I.e. attempt to read/write on a path that points to a directory"""
    INVALID_VALUE: ClassVar[int] = 22
    """E.g. file name is not valid for the target file system"""
    FILE_TOO_LARGE: ClassVar[int] = 27
    OUT_OF_SPACE: ClassVar[int] = 28
    NOT_IMPLEMENTED: ClassVar[int] = 38

    __slots__ = ("value",)

    value: int

    def __init__(
        self,
        value: int = 0,
    ) -> None:
        _setattr(self, "value", value)


@frozen_dataclass
class EntryType(HtmlDisplay):
    """``uavcan.protocol.file.EntryType`` (nested; ``protocol/file/EntryType.uavcan``).

    Nested type.
    Represents the type of the file system entry (e.g. file or directory).
    If such entry does not exist, 'flags' must be set to zero.
    """

    FLAG_FILE: ClassVar[int] = 1
    """Excludes FLAG_DIRECTORY"""
    FLAG_DIRECTORY: ClassVar[int] = 2
    """Excludes FLAG_FILE"""
    FLAG_SYMLINK: ClassVar[int] = 4
    """Link target is either FLAG_FILE or FLAG_DIRECTORY"""
    FLAG_READABLE: ClassVar[int] = 8
    FLAG_WRITEABLE: ClassVar[int] = 16

    __slots__ = ("flags",)

    flags: int

    def __init__(
        self,
        flags: int = 0,
    ) -> None:
        _setattr(self, "flags", flags)


@frozen_dataclass
class FileGetInfoResponse(HtmlDisplay):
    """``uavcan.protocol.file.GetInfo`` response, service 45 (``protocol/file/45.GetInfo.uavcan``)."""

    __slots__ = ("size", "error", "entry_type",)

    size: int
    error: FileErrorCode
    entry_type: EntryType

    def __init__(
        self,
        size: int = 0,
        error: FileErrorCode = FileErrorCode(),
        entry_type: EntryType = EntryType(),
    ) -> None:
        _setattr(self, "size", size)
        _setattr(self, "error", error)
        _setattr(self, "entry_type", entry_type)


@frozen_dataclass
class GetDirectoryEntryInfoRequest(HtmlDisplay):
    """``uavcan.protocol.file.GetDirectoryEntryInfo`` request, service 46 (``protocol/file/46.GetDirectoryEntryInfo.uavcan``).

    This service can be used to retrieve a remote directory listing, one entry per request.

    The client should query each entry independently, iterating 'entry_index' from 0 until the last entry is passed,
    in which case the server will report that there is no such entry (via the fields 'entry_type' and 'error').

    The entry_index shall be applied to the ordered list of directory entries (e.g. alphabetically ordered). The exact
    sorting criteria does not matter as long as it provides the same ordering for subsequent service calls.
    """

    __slots__ = ("entry_index", "directory_path",)

    entry_index: int
    directory_path: Path

    def __init__(
        self,
        entry_index: int = 0,
        directory_path: Path = Path(),
    ) -> None:
        _setattr(self, "entry_index", entry_index)
        _setattr(self, "directory_path", directory_path)


@frozen_dataclass
class GetDirectoryEntryInfoResponse(HtmlDisplay):
    """``uavcan.protocol.file.GetDirectoryEntryInfo`` response, service 46 (``protocol/file/46.GetDirectoryEntryInfo.uavcan``)."""

    __slots__ = ("error", "entry_type", "entry_full_path",)

    error: FileErrorCode
    entry_type: EntryType
    entry_full_path: Path
    """Ignored/Empty if such entry does not exist."""

    def __init__(
        self,
        error: FileErrorCode = FileErrorCode(),
        entry_type: EntryType = EntryType(),
        entry_full_path: Path = Path(),
    ) -> None:
        _setattr(self, "error", error)
        _setattr(self, "entry_type", entry_type)
        _setattr(self, "entry_full_path", entry_full_path)


@frozen_dataclass
class DeleteRequest(HtmlDisplay):
    """``uavcan.protocol.file.Delete`` request, service 47 (``protocol/file/47.Delete.uavcan``).

    Delete remote file system entry.
    If the remote entry is a directory, all nested entries will be removed too.
    """

    __slots__ = ("path",)

    path: Path

    def __init__(
        self,
        path: Path = Path(),
    ) -> None:
        _setattr(self, "path", path)


@frozen_dataclass
class DeleteResponse(HtmlDisplay):
    """``uavcan.protocol.file.Delete`` response, service 47 (``protocol/file/47.Delete.uavcan``)."""

    __slots__ = ("error",)

    error: FileErrorCode

    def __init__(
        self,
        error: FileErrorCode = FileErrorCode(),
    ) -> None:
        _setattr(self, "error", error)


@frozen_dataclass
class FileReadRequest(HtmlDisplay):
    """``uavcan.protocol.file.Read`` request, service 48 (``protocol/file/48.Read.uavcan``).

    Read file from a remote node.

    There are two possible outcomes of a successful service call:
    1. Data array size equals its capacity. This means that the end of the file is not reached yet.
    2. Data array size is less than its capacity, possibly zero. This means that the end of file is reached.

    Thus, if the client needs to fetch the entire file, it should repeatedly call this service while increasing the
    offset, until incomplete data is returned.

    If the object pointed by 'path' cannot be read (e.g. it is a directory or it does not exist), appropriate error code
    will be returned, and data array will be empty.
    """

    __slots__ = ("offset", "path",)

    offset: int
    path: Path

    def __init__(
        self,
        offset: int = 0,
        path: Path = Path(),
    ) -> None:
        _setattr(self, "offset", offset)
        _setattr(self, "path", path)


@frozen_dataclass
class FileReadResponse(HtmlDisplay):
    """``uavcan.protocol.file.Read`` response, service 48 (``protocol/file/48.Read.uavcan``)."""

    MAX_DATA: ClassVar[int] = 256
    """Most bytes of ``data`` in one response (its DSDL array size)."""

    __slots__ = ("error", "data",)

    error: FileErrorCode
    data: bytes

    def __init__(
        self,
        error: FileErrorCode = FileErrorCode(),
        data: bytes = b"",
    ) -> None:
        _setattr(self, "error", error)
        _setattr(self, "data", data)


@frozen_dataclass
class WriteRequest(HtmlDisplay):
    """``uavcan.protocol.file.Write`` request, service 49 (``protocol/file/49.Write.uavcan``).

    Write into a remote file.
    The server shall place the contents of the field 'data' into the file pointed by 'path' at the offset specified by
    the field 'offset'.

    When writing a file, the client should repeatedly call this service with data while advancing offset until the file
    is written completely. When write is complete, the client shall call the service one last time, with the offset
    set to the size of the file and with the data field empty, which will signal the server that the write operation is
    complete.

    When the write operation is complete, the server shall truncate the resulting file past the specified offset.

    Server implementation advice:
    It is recommended to implement proper handling of concurrent writes to the same file from different clients, for
    example by means of creating a staging area for uncompleted writes (like FTP servers do).
    """

    __slots__ = ("offset", "path", "data",)

    offset: int
    path: Path
    data: bytes

    def __init__(
        self,
        offset: int = 0,
        path: Path = Path(),
        data: bytes = b"",
    ) -> None:
        _setattr(self, "offset", offset)
        _setattr(self, "path", path)
        _setattr(self, "data", data)


@frozen_dataclass
class WriteResponse(HtmlDisplay):
    """``uavcan.protocol.file.Write`` response, service 49 (``protocol/file/49.Write.uavcan``)."""

    __slots__ = ("error",)

    error: FileErrorCode

    def __init__(
        self,
        error: FileErrorCode = FileErrorCode(),
    ) -> None:
        _setattr(self, "error", error)


@frozen_dataclass
class ExecuteOpcodeRequest(HtmlDisplay):
    """``uavcan.protocol.param.ExecuteOpcode`` request, service 10 (``protocol/param/10.ExecuteOpcode.uavcan``).

    Service to control the node configuration.
    """

    OPCODE_SAVE: ClassVar[int] = 0
    """Save all parameters to non-volatile storage."""
    OPCODE_ERASE: ClassVar[int] = 1
    """Clear the non-volatile storage; some changes may take effect only after reboot."""

    __slots__ = ("opcode", "argument",)

    opcode: Opcode | int
    argument: int

    def __init__(
        self,
        opcode: Opcode | int = 0,
        argument: int = 0,
    ) -> None:
        _setattr(self, "opcode", opcode)
        _setattr(self, "argument", argument)


@frozen_dataclass
class ExecuteOpcodeResponse(HtmlDisplay):
    """``uavcan.protocol.param.ExecuteOpcode`` response, service 10 (``protocol/param/10.ExecuteOpcode.uavcan``)."""

    __slots__ = ("argument", "ok",)

    argument: int
    ok: bool

    def __init__(
        self,
        argument: int = 0,
        ok: bool = False,
    ) -> None:
        _setattr(self, "argument", argument)
        _setattr(self, "ok", ok)


@frozen_dataclass
class BooleanValue(HtmlDisplay):
    """Member ``boolean_value`` of the union ``uavcan.protocol.param.Value``."""

    __slots__ = ("value",)

    value: int

    def __init__(
        self,
        value: int = 0,
    ) -> None:
        _setattr(self, "value", value)


@frozen_dataclass
class StringValue(HtmlDisplay):
    """Member ``string_value`` of the union ``uavcan.protocol.param.Value``."""

    _TEXT_FIELDS_: ClassVar[frozenset[str]] = frozenset({"value"})

    __slots__ = ("value",)

    value: bytes

    def __init__(
        self,
        value: bytes = b"",
    ) -> None:
        _setattr(self, "value", value)


Value: TypeAlias = Empty | IntegerValue | RealValue | BooleanValue | StringValue
"""``uavcan.protocol.param.Value`` (nested; ``protocol/param/Value.uavcan``).

Single parameter value.

This is a union, which means that this structure can contain either one of the fields below.
The structure is prefixed with tag - a selector value that indicates which particular field is encoded.
"""


@frozen_dataclass
class GetSetRequest(HtmlDisplay):
    """``uavcan.protocol.param.GetSet`` request, service 11 (``protocol/param/11.GetSet.uavcan``).

    Get or set a parameter by name or by index.
    Note that access by index should only be used to retrieve the list of parameters; it is highly
    discouraged to use it for anything else, because persistent ordering is not guaranteed.
    """

    _TEXT_FIELDS_: ClassVar[frozenset[str]] = frozenset({"name"})

    __slots__ = ("index", "value", "name",)

    index: int
    value: Value
    name: bytes

    def __init__(
        self,
        index: int = 0,
        value: Value = Empty(),
        name: bytes = b"",
    ) -> None:
        _setattr(self, "index", index)
        _setattr(self, "value", value)
        _setattr(self, "name", name)


@frozen_dataclass
class GetSetResponse(HtmlDisplay):
    """``uavcan.protocol.param.GetSet`` response, service 11 (``protocol/param/11.GetSet.uavcan``)."""

    _TEXT_FIELDS_: ClassVar[frozenset[str]] = frozenset({"name"})

    __slots__ = ("value", "default_value", "max_value", "min_value", "name",)

    value: Value
    default_value: Value
    """Optional"""
    max_value: NumericValue
    """Optional, not applicable for bool/string"""
    min_value: NumericValue
    """Optional, not applicable for bool/string"""
    name: bytes

    def __init__(
        self,
        value: Value = Empty(),
        default_value: Value = Empty(),
        max_value: NumericValue = Empty(),
        min_value: NumericValue = Empty(),
        name: bytes = b"",
    ) -> None:
        _setattr(self, "value", value)
        _setattr(self, "default_value", default_value)
        _setattr(self, "max_value", max_value)
        _setattr(self, "min_value", min_value)
        _setattr(self, "name", name)


@frozen_dataclass
class Protocol(HtmlDisplay):
    """``uavcan.tunnel.Protocol`` (nested; ``tunnel/Protocol.uavcan``).

    This enumeration specifies the encapsulated protocol.
    New protocols are likely to be added in the future.
    """

    MAVLINK: ClassVar[int] = 0
    """MAVLink"""
    MAVLINK2: ClassVar[int] = 1
    """MAVLink2"""
    GPS_GENERIC: ClassVar[int] = 2
    """GPS in any protocol (e.g. UBX, NMEA, etc.)"""
    UNDEFINED: ClassVar[int] = 255
    """Undefined"""

    __slots__ = ("protocol",)

    protocol: ProtocolProtocol | int

    def __init__(
        self,
        protocol: ProtocolProtocol | int = 0,
    ) -> None:
        _setattr(self, "protocol", protocol)


@frozen_dataclass
class Broadcast(HtmlDisplay):
    """``uavcan.tunnel.Broadcast``, message 2010 (``tunnel/2010.Broadcast.uavcan``).

    This message struct carries arbitrary data in the format of the specified high-level protocol.
    The data will be delivered to all nodes that are interested in tunneled protocols.
    Finer addressing schemes may be implemented using the means provided by the encapsulated protocol.
    The channelID allows for additional routing between the source and target nodes.
    """

    __slots__ = ("protocol", "channel_id", "buffer",)

    protocol: Protocol
    channel_id: int
    buffer: bytes
    """TAO rules apply"""

    def __init__(
        self,
        protocol: Protocol = Protocol(),
        channel_id: int = 0,
        buffer: bytes = b"",
    ) -> None:
        _setattr(self, "protocol", protocol)
        _setattr(self, "channel_id", channel_id)
        _setattr(self, "buffer", buffer)


@frozen_dataclass
class SerialConfig(HtmlDisplay):
    """``uavcan.tunnel.SerialConfig``, message 2011 (``tunnel/2011.SerialConfig.uavcan``).

    This message carries baudrate for tunnel channel_id
    """

    __slots__ = ("channel_id", "baud", "options",)

    channel_id: int
    baud: int
    options: int

    def __init__(
        self,
        channel_id: int = 0,
        baud: int = 0,
        options: int = 0,
    ) -> None:
        _setattr(self, "channel_id", channel_id)
        _setattr(self, "baud", baud)
        _setattr(self, "options", options)


@frozen_dataclass
class Targetted(HtmlDisplay):
    """``uavcan.tunnel.Targetted``, message 3001 (``tunnel/3001.Targetted.uavcan``).

    This message struct carries arbitrary data in the format of the specified high-level protocol.
    The message is sent as a broadcast but it is expected that the target_node to select which node
    will process the data. This is used instead of a service request to avoid the round trip which
    impacts high rate messages
    a send with a buffer length of 0 can be used as a keepalive or to trigger initial
    setup of the link on the target node
    """

    OPTION_LOCK_PORT: ClassVar[int] = 1

    __slots__ = ("protocol", "target_node", "serial_id", "options", "baudrate", "buffer",)

    protocol: Protocol
    target_node: int
    serial_id: int
    options: int
    baudrate: int
    buffer: bytes

    def __init__(
        self,
        protocol: Protocol = Protocol(),
        target_node: int = 0,
        serial_id: int = 0,
        options: int = 0,
        baudrate: int = 0,
        buffer: bytes = b"",
    ) -> None:
        _setattr(self, "protocol", protocol)
        _setattr(self, "target_node", target_node)
        _setattr(self, "serial_id", serial_id)
        _setattr(self, "options", options)
        _setattr(self, "baudrate", baudrate)
        _setattr(self, "buffer", buffer)


@frozen_dataclass
class CallRequest(HtmlDisplay):
    """``uavcan.tunnel.Call`` request, service 63 (``tunnel/63.Call.uavcan``).

    This service carries arbitrary data in the format of the specified high-level protocol.
    The data will be delivered to the specified node only (not broadcast), and the addressed node
    will be required to respond (although the response may be empty, if the chosen protocol allows so).
    The specified protocol applies both to the request and to the response. The channelID allows for
    additional routing between the source and target nodes.
    """

    __slots__ = ("protocol", "channel_id", "buffer",)

    protocol: Protocol
    channel_id: int
    buffer: bytes
    """TAO rules apply"""

    def __init__(
        self,
        protocol: Protocol = Protocol(),
        channel_id: int = 0,
        buffer: bytes = b"",
    ) -> None:
        _setattr(self, "protocol", protocol)
        _setattr(self, "channel_id", channel_id)
        _setattr(self, "buffer", buffer)


@frozen_dataclass
class CallResponse(HtmlDisplay):
    """``uavcan.tunnel.Call`` response, service 63 (``tunnel/63.Call.uavcan``)."""

    __slots__ = ("buffer",)

    buffer: bytes
    """TAO rules apply"""

    def __init__(
        self,
        buffer: bytes = b"",
    ) -> None:
        _setattr(self, "buffer", buffer)


__all__ = [
    'AccessCommandShellRequest',
    'AccessCommandShellRequestFlag',
    'AccessCommandShellResponse',
    'AccessCommandShellResponseFlag',
    'ActuatorCommand',
    'ActuatorStatus',
    'Allocation',
    'AngleOfAttack',
    'AngularCommand',
    'AppendEntriesRequest',
    'AppendEntriesResponse',
    'ArmingStatus',
    'ArmingStatusStatus',
    'ArrayCommand',
    'Auxiliary',
    'BatteryInfo',
    'BeepCommand',
    'BeginFirmwareUpdateRequest',
    'BeginFirmwareUpdateResponse',
    'BeginRequest',
    'BeginResponse',
    'BooleanValue',
    'Broadcast',
    'CANIfaceStats',
    'CallRequest',
    'CallResponse',
    'CameraGimbalMode',
    'CameraGimbalStatus',
    'CircuitStatus',
    'CoarseOrientation',
    'CommandMode',
    'CommandType',
    'CylinderStatus',
    'DataTypeKind',
    'DataTypeKindValue',
    'DeleteRequest',
    'DeleteResponse',
    'Discovery',
    'ECEFPositionVelocity',
    'Empty',
    'Entry',
    'EntryType',
    'EntryTypeFlag',
    'Error',
    'ErrorFlag',
    'EscStatus',
    'ExecuteOpcodeRequest',
    'ExecuteOpcodeResponse',
    'FileError',
    'FileErrorCode',
    'FileGetInfoRequest',
    'FileGetInfoResponse',
    'FileReadRequest',
    'FileReadResponse',
    'FirmwareUpdateError',
    'Fix',
    'Fix2',
    'Fix2GnssTimeStandard',
    'Fix2Mode',
    'Fix2Status',
    'FixGnssTimeStandard',
    'FixStatus',
    'FuelTankStatus',
    'GEOPOICommand',
    'GetDataTypeInfoRequest',
    'GetDataTypeInfoResponse',
    'GetDataTypeInfoResponseFlag',
    'GetDirectoryEntryInfoRequest',
    'GetDirectoryEntryInfoResponse',
    'GetNodeInfoRequest',
    'GetNodeInfoResponse',
    'GetSetRequest',
    'GetSetResponse',
    'GetTransportStatsRequest',
    'GetTransportStatsResponse',
    'GlobalNavigationSolution',
    'GlobalTimeSync',
    'HardpointCommand',
    'HardpointStatus',
    'HardwareVersion',
    'Health',
    'HeightReference',
    'IndicatedAirspeed',
    'Indication',
    'IntegerValue',
    'KeyValue',
    'LightId',
    'LightsCommand',
    'LogLevel',
    'LogLevelValue',
    'LogMessage',
    'MagneticFieldStrength',
    'MagneticFieldStrength2',
    'Measurement',
    'Mode',
    'NodeStatus',
    'NumericValue',
    'Opcode',
    'Panic',
    'Path',
    'PrimaryPowerSupplyStatus',
    'Protocol',
    'ProtocolId',
    'ProtocolProtocol',
    'RGB565',
    'RPMCommand',
    'RTCMStream',
    'RawAirData',
    'RawAirDataFlag',
    'RawCommand',
    'RawIMU',
    'ReadingType',
    'RealValue',
    'ReciprocatingStatus',
    'ReciprocatingStatusFlag',
    'RequestVoteRequest',
    'RequestVoteResponse',
    'RestartNodeRequest',
    'RestartNodeResponse',
    'SensorId',
    'SensorType',
    'SerialConfig',
    'Sideslip',
    'SingleLightCommand',
    'SoftwareVersion',
    'SoftwareVersionFlag',
    'Solution',
    'State',
    'StaticPressure',
    'StaticTemperature',
    'StatusExtended',
    'StatusFlag',
    'StringValue',
    'Targetted',
    'Temperature',
    'TemperatureErrorFlag',
    'Timestamp',
    'TrueAirspeed',
    'Value',
    'WriteRequest',
    'WriteResponse',
]

CLASSES: dict[str, Any] = {
    'uavcan.CoarseOrientation': CoarseOrientation,
    'uavcan.Timestamp': Timestamp,
    'uavcan.equipment.actuator.Command': ActuatorCommand,
    'uavcan.equipment.actuator.ArrayCommand': ArrayCommand,
    'uavcan.equipment.actuator.Status': ActuatorStatus,
    'uavcan.equipment.ahrs.Solution': Solution,
    'uavcan.equipment.ahrs.MagneticFieldStrength': MagneticFieldStrength,
    'uavcan.equipment.ahrs.MagneticFieldStrength2': MagneticFieldStrength2,
    'uavcan.equipment.ahrs.RawIMU': RawIMU,
    'uavcan.equipment.air_data.TrueAirspeed': TrueAirspeed,
    'uavcan.equipment.air_data.IndicatedAirspeed': IndicatedAirspeed,
    'uavcan.equipment.air_data.AngleOfAttack': AngleOfAttack,
    'uavcan.equipment.air_data.Sideslip': Sideslip,
    'uavcan.equipment.air_data.RawAirData': RawAirData,
    'uavcan.equipment.air_data.StaticPressure': StaticPressure,
    'uavcan.equipment.air_data.StaticTemperature': StaticTemperature,
    'uavcan.equipment.camera_gimbal.Mode': CameraGimbalMode,
    'uavcan.equipment.camera_gimbal.AngularCommand': AngularCommand,
    'uavcan.equipment.camera_gimbal.GEOPOICommand': GEOPOICommand,
    'uavcan.equipment.camera_gimbal.Status': CameraGimbalStatus,
    'uavcan.equipment.device.Temperature': Temperature,
    'uavcan.equipment.esc.RawCommand': RawCommand,
    'uavcan.equipment.esc.RPMCommand': RPMCommand,
    'uavcan.equipment.esc.Status': EscStatus,
    'uavcan.equipment.esc.StatusExtended': StatusExtended,
    'uavcan.equipment.gnss.Fix': Fix,
    'uavcan.equipment.gnss.Auxiliary': Auxiliary,
    'uavcan.equipment.gnss.RTCMStream': RTCMStream,
    'uavcan.equipment.gnss.ECEFPositionVelocity': ECEFPositionVelocity,
    'uavcan.equipment.gnss.Fix2': Fix2,
    'uavcan.equipment.hardpoint.Command': HardpointCommand,
    'uavcan.equipment.hardpoint.Status': HardpointStatus,
    'uavcan.equipment.ice.FuelTankStatus': FuelTankStatus,
    'uavcan.equipment.ice.reciprocating.CylinderStatus': CylinderStatus,
    'uavcan.equipment.ice.reciprocating.Status': ReciprocatingStatus,
    'uavcan.equipment.indication.BeepCommand': BeepCommand,
    'uavcan.equipment.indication.RGB565': RGB565,
    'uavcan.equipment.indication.SingleLightCommand': SingleLightCommand,
    'uavcan.equipment.indication.LightsCommand': LightsCommand,
    'uavcan.equipment.power.PrimaryPowerSupplyStatus': PrimaryPowerSupplyStatus,
    'uavcan.equipment.power.CircuitStatus': CircuitStatus,
    'uavcan.equipment.power.BatteryInfo': BatteryInfo,
    'uavcan.equipment.range_sensor.Measurement': Measurement,
    'uavcan.equipment.safety.ArmingStatus': ArmingStatus,
    'uavcan.navigation.GlobalNavigationSolution': GlobalNavigationSolution,
    'uavcan.protocol.GetNodeInfo.Request': GetNodeInfoRequest,
    'uavcan.protocol.NodeStatus': NodeStatus,
    'uavcan.protocol.SoftwareVersion': SoftwareVersion,
    'uavcan.protocol.HardwareVersion': HardwareVersion,
    'uavcan.protocol.GetNodeInfo.Response': GetNodeInfoResponse,
    'uavcan.protocol.DataTypeKind': DataTypeKind,
    'uavcan.protocol.GetDataTypeInfo.Request': GetDataTypeInfoRequest,
    'uavcan.protocol.GetDataTypeInfo.Response': GetDataTypeInfoResponse,
    'uavcan.protocol.GetTransportStats.Request': GetTransportStatsRequest,
    'uavcan.protocol.CANIfaceStats': CANIfaceStats,
    'uavcan.protocol.GetTransportStats.Response': GetTransportStatsResponse,
    'uavcan.protocol.GlobalTimeSync': GlobalTimeSync,
    'uavcan.protocol.Panic': Panic,
    'uavcan.protocol.RestartNode.Request': RestartNodeRequest,
    'uavcan.protocol.RestartNode.Response': RestartNodeResponse,
    'uavcan.protocol.AccessCommandShell.Request': AccessCommandShellRequest,
    'uavcan.protocol.AccessCommandShell.Response': AccessCommandShellResponse,
    'uavcan.protocol.debug.KeyValue': KeyValue,
    'uavcan.protocol.debug.LogLevel': LogLevel,
    'uavcan.protocol.debug.LogMessage': LogMessage,
    'uavcan.protocol.dynamic_node_id.Allocation': Allocation,
    'uavcan.protocol.dynamic_node_id.server.Entry': Entry,
    'uavcan.protocol.dynamic_node_id.server.AppendEntries.Request': AppendEntriesRequest,
    'uavcan.protocol.dynamic_node_id.server.AppendEntries.Response': AppendEntriesResponse,
    'uavcan.protocol.dynamic_node_id.server.RequestVote.Request': RequestVoteRequest,
    'uavcan.protocol.dynamic_node_id.server.RequestVote.Response': RequestVoteResponse,
    'uavcan.protocol.dynamic_node_id.server.Discovery': Discovery,
    'uavcan.protocol.enumeration.Begin.Request': BeginRequest,
    'uavcan.protocol.enumeration.Begin.Response': BeginResponse,
    'uavcan.protocol.param.Empty': Empty,
    'uavcan.protocol.param.NumericValue': NumericValue,
    'uavcan.protocol.enumeration.Indication': Indication,
    'uavcan.protocol.file.Path': Path,
    'uavcan.protocol.file.BeginFirmwareUpdate.Request': BeginFirmwareUpdateRequest,
    'uavcan.protocol.file.BeginFirmwareUpdate.Response': BeginFirmwareUpdateResponse,
    'uavcan.protocol.file.GetInfo.Request': FileGetInfoRequest,
    'uavcan.protocol.file.Error': FileErrorCode,
    'uavcan.protocol.file.EntryType': EntryType,
    'uavcan.protocol.file.GetInfo.Response': FileGetInfoResponse,
    'uavcan.protocol.file.GetDirectoryEntryInfo.Request': GetDirectoryEntryInfoRequest,
    'uavcan.protocol.file.GetDirectoryEntryInfo.Response': GetDirectoryEntryInfoResponse,
    'uavcan.protocol.file.Delete.Request': DeleteRequest,
    'uavcan.protocol.file.Delete.Response': DeleteResponse,
    'uavcan.protocol.file.Read.Request': FileReadRequest,
    'uavcan.protocol.file.Read.Response': FileReadResponse,
    'uavcan.protocol.file.Write.Request': WriteRequest,
    'uavcan.protocol.file.Write.Response': WriteResponse,
    'uavcan.protocol.param.ExecuteOpcode.Request': ExecuteOpcodeRequest,
    'uavcan.protocol.param.ExecuteOpcode.Response': ExecuteOpcodeResponse,
    'uavcan.protocol.param.Value': Value,
    'uavcan.protocol.param.GetSet.Request': GetSetRequest,
    'uavcan.protocol.param.GetSet.Response': GetSetResponse,
    'uavcan.tunnel.Protocol': Protocol,
    'uavcan.tunnel.Broadcast': Broadcast,
    'uavcan.tunnel.SerialConfig': SerialConfig,
    'uavcan.tunnel.Targetted': Targetted,
    'uavcan.tunnel.Call.Request': CallRequest,
    'uavcan.tunnel.Call.Response': CallResponse,
}
"""The class of each key (full name, with ``.Request``/``.Response``)."""

ENUMS: dict[tuple[str, str], type] = {
    ('uavcan.protocol.NodeStatus', 'health'): Health,
    ('uavcan.protocol.NodeStatus', 'mode'): Mode,
    ('uavcan.protocol.file.BeginFirmwareUpdate.Response', 'error'): FirmwareUpdateError,
    ('uavcan.protocol.param.ExecuteOpcode.Request', 'opcode'): Opcode,
    ('uavcan.equipment.actuator.Command', 'command_type'): CommandType,
    ('uavcan.equipment.air_data.AngleOfAttack', 'sensor_id'): SensorId,
    ('uavcan.equipment.camera_gimbal.GEOPOICommand', 'height_reference'): HeightReference,
    ('uavcan.equipment.camera_gimbal.Mode', 'command_mode'): CommandMode,
    ('uavcan.equipment.gnss.Fix', 'gnss_time_standard'): FixGnssTimeStandard,
    ('uavcan.equipment.gnss.Fix', 'status'): FixStatus,
    ('uavcan.equipment.gnss.RTCMStream', 'protocol_id'): ProtocolId,
    ('uavcan.equipment.gnss.Fix2', 'gnss_time_standard'): Fix2GnssTimeStandard,
    ('uavcan.equipment.gnss.Fix2', 'status'): Fix2Status,
    ('uavcan.equipment.gnss.Fix2', 'mode'): Fix2Mode,
    ('uavcan.equipment.ice.reciprocating.Status', 'state'): State,
    ('uavcan.equipment.indication.SingleLightCommand', 'light_id'): LightId,
    ('uavcan.equipment.range_sensor.Measurement', 'sensor_type'): SensorType,
    ('uavcan.equipment.range_sensor.Measurement', 'reading_type'): ReadingType,
    ('uavcan.equipment.safety.ArmingStatus', 'status'): ArmingStatusStatus,
    ('uavcan.protocol.DataTypeKind', 'value'): DataTypeKindValue,
    ('uavcan.protocol.debug.LogLevel', 'value'): LogLevelValue,
    ('uavcan.protocol.enumeration.Begin.Response', 'error'): Error,
    ('uavcan.tunnel.Protocol', 'protocol'): ProtocolProtocol,
}
"""The enum a field decodes to, by (key, field name)."""

UNION_MEMBERS: dict[str, tuple[type, ...]] = {
    'uavcan.protocol.param.NumericValue': (Empty, IntegerValue, RealValue,),
    'uavcan.protocol.param.Value': (Empty, IntegerValue, RealValue, BooleanValue, StringValue,),
}
"""The member classes of each union, in member order."""
