"""Ctrl-C between records, never inside one: what a command has written and what it reports
having written stay the same.

Python raises `KeyboardInterrupt` between any two bytecodes; a record half handled (counted
but not yet written, say) would make the summary disagree with the output. Inside
`Interrupts.whole`, a Ctrl-C is held until the block ends; anywhere else (a read waiting
for input, a decode) it interrupts at once, as usual.
"""

from __future__ import annotations

import signal
from types import FrameType, TracebackType


class Interrupts:
    """Holds Ctrl-C while a record is handled whole; use as a context around the loop.

    Examples:
        >>> with Interrupts() as interrupts:
        ...     with interrupts.whole:
        ...         handled = 1
        >>> handled
        1
    """

    def __init__(self) -> None:
        self._busy = False
        self._held = False
        self._previous: object = None
        self.whole = _Whole(self)
        """The context in which a Ctrl-C waits for the block's end."""

    def __enter__(self) -> Interrupts:
        self._previous = signal.signal(signal.SIGINT, self._on_sigint)
        return self

    def __exit__(self, *exc: object) -> None:
        signal.signal(signal.SIGINT, self._previous)  # type: ignore[arg-type]

    def _on_sigint(self, signum: int, frame: FrameType | None) -> None:
        if self._busy:
            self._held = True
        else:
            raise KeyboardInterrupt


class _Whole:
    """The block a Ctrl-C does not cut; it is raised at the block's end."""

    def __init__(self, owner: Interrupts) -> None:
        self._owner = owner

    def __enter__(self) -> None:
        self._owner._busy = True

    def __exit__(
        self,
        kind: type[BaseException] | None,
        error: BaseException | None,
        traceback: TracebackType | None,
    ) -> None:
        owner = self._owner
        owner._busy = False
        if owner._held and kind is None:
            owner._held = False
            raise KeyboardInterrupt
