"""Generated captures for the columnar differential tests, and a table comparison."""

from __future__ import annotations

import contextlib
import functools
import io
import math
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from hypothesis import strategies as st

from veronte4x import capture, codec, dronecan
from veronte4x.capture import BusMap
from veronte4x.capture.busmap import TEXT_FORMS
from veronte4x.capture.columnar import engine
from veronte4x.codec import Linear
from veronte4x.dronecan.codec import BY_CLASS, CODECS, TypeCodec
from veronte4x.dronecan.compiled import can_id_base
from veronte4x.dronecan.crc import crc16
from veronte4x.dronecan.schema import Array, Scalar, Struct, Union
from veronte4x.dronecan.tail import SINGLE_FRAME_MAX, split_payload
from veronte4x.dronecan.typeset import TypeSet

DECLARED = codec.Layout(
    5,
    "ScorpionTelemetry",
    [
        codec.unsigned("throttle", 8, scale=Linear(0, 200, 0.0, 100.0)),
        codec.skip(4),
        codec.signed("current", 8),
        codec.constant(0xA, 4),
        codec.float32("voltage"),
    ],
    codec.ByteOrder.LITTLE,
)
"""A declared layout with every field kind, for command 5."""

VENDOR_DSDL = (
    Path(__file__).resolve().parents[2] / "examples" / "dsdl" / "com",
    Path(__file__).resolve().parent / "data" / "dsdl" / "acme",
)
"""Vendor namespaces: the docs' ``com.example``, and ``acme``, whose fields are named as
head columns (``channel``, ``timestamp``, ``can_id``, ``node_id``, ``sender``,
``destination_node_id``, ``error``, ``detail``, ``data``)."""
VENDOR_TYPES = TypeSet.standard().with_dsdl(*VENDOR_DSDL)

_NODE_STATUS_OF_20 = 16 << 24 | 341 << 8 | 20
"""The 29-bit id of a NodeStatus from node 20: a Veronte id may take a DroneCAN one."""


@st.composite
def drawn_bus_maps(draw: st.DrawFn) -> BusMap:
    """A bus map with any five Veronte ids of either width (29-bit ones among the DroneCAN
    ids too, where the bus map wins), with or without DroneCAN and declared layouts, DroneCAN
    text as strings or bytes."""
    extended = draw(st.booleans())
    top = 2**29 - 1 if extended else 0x7FF
    some = st.integers(0, top) | st.sampled_from([0, top])
    if extended:
        some |= st.just(_NODE_STATUS_OF_20)
    ids = draw(st.lists(some, min_size=5, max_size=5, unique=True))
    return BusMap(
        arbiter_id=ids[0],
        autopilot_ids=(ids[1], ids[2], ids[3], ids[4]),
        extended=extended,
        pwm_packing=draw(st.sampled_from(codec.PwmPacking)),
        allow_excess=draw(st.booleans()),
        layouts=draw(st.sampled_from([(), (DECLARED,)])),
        dronecan=draw(st.booleans()),
        dronecan_text=draw(st.sampled_from(TEXT_FORMS)),
    )


BUS_MAPS = (
    st.sampled_from(
        [
            BusMap(),
            BusMap(pwm_packing=codec.PwmPacking.MSB_FIRST),
            BusMap(layouts=(DECLARED,), allow_excess=True),
            BusMap(arbiter_id=0x100, autopilot_ids=(0x101, 0x102, 0x103, 0x104), extended=True),
            BusMap(dronecan_text="binary"),
        ]
    )
    | drawn_bus_maps()
)
"""Five fixed bus maps, and drawn ones."""
VENDOR_BUS_MAPS = BUS_MAPS.map(lambda bus_map: bus_map.with_types(VENDOR_TYPES))
"""The bus maps with the vendor type set."""


def texts(max_size: int) -> st.SearchStrategy[bytes]:
    """The bytes of a text field: empty, UTF-8 (multi-byte characters too), UTF-8 cut
    inside a character, or any bytes (mostly not UTF-8)."""
    characters = st.characters(exclude_categories=["Cs"])  # no lone surrogate: not UTF-8
    utf8 = st.text(characters, max_size=max_size).map(lambda text: text.encode()[:max_size])
    wide = st.characters(min_codepoint=0x80, exclude_categories=["Cs"])
    cut = st.text(wide, min_size=1, max_size=max_size).map(
        lambda text: text.encode()[: min(max_size, len(text.encode()) - 1)]
    )
    return st.one_of(st.just(b""), utf8, cut, st.binary(max_size=max_size))


