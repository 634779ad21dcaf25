# camdyn: two commands do everything on a fresh machine (Python 3.11 + a C compiler):
#   make run    virtual environment, install, build, main job -> out/report.md + charts
#   make test   virtual environment, install, build, test suite (both cores, slow checks left out)
PYTHON ?= python3
VENV   ?= .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.camdyn-built
SOURCES := pyproject.toml setup.py $(wildcard generated/*.pyx generated/*.pxd runtime/*.pyx runtime/*.pxd runtime/*.pxi)

.PHONY: all build run test test-slow wheel-check mutation mutation-findings bench figures derive check-generated clean

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

# what a user gets from `pip install .`: a non-editable install into a fresh virtual environment
# outside the checkout (so the source folders cannot stand in for missing packages), and the
# commands run from there
WHEEL_DIR := $(shell mktemp -d -u /tmp/camdyn-wheel-check.XXXXXX)
wheel-check:
	$(PYTHON) -m venv $(WHEEL_DIR)/venv
	$(WHEEL_DIR)/venv/bin/python -m pip install --quiet --upgrade pip
	$(WHEEL_DIR)/venv/bin/python -m pip install --quiet .
	cd $(WHEEL_DIR) && venv/bin/camdyn check > check.txt && tail -1 check.txt
	cd $(WHEEL_DIR) && venv/bin/camdyn simulate spring_loaded --json > simulate.json && \
		venv/bin/python -c "import json; s = json.load(open('simulate.json')); print('simulate spring_loaded: Xdd_min_rise', s['Xdd_min_rise'])"
	cd $(WHEEL_DIR) && venv/bin/camdyn residual --model camshaft1 --tau 0.15 --fa 2 --json
	$(PYTHON) -c "import re, sys; t = open('README.md').read(); \
		sys.stdout.write(re.search(r'user-model: oscillator.py -->\s*\x60\x60\x60python\n(.*?)\x60\x60\x60', t, re.S).group(1))" \
		> $(WHEEL_DIR)/oscillator.py
	cd $(WHEEL_DIR) && CAMDYN_CACHE_DIR=$(WHEEL_DIR)/cache venv/bin/camdyn integrate oscillator.py --t-end 3 --json
	cd $(WHEEL_DIR) && venv/bin/camdyn sweep camshaft1 --grid Fa=0,1 --grid tau=0.1:0.3:5 --out sweep --quiet
	cd $(WHEEL_DIR) && venv/bin/camdyn design --stroke 0.02 --tau 0.2 --fa 0.1 --accuracy 1e-4 --no-check --quiet | tail -3
	cd $(WHEEL_DIR) && venv/bin/camdyn simulate fig8_1b --model auto | grep chosen
	cd $(WHEEL_DIR) && venv/bin/camdyn figures --only 3.4 --out figures --quiet | tail -2
	rm -rf $(WHEEL_DIR)

# mutation testing of the pure-Python physics in scratch copies of the tree; report in
# out/mutation/report.md (targets, sample and time budget: tests/mutation/targets.toml)
# (the mutation extra is installed once: a reinstall of the package would recompile everything)
MUTATION_TOOLS = $(BIN)/python -c 'import cosmic_ray, Cython' 2>/dev/null || \
	$(BIN)/python -m pip install --quiet -e '.[test,mutation]'

mutation: build
	$(MUTATION_TOOLS)
	$(BIN)/python tests/mutation/run.py

# the five findings of issue 11 as mutants, each with the test that kills it now
mutation-findings: build
	$(MUTATION_TOOLS)
	$(BIN)/python tests/mutation/findings.py

bench: build
	$(BIN)/python -c 'import Cython' 2>/dev/null || $(BIN)/python -m pip install --quiet -e '.[test,bench]'
	$(BIN)/python bench/run.py
	$(BIN)/python bench/beam.py
	$(BIN)/python bench/stiff.py
	$(BIN)/python bench/scene_load.py
	$(BIN)/python bench/derive_time.py
	$(BIN)/python bench/derive_seeds.py --seeds 0 random random
	$(BIN)/python -c 'import distributed' 2>/dev/null || $(BIN)/python -m pip install --quiet 'dask[distributed]>=2024.1'
	$(BIN)/python bench/sweep.py

# every thesis and paper figure the models determine, with out/figures/index.html
figures: build
	$(BIN)/camdyn figures --out out/figures

derive: build
	$(BIN)/camdyn derive
	$(MAKE) build

check-generated: build
	$(BIN)/camdyn derive --check

clean:
	rm -rf build out *.egg-info $(STAMP)
	find generated runtime bench -name '*.so' -delete -o -name '*.c' -delete
