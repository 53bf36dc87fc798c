# planargeo: two commands do all set-up on a fresh machine.
#   make lab    create .venv if missing, install planargeo with its extras, start JupyterLab
#   make test   create/update .venv, install everything the tests need, run the whole suite
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed-stamp
ROOT_FLAG := $(if $(filter 0,$(shell id -u)),--allow-root,)
PYTEST_ARGS ?=

.PHONY: lab test install gallery bench clean help

help:
	@echo "make lab    - set up .venv and start JupyterLab on notebooks/00-tour.ipynb"
	@echo "make test   - set up .venv and run the whole test suite"
	@echo "make gallery- regenerate gallery/*.svg"
	@echo "make bench  - run the benchmarks and rewrite benchmarks/results"

$(BIN)/python:
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip

$(STAMP): pyproject.toml | $(BIN)/python
	$(BIN)/python -m pip install --quiet -e '.[dev]'
	@touch $(STAMP)

install: $(STAMP)

lab: $(STAMP)
	$(BIN)/jupyter lab $(ROOT_FLAG) --notebook-dir=notebooks 00-tour.ipynb

test: $(STAMP)
	MPLBACKEND=Agg $(BIN)/python -m pytest -n 2 $(PYTEST_ARGS)

gallery: $(STAMP)
	MPLBACKEND=Agg $(BIN)/planargeo gallery

bench: $(STAMP)
	MPLBACKEND=Agg $(BIN)/planargeo bench

clean:
	rm -rf $(VENV) build *.egg-info