float32s = st.floats(width=32, allow_nan=True)
int14 = st.integers(-8192, 8191)
nodes = st.sampled_from([20, 21, 22]) | st.sampled_from([1, 127]) | st.integers(1, 127)
"""Node ids: a few that repeat (sessions with several transfers), the bounds, any."""
DRONECAN_MESSAGES = st.one_of(
    st.builds(
        dronecan.NodeStatus,
        uptime_sec=st.integers(0, 2**32 - 1),
        health=st.sampled_from(list(dronecan.Health)),
        mode=st.integers(0, 7),
        sub_mode=st.integers(0, 7),
        vendor_specific_status_code=st.integers(0, 65535),
    ),
    st.builds(
        dronecan.EscStatus,
        error_count=st.integers(0, 2**32 - 1),
        voltage=st.floats(-65504, 65504, width=16),
        current=st.floats(width=16),
        temperature=st.floats(0, 400, width=16),
        rpm=st.integers(-(2**17), 2**17 - 1),
        power_rating_pct=st.integers(0, 127),
        esc_index=st.integers(0, 31),
    ),
    st.builds(
        dronecan.Temperature,
        device_id=st.integers(0, 65535),
        temperature=st.floats(0, 400, width=16),
        error_flags=st.integers(0, 255),
    ),
    st.builds(dronecan.RawCommand, cmd=st.lists(int14, max_size=20).map(tuple)),
    st.builds(dronecan.KeyValue, value=float32s, key=texts(58)),  # text in one to 9 frames
)
SERVICES = st.one_of(
    st.builds(dronecan.GetNodeInfoRequest),
    st.builds(
        dronecan.GetSetRequest,
        index=st.integers(0, 8191),
        value=st.one_of(
            st.builds(dronecan.Empty),
            st.builds(dronecan.IntegerValue, value=st.integers(-(2**63), 2**63 - 1)),
            st.builds(dronecan.RealValue, value=st.floats(width=32, allow_nan=False)),
            st.builds(dronecan.StringValue, value=texts(20)),
        ),
        name=texts(12),
    ),
    st.builds(dronecan.RestartNodeRequest, magic_number=st.integers(0, 2**40 - 1)),
)


@functools.cache
def schema_values(t: Struct | Union | Array | Scalar) -> st.SearchStrategy[Any]:
    """Plain data (as `veronte4x.dronecan.from_builtin` takes it) of any DSDL type: arrays
    empty, full or between, every union member, integers at their ends. Made once a type
    (a strategy is drawn from again and again; building it each time cost more than the
    tests that draw it)."""
    if isinstance(t, Struct):
        return st.fixed_dictionaries({f.name: schema_values(f.type) for f in t.fields if f.name})
    if isinstance(t, Union):
        return st.one_of([schema_values(m.type).map(_named(m.name)) for m in t.members])
    if isinstance(t, Array):
        items = schema_values(t.item)
        if not t.dynamic:
            return st.lists(items, min_size=t.max_size, max_size=t.max_size)
        some = st.one_of(
            st.just([]),
            st.lists(items, min_size=t.max_size, max_size=t.max_size),
            st.lists(items, max_size=min(t.max_size, 8)),
        )
        return some | texts(t.max_size).map(list) if t.is_bytes else some
    if t.kind == "float":
        return st.floats(width=32) if t.bits < 64 else st.floats()
    if t.kind == "bool":
        return st.booleans()
    return st.one_of(st.sampled_from((t.low, t.high)), st.integers(t.low, t.high))


def _named(name: str) -> Any:
    return lambda value: {name: value}


@st.composite
def any_payload(draw: st.DrawFn, types: TypeSet | None = None) -> tuple[TypeCodec, bytes]:
    """A type of ``types`` (None: the standard set; a vendor type one time in two where
    the set has any) and a payload for it: a value's encoding (saturated), that cut short
    or lengthened, or any bytes."""
    codecs = CODECS if types is None else types.codecs
    vendor = codecs[len(CODECS) :]
    pick_vendor: bool = bool(vendor) and draw(st.booleans())
    found = draw(st.sampled_from(vendor if pick_vendor else CODECS))
    data = draw(schema_values(found.data_type.schema))
    message: Any = dronecan.from_builtin(found.data_type.schema.cls, data, types)
    payload = found.encode(message, True)
    change = draw(st.integers(0, 5))
    if change == 0:
        payload = draw(st.binary(max_size=min(found.max_payload + 2, 300)))
    elif change == 1 and payload:
        payload = payload[: draw(st.integers(0, len(payload) - 1))]
    elif change == 2:
        payload += draw(st.binary(min_size=1, max_size=3))
    return found, payload


