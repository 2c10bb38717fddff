"""The exit codes of the command line, as the docs list them."""

EXIT_OK = 0
"""Success; bad frames skipped or kept are not failures."""
EXIT_BAD_FRAME = 1
"""``--on-error raise`` met a bad frame."""
EXIT_USAGE = 2
"""A usage error, or an input that cannot be opened (missing file, bad bus map)."""
EXIT_NO_ANSWER = 3
"""A node did not answer: none on the bus, a request timed out, an update stalled."""
EXIT_REFUSED = 4
"""A node answered no: unknown parameter, value out of range, refused or failed update."""
EXIT_INTERRUPTED = 130
"""Stopped by Ctrl-C (motors, if any, were sent zero throttle first)."""
