# Language bindings (docs/bindings.md), tested on the shared library of
# $(BUILD):
#   make check-python    pytest on bindings/python/tests (ctypes, CAROM_LIBRARY)
#   make check-rust      cargo test in bindings/rust/carom-sys (CAROM_LIB_DIR);
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

check-python: $(BUILD)/libcarom.so
	@$(PYTHON) -m pytest --version >/dev/null 2>&1 || $(PYTHON) -m pip install --quiet pytest \
	  || tools/ensure-deps python
	CAROM_LIBRARY=$(BINDINGS_LIB_DIR)/$(SONAME) PYTHONDONTWRITEBYTECODE=1 \
	  $(PYTHON) -m pytest -p no:cacheprovider -q bindings/python/tests

# The crate's target directory lives in $(BUILD), not in the source tree.
# --locked: Cargo.lock is committed and must not change.
check-rust: $(BUILD)/libcarom.so
	@if ! command -v $(CARGO) >/dev/null 2>&1; then \
	  if [ -n "$${CI:-}" ]; then echo "check-rust: cargo not found: the Rust binding cannot be tested"; \
	    echo "check-rust: 0 passed, 1 failed"; exit 1; fi; \
	  echo "check-rust: cargo not found, Rust binding not tested (install Rust: rustup, or apt-get install cargo)"; \
	  echo "check-rust: 0 passed, 0 failed, 1 skipped"; exit 0; fi; \
	set -x; \
	CAROM_LIB_DIR=$(BINDINGS_LIB_DIR) \
	LD_LIBRARY_PATH=$(BINDINGS_LIB_DIR)$${LD_LIBRARY_PATH:+:$$LD_LIBRARY_PATH} \
	CARGO_TARGET_DIR=$(BINDINGS_LIB_DIR)/rust \
	$(CARGO) test --locked --manifest-path bindings/rust/carom-sys/Cargo.toml

# One after the other: the scripts build into $(BUILD) themselves.
check-bindings:
	@rc=0; for t in check-abi check-install check-python check-rust; do \
	  echo "== $$t"; \
	  $(MAKE) --no-print-directory BUILD=$(BUILD) $$t || { rc=1; echo "== $$t FAILED"; }; \
	done; exit $$rc