def transfer_frames(
    found: TypeCodec, payload: bytes, source: int, destination: int | None, transfer_id: int
) -> list[tuple[int, bytes, bool]]:
    """The frames of one transfer of any payload, cut as the encoder cuts them."""
    can_id = 16 << 24 | can_id_base(found.data_type) | source
    if destination is not None:
        can_id |= destination << 8
    if len(payload) <= SINGLE_FRAME_MAX:
        return [(can_id, payload + bytes((0xC0 | transfer_id,)), True)]
    crc = crc16(payload, found.crc_seed)
    return [(can_id, data, True) for data in split_payload(payload, crc, transfer_id)]


ODD_CHANNELS = ("can1\x00", "can1\x7f", "can1\x0b", "can1\x1f", "cän1")
"""Interface names with bytes the column parser leaves to the per-line parser (a control
character, DEL, white space to ``str.split``, non-ASCII), one character longer than can1."""
LINE_ENDINGS = st.sampled_from(["\n", "\r\n"])


@functools.cache
def veronte_payloads(sender: codec.Sender) -> st.SearchStrategy[bytes]:
    """Valid frames of every type the sender sends, and arbitrary bytes. Made once a sender:
    its MSB-first codec, compiled on each call, cost more than the tests that draw it."""
    from tests.codec.strategies import MESSAGES

    arbiter_only = {"Status", "Score"}
    autopilot_only = {"Ready", "ArbitrationVariable"}
    skip = autopilot_only if sender is codec.Sender.ARBITER else arbiter_only
    kinds = [s for name, s in MESSAGES.items() if name not in skip]
    pwm = st.builds(
        codec.PwmSet,
        first_channel=st.sampled_from([0, 4, 8, 12, 16]),
        values=st.tuples(*[st.integers(0, 4095)] * 4),
    )
    valid = st.one_of(*kinds).map(codec.encode)
    msb = pwm.map(codec.Codec(pwm_packing=codec.PwmPacking.MSB_FIRST).encode)
    declared = st.builds(
        lambda t, c, v: DECLARED.encode(DECLARED.message_class(t * 0.5, c, v)),
        st.integers(0, 200),
        st.integers(-128, 127),
        float32s,
    )
    return st.one_of(valid, msb, declared, st.binary(max_size=9), valid.map(lambda b: b + b"\0"))


