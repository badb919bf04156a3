# make demo / make test each work from nothing: they create .venv and install what they need.
SHELL := /bin/bash
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
PIP := $(VENV)/bin/pip
STAMP := $(VENV)/.installed
PYTEST_ARGS ?=

.PHONY: demo test install sysdeps bench clean docs docs-pages docs-examples

$(STAMP): pyproject.toml
	@$(MAKE) --no-print-directory sysdeps
	@test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PIP) install -q --upgrade pip setuptools wheel
	$(PIP) install -q -e ".[test,docs]"
	@touch $(STAMP)

install: $(STAMP) viewer

# The web viewer of `ws publish`: web/ (npm: three, copc, laz-perf; esbuild) bundled into
# workstation/publish/viewer/ with the licences of what it vendors. The bundle is committed, so
# a machine without Node.js uses it as is; it is rebuilt only when web/ changed and npm exists.
VIEWER_BUNDLE := workstation/publish/viewer/viewer.js
.PHONY: viewer
viewer: $(VIEWER_BUNDLE)
$(VIEWER_BUNDLE): web/package.json web/package-lock.json web/build.mjs $(wildcard web/src/*) $(wildcard web/licenses/*)
	@if command -v npm >/dev/null; then \
	  echo "Building the web viewer (npm ci + esbuild)..."; \
	  (cd web && npm ci --no-audit --no-fund --loglevel=error && node build.mjs) \
	    || { [ -f $@ ] && echo "viewer build failed: keeping the committed bundle $@"; } || exit 1; \
	elif [ -f $@ ]; then \
	  echo "npm not found: keeping the committed viewer bundle $@ (install Node.js and npm to rebuild it)"; \
	else \
	  echo "npm not found and $@ is missing: install Node.js and npm, then run make viewer"; exit 1; \
	fi

# System libraries from Debian: libusb for open3d; EGL/Mesa for VTK's off-screen rendering
# with no display; chromium only for the HTML-report test (best effort: that test skips
# without it).
SYSLIBS := libusb-1.0-0 libegl1 libegl-mesa0 libgl1-mesa-dri
sysdeps:
	@missing=""; for p in $(SYSLIBS); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = "0" ] && command -v apt-get >/dev/null; then \
	    echo "Installing$$missing (system libraries for open3d and off-screen rendering)..."; \
	    (apt-get install -y -qq $$missing >/dev/null 2>&1 || (apt-get update -qq && apt-get install -y -qq $$missing >/dev/null)) \
	      || { echo "apt-get could not install$$missing"; exit 1; }; \
	  else \
	    echo "Missing system libraries. Run: sudo apt-get install -y$$missing"; exit 1; \
	  fi; \
	fi
	@if ! command -v chromium >/dev/null && [ "$$(id -u)" = "0" ] && command -v apt-get >/dev/null; then \
	  echo "Installing chromium (used by the HTML report test)..."; \
	  (apt-get install -y -qq chromium >/dev/null 2>&1 || (apt-get update -qq && apt-get install -y -qq chromium >/dev/null 2>&1)) \
	    || echo "chromium not installed: the report rendering test will be skipped"; \
	fi

demo: $(STAMP) viewer
	$(VENV)/bin/ws demo -o demo_output --overwrite
	$(VENV)/bin/ws publish demo_output/classified.laz demo_output/raster_hillshade.tif -o demo_output/site --overwrite

test: $(STAMP) viewer
	$(PY) -m pytest -q $(PYTEST_ARGS)

# The user guide (MkDocs, in docs/guide; the tools are the `docs` extra, installed with the rest
# so that tests/test_docs.py builds it in `make test` too). docs-pages rewrites the generated
# pages (command pages from each command's --help, worked examples from their recorded output);
# docs-examples reruns every worked example first (minutes; the pages showing a real file need
# ../shared/data). The site goes to build/site.
docs-pages: $(STAMP)
	$(PY) scripts/gen_cli_docs.py

docs: docs-pages
	NO_MKDOCS_2_WARNING=1 $(VENV)/bin/mkdocs build --strict
	@echo "User guide: build/site/index.html"

docs-examples: $(STAMP)
	$(PY) scripts/gen_cli_docs.py --run-examples

# the benchmarks also need the `bench` extra (the CSF package they compare against); make test does not
BENCH_STAMP := $(VENV)/.installed-bench
$(BENCH_STAMP): $(STAMP)
	$(PIP) install -q -e ".[test,docs,bench]"
	@touch $(BENCH_STAMP)

bench: $(BENCH_STAMP)
	@for s in scripts/bench_*.py; do echo "== $$s"; $(PY) $$s; done

clean:
	rm -rf $(VENV) demo_output .pytest_cache build/site build/doc-examples
