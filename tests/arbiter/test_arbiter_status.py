"""Status management (seed 002, seed 000 chapter 4): boot, Idle, Normal, Maintenance, Ready."""

from __future__ import annotations

import pytest
from arbiter_support import NOT_READY, READY, SEED_VARIABLES, Rig

from veronte4x.arbiter import (
    Arbiter,
    ArbiterConfig,
    ArbiterMode,
    ArbiterPhase,
    DecisionKind,
    InputError,
    SystemChecks,
)

CONFIG = ArbiterConfig(variables=SEED_VARIABLES)


def kinds(arb: Arbiter) -> list[tuple[float, DecisionKind, str]]:
    return [(d.time, d.kind, d.reason) for d in arb.decisions]


def test_boot_checks_pass_at_the_first_timestamp() -> None:
    arb = Arbiter(CONFIG)
    assert arb.state.mode is ArbiterMode.IDLE and arb.state.time is None
    assert arb.poll(12.5) == [(255, bytes.fromhex("00ff0000ffff"))]
    assert arb.state.mode is ArbiterMode.NORMAL
    assert arb.state.phase is ArbiterPhase.NORMAL
    assert kinds(arb) == [
        (12.5, DecisionKind.MODE, "boot: Idle, checking the system"),
        (12.5, DecisionKind.MODE, "Normal, waiting for Ready: boot checks pass"),
    ]


def test_idle_sends_nothing_then_normal_when_the_checks_pass() -> None:
    arb = Arbiter(CONFIG, checks=SystemChecks(pdi_ok=False))
    assert arb.poll(0.0) == []
    assert arb.poll(10.0) == []
    assert arb.state.mode is ArbiterMode.IDLE
    arb.set_checks(20.0, SystemChecks())
    assert arb.state.mode is ArbiterMode.NORMAL
    assert arb.poll(20.0) == [(255, bytes.fromhex("00ff0000ffff"))]
    assert arb.poll(50.0)[0] == (255, bytes.fromhex("00ff0000ffff"))  # no Maintenance


def test_errors_persisting_30_s_mean_maintenance() -> None:
    arb = Arbiter(CONFIG, checks=SystemChecks(pdi_ok=False, can_b_ok=False))
    arb.poll(1.0)
    assert arb.poll(30.9) == []
    frames = arb.poll(31.0)
    assert arb.state.mode is ArbiterMode.MAINTENANCE
    assert arb.decisions[-1].time == 31.0
    assert arb.decisions[-1].reason == (
        "Maintenance: errors persist 30 s after boot (pdi_ok, can_b_ok)"
    )
    # CBIT, PDI and CAN B fail; byte 5 all OK but the mode bit (Maintenance).
    assert frames == [(255, bytes.fromhex("00ff0000da7f"))]


def test_checks_passing_after_maintenance_change_nothing() -> None:
    arb = Arbiter(CONFIG, checks=SystemChecks(pbit_ok=False))
    arb.poll(0.0)
    arb.set_checks(40.0, SystemChecks())
    assert arb.state.mode is ArbiterMode.MAINTENANCE


def test_maintenance_sends_status_even_when_disabled_but_no_score() -> None:
    config = ArbiterConfig(variables=SEED_VARIABLES, send_status=False)
    rig = Rig(config)
    sent = rig.run_until(0.5)
    assert [data[:2] for _, _, data in sent] == [b"\x00\x00", b"\x00\x01", b"\x00\x02"]
    rig.arb.command_maintenance(0.55)
    sent = rig.run_until(6.5)
    assert all(data[:2] == b"\x00\xff" for _, _, data in sent)
    assert [time for time, _, _ in sent][:3] == [0.75, 1.0, 1.25]
    assert len(sent) == 24  # 0.75 .. 6.5 every 0.25 s: Status only, no Score
    assert rig.arb.state.phase is ArbiterPhase.MAINTENANCE
    assert not rig.arb.state.arbitrating


def test_maintenance_command_frame_from_an_autopilot() -> None:
    arb = Arbiter(CONFIG)
    message = arb.receive(9, bytes.fromhex("10"), 1.0)
    assert type(message).__name__ == "MaintenanceCommand"
    assert arb.state.mode is ArbiterMode.MAINTENANCE
    assert arb.decisions[-1].reason == "Maintenance: maintenance command from AP2"


def test_arbitration_waits_for_a_ready_from_every_autopilot() -> None:
    arb = Arbiter(CONFIG)
    arb.receive(8, READY, 0.0)
    arb.receive(9, READY, 0.01)
    arb.receive(11, READY, 0.015)  # the external autopilot does not take part
    assert arb.state.phase is ArbiterPhase.NORMAL
    arb.receive(10, NOT_READY, 0.02)
    assert arb.state.phase is ArbiterPhase.NORMAL
    assert arb.state.ready == (True, True, False, False)
    arb.receive(10, READY, 0.03)
    assert arb.state.phase is ArbiterPhase.ARBITRATING
    assert arb.state.alive == (True, True, True, False)
    assert arb.decisions[-1].reason == "arbitration starts: AP1, AP2, AP3 alive"


def test_a_not_ready_before_arbitration_withdraws_the_ready() -> None:
    arb = Arbiter(CONFIG)
    arb.receive(8, READY, 0.0)
    arb.receive(8, NOT_READY, 0.01)
    arb.receive(9, READY, 0.02)
    arb.receive(10, READY, 0.03)
    assert arb.state.phase is ArbiterPhase.NORMAL
    assert arb.state.ready == (False, True, True, False)


def test_ready_in_idle_counts_once_normal() -> None:
    arb = Arbiter(CONFIG, checks=SystemChecks(memory_ok=False))
    for can_id in (8, 9, 10):
        arb.receive(can_id, READY, 0.0)
    assert arb.state.phase is ArbiterPhase.IDLE
    arb.set_checks(0.05, SystemChecks())
    assert arb.state.phase is ArbiterPhase.ARBITRATING


def test_maintenance_never_starts_arbitration() -> None:
    rig = Rig(CONFIG, checks=SystemChecks(cio_high_ok=False))
    rig.run_until(35.0)
    assert rig.arb.state.phase is ArbiterPhase.MAINTENANCE
    assert rig.arb.state.ready == (True, True, True, False)
    assert rig.arb.state.alive == (False, False, False, False)
    assert not any(d.kind is DecisionKind.ARBITRATION for d in rig.arb.decisions)


def test_timestamps_must_not_go_backwards() -> None:
    arb = Arbiter(CONFIG)
    arb.poll(2.0)
    with pytest.raises(InputError, match=r"timestamp = 1\.0: expected >= the previous one, 2\.0"):
        arb.receive(8, READY, 1.0)
    with pytest.raises(InputError, match="a finite number of seconds"):
        arb.advance(float("nan"))
    with pytest.raises(InputError, match="autopilot = 4"):
        arb.set_fts(3.0, 4, False)


def test_frames_on_other_ids_are_ignored() -> None:
    arb = Arbiter(CONFIG)
    assert arb.receive(255, bytes.fromhex("00ff0000"), 0.0) is None
    assert arb.receive(12, READY, 0.0) is None
    assert arb.state.ready == (False, False, False, False)