@st.composite
def captures(draw: st.DrawFn, bus_map: BusMap) -> list[str]:
    """candump lines: Veronte frames of both senders, DroneCAN transfers with faults (from
    any node id, anonymous, to node 0), unknown IDs, error and remote frames, bad lines;
    log and human forms, 11-bit and 29-bit ids in both."""
    frames: list[tuple[int, bytes, bool] | str] = []
    tids: dict[tuple[int, int], int] = {}
    for _ in range(draw(st.integers(0, 40))):
        what = draw(st.integers(0, 9))
        if what <= 2:
            index = draw(st.integers(0, 4))
            ids = (bus_map.arbiter_id, *bus_map.autopilot_ids)
            sender = codec.Sender.ARBITER if index == 0 else codec.Sender.AUTOPILOT
            frames.append((ids[index], draw(veronte_payloads(sender)), bus_map.extended))
        elif what <= 6:
            source = draw(nodes)
            if draw(st.booleans()):  # any standard type, any payload
                found, payload = draw(any_payload(bus_map.dronecan_types))
                service = found.data_type.kind is not dronecan.TransferKind.MESSAGE
                key = (source, found.data_type.kind.value << 16 | found.data_type.data_type_id)
            else:
                service = draw(st.integers(0, 4)) == 0
                message = draw(SERVICES if service else DRONECAN_MESSAGES)
                found, payload = BY_CLASS[type(message)], None
                key = (source, hash(type(message)))
            tid = tids.get(key, draw(st.integers(0, 31)))
            # The next transfer id, or the same (a stuck node), one more, or one less.
            tid = (tid + draw(st.sampled_from([0, 1, 1, 1, 1, 2, 31]))) % 32
            tids[key] = tid
            destination = draw(nodes) if service else None
            if payload is None:
                made = dronecan.encode(
                    message, source_node_id=source, transfer_id=tid, destination_node_id=destination
                )
                transfer = [(f.can_id, f.data, True) for f in made]
            else:
                transfer = transfer_frames(found, payload, source, destination, tid)
            address = draw(st.integers(0, 7))
            if address == 0:  # anonymous (source 0), or a service to node 0: refused
                mask = 0x7F00 if service and draw(st.booleans()) else 0x7F
                transfer = [(can_id & ~mask, data, ext) for can_id, data, ext in transfer]
            fault = draw(st.integers(0, 9))
            if fault == 1 and transfer:
                del transfer[draw(st.integers(0, len(transfer) - 1))]
            elif fault == 2 and transfer:
                at = draw(st.integers(0, len(transfer) - 1))
                transfer.insert(at, transfer[at])
            elif fault == 3 and len(transfer) > 1:
                transfer[0], transfer[1] = transfer[1], transfer[0]
            elif fault == 4 and transfer:
                at = draw(st.integers(0, len(transfer) - 1))
                can_id, data, ext = transfer[at]
                flipped = bytearray(data)
                flipped[draw(st.integers(0, len(data) - 1))] ^= 1 << draw(st.integers(0, 7))
                transfer[at] = (can_id, bytes(flipped), ext)
            elif fault == 5 and transfer:  # the toggle bit of one frame flipped
                at = draw(st.integers(0, len(transfer) - 1))
                can_id, data, ext = transfer[at]
                transfer[at] = (can_id, data[:-1] + bytes((data[-1] ^ 0x20,)), ext)
            elif fault == 6 and transfer:  # one frame cut short
                at = draw(st.integers(0, len(transfer) - 1))
                can_id, data, ext = transfer[at]
                transfer[at] = (can_id, data[: draw(st.integers(0, len(data) - 1))], ext)
            frames += transfer
        elif what == 7:
            frames.append((draw(st.integers(0, 0x7FF)), draw(st.binary(max_size=8)), False))
        elif what == 8:
            frames.append((draw(st.integers(0, 2**29 - 1)), draw(st.binary(max_size=8)), True))
        else:
            frames.append(
                draw(
                    st.sampled_from(
                        [
                            "(1.0) can0 20000080#0000000000000000",
                            "(1.0) can0 123#R",
                            "(1.0) can0 123##1DEADBEEF",
                            "not a frame",
                            "",
                            "(1.0) can0 123#1122_E",
                        ]
                    )
                )
            )
    lines = []
    stamp = 1_700_000_000.0
    human = draw(st.sampled_from([0.0, 0.2]))
    for item in frames:
        # 1.5 s: past libcanard's interface switch delay (1 s), within the timeout (2 s).
        stamp += draw(st.sampled_from([0.0, 0.001, 0.01, 0.5, 1.5, 3.0]))
        if isinstance(item, str):
            lines.append(item)
            continue
        can_id, data, extended = item
        ident = f"{can_id:08X}" if extended else f"{can_id:03X}"
        channel = draw(st.sampled_from(["can0", "can0", "can1", *ODD_CHANNELS]))
        if draw(st.floats(0, 1)) < human:
            lines.append(f"({stamp:.6f})  {channel}  {ident}   [{len(data)}]  {data.hex(' ')}")
        else:
            lines.append(f"({stamp:.6f}) {channel} {ident}#{data.hex().upper()}")
    return lines


def write(path: Path, lines: list[str], ending: str = "\n") -> Path:
    path.write_bytes("".join(line + ending for line in lines).encode())
    return path


@contextlib.contextmanager
def piped(path: Path) -> Iterator[None]:
    """Standard input holding the bytes of ``path`` (peekable, as a pipe is), for ``-``."""
    stdin = sys.stdin
    sys.stdin = io.TextIOWrapper(io.BufferedReader(io.BytesIO(path.read_bytes())))
    try:
        yield
    finally:
        sys.stdin = stdin


def read_piped(path: Path, *args: Any, **kwargs: Any) -> dict[str, Any]:
    """`capture.read_tables` of ``path`` given on standard input."""
    with piped(path):
        tables: dict[str, Any] = capture.read_tables("-", *args, **kwargs)
    return tables


def rows(table: Any) -> list[dict[str, Any]]:
    """A table's rows with NaN made comparable."""
    return [{k: _plain(v) for k, v in row.items()} for row in table.to_pylist()]


