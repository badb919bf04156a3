# make demo / make test each work from nothing: they create .venv and install what they need.
SHELL := /bin/bash
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
PIP := $(VENV)/bin/pip
STAMP := $(VENV)/.installed
PYTEST_ARGS ?=

.PHONY: demo test install sysdeps bench clean

$(STAMP): pyproject.toml
	@$(MAKE) --no-print-directory sysdeps
	@test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PIP) install -q --upgrade pip setuptools wheel
	$(PIP) install -q -e ".[test]"
	@touch $(STAMP)

install: $(STAMP)

# open3d needs libusb-1.0 from Debian.
sysdeps:
	@if ! ldconfig -p 2>/dev/null | grep -q 'libusb-1.0.so.0'; then \
	  if [ "$$(id -u)" = "0" ] && command -v apt-get >/dev/null; then \
	    echo "Installing libusb-1.0-0 (needed by open3d)..."; \
	    (apt-get install -y -qq libusb-1.0-0 >/dev/null 2>&1 || (apt-get update -qq && apt-get install -y -qq libusb-1.0-0 >/dev/null)); \
	  else \
	    echo "open3d needs the system library libusb-1.0. Run: sudo apt-get install -y libusb-1.0-0"; exit 1; \
	  fi; \
	fi

demo: $(STAMP)
	$(VENV)/bin/ws demo -o demo_output --overwrite

test: $(STAMP)
	$(PY) -m pytest -q $(PYTEST_ARGS)

bench: $(STAMP)
	@for s in scripts/bench_*.py; do echo "== $$s"; $(PY) $$s; done

clean:
	rm -rf $(VENV) demo_output .pytest_cache
