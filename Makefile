# camdyn: two commands do everything on a fresh machine (Python 3.11 + a C compiler):
#   make run    virtual environment, install, build, main job -> out/report.md + charts
#   make test   virtual environment, install, build, test suite (both cores, slow checks left out)
PYTHON ?= python3
VENV   ?= .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.camdyn-built
SOURCES := pyproject.toml setup.py $(wildcard generated/*.pyx generated/*.pxd runtime/engine/*.pyx runtime/engine/*.pxd runtime/engine/*.pxi)

.PHONY: all build browser docs run test test-slow wheel-check mutation mutation-findings bench bench-quick figures derive check-generated clean

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

test: build browser
	$(BIN)/python -m pytest -q -n auto -m "not slow"

# the browser the design page's test drives: Debian's Chromium through apt-get where it is
# missing and the machine lets us (root), never a browser downloaded by Playwright; without
# it that one test is skipped, saying so
browser:
	@command -v chromium >/dev/null || command -v chromium-browser >/dev/null || \
		{ [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null && \
		  (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium >/dev/null) ; } || \
		echo "make browser: no chromium, and no root to install Debian's; the browser test is skipped"

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

# The requirements an extra of pyproject.toml adds, its references to other extras
# (camdyn[dask]) followed, installed by pip: make bench and make mutation install their extra
# so, not by reinstalling camdyn (which would compile every extension again). pip passes over
# what is installed already in a second or two, so a requirement added to an extra is installed
# by the next run, whatever it is.
define INSTALL_EXTRA
import subprocess, sys, tomllib
extras = tomllib.load(open("pyproject.toml", "rb"))["project"]["optional-dependencies"]
def follow(name):
    for req in extras[name]:
        if req.startswith("camdyn["):
            for sub in req[len("camdyn["):req.index("]")].split(","):
                yield from follow(sub.strip())
        else:
            yield req
reqs = list(dict.fromkeys(follow(sys.argv[1])))
subprocess.run([sys.executable, "-m", "pip", "install", "--quiet", *reqs], check=True)
endef
export INSTALL_EXTRA
install-extra = $(BIN)/python -c "$$INSTALL_EXTRA" $(1)

# the documentation site (docs/mkdocs.yml): the README's sections, the tutorial notebook run,
# the API reference; a warning fails the build.  Into out/site
docs: build
	$(call install-extra,docs)
	NO_MKDOCS_2_WARNING=1 $(BIN)/mkdocs build --strict --quiet -f docs/mkdocs.yml

# mutation testing of the pure-Python physics in scratch copies of the tree; report in
# out/mutation/report.md (targets, sample and time budget: tests/mutation/targets.toml)
mutation: build
	$(call install-extra,mutation)
	$(BIN)/python tests/mutation/run.py

# the five gaps a review of the suite found, as mutants, each with the test that kills it now
mutation-findings: build
	$(call install-extra,mutation)
	$(BIN)/python tests/mutation/findings.py

# the benchmarks; each writes its report into bench/results/ (BENCHMARKS.md is the index)
bench: build
	$(call install-extra,bench)
	$(BIN)/python bench/run.py
	$(BIN)/python bench/beam.py
	$(BIN)/python bench/stiff.py
	$(BIN)/python bench/scene_load.py
	$(BIN)/python bench/derive_time.py
	$(BIN)/python bench/derive_seeds.py --seeds 0 random random
	$(BIN)/python bench/sweep.py
	$(BIN)/python bench/atlas.py
	$(BIN)/python bench/startup.py

# every benchmark in miniature (seconds each), through the same code, reports and charts
# written into temporary folders (bench/results/ untouched): CI runs it, so that no benchmark
# rots unnoticed
bench-quick: build
	$(call install-extra,bench)
	$(BIN)/python bench/run.py --quick
	$(BIN)/python bench/beam.py --quick
	$(BIN)/python bench/stiff.py --quick
	$(BIN)/python bench/scene_load.py --quick
	$(BIN)/python bench/derive_time.py --quick
	$(BIN)/python bench/derive_seeds.py --quick
	$(BIN)/python bench/sweep.py --quick
	$(BIN)/python bench/atlas.py --quick
	$(BIN)/python bench/startup.py --quick

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
