# camdyn: two commands do everything on a fresh machine (Python 3.11 + a C compiler):
#   make run    virtual environment, install, build, main job -> out/report.md + charts
#   make test   virtual environment, install, build, test suite (both cores, slow checks left out)
PYTHON ?= python3
VENV   ?= .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.camdyn-built
SOURCES := pyproject.toml setup.py $(wildcard generated/*.pyx generated/*.pxd runtime/*.pyx runtime/*.pxd runtime/*.pxi)

.PHONY: all build run test test-slow mutation bench figures derive check-generated clean

all: build

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip

# pip builds the Cython extensions (Cython is a build requirement in pyproject.toml)
$(STAMP): $(SOURCES) | $(BIN)/python
	$(BIN)/python -m pip install --quiet -e '.[test]'
	touch $@

build: $(STAMP)

run: build
	$(BIN)/camdyn run --out out

test: build
	$(BIN)/python -m pytest -q -n auto -m "not slow"

# the checks marked slow (long runs, full grids); CI runs them after make test
test-slow: build
	$(BIN)/python -m pytest -q -n auto -m slow

# mutation testing of the pure-Python physics in scratch copies of the tree; report in
# out/mutation/report.md (targets, sample and time budget: tests/mutation/targets.toml)
mutation: build
	$(BIN)/python -m pip install --quiet 'cosmic-ray>=8.4'
	$(BIN)/python tests/mutation/run.py

bench: build
	$(BIN)/python bench/run.py
	$(BIN)/python bench/beam.py

figures: build
	$(BIN)/camdyn run --out out

derive: build
	$(BIN)/camdyn derive
	$(MAKE) build

check-generated: build
	$(BIN)/camdyn derive --check

clean:
	rm -rf build out *.egg-info $(STAMP)
	find generated runtime bench -name '*.so' -delete -o -name '*.c' -delete
