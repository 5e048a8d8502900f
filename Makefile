# The two newcomer commands: `make book` and `make test`. Each does its own set-up.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed-$(shell cat requirements.lock pyproject.toml 2>/dev/null | cksum | cut -d' ' -f1)
JB     := $(BIN)/jupyter-book
# Whole-book parameter overrides: make book PARAMS=my-params.toml (see README).
PARAMS ?=
export MAGBENCH_PARAMS := $(if $(PARAMS),$(abspath $(PARAMS)),)
# One BLAS thread: reproducible timings on two cores, no oversubscription.
export OMP_NUM_THREADS := 1
export OPENBLAS_NUM_THREADS := 1
export MPLBACKEND := Agg
# The footer's date is the last commit's (reproducible builds: two builds of one commit
# give the same pages); set SOURCE_DATE_EPOCH yourself to stamp another.
export SOURCE_DATE_EPOCH ?= $(shell git log -1 --format=%ct 2>/dev/null)

.PHONY: book book-unlocked test pytest sweep book-check book-check-unlocked env lock bench bench-peers clean checksums

env: $(STAMP)

# The stamp's name carries the checksum of the lock file and pyproject, so it needs no
# file-time prerequisites (a fresh checkout or worktree has newer mtimes, same content).
$(STAMP):
	@$(PYTHON) -c 'import sys; sys.exit(sys.version_info < (3, 11))' || \
	  { echo "magbench needs Python >= 3.11 (set PYTHON=...)"; exit 1; }
	rm -rf $(VENV)
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --disable-pip-version-check -r requirements.lock
	$(BIN)/python -m pip install --quiet --disable-pip-version-check --no-deps --no-build-isolation -e .
	$(BIN)/python -c "import matplotlib.pyplot"   # build the font cache once, outside the book
	touch $(STAMP)

# Builds of one clone share _build: a second `make book` or `make book-check` started
# while one runs waits for it (flock on _build/.lock) instead of clashing with it.
LOCK   := _build/.lock
define locked
	@mkdir -p _build
	@flock -n $(LOCK) true || echo "make: another book build is running in this clone; waiting for it ($(LOCK))"
	@flock $(LOCK) $(MAKE) --no-print-directory $(1)
endef

# A parameter file that does not exist, or that names an unknown parameter, is refused
# before anything is built (every page would otherwise fail on it).
define check_params
	@if [ -n "$(PARAMS)" ] && [ ! -f "$(PARAMS)" ]; then \
	  echo "make: PARAMS=$(PARAMS): no such file (a TOML file of SI overrides, see README)"; exit 2; fi
	@if [ -n "$(PARAMS)" ]; then $(BIN)/python tools/check_params.py "$(PARAMS)"; fi
endef

# Each stage of `make book` and `make test` is timed; the times are printed at the end.
define stage
	@$(BIN)/python tools/stages.py run $(STAGES) $(1) -- $(2)
endef

# The book, with the execution cache invalidated whenever the library, data, lock file
# or parameter overrides change (jupyter-cache itself only looks at cell sources). The
# pages are executed on both cores first (tools/execute_pages.py), then built; the
# expensive results (studies, figures' numbers) are computed once into the result cache
# (magbench.result_cache), where the summary pages and the command line find them.
book: $(STAMP)
	$(check_params)
	$(call locked,book-unlocked)

book-unlocked: export MAGBENCH_RESULT_CACHE = $(CURDIR)/_build/results
book-unlocked: STAGES = _build/stages.log
book-unlocked:
	@rm -rf _build/html/reports $(STAGES)   # a failed build's logs would otherwise outlive it
	$(call stage,fingerprint,$(BIN)/python tools/fingerprint.py --cache _build/.jupyter_cache --doctrees _build/.doctrees --results _build/results --stamp _build/.fingerprint)
	$(call stage,execute,$(BIN)/python tools/execute_pages.py --cache _build/.jupyter_cache)
	$(call stage,build,$(JB) build . -W -n --keep-going)
	$(call stage,check-html,$(BIN)/python tools/check_book.py _build/html)
	@$(BIN)/python tools/stages.py report $(STAGES)

