"""The allocation table of a dynamic node ID allocation server, and its file.

DroneCAN's allocation table maps unique ids to node ids; it only grows, and a unique id
in it always gets the same node id again (DroneCAN specification, 6 "Application-level
functions", "Dynamic node ID allocation"). A node on the bus that does not answer
GetNodeInfo is entered with the unique id zero, the specification's *mock entry*, which
keeps its node id from being allocated.

The file is JSON Lines (one JSON object a line, UTF-8): a first line naming the format,
then one line per entry, by node id::

    {"format": "veronte4x-node-id-allocations/1"}
    {"node_id": 21, "unique_id": "7665726f6e746534782e73696d000015"}
    {"node_id": 125, "unique_id": "44c08b635e05f4bc1096df11a8ba5447"}

``unique_id`` is the 16 bytes in hex, 32 zeros for a mock entry. A file that binds one unique
id, or one node id, twice is refused, as is anything else it cannot hold. `save` writes a
whole new file beside the old one, flushed to the disk, and renames it over the old: a crash
leaves the old table or the new one, never a part.
"""

from __future__ import annotations

import contextlib
import json
import os
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

from veronte4x.errors import SourceError
from veronte4x.files import whole_file
from veronte4x.node.allocatee import UNIQUE_ID_SIZE

FORMAT = "veronte4x-node-id-allocations/1"
"""The ``format`` of the file's first line: its layout and version."""

MOCK = bytes(UNIQUE_ID_SIZE)
"""The unique id of a mock entry: a node seen on the bus that did not answer GetNodeInfo."""


class AllocationTableError(SourceError):
    """An allocation table file that cannot be read as one; the message is one line naming
    the file and line."""


class AllocationConflictError(AllocationTableError):
    """An entry that contradicts the table: its node id or its unique id is bound to
    another already."""


@dataclass(frozen=True, slots=True)
class Entry:
    """One allocation: a node id and the unique id it belongs to (`MOCK` for a node seen on
    the bus that did not say its unique id)."""

    node_id: int
    unique_id: bytes

    @property
    def mock(self) -> bool:
        """Whether this is a mock entry."""
        return self.unique_id == MOCK


class AllocationTable:
    """Unique ids and their node ids, each bound once.

    Examples:
        >>> table = AllocationTable()
        >>> table.add(Entry(125, bytes(range(16))))
        >>> table.node_id(bytes(range(16))), table.unique_id(125) == bytes(range(16))
        (125, True)
        >>> table.add(Entry(124, bytes(16)))  # a mock entry: node 124 did not answer
        >>> table.add(Entry(124, bytes(range(16))))  # doctest: +ELLIPSIS
        Traceback (most recent call last):
        veronte4x.client.allocation_table.AllocationConflictError: unique id 0001...0f is ...
    """

    def __init__(self, entries: tuple[Entry, ...] = ()) -> None:
        self._by_node: dict[int, Entry] = {}
        self._by_unique_id: dict[bytes, Entry] = {}
        for entry in entries:
            self.add(entry)

    def __len__(self) -> int:
        return len(self._by_node)

    def __iter__(self) -> Iterator[Entry]:
        """The entries by node id."""
        return iter([self._by_node[n] for n in sorted(self._by_node)])

    def node_id(self, unique_id: bytes) -> int | None:
        """The node id bound to ``unique_id``, or None (never one of a mock entry)."""
        entry = None if unique_id == MOCK else self._by_unique_id.get(unique_id)
        return None if entry is None else entry.node_id

    def unique_id(self, node_id: int) -> bytes | None:
        """The unique id bound to ``node_id`` (`MOCK` for a mock entry), or None."""
        entry = self._by_node.get(node_id)
        return None if entry is None else entry.unique_id

    def add(self, entry: Entry) -> None:
        """Bind ``entry.unique_id`` to ``entry.node_id``; a mock entry's node id may then get
        its real unique id. Adding an entry the table has already changes nothing.

        Raises:
            AllocationConflictError: The node id is bound to another unique id, or the
                unique id to another node id.
            ValueError: No node id 1..127, or no 16-byte unique id.
        """
        if not 1 <= entry.node_id <= 127 or len(entry.unique_id) != UNIQUE_ID_SIZE:
            raise ValueError(f"not an allocation: node {entry.node_id}, {entry.unique_id!r}")
        old = self._by_node.get(entry.node_id)
        if old is not None and not old.mock and old.unique_id != entry.unique_id:
            raise AllocationConflictError(
                f"node {entry.node_id} is bound to unique id {old.unique_id.hex()} already, "
                f"not to {entry.unique_id.hex()}"
            )
        other = self.node_id(entry.unique_id)
        if other is not None and other != entry.node_id:
            raise AllocationConflictError(
                f"unique id {entry.unique_id.hex()} is bound to node {other} already, "
                f"not to node {entry.node_id}"
            )
        if old is not None and not entry.mock and old.mock:
            del self._by_node[entry.node_id]
        if entry.node_id not in self._by_node:
            self._by_node[entry.node_id] = entry
            if not entry.mock:
                self._by_unique_id[entry.unique_id] = entry


