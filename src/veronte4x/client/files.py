"""A file server for nodes that pull a file, as during a firmware update (sans-IO)."""

from __future__ import annotations

from dataclasses import dataclass

from veronte4x.dronecan.messages import (
    EntryType,
    EntryTypeFlag,
    FileError,
    FileErrorCode,
    FileGetInfoRequest,
    FileGetInfoResponse,
    FileReadRequest,
    FileReadResponse,
)

_OK = FileErrorCode(FileError.OK)
_NOT_FOUND = FileErrorCode(FileError.NOT_FOUND)


@dataclass(frozen=True, slots=True)
class FileRead:
    """One ``file.Read`` the server answered.

    Attributes:
        path: The path asked for.
        offset: The offset asked for.
        length: Bytes sent back (fewer than 256 at the end of the file).
        size: The file's size, or None when no such file is served.
    """

    path: bytes
    offset: int
    length: int
    size: int | None

    @property
    def end_of_file(self) -> bool:
        """The read reached the end of a served file (a short read, spec file.Read)."""
        return self.size is not None and self.length < FileReadResponse.MAX_DATA


class FileServer:
    """Files in memory, by path, answered to ``file.GetInfo`` and ``file.Read`` requests.

    Examples:
        >>> from veronte4x import dronecan
        >>> server = FileServer()
        >>> server.add(b"fw.bin", bytes(300))
        >>> response, read = server.read(dronecan.FileReadRequest(256, dronecan.Path(b"fw.bin")))
        >>> len(response.data), read.end_of_file
        (44, True)
    """

    def __init__(self) -> None:
        self._files: dict[bytes, bytes] = {}
        self._users: dict[bytes, int] = {}

    def add(self, path: bytes, data: bytes) -> None:
        """Serve ``data`` at ``path`` (replacing what was there) until as many `remove`
        calls as `add` calls: several updates of one image share it."""
        self._files[path] = bytes(data)
        self._users[path] = self._users.get(path, 0) + 1

    def remove(self, path: bytes) -> None:
        """Stop serving ``path`` once every `add` of it has been removed."""
        users = self._users.get(path, 0) - 1
        if users > 0:
            self._users[path] = users
        else:
            self._users.pop(path, None)
            self._files.pop(path, None)

    def get_info(self, request: FileGetInfoRequest) -> FileGetInfoResponse:
        """The answer to a GetInfo: size, OK and a readable file, or NOT_FOUND."""
        data = self._files.get(request.path.path)
        if data is None:
            return FileGetInfoResponse(0, _NOT_FOUND, EntryType(0))
        flags = EntryTypeFlag.FILE | EntryTypeFlag.READABLE
        return FileGetInfoResponse(len(data), _OK, EntryType(int(flags)))

    def read(self, request: FileReadRequest) -> tuple[FileReadResponse, FileRead]:
        """The answer to a Read: up to 256 bytes at the offset, or NOT_FOUND; and what it was."""
        path = request.path.path
        data = self._files.get(path)
        if data is None:
            return FileReadResponse(_NOT_FOUND), FileRead(path, request.offset, 0, None)
        chunk = data[request.offset : request.offset + FileReadResponse.MAX_DATA]
        return FileReadResponse(_OK, chunk), FileRead(path, request.offset, len(chunk), len(data))
