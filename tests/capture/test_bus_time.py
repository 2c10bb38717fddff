"""`veronte4x.capture.bus_time`: frames stamped as one classic CAN bus carries them."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from veronte4x.capture.bus_time import PendingFrame, transmit
from veronte4x.capture.rates import frame_bits


def test_the_lowest_id_goes_first_and_a_base_frame_beats_an_extended_one() -> None:
    base = PendingFrame(0.0, 0x100, False, 8, "a")  # base ID 0x100
    extended = PendingFrame(0.0, 0x100 << 18, True, 8, "b")  # the same 11 base bits
    low = PendingFrame(0.0, 0x0FF, False, 0, "c")
    ends = transmit([base, extended, low], bitrate=1_000_000)
    first = frame_bits(0, False) / 1e6
    assert ends[2] == first
    assert ends[0] == first + frame_bits(8, False) / 1e6
    assert ends[1] == ends[0] + frame_bits(8, True) / 1e6


def test_an_idle_bus_sends_a_frame_when_it_is_ready() -> None:
    ends = transmit([PendingFrame(1.0, 0x10, False, 2, "a"), PendingFrame(5.0, 0x1, False, 2, "b")])
    assert ends == [1.0 + frame_bits(2, False) / 1e6, 5.0 + frame_bits(2, False) / 1e6]


def test_a_sender_keeps_its_order_even_when_a_later_frame_has_a_lower_id() -> None:
    ends = transmit(
        [PendingFrame(0.0, 0x200, False, 8, "a"), PendingFrame(0.0, 0x001, False, 8, "a")]
    )
    assert ends[0] < ends[1]


frames = st.lists(
    st.builds(
        PendingFrame,
        st.floats(0.0, 0.01),
        st.integers(0, 0x7FF),
        st.just(False),
        st.integers(0, 8),
        st.sampled_from("abcd"),
    ),
    max_size=40,
)


@given(frames, st.sampled_from([125_000, 1_000_000]))
def test_frames_never_overlap_nor_start_before_they_are_ready(
    pending: list[PendingFrame], bitrate: int
) -> None:
    ends = transmit(pending, bitrate)
    order = sorted(range(len(pending)), key=ends.__getitem__)
    previous_end = 0.0
    for i in order:
        start = ends[i] - frame_bits(pending[i].data_bytes, pending[i].extended) / bitrate
        assert start >= pending[i].ready - 1e-12
        assert start >= previous_end - 1e-12
        previous_end = ends[i]
    for sender in "abcd":
        mine = [ends[i] for i, f in enumerate(pending) if f.sender == sender]
        assert mine == sorted(mine)
