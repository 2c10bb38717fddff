"""Behaviours the mutation run found unchecked (`make mutation`, docs/mutation.md): each
test here fails on the mutant named beside it."""

from __future__ import annotations

from typing import Any

import pytest

from veronte4x import dronecan
from veronte4x.errors import EncodeError
from veronte4x.node.requests import Requester
from veronte4x.times import EPOCH_THRESHOLD, format_time


def test_a_request_of_a_message_that_is_no_request_is_refused() -> None:
    """``node/requests.py`` (the refusal made ``pass``): nothing is queued or sent."""
    requester = Requester(node_id=127)
    status = dronecan.NodeStatus(1, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
    for message in (status, dronecan.GetNodeInfoResponse.__name__):
        with pytest.raises(EncodeError) as refused:
            requester.request(message, 21, now=0.0)
        assert str(refused.value) == (
            f"request.message = {message!r}: expected a DroneCAN service request"
        )
    assert requester.take_frames() == []


def test_the_epoch_threshold_is_read_as_unix_time() -> None:
    """``times.py`` (``<`` made ``<=``): at the threshold a time is Unix time, below it a
    capture's own seconds."""
    assert format_time(EPOCH_THRESHOLD) == "1973-03-03T09:46:40.000000Z"
    assert format_time(EPOCH_THRESHOLD - 1e-6) == "99999999.999999"


def test_a_classic_frame_of_nine_bytes_is_no_dronecan_frame() -> None:
    """``canbus.py::is_dronecan_frame`` (``dlc <= 8`` made ``<= 9``)."""
    can = pytest.importorskip("can")
    from veronte4x.canbus import is_dronecan_frame

    def frame(size: int) -> Any:
        return can.Message(
            arbitration_id=0x1001, is_extended_id=True, data=bytes(size), check=False
        )

    assert [is_dronecan_frame(frame(size)) for size in (0, 1, 8, 9)] == [False, True, True, False]


def test_a_replay_keeps_two_different_disagreements_of_a_field_apart() -> None:
    """``arbiter/replay.py`` (a run closed on ``same or`` a new pair, made ``and``): a
    disagreement followed at once by another one of the same field is two runs, and
    frames that repeat a disagreement extend its run."""
    from veronte4x.arbiter.replay import Disagreement, _Comparer

    compare = _Comparer(tolerance=0.0)
    compare.check(1.0, "selected", 1, 0)
    compare.check(2.0, "selected", 1, 0)
    compare.check(3.0, "selected", 2, 0)
    compare.check(4.0, "selected", 0, 0)
    compare.check(5.0, "selected", 3, 0)
    assert compare.finish() == (
        Disagreement(1.0, 2.0, "selected", 1, 0, 2),
        Disagreement(3.0, 3.0, "selected", 2, 0, 1),
        Disagreement(5.0, 5.0, "selected", 3, 0, 1),
    )


def test_a_bar_of_bytes_counts_in_kilobytes_and_megabytes(capsys: Any) -> None:
    """``progress.py`` (``unit_scale=unit == "B"`` made ``unit == None``): a bar of bytes
    reads ``2.10M/4.00M``, a bar of frames counts them one by one."""
    pytest.importorskip("tqdm")
    from veronte4x.progress import Bar

    for unit, amount, shown in (
        ("B", 2_100_000, " 2.10M/4.00M "),
        ("frames", 2_100, " 2100/4000000 "),
    ):
        bar = Bar(True, 4_000_000, unit, "decoding")
        bar.update(amount)
        bar._bar.refresh()
        assert shown in capsys.readouterr().err
        bar.close()


def test_seconds_past_two_to_the_53_microseconds_stay_exact(tmp_path: Any) -> None:
    """``capture/dataframe.py`` (the exact path from ``1 << 53`` microseconds made
    ``1 << 54``): a time in the year 2255 keeps its last microsecond in a DataFrame of
    seconds (a float64 division of the microseconds would give ...740992)."""
    pytest.importorskip("pandas")
    from veronte4x import capture

    log = tmp_path / "late.log"
    log.write_text("(9007199254.740993) can0 123#0011\n")
    frame = capture.to_dataframe(capture.read(log), time="seconds")
    assert repr(float(frame["timestamp"][0])) == "9007199254.740993"


def test_the_reserved_commands_have_no_layout_and_are_refused() -> None:
    """``codec/layouts.py`` (``RESERVED_COMMANDS`` {4, 14, 15} made {4, 13, 15}): the
    commands the Software Manual's message-type table reserves are those without a layout,
    and a frame of one is refused as reserved or unknown from either sender."""
    from veronte4x import codec
    from veronte4x.codec.layouts import RESERVED_COMMANDS

    veronte = codec.Codec()
    for command in sorted(RESERVED_COMMANDS):
        data = bytes([command, 0, 0, 0])
        for sender in codec.Sender:
            with pytest.raises(codec.UnknownCommandError) as refused:
                veronte.decode(data, sender=sender)
            assert f"command byte {command} is reserved or unknown" in str(refused.value)


@pytest.mark.parametrize("timeout", [float("nan"), float("inf"), 0.0, -1.0])
def test_a_request_timeout_must_be_finite_and_above_zero(timeout: float) -> None:
    """A NaN timeout timed a request out at once ("nan s each"), an infinite one never:
    both are refused before anything is queued."""
    requester = Requester(node_id=127)
    with pytest.raises(EncodeError) as refused:
        requester.request(dronecan.GetNodeInfoRequest(), 21, now=0.0, timeout=timeout)
    assert str(refused.value) == (
        f"request.timeout = {timeout!r}: expected a finite number of seconds above 0"
    )
    assert requester.take_frames() == []
