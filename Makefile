# LadderLab: `make run` and `make test` do all set-up on a fresh machine
# (Python 3.11, Node and npm present; Debian packages installed with apt-get when missing).

PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
PIP    := $(VENV)/bin/pip
HOST   ?= 127.0.0.1
PORT   ?= 8000
SUDO   := $(shell [ "$$(id -u)" = 0 ] || echo sudo)
PYTEST_ARGS ?=
# pytest-xdist: one worker per core, each test file on one worker (its module fixtures built once, in order)
XDIST ?= -n auto --dist loadfile

.PHONY: run test lint test-slow bench schema frontend chromium clean

FRONTEND_DEPS := frontend/node_modules/.installed

run: $(VENV)/.installed frontend
	$(VENV)/bin/ladderlab serve --host $(HOST) --port $(PORT)

test: $(VENV)/.installed chromium $(FRONTEND_DEPS) frontend lint
	cd frontend && npm run --silent check:types && npm test --silent
	$(PY) -m pytest -q $(XDIST) $(PYTEST_ARGS)

# Lint, format and layer checks (docs/architecture.md), and ESLint (typescript-eslint, React hooks) on the frontend;
# `ruff format .` and `npm run format` (frontend) fix the format.
lint: $(VENV)/.installed $(FRONTEND_DEPS)
	$(VENV)/bin/ruff check .
	$(VENV)/bin/ruff format --check .
	$(VENV)/bin/lint-imports
	$(VENV)/bin/mypy
	cd frontend && npm run --silent format:check
	cd frontend && npm run lint -- --max-warnings 0

test-slow: $(VENV)/.installed chromium
	LADDERLAB_HYPOTHESIS=thorough $(PY) -m pytest -q $(XDIST) -m "slow or not slow" $(PYTEST_ARGS)

bench: $(VENV)/.installed
	@for script in benchmarks/*.py; do echo "== $$script"; $(PY) $$script || exit 1; done

# shared_schema/ (schemas, OpenAPI, IEC vocabulary, diagnostics), docs/diagnostics.md's table, frontend/src/generated/.
schema: $(VENV)/.installed $(FRONTEND_DEPS)
	$(PY) -m ladderlab.cli.shared
	cd frontend && npm run --silent gen:types

# The virtual environment is rebuilt whenever pyproject.toml changes.
$(VENV)/.installed: pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(PIP) install --quiet --upgrade pip
	$(PIP) install --quiet -e '.[test]'
	touch $@

# Frontend packages are reinstalled whenever the lock file changes.
$(FRONTEND_DEPS): frontend/package-lock.json
	cd frontend && npm ci --no-audit --no-fund
	touch $@

# The browser app is built into the server's static folder (backend/ladderlab/server/static).
frontend: $(FRONTEND_DEPS)
	cd frontend && npm run build

# Browser tests drive Debian's chromium (never a downloaded browser).
chromium:
	@command -v chromium >/dev/null 2>&1 || { \
		echo "installing Debian's chromium for the browser tests"; \
		$(SUDO) apt-get update -qq && \
		DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends chromium >/dev/null; }

clean:
	rm -rf $(VENV) frontend/node_modules frontend/dist backend/ladderlab/server/static .pytest_cache .hypothesis
