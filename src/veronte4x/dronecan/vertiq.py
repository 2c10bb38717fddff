"""Vertiq ESC specifics (Vertiq's "Standard DroneCAN Support" document).

Parameter names and types (section 3), the zero-behaviour values (3.4), the RestartNode
magic numbers (2.3), the node name (2.1), GetSet requests by name and by index (2.2) and
RawCommand throttle helpers (1.4: setpoints normalized over [-8192, 8191], entry i read by
the ESC of index i, at most 20 entries).
"""

from __future__ import annotations

import enum
import math
from collections.abc import Iterable, Mapping, Sequence

from veronte4x.dronecan.messages import (
    BooleanValue,
    Empty,
    GetSetRequest,
    GetSetResponse,
    IntegerValue,
    RawCommand,
    RealValue,
    RestartNodeRequest,
    StringValue,
    Value,
)
from veronte4x.errors import (
    EncodeError,
    argument_type_error,
    boolean,
    int_argument,
    integer,
    real,
    real_argument,
)

NODE_NAME = "iq_motion.esc"
"""The GetNodeInfo ``name`` of Vertiq modules (Vertiq's DroneCAN support document, section 2.1)."""

RESTART_MAGIC = 0xACCE551B1E
"""RestartNode magic number of a normal reboot (Vertiq's DroneCAN support, 2.3; the DSDL
MAGIC_NUMBER)."""

BOOTLOADER_MAGIC = 0xBEEFCAFE
"""Vertiq's RestartNode magic number that reboots into the ST bootloader (Vertiq's DroneCAN
support, 2.3)."""


class Parameter(str, enum.Enum):
    """Configuration parameters of Vertiq modules (Vertiq's DroneCAN support document, section 3),
    all integers.

    Not every module supports every parameter; access them by name, not by index.
    """

    UAVCAN_NODE_ID = "uavcan_node_id"
    """Node ID on the bus; typically needs a reboot to take effect (3.1)."""
    BIT_RATE = "bit_rate"
    """Bus bit rate in bit/s, effective immediately; fixed 500000 where unsupported (3.2)."""
    ESC_INDEX = "esc_index"
    """Which RawCommand entry the module reads (3.3)."""
    ZERO_BEHAVIOR = "zero_behavior"
    """What a zero RawCommand setpoint does: a `ZeroBehavior` (3.4)."""
    TELEM_FREQUENCY = "telem_frequency"
    """esc.Status and Temperature broadcast rate in Hz; 0 turns them off (3.5)."""


class ZeroBehavior(enum.IntEnum):
    """Values of the ``zero_behavior`` parameter (Vertiq's DroneCAN support document, section
    3.4)."""

    COAST = 0
    """Stop driving the motor and let it coast to a stop."""
    BRAKE = 1
    """Brake to a stop, then coast."""
    NORMAL_CONTROLLER = 2
    """Keep the controller running at 0 % throttle."""


RAW_COMMAND_MIN = -8192
"""Full speed in reverse (Vertiq's DroneCAN support, 1.4)."""
RAW_COMMAND_MAX = 8191
"""Full speed forward (Vertiq's DroneCAN support, 1.4)."""
MAX_ESCS = 20
"""Most entries of a RawCommand (DSDL ``int14[<=20] cmd``)."""


_VALUE_KINDS = "an int, float, bool, str, bytes or param.Value"


def _name(function: str, name: str | Parameter) -> bytes:
    if not isinstance(name, str):
        raise argument_type_error(function, "name", "a str or Parameter", name)
    text = name.value if isinstance(name, Parameter) else name
    if not text:
        # An empty name with index 0 addresses the parameter at index 0 (DSDL param.GetSet).
        raise EncodeError(
            "uavcan.protocol.param.GetSet request",
            "name",
            text,
            "a parameter name; an empty name would address index 0"
            " (use get_parameter_by_index to read by index)",
        )
    return text.encode("utf-8")


def _value(value: int | float | bool | str | bytes | Value | None) -> Value:
    """Wrap a Python value as a ``param.Value`` member (`TypeError` for any other type)."""
    if value is None:
        return Empty()
    if isinstance(value, (Empty, IntegerValue, RealValue, BooleanValue, StringValue)):
        return value
    # Python's numbers and NumPy's alike (see veronte4x.errors.integer and .real).
    flag, whole, number = boolean(value), integer(value), real(value)
    if flag is not None:
        return BooleanValue(int(flag))
    if whole is not None:
        return IntegerValue(whole)
    if number is not None:
        return RealValue(number)
    if isinstance(value, str):
        return StringValue(value.encode("utf-8"))
    if isinstance(value, bytes):
        return StringValue(value)
    raise argument_type_error("set_parameter", "value", _VALUE_KINDS, value)


def get_parameter(name: str | Parameter) -> GetSetRequest:
    """A GetSet request reading parameter ``name`` (the recommended access, Vertiq's DroneCAN
    support, 2.2).

    Raises:
        TypeError: ``name`` is not a str.
        EncodeError: ``name`` is empty (it would address the parameter at index 0).
    """
    return GetSetRequest(index=0, value=Empty(), name=_name("get_parameter", name))


def set_parameter(
    name: str | Parameter, value: int | float | bool | str | bytes | Value
) -> GetSetRequest:
    """A GetSet request setting parameter ``name``; Vertiq parameters are integers.

    ``value`` may be an int (``IntegerValue``), a float, a bool, a str or a ready
    ``param.Value`` member.

    Raises:
        TypeError: ``name`` is not a str, or ``value`` none of these.
        EncodeError: ``name`` is empty (it would set the parameter at index 0).
    """
    encoded = _name("set_parameter", name)
    return GetSetRequest(index=0, value=_value(value), name=encoded)


