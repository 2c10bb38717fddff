"""The exit codes of the command line, as the docs list them."""

EXIT_OK = 0
"""Success; bad frames skipped or kept are not failures."""
EXIT_BAD_FRAME = 1
"""``--on-error raise`` met a bad frame."""
EXIT_USAGE = 2
"""A usage error, or an input that cannot be opened (missing file, bad bus map)."""
