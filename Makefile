# Every target builds its own virtual environment in .venv from pyproject.toml;
# nothing relies on what happens to be installed.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
# what running needs (demo), and that with the test tools (test, bench, ...)
RUN    := $(VENV)/.installed-run
# and with openTorsion, for the demo's torsion result
TORSION := $(VENV)/.installed-torsion
STAMP  := $(VENV)/.installed-test
# the linters (lint)
LINT   := $(VENV)/.installed-lint
# the documentation tools (docs)
DOCS   := $(VENV)/.installed-docs

.PHONY: setup demo test lint docs bench validate schemas regress-update install-check clean

$(VENV)/bin/python:
	@$(PYTHON) -c 'import sys; sys.exit(sys.version_info < (3, 11))' || \
	  { echo "balance needs Python 3.11 or newer (PYTHON=$(PYTHON))"; exit 1; }
	$(PYTHON) -m venv $(VENV)

# the distribution was called balance before 0.2.0 (now engine-balance): an environment built
# then still holds it
OLD_NAME := if $(BIN)/python -m pip show --quiet balance >/dev/null 2>&1; then \
	      $(BIN)/python -m pip uninstall --quiet --yes balance; fi

$(RUN): pyproject.toml setup.py | $(VENV)/bin/python
	@$(OLD_NAME)
	$(BIN)/python -m pip install --quiet --disable-pip-version-check -e .
	@touch $(RUN)

$(TORSION): pyproject.toml setup.py | $(VENV)/bin/python
	@$(OLD_NAME)
	$(BIN)/python -m pip install --quiet --disable-pip-version-check -e '.[torsion]'
	@touch $(RUN) $(TORSION)

$(STAMP): pyproject.toml setup.py | $(VENV)/bin/python
	@$(OLD_NAME)
	$(BIN)/python -m pip install --quiet --disable-pip-version-check -e '.[test]'
	@touch $(RUN) $(STAMP)

$(LINT): pyproject.toml setup.py | $(VENV)/bin/python
	@$(OLD_NAME)
	$(BIN)/python -m pip install --quiet --disable-pip-version-check -e '.[lint]'
	@touch $(RUN) $(LINT)

$(DOCS): pyproject.toml setup.py | $(VENV)/bin/python
	@$(OLD_NAME)
	$(BIN)/python -m pip install --quiet --disable-pip-version-check -e '.[docs]'
	@touch $(RUN) $(DOCS)

setup: $(STAMP)

demo: $(TORSION)
	$(BIN)/balance validate configs
	$(BIN)/balance compare configs/tanaka-part3
	$(BIN)/balance report configs/tanaka-part3 --output report --html
	$(BIN)/balance torsion configs/today/inline/inline-6-truck-diesel.toml --criticals major

test: $(STAMP)
	$(BIN)/python -m pytest

# ruff (rules B, E, F, I, NPY, UP, W and the format), mypy on the package, and the import
# contracts: the layers of the package and no cycles (pyproject.toml)
lint: $(LINT)
	$(BIN)/ruff check balance_cli tests tools docs
	$(BIN)/ruff format --check balance_cli tests tools docs
	$(BIN)/mypy
	$(BIN)/lint-imports

# the documentation site in docs/_build/html: the tutorials and examples run, the reference is
# generated from the package (API, commands, configuration keys); any warning is an error and
# every cross-reference must resolve (-n). Nothing is fetched from the network. Then the built
# tutorials open in headless Chromium: their pictures load, their consoles show no error
# (tools/check_site.py; without Chromium it says so and passes).
docs: $(DOCS)
	rm -rf docs/_build docs/generated
	MPLBACKEND=Agg $(BIN)/python -m sphinx -b html -W --keep-going -n docs docs/_build/html
	$(BIN)/python tools/check_site.py docs/_build/html
	@echo "docs: docs/_build/html/index.html"

bench: $(STAMP)
	$(BIN)/python tools/bench.py

# docs/VALIDATION.md from tests/validation/reference (CI checks that the committed one is current)
validate: $(STAMP)
	$(BIN)/python tools/validation_report.py

# balance_cli/schemas/*.json, the JSON Schemas of the documents, from tools/json_schemas.py (a
# test checks that the committed ones are current)
schemas: $(STAMP)
	$(BIN)/python tools/json_schemas.py

# rewrite the golden regression tables after an intended change (balance regress --update);
# never in CI
regress-update: $(STAMP)
	$(BIN)/balance regress tests/golden/compare.json configs --update
	@git diff --stat -- tests/golden || true

# A regular install (not editable) of this checkout into a fresh environment in a temporary
# folder, used from another one: the command, the engine library and the templates installed
# as package data, the distribution's metadata. Prints each command's first lines; fails on
# any error (a command's, or output without what it must show). pip builds in the checkout's
# build/ (setuptools' scratch, which make clean removes): emptied first, so that nothing left
# there from an older tree is installed.
install-check:
	@set -e; tmp=$$(mktemp -d); trap 'rm -rf "$$tmp"' EXIT; passed=0; \
	  run() { expected=$$1; shift; echo "\$$ $$*"; "$$tmp/venv/bin/$$@" > "$$tmp/out.txt"; \
	          head -n 3 "$$tmp/out.txt" | cut -c 1-100; grep -q -e "$$expected" "$$tmp/out.txt" \
	          || { echo "install-check: $$1 printed no $$expected"; exit 1; }; \
	          passed=$$((passed + 1)); }; \
	  $(PYTHON) -m venv "$$tmp/venv"; rm -rf build; \
	  echo "pip install $(CURDIR) into $$tmp/venv"; \
	  "$$tmp/venv/bin/python" -m pip install --quiet --disable-pip-version-check "$(CURDIR)"; \
	  rm -rf build; mkdir "$$tmp/elsewhere"; cd "$$tmp/elsewhere"; \
	  run '^library:today/v (11 engines)' balance list; \
	  run '^9-cylinder rotary ' balance compare library:tanaka-part3; \
	  run '"results"' balance search template:inline-3-2stroke.toml --top 1 --format json; \
	  run 'GM LS3' balance show library:today/v/v8-90-cross-plane; \
	  run '^Name: engine-balance$$' pip show engine-balance; \
	  run '/site-packages/balance_cli/library$$' \
	    python -c 'import balance_cli.config.library as l; print(l.library_folder())'; \
	  run '^balance compare document, version 3$$' \
	    python -c 'from balance_cli.schemas import schema; print(schema("compare")["title"])'; \
	  run 'balance animate: an engine turning' \
	    python -c 'from balance_cli.plot.page import script; print(script()[:80])'; \
	  echo "install-check: $$passed passed, 0 failed"

clean:
	rm -rf $(VENV) build *.egg-info .pytest_cache docs/_build docs/generated