def get_parameter_by_index(index: int) -> GetSetRequest:
    """A GetSet request reading the parameter at ``index`` (for discovery only, Vertiq's DroneCAN
    support, 3).

    Raises:
        TypeError: ``index`` is not an int.
    """
    index = int_argument("get_parameter_by_index", "index", index)
    return GetSetRequest(index=index, value=Empty(), name=b"")


def is_end_of_parameters(response: GetSetResponse) -> bool:
    """Whether a GetSet response is the empty reply that ends a discovery walk.

    The DSDL: an empty name and/or an empty value means there is no such parameter.

    Raises:
        TypeError: ``response`` is not a GetSetResponse.
    """
    if not isinstance(response, GetSetResponse):
        raise argument_type_error("is_end_of_parameters", "response", "a GetSetResponse", response)
    return not response.name or isinstance(response.value, Empty)


def discovered_parameters(responses: Sequence[GetSetResponse]) -> dict[str, Value]:
    """Collect the replies of a discovery walk (index 0, 1, ...) up to the first empty one.

    Returns:
        Parameter name (decoded as UTF-8, undecodable bytes replaced) to its value.

    Raises:
        TypeError: ``responses`` is not an iterable of GetSetResponse.
    """
    if not isinstance(responses, Iterable):
        raise argument_type_error(
            "discovered_parameters", "responses", "a sequence of GetSetResponse", responses
        )
    found: dict[str, Value] = {}
    for index, response in enumerate(responses):
        if not isinstance(response, GetSetResponse):
            raise argument_type_error(
                "discovered_parameters", f"responses[{index}]", "a GetSetResponse", response
            )
        if is_end_of_parameters(response):
            break
        found[response.name.decode("utf-8", "replace")] = response.value
    return found


def restart(bootloader: bool = False) -> RestartNodeRequest:
    """A RestartNode request: normal reboot, or into the ST bootloader (Vertiq's DroneCAN support,
    2.3).

    Raises:
        TypeError: ``bootloader`` is not a bool.
    """
    flag = boolean(bootloader)
    if flag is None:
        raise argument_type_error("restart", "bootloader", "a bool", bootloader)
    return RestartNodeRequest(BOOTLOADER_MAGIC if flag else RESTART_MAGIC)


def throttle_to_raw(throttle: float) -> int:
    """Map a throttle fraction in [-1, 1] to the 14-bit setpoint [-8192, 8191].

    Positive fractions scale by 8191 and negative ones by 8192, so -1 and 1 are full speed
    in reverse and forward (Vertiq's DroneCAN support, 1.4); values round to the nearest integer,
    halves
    away from zero.

    Raises:
        EncodeError: ``throttle`` is outside [-1, 1] or not a finite number.
        TypeError: ``throttle`` is not a number.
    """
    throttle = real_argument("throttle_to_raw", "throttle", throttle)
    if not (math.isfinite(throttle) and -1.0 <= throttle <= 1.0):
        raise EncodeError("RawCommand", "throttle", throttle, "a float in [-1, 1]")
    scaled = throttle * (RAW_COMMAND_MAX if throttle >= 0 else -RAW_COMMAND_MIN)
    return int(math.copysign(math.floor(abs(scaled) + 0.5), scaled))


def raw_to_throttle(raw: int) -> float:
    """Map a 14-bit setpoint back to a throttle fraction in [-1, 1] (inverse of the scale).

    Raises:
        TypeError: ``raw`` is not an int.
    """
    return _fraction(int_argument("raw_to_throttle", "raw", raw))


def _fraction(raw: int) -> float:
    return raw / (RAW_COMMAND_MAX if raw >= 0 else -RAW_COMMAND_MIN)


def raw_command(throttles: Sequence[float] | Mapping[int, float]) -> RawCommand:
    """Build a RawCommand from throttle fractions.

    Args:
        throttles: A sequence (entry i for ESC index i) or a mapping from ESC index
            (0..19) to fraction; indices missing from a mapping get 0 (which the ESC
            handles as its ``zero_behavior`` says).

    Raises:
        EncodeError: More than 20 ESCs, an index out of 0..19, or a fraction out of [-1, 1].
        TypeError: ``throttles`` is neither, an index is not an int or a fraction not a
            number.
    """
    if isinstance(throttles, Mapping):
        for index, throttle in throttles.items():
            index = int_argument("raw_command", "throttles keys", index, "ints")
            if not 0 <= index < MAX_ESCS:
                raise EncodeError("RawCommand", "cmd", index, f"ESC indices 0..{MAX_ESCS - 1}")
            real_argument("raw_command", f"throttles[{index}]", throttle)
        count = max(throttles, default=-1) + 1
        values = [throttles.get(i, 0.0) for i in range(count)]
    elif isinstance(throttles, Iterable):
        values = list(throttles)
        for index, throttle in enumerate(values):
            real_argument("raw_command", f"throttles[{index}]", throttle)
    else:
        raise argument_type_error(
            "raw_command", "throttles", "a sequence or mapping of floats", throttles
        )
    if len(values) > MAX_ESCS:
        raise EncodeError("RawCommand", "cmd", values, f"at most {MAX_ESCS} entries")
    return RawCommand(tuple(throttle_to_raw(v) for v in values))


def throttles(command: RawCommand) -> tuple[float, ...]:
    """The throttle fraction of each ESC index in a RawCommand.

    Raises:
        TypeError: ``command`` is not a RawCommand.
    """
    if not isinstance(command, RawCommand):
        raise argument_type_error("throttles", "command", "a RawCommand", command)
    return tuple(_fraction(v) for v in command.cmd)
