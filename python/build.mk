# python/build.mk - the Python package `generic` (python/generic/, cffi in ABI mode over libgeneric.so and
# libgtrace.so): `make python` copies it into BUILD/python/generic/ with a _config.py naming BUILD/lib, so that
# PYTHONPATH=BUILD/python imports it from the tree; `make install` puts it where Debian's python3 looks for
# packages under PREFIX (PREFIX/lib/python3.X/dist-packages, X of PYTHON's version: on sys.path for /usr/local and
# /usr alike), its _config.py naming PREFIX/lib. Its tests
# (tests/python/, pytest) run from tests/scripts/python.sh and compare with bench_batch --reference (bench/).
# PYTHON: the interpreter with python3-cffi and numpy.
PYTHON ?= /usr/bin/python3
PY_SRC := $(wildcard python/generic/*.py)
PY_PKG := $(BUILD)/python/generic
PY_OUT := $(PY_SRC:python/generic/%=$(PY_PKG)/%) $(PY_PKG)/_config.py
PY_VERSION := $(shell $(PYTHON) -c 'import sys; print("%d.%d" % sys.version_info[:2])' 2>/dev/null || echo 3)
PY_INSTALL_DIR := $(PREFIX)/lib/python$(PY_VERSION)/dist-packages
.PHONY: python install-python uninstall-python
all: python
python: $(PY_OUT) $(LIBSO) $(GTRACE_SO) $(BUILD)/bench/bench_batch

$(PY_PKG)/%.py: python/generic/%.py
	@mkdir -p $(dir $@)
	cp $< $@

# the directory of the libraries, written when it would change
py_config = printf '"""Where the package finds its libraries (written by python/build.mk)."""\nLIBDIR = "%s"\n' '$(1)'
$(PY_PKG)/_config.py: FORCE
	@mkdir -p $(dir $@)
	@$(call py_config,$(abspath $(BUILD)/lib)) > $@.tmp
	@if cmp -s $@.tmp $@; then rm $@.tmp; else mv $@.tmp $@; fi

install: install-python
install-python: python
	install -d $(DESTDIR)$(PY_INSTALL_DIR)/generic
	install -m 644 $(PY_SRC) $(DESTDIR)$(PY_INSTALL_DIR)/generic/
	$(call py_config,$(PREFIX)/lib) > $(DESTDIR)$(PY_INSTALL_DIR)/generic/_config.py
uninstall: uninstall-python
uninstall-python:
	rm -rf $(DESTDIR)$(PY_INSTALL_DIR)/generic
	rmdir $(DESTDIR)$(PY_INSTALL_DIR) $(DESTDIR)$(PREFIX)/lib/python$(PY_VERSION) 2>/dev/null || true

# Batch throughput from Python beside the same loop in C (bench/bench_batch.c): figures, never a failure.
.PHONY: bench-python
bench: bench-python
bench-python: python $(BUILD)/bench/bench_batch
	@echo "== C: $(BUILD)/bench/bench_batch"; $(BUILD)/bench/bench_batch
	@echo "== Python: bench/python_batch.py"; PYTHONPATH=$(BUILD)/python $(PYTHON) bench/python_batch.py
