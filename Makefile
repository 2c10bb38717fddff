# The two commands of the README: `make demo` (the main job) and `make check` (every check).
# Both create a virtual environment in .venv from nothing, with only Python and pip.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin

.PHONY: demo check lint types test docs bench mutation coverage soak clean

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip

# The package with what the README's snippets, its bench and examples/flight.ipynb use.
$(VENV)/.installed-run: pyproject.toml | $(BIN)/python
	$(BIN)/python -m pip install --quiet -e '.[notebook,bench]'
	touch $@

$(VENV)/.installed-dev: pyproject.toml | $(BIN)/python
	$(BIN)/python -m pip install --quiet -e '.[dev,can,pandas,plot,notebook]'
	touch $@ $(VENV)/.installed-run

demo: $(VENV)/.installed-run
	$(BIN)/python examples/make_capture.py examples/flight.log
	$(BIN)/veronte4x decode examples/flight.log | head -n 25
	$(BIN)/veronte4x stats examples/flight.log
	$(BIN)/veronte4x replay examples/flight.log --config examples/arbiter.toml
	$(BIN)/python examples/make_vehicle_bus.py examples/vehicle.log
	@echo "next: open examples/flight.ipynb in Jupyter with the kernel .venv/bin/python (README)"
	@echo "      and examples/vehicle_bus.ipynb, a whole DroneCAN vehicle bus"

lint: $(VENV)/.installed-dev
	$(BIN)/ruff check src tests examples benchmarks docs
	$(BIN)/ruff format --check src tests examples benchmarks docs

types: $(VENV)/.installed-dev
	$(BIN)/mypy

# On one worker per CPU, four at most (each Dask test starts a cluster of its own), where the
# udp_multicast test buses stay on this machine (tests/on_loopback).
test: $(VENV)/.installed-dev
	tests/on_loopback $(BIN)/python -m pytest --numprocesses auto --maxprocesses 4

# Not --quiet: it hides the warnings that --strict should count (mkdocstrings' broken
# cross-references among them). Every WARNING line of the build fails it, whichever plugin
# logged it; INFO lines are dropped.
docs: $(VENV)/.installed-dev
	@NO_MKDOCS_2_WARNING=1 $(BIN)/mkdocs build --strict > $(VENV)/docs-build.log 2>&1; \
	status=$$?; grep -v '^INFO' $(VENV)/docs-build.log; \
	if [ $$status -ne 0 ] || grep -q '^WARNING' $(VENV)/docs-build.log; then \
		echo "docs: the build above has warnings or errors"; exit 1; fi

# Every step runs, whichever failed before it; the last line names the steps that failed.
CHECK_STEPS := lint types test docs
check: $(VENV)/.installed-dev
	@failed=""; \
	for step in $(CHECK_STEPS); do \
		$(MAKE) --no-print-directory $$step || failed="$$failed $$step"; \
	done; \
	if [ -n "$$failed" ]; then echo "make check: failed:$$failed"; exit 1; fi; \
	echo "make check: $(CHECK_STEPS) passed"

bench: $(VENV)/.installed-dev
	$(BIN)/python benchmarks/bench_codec.py
	$(BIN)/python benchmarks/bench_decode_floor.py
	$(BIN)/python benchmarks/bench_dronecan.py
	$(BIN)/python benchmarks/bench_bitstruct.py
	$(BIN)/python benchmarks/bench_capture.py
	$(BIN)/python benchmarks/bench_columnar.py
	$(BIN)/python benchmarks/bench_fleet.py
	$(BIN)/python benchmarks/bench_dbc.py
	$(BIN)/python benchmarks/bench_dronecan_types.py
	$(BIN)/python benchmarks/bench_mf4_memory.py

# Not part of check: a sampled mutation run (docs/mutation.md), each mutant against the
# tests that run its line (the map of make coverage, built first if the sources changed). Override with
# e.g. make mutation MUTATION_ARGS="--size 30 --jobs 2".
MUTATION_ARGS ?= --size 300 --jobs 2
mutation: $(VENV)/.installed-dev
	$(BIN)/python tests/mutation.py $(MUTATION_ARGS) --report $(VENV)/mutation-report.md

# Not part of check: line and branch coverage of the whole suite, the CLI's subprocesses and
# the simulated ESCs' processes included ([tool.coverage.run] in pyproject.toml), each line
# with the tests that ran it: the mutation run's test map (docs/mutation.md).
coverage: $(VENV)/.installed-dev
	$(BIN)/python tests/mutation.py --coverage

# Not part of check: the long runs (tests/soak.py), the tests marked soak, which the suite
# deselects, and the differential tests with more examples (FACTOR times, hypothesis profile soak).
soak: $(VENV)/.installed-dev
	tests/on_loopback $(BIN)/python -m pytest --numprocesses auto --maxprocesses 4 \
		-m "soak or differential" --hypothesis-profile=soak --timeout 3600

clean:
	rm -rf $(VENV) site build *.egg-info src/*.egg-info
