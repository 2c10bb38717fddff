"""`SimulatedEsc`: a sans-IO Vertiq ESC node that takes frames and gives frames.

Behaviour from Vertiq's "Standard DroneCAN Support" document: NodeStatus at 1 Hz with
health OK, mode OPERATIONAL, no sub-mode or vendor code (1.1); esc.Status and
device.Temperature at ``telem_frequency`` Hz, none at 0 (1.2, 1.3, 3.5); the RawCommand
entry at ``esc_index`` (1.4, 3.3) with ``zero_behavior`` for a zero setpoint (3.4);
GetNodeInfo with the name ``iq_motion.esc`` (2.1); GetSet by name and by index (2.2, 3);
RestartNode with the normal and the bootloader magic numbers (2.3); BeginFirmwareUpdate,
answered INVALID_MODE by modules without DroneCAN firmware updates (2.4). Responses reuse
the request's transfer id and priority (spec 4.1; as libcanard and the dronecan package do).

After an accepted BeginFirmwareUpdate the simulator pulls the image as section 2.4 says a
module does: ``file.GetInfo`` on the file server, then ``file.Read`` from offset 0 until a
short read, through the sans-IO `veronte4x.node.Requester` it shares with the ground
client. A request that got no answer in ``file_timeout`` seconds is sent again, as real
bootloaders do (a lost frame loses the whole 38-frame answer to a read), for up to
`FILE_SERVER_SILENCE` seconds. It then restarts with the image's CRC-64-WE in its software
version. A file server that stops answering for that long ends the update: the module
restarts into its old firmware. A BeginFirmwareUpdate repeated by the same node for the
same path during the update (its answer was lost) is answered OK again. param.ExecuteOpcode
SAVE is accepted (sets are kept at once, which the DSDL allows) and ERASE restores the
defaults.

With ``dynamic_node_id`` the module starts without a node id at every (re)start and asks an
allocation server for one (DroneCAN dynamic node ID allocation, `veronte4x.node.allocatee`):
silent but for its anonymous requests until granted, then a node at the id granted.

Nothing here reads a clock: every time is a ``timestamp`` argument.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

from veronte4x.dronecan.can_id import TransferKind, service_destination
from veronte4x.dronecan.frame import TransferFrame
from veronte4x.dronecan.image_crc import crc64we
from veronte4x.dronecan.messages import (
    BeginFirmwareUpdateRequest,
    BeginFirmwareUpdateResponse,
    EscStatus,
    ExecuteOpcodeRequest,
    ExecuteOpcodeResponse,
    FileError,
    FileGetInfoRequest,
    FileGetInfoResponse,
    FileReadRequest,
    FileReadResponse,
    FirmwareUpdateError,
    GetNodeInfoRequest,
    GetNodeInfoResponse,
    GetSetRequest,
    GetSetResponse,
    HardwareVersion,
    Health,
    Mode,
    NodeStatus,
    Opcode,
    Path,
    RawCommand,
    RestartNodeRequest,
    RestartNodeResponse,
    SoftwareVersion,
    SoftwareVersionFlag,
    Temperature,
    TemperatureErrorFlag,
)
from veronte4x.dronecan.reassembler import Reassembler
from veronte4x.dronecan.tail import TRANSFER_ID_MASK
from veronte4x.dronecan.transfer import DEFAULT_PRIORITY, Transfer, encode
from veronte4x.dronecan.vertiq import (
    BOOTLOADER_MAGIC,
    NODE_NAME,
    RESTART_MAGIC,
    Parameter,
    ZeroBehavior,
    raw_to_throttle,
)
from veronte4x.errors import EncodeError, check_seconds
from veronte4x.node.allocatee import Allocatee
from veronte4x.node.requests import Answered, Requester
from veronte4x.simulator import motor, parameters
from veronte4x.simulator.motor import DEFAULT_MODEL, MotorModel, MotorState
from veronte4x.simulator.schedule import Periodic

NODE_STATUS_FREQUENCY = 1.0
"""NodeStatus rate in Hz (Vertiq's DroneCAN support, 1.1)."""

SOFTWARE_VERSION = SoftwareVersion(
    major=1, minor=0, optional_field_flags=0, vcs_commit=0, image_crc=0
)
"""The simulator's GetNodeInfo software version (the document gives none for real modules)."""

HARDWARE_VERSION_MAJOR = 1
"""The simulator's GetNodeInfo hardware version, major (minor is 0)."""

FILE_REQUEST_TIMEOUT = 0.5
"""Seconds the simulator waits for each file.GetInfo or file.Read answer (then asks again),
unless told otherwise (``file_timeout``)."""

FILE_SERVER_SILENCE = 60.0
"""Seconds a file request is asked again without an answer before the simulator gives the
update up. Vertiq's document gives no figure: an assumption, long enough for a read to get
through a bus that loses 10 % of its frames (each attempt then succeeds about once in 75)."""

COMMAND_TIMEOUT = 0.2
"""Seconds a RawCommand setpoint holds without a new one; then the ESC takes a zero
setpoint (its ``zero_behavior``). Vertiq's DroneCAN document gives no figure: this is an
assumption, ArduPilot's AP_Periph ESC default (its ``ESC_CMD_TIMO`` parameter: 200 ms, 0 to
disable, "hold the last driven ESC command before timing out and zeroing the ESC
outputs")."""

UNIQUE_ID_PREFIX = b"veronte4x.sim\x00\x00"
"""First 15 bytes of the 16-byte unique id; the last is the node id given at construction."""


@dataclass(frozen=True, slots=True)
class EscState:
    """A snapshot of a `SimulatedEsc` at the latest timestamp it was given.

    Attributes:
        time: The latest timestamp given to `SimulatedEsc.receive` or `SimulatedEsc.poll`.
        uptime_sec: Whole seconds since the last (re)start.
        node_id: The node id in use (a new ``uavcan_node_id`` waits for a restart); None
            while it waits for a dynamic node id.
        mode: The NodeStatus mode: OPERATIONAL, or SOFTWARE_UPDATE after a
            BeginFirmwareUpdate.
        in_bootloader: Rebooted into the bootloader: silent until `SimulatedEsc.power_cycle`.
        firmware_source: Node id and path of the firmware image asked for by
            BeginFirmwareUpdate, else None.
        parameters: Each parameter's stored value, by name.
        throttle: Commanded throttle fraction in [-1, 1].
        rpm: Motor speed, negative in reverse.
        power_rating_pct: PWM duty cycle, 0..100.
        voltage: Supply voltage, V.
        current: Supply current, A.
        coil_temperature: Motor coil temperature, K (esc.Status).
        mcu_temperature: Microcontroller temperature, K (device.Temperature).
        overheating: Whether the MCU is at or above the model's overheat temperature.
    """

    time: float
    uptime_sec: int
    node_id: int | None
    mode: Mode
    in_bootloader: bool
    firmware_source: tuple[int, bytes] | None
    parameters: MappingProxyType[str, int]
    throttle: float
    rpm: float
    power_rating_pct: int
    voltage: float
    current: float
    coil_temperature: float
    mcu_temperature: float
    overheating: bool


@dataclass(slots=True)
class _Pull:
    """An image being pulled: from whom, which file, how far, its CRC so far."""

    source: int
    path: bytes
    handle: int = 0
    received: int = 0
    crc: int = 0


def _check(field: str, value: Any, low: int, high: int) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise EncodeError("SimulatedEsc", field, value, f"a whole number in {low}..{high}")
    if not (math.isfinite(value) and value == int(value) and low <= value <= high):
        raise EncodeError("SimulatedEsc", field, value, f"a whole number in {low}..{high}")
    return int(value)


class SimulatedEsc:
    """A simulated Vertiq ESC: feed it the bus's frames, poll it for the frames it sends.

    Args:
        node_id: DroneCAN node id, 1..127 (also the ``uavcan_node_id`` default).
        esc_index: Which RawCommand entry it reads, 0..19.
        telem_frequency: esc.Status and device.Temperature rate in Hz, a whole number
            (the parameter is an integer, Vertiq's DroneCAN support, 3.5), 0 for none.
        zero_behavior: What a zero setpoint does (`ZeroBehavior` or its int value).
        bit_rate: The ``bit_rate`` parameter, bit/s (stored and reported only).
        supports_firmware_update: False for modules such as the 81-08 that answer
            BeginFirmwareUpdate with INVALID_MODE (Vertiq's DroneCAN support, 2.4).
        start_time: Power-on time: frames before it are ignored, NodeStatus and telemetry
            start at it.
        update_stall_offset: A fault to test ground tools with: during a firmware update
            the module hangs (falls silent until `power_cycle`) once it has read this many
            bytes. None (the default) for a module that does not hang.
        priority: CAN priority of the messages it publishes, 0 (highest) to 31.
        model: The motor model's constants.
        response_delay: Seconds the module takes to act on a request: to answer it, and
            during a firmware update to write a chunk before reading the next (0: at the
            poll after the request). A load to test ground tools and benchmarks with; Vertiq's
            document gives no figure.
        command_timeout: Seconds a RawCommand setpoint holds without a new command
            (`COMMAND_TIMEOUT`); then a zero setpoint takes over, as when a ground tool is
            killed or loses the bus. None never times out (a fault to test with).
        file_timeout: Seconds each file request of a firmware update waits for its answer
            before it is sent again (`FILE_REQUEST_TIMEOUT`), for up to
            `FILE_SERVER_SILENCE` seconds.
        dynamic_node_id: Start without a node id and ask an allocation server for one at
            every (re)start (`veronte4x.node.allocatee.Allocatee`); ``node_id`` then names
            the unique id and is the node id preferred.
        preferred_node_id: The node id asked for with ``dynamic_node_id``: 1..125, 0 for
            any; None for ``node_id`` (125 for 126 or 127, the tools' node ids).

    The arguments are also the parameters' defaults (``default_value`` in GetSet replies).

    Raises:
        EncodeError: An argument out of its range.
    """

    def __init__(
        self,
        node_id: int,
        esc_index: int = 0,
        *,
        telem_frequency: float = 10.0,
        zero_behavior: ZeroBehavior | int = ZeroBehavior.COAST,
        bit_rate: int = 500000,
        supports_firmware_update: bool = True,
        start_time: float = 0.0,
        priority: int = DEFAULT_PRIORITY,
        model: MotorModel = DEFAULT_MODEL,
        update_stall_offset: int | None = None,
        command_timeout: float | None = COMMAND_TIMEOUT,
        response_delay: float = 0.0,
        file_timeout: float = FILE_REQUEST_TIMEOUT,
        dynamic_node_id: bool = False,
        preferred_node_id: int | None = None,
    ) -> None:
        given = (
            ("node_id", node_id),
            ("bit_rate", bit_rate),
            ("esc_index", esc_index),
            ("zero_behavior", zero_behavior),
            ("telem_frequency", telem_frequency),
        )  # in the order of parameters.PARAMETERS
        self._defaults = tuple(
            _check(argument, value, r.minimum, r.maximum)
            for r, (argument, value) in zip(parameters.PARAMETERS, given, strict=True)
        )
        self._priority = _check("priority", priority, 0, 31)
        if command_timeout is not None and (
            isinstance(command_timeout, bool)
            or not isinstance(command_timeout, (int, float))
            or not (math.isfinite(command_timeout) and command_timeout > 0)
        ):
            raise EncodeError(
                "SimulatedEsc", "command_timeout", command_timeout, "seconds above 0, or None"
            )
        self._command_timeout = command_timeout
        self._command_deadline: float | None = None
        if (
            isinstance(response_delay, bool)
            or not isinstance(response_delay, (int, float))
            or not (math.isfinite(response_delay) and response_delay >= 0)
        ):
            raise EncodeError(
                "SimulatedEsc", "response_delay", response_delay, "seconds, 0 or above"
            )
        self._delay = float(response_delay)
        if (
            isinstance(file_timeout, bool)
            or not isinstance(file_timeout, (int, float))
            or not (math.isfinite(file_timeout) and 0 < file_timeout <= FILE_SERVER_SILENCE)
        ):
            raise EncodeError(
                "SimulatedEsc",
                "file_timeout",
                file_timeout,
                f"seconds above 0, at most {FILE_SERVER_SILENCE:g}",
            )
        self._file_timeout = float(file_timeout)
        self._file_retries = math.ceil(FILE_SERVER_SILENCE / self._file_timeout) - 1
        self._later: list[tuple[float, list[TransferFrame]]] = []
        self._read_at: float | None = None
        self._values = list(self._defaults)
        self._supports_firmware_update = supports_firmware_update
        self._model = model
        self._unique_id = UNIQUE_ID_PREFIX + bytes((self._defaults[0],))
        self._dynamic = dynamic_node_id
        self._preferred = (
            min(self._defaults[0], 125)
            if preferred_node_id is None
            else _check("preferred_node_id", preferred_node_id, 0, 125)
        )
        self._allocatee: Allocatee | None = None
        self._start_time = start_time
        self._now = start_time
        self._motor = motor.at_rest(model)
        self._outbox: list[TransferFrame] = []
        self._in_bootloader = False
        self._software_version = SOFTWARE_VERSION
        self._update_stall_offset = update_stall_offset
        self._node_status = Periodic(NODE_STATUS_FREQUENCY, start_time)
        self._telemetry = Periodic(self._value(Parameter.TELEM_FREQUENCY), start_time)
        self._boot(start_time)

    # -- parameters and state -------------------------------------------------------------

    def _value(self, parameter: Parameter) -> int:
        return self._values[_INDEX[parameter]]

    @property
    def node_id(self) -> int | None:
        """The node id in use; None while it waits for a dynamic node id."""
        return None if self._allocatee is not None else self._node_id

    @property
    def esc_index(self) -> int:
        """The RawCommand entry it reads."""
        return self._value(Parameter.ESC_INDEX)

    @property
    def state(self) -> EscState:
        """A snapshot at the latest timestamp given (see `EscState`)."""
        m = self._motor
        return EscState(
            time=self._now,
            uptime_sec=self._uptime(self._now),
            node_id=self.node_id,
            mode=self._mode,
            in_bootloader=self._in_bootloader,
            firmware_source=self._firmware_source,
            parameters=MappingProxyType(
                {
                    r.parameter.value: v
                    for r, v in zip(parameters.PARAMETERS, self._values, strict=True)
                }
            ),
            throttle=m.throttle,
            rpm=m.rpm,
            power_rating_pct=m.power_rating_pct,
            voltage=m.voltage,
            current=m.current,
            coil_temperature=m.coil_temperature,
            mcu_temperature=m.mcu_temperature,
            overheating=m.mcu_temperature >= self._model.mcu_overheat_temperature,
        )

    @property
    def motor(self) -> MotorState:
        """The motor model's state at the latest timestamp given."""
        return self._motor

    def _uptime(self, timestamp: float) -> int:
        return max(0, math.floor(timestamp - self._boot_time))

    def _advance(self, timestamp: float) -> None:
        deadline = self._command_deadline
        if deadline is not None and deadline <= timestamp:
            self._command_deadline = None
            if deadline > self._now:
                self._motor = motor.advance(self._motor, deadline - self._now, self._model)
                self._now = deadline
            if self._motor.driven:  # the setpoint timed out: a zero setpoint takes over
                behavior = ZeroBehavior(self._value(Parameter.ZERO_BEHAVIOR))
                self._motor = motor.command(self._motor, 0.0, behavior)
        if timestamp > self._now:
            self._motor = motor.advance(self._motor, timestamp - self._now, self._model)
            self._now = timestamp

    def _boot(self, timestamp: float) -> None:
        """Start the application firmware at ``timestamp``: RAM state is lost."""
        self._boot_time = timestamp
        self._mode = Mode.OPERATIONAL
        self._firmware_source: tuple[int, bytes] | None = None
        self._in_bootloader = False
        self._pull: _Pull | None = None
        self._read_at = None
        self._reassembler = Reassembler()
        self._transfer_ids: dict[type, int] = {NodeStatus: 0, EscStatus: 0, Temperature: 0}
        self._motor = motor.release(self._motor)
        self._command_deadline = None
        self._allocatee = None
        if self._dynamic:
            self._allocatee = Allocatee(self._unique_id, self._preferred, start_time=timestamp)
        self._start(self._value(Parameter.UAVCAN_NODE_ID), timestamp)

    def _start(self, node_id: int, timestamp: float) -> None:
        """Run as ``node_id`` from ``timestamp``: NodeStatus and telemetry start."""
        self._node_id = node_id
        self._requester = Requester(node_id, priority=self._priority)
        self._node_status.restart(NODE_STATUS_FREQUENCY, timestamp)
        self._telemetry.restart(self._value(Parameter.TELEM_FREQUENCY), timestamp)

    def power_cycle(self, timestamp: float) -> None:
        """Switch the module off and on at ``timestamp`` (the way out of the bootloader).

        Like a normal restart: uptime restarts, a new ``uavcan_node_id`` takes effect, the
        motor coasts; frames not yet polled are lost.
        """
        timestamp = check_seconds("power_cycle", "timestamp", timestamp)
        self._advance(timestamp)
        self._outbox.clear()
        self._later.clear()
        self._boot(timestamp)

    # -- input ------------------------------------------------------------------------------

    def receive(self, can_id: int, data: bytes, timestamp: float) -> None:
        """Take one frame seen on the bus (29-bit ``can_id``, data with its tail byte).

        A frame before ``start_time`` or while in the bootloader is ignored. A RawCommand
        with an entry at ``esc_index`` sets the throttle; a request to this node queues
        its response for `poll`. Other frames and bad frames are ignored (the
        reassembler counts them).
        """
        timestamp = check_seconds("receive", "timestamp", timestamp)
        if timestamp < self._start_time or self._in_bootloader:
            return
        if self._allocatee is not None:
            self._allocating(can_id, data, timestamp)
            return
        destination = service_destination(can_id)
        if destination is not None and destination != self._node_id:
            return  # a service frame to another node
        self._advance(timestamp)
        transfer = self._reassembler.feed(can_id, data, timestamp)
        if transfer is None:
            return
        message = transfer.message
        if transfer.kind is TransferKind.MESSAGE:
            if isinstance(message, RawCommand):
                self._command(message)
        elif transfer.destination_node_id != self._node_id:
            return
        elif transfer.kind is TransferKind.REQUEST:
            self._serve(transfer, timestamp)
        else:
            answered = self._requester.receive(transfer)
            if answered is not None:
                self._pulled(answered, timestamp)

    def _allocating(self, can_id: int, data: bytes, timestamp: float) -> None:
        """A frame heard while waiting for a node id: only Allocation messages count."""
        assert self._allocatee is not None
        if service_destination(can_id) is not None:
            return
        self._advance(timestamp)
        transfer = self._reassembler.feed(can_id, data, timestamp)
        if transfer is None:
            return
        self._allocatee.receive(transfer)
        granted = self._allocatee.node_id
        if granted is not None:
            self._allocatee = None
            self._start(granted, timestamp)

    def _command(self, command: RawCommand) -> None:
        index = self._value(Parameter.ESC_INDEX)
        if index >= len(command.cmd) or self._mode is Mode.SOFTWARE_UPDATE:
            return
        behavior = ZeroBehavior(self._value(Parameter.ZERO_BEHAVIOR))
        self._motor = motor.command(self._motor, raw_to_throttle(command.cmd[index]), behavior)
        if self._command_timeout is not None:
            self._command_deadline = self._now + self._command_timeout

    def _serve(self, request: Transfer, timestamp: float) -> None:
        message = request.message
        after = None
        if isinstance(message, GetNodeInfoRequest):
            reply: Any = GetNodeInfoResponse(
                status=self._status(timestamp),
                software_version=self._software_version,
                hardware_version=HardwareVersion(HARDWARE_VERSION_MAJOR, 0, self._unique_id),
                name=NODE_NAME.encode(),
            )
        elif isinstance(message, GetSetRequest):
            reply = self._get_set(message, timestamp)
        elif isinstance(message, RestartNodeRequest):
            known = message.magic_number in (RESTART_MAGIC, BOOTLOADER_MAGIC)
            reply = RestartNodeResponse(ok=known)
            if known:
                after = message.magic_number
        elif isinstance(message, ExecuteOpcodeRequest):
            reply = self._execute_opcode(message)
        elif isinstance(message, BeginFirmwareUpdateRequest):
            assert request.source_node_id is not None  # a request is never anonymous
            reply = self._begin_firmware_update(message, request.source_node_id)
        else:
            return  # a request this module does not serve: no answer, as on a real node
        frames = encode(
            reply,
            source_node_id=self._node_id,
            destination_node_id=request.source_node_id,
            transfer_id=request.transfer_id,
            priority=request.priority,
        )
        if self._delay:
            self._later.append((timestamp + self._delay, frames))
        else:
            self._outbox += frames
        if after == RESTART_MAGIC:
            self._boot(timestamp)
        elif after == BOOTLOADER_MAGIC:
            self._motor = motor.release(self._motor)
            self._in_bootloader = True
        elif self._mode is Mode.SOFTWARE_UPDATE and self._pull is None:
            self._start_pull(timestamp)

    def _get_set(self, request: GetSetRequest, timestamp: float) -> GetSetResponse:
        index = parameters.find(request)
        if index is None:
            return parameters.NO_PARAMETER
        value = parameters.new_value(index, request)
        if value is not None and value != self._values[index]:
            self._values[index] = value
            if parameters.PARAMETERS[index].parameter is Parameter.TELEM_FREQUENCY:
                self._telemetry.restart(value, timestamp, skip_first=True)
        return parameters.response(index, self._values[index], self._defaults[index])

    def _execute_opcode(self, request: ExecuteOpcodeRequest) -> ExecuteOpcodeResponse:
        if request.opcode == Opcode.SAVE:
            return ExecuteOpcodeResponse(0, True)
        if request.opcode == Opcode.ERASE:
            self._values = list(self._defaults)
            return ExecuteOpcodeResponse(0, True)
        return ExecuteOpcodeResponse(0, False)

    # -- firmware update ----------------------------------------------------------------------

    def _start_pull(self, timestamp: float) -> None:
        assert self._firmware_source is not None
        source, path = self._firmware_source
        self._pull = _Pull(source, path)
        self._pull.handle = self._requester.request(
            FileGetInfoRequest(Path(path)),
            source,
            timestamp,
            timeout=self._file_timeout,
            retries=self._file_retries,
        )
        self._outbox += self._requester.take_frames()

    def _read_next(self, timestamp: float) -> None:
        pull = self._pull
        assert pull is not None
        stall = self._update_stall_offset
        if stall is not None and pull.received >= stall:
            self._motor = motor.release(self._motor)
            self._in_bootloader = True  # hung: silent until power_cycle
            return
        pull.handle = self._requester.request(
            FileReadRequest(pull.received, Path(pull.path)),
            pull.source,
            timestamp,
            timeout=self._file_timeout,
            retries=self._file_retries,
        )
        self._outbox += self._requester.take_frames()

    def _pulled(self, answered: Answered, timestamp: float) -> None:
        pull = self._pull
        if pull is None or answered.request.handle != pull.handle:
            return
        message = answered.transfer.message
        if isinstance(message, FileGetInfoResponse):
            if message.error.value != FileError.OK:
                self._boot(timestamp)
                return
            self._read_next(timestamp)
        elif isinstance(message, FileReadResponse):
            if message.error.value != FileError.OK:
                self._boot(timestamp)
                return
            pull.crc = crc64we(message.data, pull.crc)
            pull.received += len(message.data)
            if self._delay and len(message.data) == FileReadResponse.MAX_DATA:
                self._read_at = timestamp + self._delay  # writing the chunk
                return
            if len(message.data) < FileReadResponse.MAX_DATA:
                self._software_version = SoftwareVersion(
                    major=SOFTWARE_VERSION.major,
                    minor=SOFTWARE_VERSION.minor,
                    optional_field_flags=SoftwareVersionFlag.IMAGE_CRC,
                    vcs_commit=0,
                    image_crc=pull.crc,
                )
                self._boot(timestamp)  # the new image runs
            else:
                self._read_next(timestamp)

    def _begin_firmware_update(
        self, request: BeginFirmwareUpdateRequest, caller: int
    ) -> BeginFirmwareUpdateResponse:
        if not self._supports_firmware_update:
            return BeginFirmwareUpdateResponse(FirmwareUpdateError.INVALID_MODE)
        source = request.source_node_id or caller  # 0 means the caller (DSDL)
        wanted = (source, request.image_file_remote_path.path)
        if self._mode is Mode.SOFTWARE_UPDATE:
            again = wanted == self._firmware_source  # a retry: our answer was lost
            return BeginFirmwareUpdateResponse(
                FirmwareUpdateError.OK if again else FirmwareUpdateError.IN_PROGRESS
            )
        self._mode = Mode.SOFTWARE_UPDATE
        self._firmware_source = wanted
        self._motor = motor.release(self._motor)
        return BeginFirmwareUpdateResponse(FirmwareUpdateError.OK)

    # -- output -----------------------------------------------------------------------------

    def _status(self, timestamp: float) -> NodeStatus:
        return NodeStatus(
            uptime_sec=self._uptime(timestamp),
            health=Health.OK,
            mode=self._mode,
            sub_mode=0,
            vendor_specific_status_code=0,
        )

    def _publish(self, message: Any) -> list[TransferFrame]:
        kind = type(message)
        transfer_id = self._transfer_ids[kind]
        self._transfer_ids[kind] = (transfer_id + 1) & TRANSFER_ID_MASK
        return encode(
            message, source_node_id=self._node_id, transfer_id=transfer_id, priority=self._priority
        )

    def poll(self, timestamp: float) -> list[TransferFrame]:
        """The frames to send at ``timestamp``, in order.

        Queued service responses first, then NodeStatus if due (1 Hz), then esc.Status and
        device.Temperature if due (``telem_frequency``). A message due several times since
        the last poll is sent once and its schedule restarts at ``timestamp``: no burst of
        stale telemetry after a gap. Nothing before ``start_time``; only already queued
        responses while in the bootloader.
        """
        timestamp = check_seconds("poll", "timestamp", timestamp)
        if timestamp < self._start_time:
            return []
        self._advance(timestamp)
        if self._pull is not None and not self._in_bootloader and self._requester.poll(timestamp):
            self._boot(timestamp)  # the file server stopped answering: back to the old firmware
        if self._read_at is not None and self._read_at <= timestamp and not self._in_bootloader:
            self._read_at = None
            self._read_next(timestamp)
        if self._allocatee is not None:
            return self._allocatee.poll(timestamp)
        while self._later and self._later[0][0] <= timestamp:
            self._outbox += self._later.pop(0)[1]
        self._outbox += self._requester.take_frames()
        frames = self._outbox
        self._outbox = []
        if self._in_bootloader:
            return frames
        if self._node_status.due(timestamp):
            frames += self._publish(self._status(timestamp))
        if self._telemetry.due(timestamp):
            m = self._motor
            index = self._value(Parameter.ESC_INDEX)
            frames += self._publish(
                EscStatus(
                    error_count=0,
                    voltage=m.voltage,
                    current=m.current,
                    temperature=m.coil_temperature,
                    rpm=round(m.rpm),
                    power_rating_pct=m.power_rating_pct,
                    esc_index=index,
                )
            )
            overheating = m.mcu_temperature >= self._model.mcu_overheat_temperature
            frames += self._publish(
                Temperature(
                    device_id=index,
                    temperature=m.mcu_temperature,
                    error_flags=TemperatureErrorFlag.OVERHEATING if overheating else 0,
                )
            )
        return frames

    def next_time(self) -> float | None:
        """When `poll` next has something to send, or None if never without new input.

        For adapters that wait on the bus: block for at most until this time.
        """
        if self._allocatee is not None:
            return self._allocatee.next_time()
        if self._outbox:
            return self._now
        if self._in_bootloader:
            return self._later[0][0] if self._later else None
        times = [
            t
            for t in (
                self._later[0][0] if self._later else None,
                self._read_at,
                self._node_status.next_time,
                self._telemetry.next_time,
                self._requester.next_deadline(),
            )
            if t is not None
        ]
        return max(min(times), self._start_time) if times else None


_INDEX = {r.parameter: i for i, r in enumerate(parameters.PARAMETERS)}
