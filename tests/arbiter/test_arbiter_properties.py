"""Hypothesis: random traffic and fault schedules keep the seed's invariants."""

from __future__ import annotations

from dataclasses import dataclass

from arbiter_support import NOT_READY, READY, variable
from hypothesis import given, settings
from hypothesis import strategies as st

from veronte4x import codec
from veronte4x.arbiter import Arbiter, ArbiterConfig, ArbiterState, Method, VariableConfig


@dataclass(frozen=True)
class Step:
    """One step of a schedule: how long after the last, and what each autopilot does."""

    gap: float
    sends: tuple[int, ...]  # per autopilot: 0 nothing, 1 Ready only, 2 all, 3 Not Ready
    values: tuple[tuple[float, ...], ...]
    fault: tuple[str, int] | None  # ("fts" | "watchdog" | "maintenance", autopilot)


variables_st = st.lists(
    st.builds(VariableConfig, weight=st.floats(0.0, 10.0), absolute=st.booleans()),
    min_size=0,
    max_size=3,
)


@st.composite
def configs(draw: st.DrawFn) -> ArbiterConfig:
    method = draw(st.sampled_from(Method))
    external = draw(st.booleans())
    return ArbiterConfig(
        variables=draw(variables_st),
        method=method,
        preferred=draw(st.integers(0, 3 if external else 2)),
        holding_time=draw(
            st.sampled_from([0.0, 0.3, 1.0] if method is not Method.ROUND_ROBIN else [0.3, 1.0])
        ),
        hysteresis=draw(st.floats(0.0, 1.0)),
        external_enabled=external,
    )


def steps(count: int) -> st.SearchStrategy[list[Step]]:
    value = st.floats(-1e3, 1e3, width=32) | st.sampled_from([float("nan"), float("inf")])
    step = st.builds(
        Step,
        gap=st.sampled_from([0.0, 0.02, 0.05, 0.08, 0.15]),
        sends=st.tuples(*[st.sampled_from([2, 2, 2, 2, 1, 0, 3])] * 4),
        values=st.tuples(*[st.tuples(value, value, value)] * 4),
        fault=st.none()
        | st.none()
        | st.none()
        | st.tuples(st.sampled_from(["fts", "watchdog", "maintenance"]), st.integers(0, 3)),
    )
    return st.lists(step, min_size=1, max_size=count)


def drive(
    config: ArbiterConfig, schedule: list[Step]
) -> list[tuple[ArbiterState, codec.Status, list[tuple[int, bytes]]]]:
    """Run a schedule; after each step, the model's state and Status, and its frames."""
    arb = Arbiter(config)
    time = 0.0
    seen = []
    for step in schedule:
        time = round(time + step.gap, 9)
        for autopilot, sends in enumerate(step.sends):
            can_id = config.autopilot_ids[autopilot]
            if sends == 3:
                arb.receive(can_id, NOT_READY, time)
            elif sends:
                arb.receive(can_id, READY, time)
            if sends == 2:
                for number in range(len(config.variables)):
                    arb.receive(can_id, variable(number, step.values[autopilot][number]), time)
        if step.fault is not None:
            kind, autopilot = step.fault
            if kind == "fts":
                arb.set_fts(time, autopilot, False)
            elif kind == "watchdog":
                arb.set_watchdog(time, autopilot, False)
            elif autopilot == 3:  # rarely: the maintenance command
                arb.command_maintenance(time)
        frames = arb.poll(time)
        seen.append((arb.state, arb.status_message(), frames))
    return seen


@settings(max_examples=250)
@given(configs(), steps(40))
def test_never_a_dead_selection_while_one_lives_and_never_a_revival(
    config: ArbiterConfig, schedule: list[Step]
) -> None:
    dead_before: set[int] = set()
    for state, _, _ in drive(config, schedule):
        dead = {ap for ap in range(4) if state.dead[ap]}
        assert dead_before <= dead, "an autopilot came back from the dead"
        dead_before = dead
        assert not (set(range(4)) - set(config.participants)) & dead
        alive = [ap for ap in config.participants if state.alive[ap]]
        if config.method.fixed_autopilot is None and alive:
            assert state.selected in alive
        if config.method.fixed_autopilot is None and state.arbitrating and not alive:
            assert state.selected == config.preferred


@settings(max_examples=100)
@given(configs(), steps(40), st.sampled_from([Method.FIXED_0, Method.FIXED_1, Method.FIXED_2]))
def test_a_fixed_method_stays_fixed(
    config: ArbiterConfig, schedule: list[Step], method: Method
) -> None:
    fixed = ArbiterConfig(
        variables=config.variables,
        method=method,
        preferred=config.preferred,
        external_enabled=config.external_enabled,
    )
    for state, _, _ in drive(fixed, schedule):
        assert state.selected == method.fixed_autopilot
        assert not state.arbitrating


@settings(max_examples=100)
@given(configs(), steps(40))
def test_only_frames_the_codec_decodes(config: ArbiterConfig, schedule: list[Step]) -> None:
    for _, status, frames in drive(config, schedule):
        for can_id, data in frames:
            assert can_id == config.arbiter_id
            message = codec.decode(data, sender=codec.Sender.ARBITER)
            assert codec.encode(message) == data
            if isinstance(message, codec.Status):
                assert message == status
            else:
                assert isinstance(message, codec.Score)
                assert message.autopilot in config.participants
