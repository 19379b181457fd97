# Language bindings (docs/bindings.md), tested on the shared library of
# $(BUILD):
#   make check-python    pytest on the installed package (pip install of
#                        bindings/python and of its sdist, in fresh venvs),
#                        then on the checkout with CAROM_LIBRARY
#   make check-rust      cargo test in bindings/rust/carom-sys: bundled (no
#                        environment, no prior make), then the system
#                        feature on a staged install (pkg-config);
#                        skipped (and counted as skipped) when cargo is
#                        missing; under CI a missing cargo fails
#   make check-bindings  check-abi, check-install, check-python, check-rust,
#                        one after the other; fails if any failed
# (check-abi is in mk/abi.mk, check-install in mk/install.mk.)

PYTHON ?= python3
# rustup puts cargo in ~/.cargo/bin, which a non-login shell may not have.
CARGO  ?= $(or $(shell command -v cargo 2>/dev/null),$(wildcard $(HOME)/.cargo/bin/cargo),cargo)

BINDINGS_LIB_DIR := $(abspath $(BUILD))

.PHONY: check-python check-rust check-bindings

# The installed package, twice, each in a fresh venv, tested from outside
# the source tree: the wheel pip builds from bindings/python (the C library
# compiled into it), and the one it builds from the sdist that
# `python -m build` makes (the C sources travel in it). No CAROM_LIBRARY:
# the package loads its own copy. Then the checkout's package on the build
# tree's library (CAROM_LIBRARY), as a developer runs it.
PY_DIR := $(abspath $(BUILD))/python
check-python: $(BUILD)/libcarom.so
	@tools/ensure-deps python
	@rm -rf $(PY_DIR) && mkdir -p $(PY_DIR)/run
	@$(PYTHON) -m venv $(PY_DIR)/venv
	@$(PY_DIR)/venv/bin/python -m pip install --quiet --upgrade pip setuptools wheel build pytest \
	  && { $(PY_DIR)/venv/bin/python -m pip install --quiet matplotlib || echo "check-python: no matplotlib: carom.draw is tested with a stand-in only"; } \
	  || { echo "check-python: cannot install pip, setuptools, build, pytest from PyPI"; \
	       echo "check-python: 0 passed, 1 failed"; exit 1; }
	@echo "check-python: pip install ./bindings/python in a fresh venv, tests run from $(PY_DIR)/run"
	@cd $(PY_DIR)/run && $(PY_DIR)/venv/bin/python -m pip install --quiet $(abspath bindings/python)
	@cd $(PY_DIR)/run && CAROM_TEST_INSTALLED=1 PYTHONDONTWRITEBYTECODE=1 \
	  $(PY_DIR)/venv/bin/python -m pytest -p no:cacheprovider -q $(abspath bindings/python/tests)
	@echo "check-python: python -m build --sdist, then pip install of the sdist in another fresh venv"
	@$(PY_DIR)/venv/bin/python -m build --sdist --no-isolation --outdir $(PY_DIR)/dist bindings/python >/dev/null 2>&1
	@$(PYTHON) -m venv $(PY_DIR)/venv-sdist
	@$(PY_DIR)/venv-sdist/bin/python -m pip install --quiet --upgrade pip setuptools pytest
	@cd $(PY_DIR)/run && $(PY_DIR)/venv-sdist/bin/python -m pip install --quiet $(PY_DIR)/dist/carom-*.tar.gz
	@cd $(PY_DIR)/run && CAROM_TEST_INSTALLED=1 PYTHONDONTWRITEBYTECODE=1 \
	  $(PY_DIR)/venv-sdist/bin/python -m pytest -p no:cacheprovider -q $(abspath bindings/python/tests)
	@echo "check-python: the checkout's package on $(BINDINGS_LIB_DIR)/$(SONAME) (CAROM_LIBRARY)"
	@CAROM_LIBRARY=$(BINDINGS_LIB_DIR)/$(SONAME) PYTHONDONTWRITEBYTECODE=1 \
	  $(PY_DIR)/venv/bin/python -m pytest -p no:cacheprovider -q bindings/python/tests
	@rm -rf bindings/python/build bindings/python/carom.egg-info

# The crate's target directory lives in $(BUILD), not in the source tree.
# --locked: Cargo.lock is committed and must not change. First as a user
# runs it: no environment variables, no prior make (the `bundled` feature
# builds the C sources in); then the `system` feature against a staged
# install found through pkg-config.
RUST_STAGE := $(abspath $(BUILD))/rust-stage
check-rust: $(BUILD)/libcarom.so
	@if ! command -v $(CARGO) >/dev/null 2>&1; then \
	  if [ -n "$${CI:-}" ]; then echo "check-rust: cargo not found: the Rust binding cannot be tested"; \
	    echo "check-rust: 0 passed, 1 failed"; exit 1; fi; \
	  echo "check-rust: cargo not found, Rust binding not tested (install Rust: rustup, or apt-get install cargo)"; \
	  echo "check-rust: 0 passed, 0 failed, 1 skipped"; exit 0; fi; \
	set -x; \
	env -u CAROM_LIB_DIR -u CAROM_STATIC CARGO_TARGET_DIR=$(BINDINGS_LIB_DIR)/rust \
	  $(CARGO) test --locked --manifest-path bindings/rust/carom-sys/Cargo.toml && \
	rm -rf $(RUST_STAGE) && \
	$(MAKE) --no-print-directory BUILD=$(BUILD) install DESTDIR=$(RUST_STAGE) PREFIX=/usr >/dev/null && \
	env -u CAROM_LIB_DIR PKG_CONFIG_PATH=$(RUST_STAGE)/usr/lib/pkgconfig PKG_CONFIG_SYSROOT_DIR=$(RUST_STAGE) \
	  LD_LIBRARY_PATH=$(RUST_STAGE)/usr/lib CARGO_TARGET_DIR=$(BINDINGS_LIB_DIR)/rust-system \
	  $(CARGO) test --locked --no-default-features --features system \
	  --manifest-path bindings/rust/carom-sys/Cargo.toml

# One after the other: the scripts build into $(BUILD) themselves.
check-bindings:
	@rc=0; for t in check-abi check-install check-python check-rust; do \
	  echo "== $$t"; \
	  $(MAKE) --no-print-directory BUILD=$(BUILD) $$t || { rc=1; echo "== $$t FAILED"; }; \
	done; exit $$rc
