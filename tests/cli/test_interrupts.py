"""Ctrl-C is held while a record is handled whole, and raised at once anywhere else."""

from __future__ import annotations

import signal

import pytest

from veronte4x.cli.interrupts import Interrupts


def test_a_ctrl_c_inside_a_whole_block_waits_for_its_end() -> None:
    done = []
    with Interrupts() as interrupts, pytest.raises(KeyboardInterrupt):
        with interrupts.whole:
            signal.raise_signal(signal.SIGINT)
            done.append("written")
            done.append("counted")
        done.append("next record")  # not reached
    assert done == ["written", "counted"]


def test_a_ctrl_c_outside_a_whole_block_interrupts_at_once() -> None:
    done = []
    with Interrupts(), pytest.raises(KeyboardInterrupt):
        signal.raise_signal(signal.SIGINT)
        done.append("reached")
    assert done == []


def test_the_previous_handler_is_back_afterwards() -> None:
    before = signal.getsignal(signal.SIGINT)
    with Interrupts():
        assert signal.getsignal(signal.SIGINT) is not before
    assert signal.getsignal(signal.SIGINT) is before
