# planargeo: two commands do all set-up on a fresh machine.
#   make lab    create .venv if missing, install planargeo with its extras, start JupyterLab
#               (on 127.0.0.1 only, with a fresh random token: see LAB_FLAGS)
#   make test   create/update .venv, install everything the tests need, run the whole suite
#   make fuzz   8000 generated calls from each parameter's domain (explorers through mouse and page paths)
#   make docs   the documentation site in docs/_build/html (Sphinx; warnings are errors)
#   make app    every explorer as a web page without code (Voila on app/planargeo-app.ipynb, 127.0.0.1)
#   make screens  regenerate docs/screens/*.png (each explorer in its default state, in the app)
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed-stamp
ROOT_FLAG := $(if $(filter 0,$(shell id -u)),--allow-root,)
PYTEST_ARGS ?=
FUZZ_ARGS ?=
# JupyterLab listens on the loopback interface only and asks for a token: scripts/lab.py makes a fresh
# random one per start, puts address and token last on Jupyter's command line (so no configuration file
# can switch them off or open the port) and prints the URL to paste, token included.  LAB_FLAGS: more
# of Jupyter's options (e.g. --no-browser --ServerApp.port=9999); the address and token cannot be changed.
LAB_FLAGS ?=

.PHONY: lab test fuzz install gallery bench clean help browser docs notebooks app screens

help:
	@echo "make lab    - set up .venv and start JupyterLab on notebooks/00-tour.ipynb (localhost, token)"
	@echo "make test   - set up .venv and run the whole test suite"
	@echo "make fuzz   - 8000 generated calls from each parameter's domain, a table of outcomes"
	@echo "make gallery- regenerate gallery/*.svg"
	@echo "make bench  - run the benchmarks and rewrite benchmarks/results"
	@echo "make docs   - build the documentation site into docs/_build/html"
	@echo "make notebooks - run every notebook deterministically and store its outputs in place"
	@echo "make app    - serve every explorer as a web page (Voila, 127.0.0.1:8866)"
	@echo "make screens- regenerate docs/screens/*.png from the app in headless chromium"

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip

# Two steps, two stamps: pip installs when pyproject.toml changes; numba's cache of the compiled kernels is
# filled again when the install or a kernel source changes (numba keys its cache to kernels.py alone, and
# freezes the limits kernels.py imports from errors.py and subspaces.py into the machine code: when one of
# those changes, kernels.py's time is renewed so that numba compiles afresh instead of loading stale code).
PIP_STAMP      := $(VENV)/.pip-stamp
KERNEL_SOURCES := planargeo/algorithms/kernels.py planargeo/algorithms/compiled.py
KERNEL_LIMITS  := planargeo/errors.py planargeo/mechanics/subspaces.py
# the label placer's two loops (numba too): every picture's labels; compiled with the kernels
PLACER_SOURCE  := planargeo/draw/_labels.py

$(PIP_STAMP): pyproject.toml | $(BIN)/python
	$(BIN)/python -m pip install --quiet -e '.[dev]'
	@touch $(PIP_STAMP)

# `make -n lab STAMP=Makefile` (tests/test_readme.py: the set-up taken as done) must not remake this Makefile:
# GNU make runs the recipe of a rule that remakes a makefile even under -n, so then no rule names it.
ifneq ($(STAMP),Makefile)
$(STAMP): $(PIP_STAMP) $(KERNEL_SOURCES) $(KERNEL_LIMITS) $(PLACER_SOURCE)
	@if [ -f $(STAMP) ] && [ -n "$(filter $(KERNEL_LIMITS),$?)" ]; then \
	  echo "kernel limits changed ($(filter $(KERNEL_LIMITS),$?)): the kernels are compiled afresh"; \
	  touch planargeo/algorithms/kernels.py; fi
	$(BIN)/python -m planargeo.algorithms.compiled --warm
	$(BIN)/python -c "from planargeo.draw.picture import warm_labels; warm_labels()"
	@touch $(STAMP)
endif

install: $(STAMP)

lab: $(STAMP)
	$(BIN)/python scripts/lab.py $(ROOT_FLAG) $(LAB_FLAGS) notebooks/00-tour.ipynb

