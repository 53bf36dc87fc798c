# planargeo: two commands do all set-up on a fresh machine.
#   make lab    create .venv if missing, install planargeo with its extras, start JupyterLab
#               (on 127.0.0.1 only, with a fresh random token: see LAB_FLAGS)
#   make test   create/update .venv, install everything the tests need, run the whole suite
#   make fuzz   at least 10^4 generated calls against the public API, a table of outcomes
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
	@echo "make fuzz   - 10^4+ generated calls with hostile arguments, a table of outcomes"
	@echo "make gallery- regenerate gallery/*.svg"
	@echo "make bench  - run the benchmarks and rewrite benchmarks/results"
	@echo "make docs   - build the documentation site into docs/_build/html"
	@echo "make notebooks - run every notebook deterministically and store its outputs in place"
	@echo "make app    - serve every explorer as a web page (Voila, 127.0.0.1:8866)"
	@echo "make screens- regenerate docs/screens/*.png from the app in headless chromium"

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip

$(STAMP): pyproject.toml | $(BIN)/python
	$(BIN)/python -m pip install --quiet -e '.[dev]'
	$(BIN)/python -m planargeo.algorithms.compiled --warm
	@touch $(STAMP)

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

# Voila runs the app notebook and shows only its outputs; 127.0.0.1 only.
app: $(STAMP)
	$(BIN)/voila app/planargeo-app.ipynb --Voila.ip=127.0.0.1 --port=8866 --theme=light --no-browser

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
