"""Settings shared by the whole suite.

Hypothesis runs without a deadline: a deadline is a timed assertion, and the suite must
pass on a loaded machine (two cores shared by several test runs). This is the only place
a deadline is set; no test passes ``deadline=`` of its own (``tests/test_suite_settings.py``
checks both).

The default DroneCAN type set reads the user's vendor DSDL roots
(`veronte4x.dronecan.vendor_roots.find_roots`: ``VERONTE4X_DSDL_PATH`` and two directories
of the home directory): the suite, and every process it starts, runs with none of them, in
an empty home directory of its own, so that no result depends on the machine's user; the
disk cache of compiled user DSDL (`veronte4x.dronecan.dsdl_cache`) is in that home too.
"""

import atexit
import os
import shutil
import tempfile

from hypothesis import settings

from tests.soak import FACTOR

os.environ.pop("VERONTE4X_DSDL_PATH", None)
os.environ["HOME"] = tempfile.mkdtemp(prefix="veronte4x-tests-home-")
atexit.register(shutil.rmtree, os.environ["HOME"], True)
os.environ["VERONTE4X_CACHE_DIR"] = os.path.join(os.environ["HOME"], "cache")

settings.register_profile("veronte4x", deadline=None)
settings.register_profile(
    "derandomized", parent=settings.get_profile("veronte4x"), derandomize=True, database=None
)
"""For runs that must be repeatable (the mutation run): ``--hypothesis-profile=derandomized``."""
settings.register_profile(
    "soak",
    parent=settings.get_profile("veronte4x"),
    max_examples=settings.get_profile("default").max_examples * FACTOR,
    derandomize=False,
)
"""For ``make soak`` (``tests/soak.py``): new random examples each run, `FACTOR` times the
default count (each differential test `FACTOR` times its own)."""
settings.load_profile("veronte4x")
