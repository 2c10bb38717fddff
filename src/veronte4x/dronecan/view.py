"""Jupyter's view of a DroneCAN transfer: what its CAN ID and tail said, and its message.

`veronte4x.dronecan.transfer.Transfer` shows itself through `transfer_html`; the message
table is the one every message shows (`veronte4x.display.message_html`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from veronte4x.display import Cells, message_html, side_by_side, table
from veronte4x.times import format_time

if TYPE_CHECKING:
    from veronte4x.dronecan.transfer import Transfer


def transfer_html(transfer: Transfer) -> str:
    """A transfer as HTML: kind, data type, nodes, priority, transfer id and time, then its
    message's fields."""
    head: list[Cells] = [
        ("kind", transfer.kind.name.lower()),
        ("data type id", transfer.data_type_id),
        ("from node", transfer.source_node_id),
    ]
    if transfer.destination_node_id is not None:
        head.append(("to node", transfer.destination_node_id))
    head += [
        ("priority", transfer.priority),
        ("transfer id", transfer.transfer_id),
        ("time", format_time(transfer.timestamp)),
    ]
    name = type(transfer.message).__name__
    return side_by_side(
        [table(f"Transfer: {name}", ("", ""), head, header=False), message_html(transfer.message)]
    )
