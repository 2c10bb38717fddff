"""A pytest plugin for ``make coverage``: which test ran each line, and how long each test took.

Loaded with ``-p tests.coverage_contexts`` under ``coverage run``. Each test's lines are
recorded under its node id as coverage's dynamic context; the subprocesses a test starts (the
command line, the simulated ESCs) get the node id as their static context through
``V4X_COVERAGE_CONTEXT`` (``context`` in ``[tool.coverage.run]``). Lines run outside any test
(imports during collection, module-scoped set-up done before the first test) keep the empty
context. The time of each test (set-up, call and tear-down) is written beside coverage's data,
one JSON file per process. ``tests/mutation.py`` reads both to choose a mutant's tests.
Without coverage running, the plugin does nothing.
"""

import json
import os
from collections.abc import Generator
from pathlib import Path

import coverage
import pytest
from coverage.config import CoverageConfig

CONFIG_VARIABLE = "COVERAGE_PROCESS_CONFIG"
_durations: dict[str, float] = {}


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item: pytest.Item) -> Generator[None]:
    """Record the lines run by ``item`` (and by the processes it starts) under its node id."""
    current = coverage.Coverage.current()
    if current is None:
        yield
        return
    current.switch_context(item.nodeid)
    config = os.environ.get(CONFIG_VARIABLE)
    if config is not None:
        for_subprocesses = CoverageConfig.deserialize(config)
        for_subprocesses.context = item.nodeid
        os.environ[CONFIG_VARIABLE] = for_subprocesses.serialize()
    try:
        yield
    finally:
        if config is not None:
            os.environ[CONFIG_VARIABLE] = config
        current.switch_context("")


def pytest_runtest_logreport(report: pytest.TestReport) -> None:
    """Add the time of one phase of a test to its total."""
    _durations[report.nodeid] = _durations.get(report.nodeid, 0.0) + report.duration


def pytest_sessionfinish(session: pytest.Session) -> None:
    """Write the times of this process's tests beside coverage's data."""
    current = coverage.Coverage.current()
    if current is None or not _durations:
        return
    folder = Path(current.config.data_file).parent
    folder.mkdir(parents=True, exist_ok=True)
    (folder / f"durations.{os.getpid()}.json").write_text(json.dumps(_durations))
