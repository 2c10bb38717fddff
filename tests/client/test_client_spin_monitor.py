"""`SpinMonitor` at its edges: settings refused in plain words, what counts as hearing from a
node, the silence boundary to the instant, and the first reason to stop kept."""

from __future__ import annotations

from typing import Any

import pytest

from veronte4x import dronecan
from veronte4x.client import SpinMonitor
from veronte4x.errors import EncodeError

K = dronecan.TransferKind


def _seen(message: Any, node: int, at: float, data_type_id: int) -> dronecan.Transfer:
    return dronecan.Transfer(message, node, None, 16, 0, at, K.MESSAGE, data_type_id)


def _esc(node: int, at: float, *, kelvin: float = 300.0, amps: float = 1.0) -> dronecan.Transfer:
    return _seen(dronecan.EscStatus(0, 25.0, amps, kelvin, 1000, 10, 0), node, at, 1034)


def _node_status(node: int, at: float) -> dronecan.Transfer:
    status = dronecan.NodeStatus(1, dronecan.Health.OK, dronecan.Mode.OPERATIONAL, 0, 0)
    return _seen(status, node, at, 341)


@pytest.mark.parametrize(
    ("settings", "text"),
    [
        ({"silence": 0}, "SpinMonitor.silence = 0: expected seconds above 0"),
        ({"silence": -1.0}, "SpinMonitor.silence = -1.0: expected seconds above 0"),
        ({"silence": None}, "SpinMonitor.silence = None: expected seconds above 0"),
        ({"silence": float("nan")}, "SpinMonitor.silence = nan: expected a finite number"),
        ({"silence": True}, "SpinMonitor.silence = True: expected a finite number"),
        ({"silence": "1.5"}, "SpinMonitor.silence = '1.5': expected a finite number"),
        (
            {"max_temperature": float("inf")},
            "SpinMonitor.max_temperature = inf: expected a finite number",
        ),
        ({"max_current": True}, "SpinMonitor.max_current = True: expected a finite number"),
        ({"max_current": "20"}, "SpinMonitor.max_current = '20': expected a finite number"),
    ],
)
def test_settings_that_are_no_finite_number_are_refused(settings: Any, text: str) -> None:
    with pytest.raises(EncodeError) as error:
        SpinMonitor([21], 0.0, **settings)
    assert str(error.value) == text


def test_only_esc_status_and_node_status_count_as_hearing_from_a_node() -> None:
    monitor = SpinMonitor([21, 22], 0.0, silence=1.0)
    monitor.observe(_node_status(21, 0.75))  # NodeStatus alone keeps a node alive
    temperature = dronecan.Temperature(0, 330.0, 0)
    monitor.observe(_seen(temperature, 22, 0.75, 1110))  # device.Temperature does not
    assert monitor.last_heard == {21: 0.75, 22: 0.0}
    assert monitor.check(1.0) is None  # exactly 1 s of silence: not yet
    silent = "node 22 fell silent: no esc.Status or NodeStatus for 1 s"
    assert monitor.check(1.0 + 2**-20) == silent
    monitor.observe(_esc(22, 1.5))
    monitor.observe(_esc(22, 1.25))  # an older transfer arriving late moves nothing back
    assert monitor.last_heard == {21: 0.75, 22: 1.5}
    assert monitor.check(1.75) is None
    assert monitor.check(1.75 + 2**-20) == (
        "node 21 fell silent: no esc.Status or NodeStatus for 1 s"
    )


def test_the_first_limit_tripped_is_the_reason_given() -> None:
    monitor = SpinMonitor([21, 22], 0.0, max_temperature=80.0, max_current=20.0)
    monitor.observe(_esc(21, 0.1, kelvin=273.15 + 80.0, amps=20.0))  # at the limits: fine
    assert monitor.check(0.1) is None and not monitor.over_limit
    monitor.observe(_esc(22, 0.2, amps=20.5))
    monitor.observe(_esc(21, 0.3, kelvin=273.15 + 95.0))  # later, hotter: not the reason
    monitor.observe(_node_status(22, 0.4))
    assert monitor.over_limit
    assert monitor.check(0.4) == "node 22 reported 20.5 A, above the limit of 20 A"
    assert monitor.check(100.0) == "node 22 reported 20.5 A, above the limit of 20 A"
    assert monitor.last_heard == {21: 0.3, 22: 0.4}