def _plain(value: Any) -> Any:
    """NaN as a string, also inside list and struct values (a NaN is not equal to another)."""
    if isinstance(value, float) and math.isnan(value):
        return "NaN"
    if isinstance(value, list):
        return [_plain(item) for item in value]
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    return value


def assert_same_tables(got: dict[str, Any], expected: dict[str, Any]) -> None:
    """Same kinds, schemas and rows, value for value (NaN equal to NaN)."""
    assert sorted(got) == sorted(expected)
    for kind, table in expected.items():
        assert got[kind].schema == table.schema, kind
        assert rows(got[kind]) == rows(table), kind


def _session_messages() -> list[tuple[Any, bool]]:
    """One message of each kind the session generator uses, and whether it is a service."""
    return [
        (dronecan.GetNodeInfoRequest(), True),
        (dronecan.RestartNodeRequest(magic_number=0xACCE551B1E), True),
        (dronecan.RestartNodeResponse(ok=True), True),
        (dronecan.ExecuteOpcodeRequest(opcode=0, argument=7), True),
        (dronecan.ExecuteOpcodeResponse(argument=-3, ok=False), True),
        (dronecan.GetSetRequest(index=3, name=b"a parameter"), True),  # three frames
        (dronecan.GetSetResponse(name=b"esc"), True),
        (
            dronecan.NodeStatus(
                uptime_sec=5,
                health=dronecan.Health.OK,
                mode=0,
                sub_mode=0,
                vendor_specific_status_code=0,
            ),
            False,
        ),
    ]


def many_sessions(
    count: int, concurrent: bool, faults: float = 0.0, transfers: int = 2, seed: int = 0
) -> list[str]:
    """candump lines of ``count`` distinct DroneCAN sessions on one bus (up to 114,427:
    services between any two nodes, messages from any node), ``transfers`` each.

    Args:
        concurrent: Sessions take turns, transfer by transfer, all open through the
            capture; else each sends its transfers and falls silent before the next begins.
        faults: Share of transfers with a fault: a frame dropped, doubled or bit-flipped.
        seed: Of the random choices (which sessions, which faults).
    """
    import random

    chooser = random.Random(seed)
    kinds = _session_messages()
    keys = [
        (kind, source, target)
        for kind, (_, service) in enumerate(kinds)
        for source in range(1, 128)
        for target in (range(1, 128) if service else (None,))
    ]
    # ExecuteOpcode only where the others do not suffice: the 256 names of its uint8 opcode
    # dictionary are more than pyarrow's unify_dictionaries joins (tables of batches).
    plain = [key for key in keys if not kinds[key[0]][0].__class__.__name__.startswith("Exec")]
    picked = chooser.sample(plain if count <= len(plain) else keys, count)
    tids = [chooser.randrange(32) for _ in picked]
    turns = [
        (session, turn)
        for turn, session in (
            ((t, s) for t in range(transfers) for s in range(count))
            if concurrent
            else ((t, s) for s in range(count) for t in range(transfers))
        )
    ]
    lines = []
    stamp = 1_700_000_000.0
    step = 1e-4 if concurrent else 1e-3
    for session, turn in turns:
        kind, source, target = picked[session]
        message, _ = kinds[kind]
        frames = [
            (f.can_id, f.data)
            for f in dronecan.encode(
                message,
                source_node_id=source,
                transfer_id=(tids[session] + turn) % 32,
                destination_node_id=target,
            )
        ]
        if faults and chooser.random() < faults:
            at = chooser.randrange(len(frames))
            fault = chooser.randrange(3)
            if fault == 0:
                del frames[at]
            elif fault == 1:
                frames.insert(at, frames[at])
            else:
                can_id, data = frames[at]
                flipped = bytearray(data)
                flipped[chooser.randrange(len(data))] ^= 1 << chooser.randrange(8)
                frames[at] = (can_id, bytes(flipped))
        for can_id, data in frames:
            stamp += step
            lines.append(f"({stamp:.6f}) can0 {can_id:08X}#{data.hex().upper()}")
    return lines


def frames_left_to_per_frame(monkeypatch: pytest.MonkeyPatch) -> list[int]:
    """The number of frames of each call to the per-frame fallback from now on (an empty
    list, or zeros, when every frame was decoded column-wise)."""
    taken: list[int] = []
    original = engine.per_frame

    def per_frame(frames: Any, rows: Any, decoder: Any) -> Any:
        taken.append(len(rows))
        return original(frames, rows, decoder)

    monkeypatch.setattr(engine, "per_frame", per_frame)
    return taken
