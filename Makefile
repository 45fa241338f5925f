# Every target builds its own virtual environment in .venv from pyproject.toml;
# nothing relies on what happens to be installed.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
# what running needs (demo), and that with the test tools (test, bench, ...)
RUN    := $(VENV)/.installed-run
STAMP  := $(VENV)/.installed-test

.PHONY: setup demo test bench validate regress-update clean

$(VENV)/bin/python:
	@$(PYTHON) -c 'import sys; sys.exit(sys.version_info < (3, 11))' || \
	  { echo "balance needs Python 3.11 or newer (PYTHON=$(PYTHON))"; exit 1; }
	$(PYTHON) -m venv $(VENV)

$(RUN): pyproject.toml | $(VENV)/bin/python
	$(BIN)/python -m pip install --quiet --disable-pip-version-check -e .
	@touch $(RUN)

$(STAMP): pyproject.toml | $(VENV)/bin/python
	$(BIN)/python -m pip install --quiet --disable-pip-version-check -e '.[test]'
	@touch $(RUN) $(STAMP)

setup: $(STAMP)

demo: $(RUN)
	$(BIN)/balance validate configs
	$(BIN)/balance compare configs/tanaka-part3
	$(BIN)/balance report configs/tanaka-part3 --output report --html

test: $(STAMP)
	$(BIN)/python -m pytest

bench: $(STAMP)
	$(BIN)/python tools/bench.py

# docs/VALIDATION.md from tests/reference (CI checks that the committed one is current)
validate: $(STAMP)
	$(BIN)/python tools/validation_report.py

# rewrite the golden regression tables after an intended change (balance regress --update);
# never in CI
regress-update: $(STAMP)
	$(BIN)/balance regress tests/golden/compare.json configs --update
	@git diff --stat -- tests/golden || true

clean:
	rm -rf $(VENV) build *.egg-info .pytest_cache
