"""A simulated Vertiq ESC (Vertiq's DroneCAN support document): a sans-IO DroneCAN node with a
motor model.

`SimulatedEsc` takes the frames seen on a bus with their timestamps (`SimulatedEsc.receive`)
and gives the frames to send at a time (`SimulatedEsc.poll`). The python-can adapters are in
`veronte4x.simulator.can_node` (the ``can`` extra); the client that talks to it is
`veronte4x.client`.

Examples:
    >>> from veronte4x import dronecan
    >>> from veronte4x.simulator import SimulatedEsc
    >>> esc = SimulatedEsc(node_id=20, esc_index=0, telem_frequency=10)
    >>> reassembler = dronecan.Reassembler()
    >>> transfers = [reassembler.feed(f.can_id, f.data, 0.0) for f in esc.poll(0.0)]
    >>> [type(t.message).__name__ for t in transfers if t is not None]
    ['NodeStatus', 'EscStatus', 'Temperature']
    >>> esc.poll(0.05)
    []
"""

from __future__ import annotations

from veronte4x.simulator.esc import (
    HARDWARE_VERSION_MAJOR,
    NODE_STATUS_FREQUENCY,
    SOFTWARE_VERSION,
    UNIQUE_ID_PREFIX,
    EscState,
    SimulatedEsc,
)
from veronte4x.simulator.motor import DEFAULT_MODEL, MotorModel, MotorState
from veronte4x.simulator.parameters import NO_PARAMETER, PARAMETERS, ParameterRange

__all__ = [
    "DEFAULT_MODEL",
    "HARDWARE_VERSION_MAJOR",
    "NODE_STATUS_FREQUENCY",
    "NO_PARAMETER",
    "PARAMETERS",
    "SOFTWARE_VERSION",
    "UNIQUE_ID_PREFIX",
    "EscState",
    "MotorModel",
    "MotorState",
    "ParameterRange",
    "SimulatedEsc",
]
