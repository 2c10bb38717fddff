"""A DroneCAN ground-station client for Vertiq ESCs: the node's logic sans-IO, a thin bus side.

`ClientProtocol` is the node as a state machine (frames and times in, frames and events
out): node table from NodeStatus, transfer ids per (destination, data type), requests
matched with responses, timeouts and retries as values, and a file server for nodes that
pull a firmware image. `Commander` schedules RawCommand with a watchdog. `BusClient` (in
`veronte4x.client.bus`, the ``can`` extra) runs them on a python-can bus and raises the
errors of `veronte4x.client.errors`.
"""

from __future__ import annotations

from veronte4x.client.commander import Commander
from veronte4x.client.errors import (
    ClientError,
    FirmwareUpdateFailedError,
    InvalidRequestError,
    NodeIdConflictError,
    NoResponseError,
    OperationCancelledError,
    ParameterError,
    RejectedError,
)
from veronte4x.client.files import FileRead, FileServer
from veronte4x.client.firmware import (
    MAX_IMAGE_SIZE,
    FirmwareOptions,
    FirmwareUpdate,
    Phase,
    UpdateProgress,
    check_image,
)
from veronte4x.client.nodes import OFFLINE_TIMEOUT, NodeEntry, NodeTable
from veronte4x.client.params import ParameterInfo, parameter_request, plain
from veronte4x.client.protocol import (
    DEFAULT_NODE_ID,
    ClientProtocol,
    Event,
    FileServed,
    Received,
    StatusSeen,
)
from veronte4x.client.spin import (
    DEFAULT_SILENCE,
    Spin,
    SpinArgumentError,
    SpinMonitor,
    SpinResult,
    SpinStoppedError,
    SpunNode,
)
from veronte4x.node.requests import Answered, Pending, Requester, TimedOut, answers
from veronte4x.node.transfer_ids import TransferIds

__all__ = [
    "DEFAULT_NODE_ID",
    "DEFAULT_SILENCE",
    "MAX_IMAGE_SIZE",
    "OFFLINE_TIMEOUT",
    "Answered",
    "ClientError",
    "ClientProtocol",
    "Commander",
    "Event",
    "FileRead",
    "FileServed",
    "FileServer",
    "FirmwareOptions",
    "FirmwareUpdate",
    "FirmwareUpdateFailedError",
    "InvalidRequestError",
    "NoResponseError",
    "NodeEntry",
    "NodeIdConflictError",
    "NodeTable",
    "OperationCancelledError",
    "ParameterError",
    "ParameterInfo",
    "Pending",
    "Phase",
    "Received",
    "RejectedError",
    "Requester",
    "Spin",
    "SpinArgumentError",
    "SpinMonitor",
    "SpinResult",
    "SpinStoppedError",
    "SpunNode",
    "StatusSeen",
    "TimedOut",
    "TransferIds",
    "UpdateProgress",
    "answers",
    "check_image",
    "parameter_request",
    "plain",
]