# Tests: the whole book built from scratch as a test (an empty execution cache and an
# empty result cache), checked in the HTML (tools/check_book.py) and in headless Chromium
# (tools/browser_check.py); then the pytest suite, which reads the results the book
# computed from the same result cache instead of computing them a second time.
TEST_RESULTS := $(CURDIR)/_build/test/results
TEST_STAGES  := _build/test/stages.log
test: book-check pytest
	@$(BIN)/python tools/stages.py report $(TEST_STAGES)

# On both cores; a test module stays on one worker (--dist loadfile), so its module-scoped
# fixtures (the chapters' source checks, the long simulations) are computed once.
pytest: export MAGBENCH_RESULT_CACHE = $(TEST_RESULTS)
pytest: STAGES = $(TEST_STAGES)
pytest: $(STAMP)
	$(call stage,pytest,$(BIN)/python -m pytest -n 2 --dist loadfile)

book-check: $(STAMP)
	$(check_params)
	$(call locked,book-check-unlocked)

book-check-unlocked: export MAGBENCH_RESULT_CACHE = $(TEST_RESULTS)
book-check-unlocked: STAGES = $(TEST_STAGES)
book-check-unlocked:
	rm -rf _build/test
	$(call stage,execute,$(BIN)/python tools/execute_pages.py --cache _build/test/_build/.jupyter_cache)
	$(call stage,build,$(JB) build . --path-output _build/test -W -n --keep-going)
	$(call stage,check-html,$(BIN)/python tools/check_book.py _build/test/_build/html)
	@$(BIN)/python tools/stages.py run $(STAGES) check-browser -- $(BIN)/python tools/browser_check.py _build/test/_build/html; status=$$?; \
	if [ $$status -eq 3 ]; then \
	  echo "browser check SKIPPED: Chromium is not installed; install it with: apt-get install -y chromium"; \
	elif [ $$status -ne 0 ]; then exit $$status; fi

# Every chapter (1-8) re-run with each of its inputs halved and doubled, on both cores
# (chapters 1-3 are also in `make pytest`; 4-8 carry the `sweep` marker it deselects).
# A case computes only what reads the scaled input: the studies no scaled input touches
# come from the result cache `make test` filled (or are computed once into it).
sweep: export MAGBENCH_RESULT_CACHE = $(TEST_RESULTS)
sweep: STAGES = _build/sweep-stages.log
sweep: $(STAMP)
	@mkdir -p _build && rm -f $(STAGES)
	$(call stage,sweep,$(BIN)/python -m pytest -n 2 --dist worksteal --durations=20 -m "sweep or not sweep" tests/chapters/test_input_sweep.py)
	@$(BIN)/python tools/stages.py report $(STAGES)

bench: $(STAMP)
	$(BIN)/python benchmarks/run.py

# Opt-in: B-dot detumbling member by member in Basilisk and in magbench. Basilisk (the bsk
# wheel, 73 MB) is a peer, not a dependency: it goes into _build/bsk-site, outside the
# environment, with the two modules it imports that the lock file lacks (colorama, pooch);
# the rest of its requirements are in the lock file, at newer versions, which it runs with.
BSK_SITE := _build/bsk-site
bench-peers: $(STAMP)
	@if [ ! -d $(BSK_SITE)/Basilisk ]; then \
	  $(BIN)/python -m pip install --quiet --disable-pip-version-check --no-deps --target $(BSK_SITE) \
	    bsk==2.12.1 colorama==0.4.6 pooch==1.9.0; fi
	PYTHONPATH=$(BSK_SITE) $(BIN)/python benchmarks/run.py peers_basilisk

# Re-resolve requirements.in into the committed lock file (maintainers only).
lock:
	rm -rf _build/lockenv
	$(PYTHON) -m venv _build/lockenv
	_build/lockenv/bin/python -m pip install --quiet -r requirements.in
	_build/lockenv/bin/python -m pip freeze --all | grep -v '^pip==' > requirements.lock

clean:
	rm -rf _build

# Record the checksums of the data folders (one manifest per source folder) after a
# deliberate, reviewed change to a data file.
checksums:
	for d in magbench/data/*/; do \
	  (cd $$d && find . -type f ! -name SHA256SUMS | sed 's|^\./||' | LC_ALL=C sort | xargs -r sha256sum > SHA256SUMS); \
	done