# Debian's chromium drives the real-browser test (Playwright's own download does not work here);
# Debian's ffmpeg writes the explorers' MP4 exports (GIF needs only pillow).
browser:
	@missing=""; command -v chromium >/dev/null 2>&1 || missing="chromium"; \
	command -v ffmpeg >/dev/null 2>&1 || missing="$$missing ffmpeg"; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then \
	    echo "installing Debian's$$missing"; \
	    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing >/dev/null; \
	  else echo "not found and cannot be installed:$$missing (browser test / MP4 export will be skipped)"; fi; fi

# Voila runs the app notebook and shows only its outputs, one kernel (Python process) per visitor;
# app/config/voila.py sets the seat limit and idle culling (docs/serving.md).
#   APP_IP        127.0.0.1 (this computer only); any other address (0.0.0.0: every network of this
#                 computer, e.g. a classroom's) also turns on a fresh random token, printed in the URL
#   APP_VISITORS  seats: visitor APP_VISITORS + 1 gets "The class is full" (0: no limit); the default
#                 is chosen from benchmarks/results/classroom.md (2 cores, 24 GiB; docs/serving.md)
#   APP_IDLE      seconds without activity (drag, slider, Play) after which a visitor's seat is freed
#   APP_TOKEN     --token to ask for a token on 127.0.0.1 too
APP_IP       ?= 127.0.0.1
APP_PORT     ?= 8866
APP_VISITORS ?= 8
APP_IDLE     ?= 900
APP_TOKEN    ?= $(if $(filter 127.0.0.1 localhost ::1,$(APP_IP)),,--token)
app: $(STAMP)
	$(BIN)/voila app/planargeo-app.ipynb --Voila.ip=$(APP_IP) --port=$(APP_PORT) --theme=light --no-browser \
	  $(APP_TOKEN) --Voila.config_file_paths=app/config \
	  --ClassroomKernelManager.max_kernels=$(APP_VISITORS) --MappingKernelManager.cull_idle_timeout=$(APP_IDLE)

screens: $(STAMP) browser
	MPLBACKEND=Agg PLANARGEO_UPDATE_SCREENS=1 $(BIN)/python -m pytest -p no:randomly -q tests/browser/test_browser_explorers.py -k in_the_app

test: $(STAMP) browser
	MPLBACKEND=Agg $(BIN)/python -m pytest -n 2 tests planargeo $(PYTEST_ARGS)
	$(MAKE) --no-print-directory docs

fuzz: $(STAMP)
	MPLBACKEND=Agg $(BIN)/python tests/fuzz/run.py --calls 8000 --seed 0 --time-limit 20 $(FUZZ_ARGS)

# The site: lessons (stored outputs), gallery, API reference, equations, errata, benchmarks.
# Warnings are errors; every warning is listed before it fails (--keep-going).
# Then docs/check_site.py opens it in headless chromium (file://, no network): every figure and
# equation of the index, the gallery, an API page and every lesson must show.
docs: $(STAMP)
	MPLBACKEND=Agg $(BIN)/python -m sphinx -W --keep-going -q -b html docs docs/_build/html
	MPLBACKEND=Agg $(BIN)/python docs/check_site.py docs/_build/html
	@echo "site: docs/_build/html/index.html"

gallery: $(STAMP)
	MPLBACKEND=Agg $(BIN)/planargeo gallery

# The lessons are committed with their outputs; tests/test_notebook_outputs.py checks them against a
# fresh run. NOTEBOOKS_ARGS: e.g. `03 05` (only those lessons) or `--check` (compare, write nothing).
NOTEBOOKS_ARGS ?=
notebooks: $(STAMP)
	PYTHONPATH=$(CURDIR) $(BIN)/python notebooks/run_all.py -j 2 $(NOTEBOOKS_ARGS)

bench: $(STAMP)
	MPLBACKEND=Agg $(BIN)/python benchmarks/run.py --out benchmarks/results --summary benchmarks/RESULTS.md --gallery gallery/benchmarks

clean:
	rm -rf $(VENV) build *.egg-info docs/_build docs/_gen