def dumps(table: AllocationTable) -> str:
    """The file's text: the format line, then one line per entry by node id."""
    lines = [json.dumps({"format": FORMAT})]
    lines += [json.dumps({"node_id": e.node_id, "unique_id": e.unique_id.hex()}) for e in table]
    return "\n".join(lines) + "\n"


def loads(text: str, name: str = "allocation table") -> AllocationTable:
    """Read a table from the file's text; ``name`` names it in errors.

    Raises:
        AllocationTableError: Not a table of this format, an entry that is not a node id
            and a 16-byte unique id, or a node id or unique id bound twice.
    """
    table = AllocationTable()
    lines = text.splitlines()
    if not lines or _json(lines[0], name, 1) != {"format": FORMAT}:
        raise AllocationTableError(
            f'{name} line 1: not an allocation table (expected {{"format": "{FORMAT}"}})'
        )
    for number, line in enumerate(lines[1:], 2):
        if not line.strip():
            continue
        try:
            table.add(_entry(_json(line, name, number)))
        except AllocationConflictError as error:
            raise AllocationConflictError(
                f"{name} line {number}: {error}; remove one of the two lines"
            ) from None
        except AllocationTableError as error:
            raise AllocationTableError(f"{name} line {number}: {error}") from None
    return table


def _json(line: str, name: str, number: int) -> object:
    try:
        return json.loads(line)
    except ValueError:
        raise AllocationTableError(f"{name} line {number}: not a JSON object") from None


def _entry(item: object) -> Entry:
    if not isinstance(item, dict) or set(item) != {"node_id", "unique_id"}:
        raise AllocationTableError('expected {"node_id": 1..127, "unique_id": "32 hex digits"}')
    node_id, unique_id = item["node_id"], item["unique_id"]
    if isinstance(node_id, bool) or not isinstance(node_id, int) or not 1 <= node_id <= 127:
        raise AllocationTableError(f"node_id {node_id!r} is not a node id (1..127)")
    try:
        raw = bytes.fromhex(unique_id) if isinstance(unique_id, str) else b""
    except ValueError:
        raw = b""
    if len(raw) != UNIQUE_ID_SIZE or len(unique_id) != 2 * UNIQUE_ID_SIZE:
        raise AllocationTableError(f"unique_id {unique_id!r} is not 16 bytes in 32 hex digits")
    return Entry(node_id, raw)


def load(path: str | os.PathLike[str]) -> AllocationTable:
    """The table in the file at ``path``; an empty one if there is no such file yet.

    Raises:
        AllocationTableError: A file that is not a valid table (`loads`), or not UTF-8.
        OSError: A file that cannot be read.
    """
    try:
        data = Path(path).read_bytes()
    except FileNotFoundError:
        return AllocationTable()
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        raise AllocationTableError(f"{os.fspath(path)}: not a UTF-8 text file") from None
    return loads(text, os.fspath(path))


def check_storable(path: str | os.PathLike[str]) -> None:
    """Refuse a table path whose directory does not exist or cannot be written, before a
    server starts (`save` writes a new file beside it and renames it).

    Raises:
        AllocationTableError: The directory is missing, not a directory, or not writable.
    """
    folder = Path(path).absolute().parent
    if not folder.is_dir() or not os.access(folder, os.W_OK | os.X_OK):
        raise AllocationTableError(
            f"{os.fspath(path)}: the directory {folder} does not exist or cannot be "
            "written: give a table path in a writable directory"
        )


def save(path: str | os.PathLike[str], table: AllocationTable) -> None:
    """Write the table to ``path`` whole: a new file beside it, flushed to the disk, then
    renamed over the old one (and the directory flushed), so that a crash at any point
    leaves one complete table.

    Raises:
        OSError: The file or its directory cannot be written.
    """
    with whole_file(path) as file:
        file.write(dumps(table).encode("utf-8"))
        file.flush()
        os.fsync(file.fileno())
    with contextlib.suppress(OSError):  # a directory that cannot be opened (Windows)
        directory = os.open(os.path.dirname(os.path.abspath(path)), os.O_RDONLY)
        try:
            os.fsync(directory)
        finally:
            os.close(directory)
