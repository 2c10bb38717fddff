"""Status frames: every bit of the 6-byte 4x form and of the 4-byte CEX form, one by one."""

import dataclasses
from typing import Any

import pytest

from veronte4x import codec
from veronte4x.codec.layouts import STATUS_FLAGS

FLAG_NAMES = [name for name, _ in STATUS_FLAGS]
ALL_CLEAR = codec.Status(
    selected=0,
    arbitrating=False,
    alive=(False,) * 4,
    ready=(False,) * 4,
    **dict.fromkeys(FLAG_NAMES, False),
)
CEX_CLEAR = codec.Status(selected=0, arbitrating=False, alive=(False,) * 4, ready=(False,) * 4)


def _frame(*body: int) -> bytes:
    return bytes([0x00, 0xFF, *body])


def _roundtrip(data: bytes, message: codec.Status) -> None:
    assert codec.decode(data, sender=codec.Sender.ARBITER) == message
    assert codec.encode(message) == data


def test_flag_order_matches_the_seed_table() -> None:
    assert FLAG_NAMES == [
        "cbit_ok", "pbit_ok", "pdi_ok", "memory_ok",
        "can_a_ok", "can_b_ok", "cio_low_ok", "cio_high_ok",
        "power_ok", "bus_a_voltage_ok", "bus_b_voltage_ok", "arbiter_voltage_ok",
        "ap1_voltage_ok", "ap2_voltage_ok", "ap3_voltage_ok", "normal_mode",
    ]  # fmt: skip


@pytest.mark.parametrize("position", range(16))
def test_each_byte_4_5_flag(position: int) -> None:
    body = [0, 0, 0, 0]
    body[2 + position // 8] = 1 << (position % 8)
    changes: dict[str, Any] = {FLAG_NAMES[position]: True}
    expected = dataclasses.replace(ALL_CLEAR, **changes)
    _roundtrip(_frame(*body), expected)


@pytest.mark.parametrize("selected", range(4))
@pytest.mark.parametrize("form", ["4x", "cex"])
def test_selected(selected: int, form: str) -> None:
    base = ALL_CLEAR if form == "4x" else CEX_CLEAR
    tail = [0, 0] if form == "4x" else []
    _roundtrip(_frame(selected, 0, *tail), dataclasses.replace(base, selected=selected))


@pytest.mark.parametrize("form", ["4x", "cex"])
def test_arbitrating_is_bit_7_of_byte_2(form: str) -> None:
    base = ALL_CLEAR if form == "4x" else CEX_CLEAR
    tail = [0, 0] if form == "4x" else []
    _roundtrip(_frame(0x83, 0, *tail), dataclasses.replace(base, selected=3, arbitrating=True))


@pytest.mark.parametrize("bit", range(8))
@pytest.mark.parametrize("form", ["4x", "cex"])
def test_alive_and_ready_bits(bit: int, form: str) -> None:
    base = ALL_CLEAR if form == "4x" else CEX_CLEAR
    tail = [0, 0] if form == "4x" else []
    flags = tuple(i == bit % 4 for i in range(4))
    field = "alive" if bit < 4 else "ready"
    changes: dict[str, Any] = {field: flags}
    _roundtrip(_frame(0, 1 << bit, *tail), dataclasses.replace(base, **changes))


def test_cex_form_has_no_flags() -> None:
    msg = codec.decode(_frame(0x81, 0x33), sender=codec.Sender.ARBITER)
    assert isinstance(msg, codec.Status)
    assert all(getattr(msg, name) is None for name in FLAG_NAMES)
    assert msg.alive == (True, True, False, False)
    assert msg.ready == (True, True, False, False)


def test_mixed_none_and_bool_flags_do_not_encode() -> None:
    half = dataclasses.replace(CEX_CLEAR, pdi_ok=True)
    with pytest.raises(codec.EncodeError) as err:
        codec.encode(half)
    assert str(err.value) == (
        "Status.pdi_ok = True: expected None like cbit_ok (the 4-byte CEX form), "
        "or set every flag (the 6-byte 4x form)"
    )
    with pytest.raises(codec.EncodeError) as err:
        codec.encode(dataclasses.replace(ALL_CLEAR, power_ok=None))
    assert str(err.value) == "Status.power_ok = None: expected a bool"


def test_selected_above_3_is_a_decode_error() -> None:
    with pytest.raises(codec.DecodeError) as err:
        codec.decode(_frame(0x04, 0), sender=codec.Sender.ARBITER)
    assert err.value.field == "selected"
    assert str(err.value) == "Status.selected: 4 out of range 0..3 (data: 00 ff 04 00)"
