"""The errors of the ground-station client: each names the node and what it did not do."""

from __future__ import annotations

from veronte4x.errors import Veronte4xError


class ClientError(Veronte4xError):
    """A request to a node failed; the message is one line that names the node."""


class NoResponseError(ClientError):
    """A node did not answer a request in time, after every retry.

    Attributes:
        node_id: The node asked.
        request: The DSDL name of the request, e.g. ``uavcan.protocol.param.GetSet``.
        attempts: How many times it was sent.
        timeout: Seconds waited for each attempt.
    """

    def __init__(self, node_id: int, request: str, attempts: int, timeout: float) -> None:
        self.node_id = node_id
        self.request = request
        self.attempts = attempts
        self.timeout = timeout
        tries = "once" if attempts == 1 else f"{attempts} times"
        super().__init__(
            f"node {node_id} did not answer {request} (sent {tries}, {timeout:g} s each); "
            "check the node id, the bus and the bit rate"
        )


class RejectedError(ClientError):
    """A node answered but refused: RestartNode not ok, ExecuteOpcode not ok, an update error."""


class ParameterError(ClientError):
    """A parameter that the node does not have, or a value it cannot take."""


class FirmwareUpdateFailedError(ClientError):
    """A firmware update that did not complete, or whose result the node contradicts.

    A node's own answer to BeginFirmwareUpdate is the DSDL enum
    `veronte4x.dronecan.FirmwareUpdateError`; a refusal raises this with its name.

    Attributes:
        timed_out: The node fell silent (rather than refusing or reporting another CRC).
    """

    def __init__(self, message: str, *, timed_out: bool = False) -> None:
        super().__init__(message)
        self.timed_out = timed_out


class InvalidRequestError(ClientError, ValueError):
    """A request refused before anything was sent: an empty parameter name, a value that
    does not parse as the parameter's type, an empty or oversized firmware image."""


class OperationCancelledError(ClientError):
    """The operation was cancelled (`Runner.cancel`) before it finished: it has no result,
    and what it had asked of a node may or may not have been done."""


class NodeIdConflictError(InvalidRequestError):
    """Another tool or node sends service frames with this client's node id: answers to
    either may reach both with the same transfer id, and one to a read by index names
    nothing that tells whose it is. From the first such frame on, the client takes no
    answer and refuses every request (its pending ones fail with this error too).

    Attributes:
        node_id: The node id both use.
        heard: The frame heard, in words.
    """

    def __init__(self, node_id: int, heard: str) -> None:
        self.node_id = node_id
        self.heard = heard
        super().__init__(
            f"another tool or node on the bus sends with this tool's node id {node_id} "
            f"({heard}), so their answers cannot be told apart; give each tool on the bus a "
            "node id of its own"
        )
