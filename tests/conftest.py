"""Settings shared by the whole suite.

Hypothesis runs without a deadline: a deadline is a timed assertion, and the suite must
pass on a loaded machine (two cores shared by several test runs). This is the only place
a deadline is set; no test passes ``deadline=`` of its own (``tests/test_suite_settings.py``
checks both).
"""

from hypothesis import settings

settings.register_profile("veronte4x", deadline=None)
settings.register_profile(
    "derandomized", parent=settings.get_profile("veronte4x"), derandomize=True, database=None
)
"""For runs that must be repeatable (the mutation run): ``--hypothesis-profile=derandomized``."""
settings.load_profile("veronte4x")
