"""The exit codes of the command line, as the docs list them."""

EXIT_OK = 0
"""Success; bad frames skipped or kept are not failures."""
EXIT_FINDINGS = 1
"""The capture failed a check: ``--on-error raise`` met a bad frame, or ``replay`` found the
recorded arbiter disagreeing with the model; or ``esc allocate`` refused an allocation."""
EXIT_BAD_FRAME = EXIT_FINDINGS
"""``--on-error raise`` met a bad frame."""
EXIT_USAGE = 2
"""A usage error, or an input that cannot be opened (missing file, bad bus map, unknown
format, a ``--dsdl`` directory with a malformed definition or a data type id claimed twice,
missing extra, a CAN bus that cannot be opened or that fails while in use)."""
EXIT_NO_ANSWER = 3
"""A node did not answer: none on the bus, a request timed out, an update stalled."""
EXIT_REFUSED = 4
"""A node answered no: unknown parameter, value out of range, refused or failed update."""
EXIT_NOT_IN_TIME_ORDER = 5
"""``replay``: the capture's timestamps step back too often to replay it (it is not in time
order: shuffled lines, many logs joined); sort it by time."""
EXIT_INTERRUPTED = 130
"""Interrupted by Ctrl-C (SIGINT), as shells report it; or SIGTERM during ``esc spin``
(motors were sent zero throttle first)."""
