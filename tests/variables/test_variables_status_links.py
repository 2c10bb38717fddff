"""Status flags link only to bit variables that exist, and only under Status field names."""

from __future__ import annotations

from veronte4x.variables import STATUS_FLAG_BITS, STATUS_STATE_BITS, Kind, by_id

# The sixteen flags of Status bytes 4-5, in wire order (seed 000 section 3.1.1), as the codec
# names them. Hard-coded here: the codec is written in parallel and is not imported.
STATUS_FLAGS = (
    "cbit_ok",
    "pbit_ok",
    "pdi_ok",
    "memory_ok",
    "can_a_ok",
    "can_b_ok",
    "cio_low_ok",
    "cio_high_ok",
    "power_ok",
    "bus_a_voltage_ok",
    "bus_b_voltage_ok",
    "arbiter_voltage_ok",
    "ap1_voltage_ok",
    "ap2_voltage_ok",
    "ap3_voltage_ok",
    "normal_mode",
)


def test_flag_names_are_status_flags() -> None:
    assert set(STATUS_FLAG_BITS) <= set(STATUS_FLAGS)
    assert list(STATUS_FLAG_BITS) == [f for f in STATUS_FLAGS if f in STATUS_FLAG_BITS]


def test_state_names_are_status_fields() -> None:
    assert list(STATUS_STATE_BITS) == ["alive", "ready", "arbitrating"]


def test_links_name_existing_bits_only() -> None:
    for bits in (*STATUS_FLAG_BITS.values(), *STATUS_STATE_BITS.values()):
        assert bits
        assert len(bits) == len(set(bits))
        for number in bits:
            var = by_id(Kind.BIT, number)
            assert var is not None
            assert var.first == var.last == number


def test_exact_links() -> None:
    assert dict(STATUS_FLAG_BITS) == {
        "cbit_ok": (7, 20),
        "pbit_ok": (12, 21),
        "pdi_ok": (9, 22),
        "memory_ok": (8, 23),
        "can_a_ok": (73, 24),
        "can_b_ok": (74, 25),
        "cio_low_ok": (400,),
        "cio_high_ok": (402, 27),
        "power_ok": (28,),
        "bus_a_voltage_ok": (125,),
        "bus_b_voltage_ok": (126,),
        "arbiter_voltage_ok": (124,),
        "ap1_voltage_ok": (127,),
        "ap2_voltage_ok": (128,),
        "ap3_voltage_ok": (129,),
        "normal_mode": (29,),
    }
    assert dict(STATUS_STATE_BITS) == {
        "alive": (30, 31, 32, 33),
        "ready": (34, 35, 36, 37),
        "arbitrating": (38,),
    }


def test_every_1x_copy_20_to_29_is_linked() -> None:
    linked = {n for bits in STATUS_FLAG_BITS.values() for n in bits}
    unlinked = [n for n in range(20, 30) if n not in linked]
    # 26 "4XV C1 arbiter" (main task of CP1): the manual ties it to no Status flag.
    assert unlinked == [26]
    for number in range(20, 30):
        var = by_id(Kind.BIT, number)
        assert var is not None and var.stored_in_1x


def test_links_are_read_only() -> None:
    assert not hasattr(STATUS_FLAG_BITS, "__setitem__")
    assert not hasattr(STATUS_STATE_BITS, "__setitem__")
