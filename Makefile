# libgeneric - one build for the library, the tools, the tests and the benchmarks.
# make                 library (build/lib), tools (build/bin), tests (build/tests)
# make test            install missing packages, build, run the test suite
# make test SANITIZE=1 the same built with -fsanitize=address,undefined,float-cast-overflow (in build/san)
# make demo            install missing packages, build, run the default demo
# make bench           benchmarks (print figures; never fail on time)
# make install PREFIX=/usr/local DESTDIR=

PREFIX  ?= /usr/local
DESTDIR ?=
VERSION := 0.1.0
SOVER   := 0

ifeq ($(SANITIZE),1)
BUILD   ?= build/san
# float-cast-overflow is not part of gcc's `undefined`: a double out of an integer type's range, cast to it, is
# undefined behaviour too (noise lattices, grid indices), so it is asked for by name and never recovers.
SANFLAGS := -fsanitize=address,undefined,float-cast-overflow -fno-omit-frame-pointer \
            -fno-sanitize-recover=undefined,float-cast-overflow
OPT     ?= -O1
LTO     :=
else
BUILD   ?= build
SANFLAGS :=
OPT     ?= -O2
# Link-time optimisation of gtrace: the library's small dispatch functions (gcolor_*, gmaterial_*, the scratch
# arena, the surface point's accessors) inline into the renderer's loops (0.944x the instructions of bench-pov's
# render, the same picture). The library and gtrace are compiled a second time for it into BUILD/obj-lto, so
# libgeneric.a and every other link (the other tools, the tests, the benchmarks, programs linking the installed
# library) stay ordinary. `make LTO=` turns it off.
LTO     ?= -flto=auto
endif

CC      ?= cc
CXX     ?= c++
WARN    := -Wall -Wextra -Werror
CPPFLAGS += -Iinclude -Ilib -I. -D_GNU_SOURCE -DGENERIC_BUILD -MMD -MP
# the tools' --version (examples/common/cli.h)
# An object's own defines, in both object trees (BUILD/obj, and BUILD/obj-lto for gtrace's optimised link).
objs_of = $(BUILD)/obj/$(1) $(BUILD)/obj-lto/$(1)
$(call objs_of,examples/%.o): CPPFLAGS += -DGENERIC_VERSION='"$(VERSION)"'
# -fvisibility=hidden: only declarations marked GENERIC_API (include/generic/export.h) are exported; the version
# scripts say the same to the linker (lib/libgeneric.map; lib/image/oiio_module.map keeps the OpenImageIO module's
# inline instantiations of OpenImageIO templates out of its dynamic symbol table).
VISIBILITY := -fvisibility=hidden
CFLAGS  += -std=c11 $(OPT) -g -fPIC -fopenmp $(WARN) $(SANFLAGS) $(VISIBILITY)
CXXFLAGS += -std=c++17 $(OPT) -g -fPIC $(WARN) $(SANFLAGS) $(VISIBILITY) -fvisibility-inlines-hidden \
            $(shell pkg-config --cflags OpenImageIO 2>/dev/null)
# The library itself needs no C++ and no OpenImageIO: the OpenImageIO shims (LIB_CXX) are the module OIIO_SO,
# which the library dlopens on the first image read or write other than PNG output (lib/image/oiio_module.h); PNG
# output goes through libpng.
DEPLIBS := -lpng -fopenmp -ldl -lpthread -lm
# OpenColorIO (display transforms, lib/image/ocio_display.cpp) is part of the module: OpenImageIO links it already.
OIIO_LIBS := $(shell pkg-config --libs OpenImageIO OpenColorIO 2>/dev/null) -lstdc++
LDFLAGS += $(SANFLAGS)

# The public headers: for applications (generic/), for type writers (generic/kit/), the tools' services
# (generic/services/).
PUBLIC_HDR := $(wildcard include/generic/*.h include/generic/kit/*.h include/generic/services/*.h)
LIB_DIRS := $(sort $(dir $(wildcard lib/*/)))
LIB_SRC := $(foreach d,$(LIB_DIRS) colormodels/ colors/ materials/ materials/*/ textures/,$(sort $(wildcard $(d)*.c)))
LIB_CXX := $(wildcard lib/*/*.cpp)
# The list of built-in types (include/generic/builtins.h), generated from the GENERIC_TYPE records of LIB_SRC.
GEN_BUILTINS = $(1)/gen/builtin_types.c
# The extensions OpenImageIO writes (gimage_write_extensions, generic/services/image.h), found at build time by a small
# program built against OpenImageIO, so that --help lists them without loading it.
GEN_WRITERS = $(1)/gen/image_writers.c
WRITERS_TOOL := $(BUILD)/gen/gen_image_writers
LIB_OBJ := $(LIB_SRC:%.c=$(BUILD)/obj/%.o) $(BUILD)/obj/gen/builtin_types.o $(BUILD)/obj/gen/image_writers.o
LIBA    := $(BUILD)/lib/libgeneric.a
LIBSO   := $(BUILD)/lib/libgeneric.so.$(SOVER)
# The OpenImageIO module, found beside libgeneric.so (lib/generic/) or the program (../lib/generic/).
OIIO_OBJ := $(LIB_CXX:%.cpp=$(BUILD)/obj/%.o)
OIIO_SO  := $(BUILD)/lib/generic/libgeneric_oiio.so
# Where `make install` puts the module: the loader's last resort when it is not beside the library.
$(call objs_of,lib/image/oiio_loader.o): CPPFLAGS += -DGENERIC_LIBDIR='"$(PREFIX)/lib"'
# Where `make install` puts the shipped OpenColorIO config (share/ocio/config.ocio); the build tree has it in
# $(BUILD)/share/generic/ocio/, found beside the programs the same way (lib/image/image_display.c).
$(call objs_of,lib/image/image_display.o): CPPFLAGS += -DGENERIC_DATADIR='"$(PREFIX)/share"'
OCIO_CONFIG := $(BUILD)/share/generic/ocio/config.ocio
# Where `make install` puts the example plug-ins: the last directory searched for a bare module name (lib/module/plugin.c).
PLUGIN_DIR := $(PREFIX)/lib/generic/plugins
$(call objs_of,lib/module/plugin.o): CPPFLAGS += -DGENERIC_PLUGIN_DIR='"$(PLUGIN_DIR)"'

TOOLS   := $(notdir $(patsubst %/,%,$(dir $(wildcard examples/*/main.c))))
TOOL_BIN := $(TOOLS:%=$(BUILD)/bin/%)
TEST_SRC := $(wildcard tests/test_*.c)
TEST_BIN := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)
BENCH_SRC := $(wildcard bench/bench_*.c)
BENCH_BIN := $(BENCH_SRC:bench/%.c=$(BUILD)/bench/%)
TESTLIBS := $(shell pkg-config --libs cmocka 2>/dev/null)

.PHONY: all lib tools tests test demo bench install clean deps
all: lib tools tests

lib: $(LIBA) $(LIBSO) $(OIIO_SO) $(OCIO_CONFIG)
tools: $(TOOL_BIN)
tests: $(TEST_BIN)

deps:
	@scripts/deps.sh

$(BUILD)/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) -c $< -o $@

$(call GEN_BUILTINS,$(BUILD)) $(call GEN_BUILTINS,build/fuzz): $(LIB_SRC) scripts/gen_builtins.sh
	@mkdir -p $(dir $@)
	@scripts/gen_builtins.sh $@ $(LIB_SRC)

# built without the sanitizers: it runs at build time, and OpenImageIO's own leaks are no concern there
$(WRITERS_TOOL): scripts/gen_image_writers.cpp
	@mkdir -p $(dir $@)
	$(CXX) -std=c++17 -O1 $(shell pkg-config --cflags OpenImageIO 2>/dev/null) $< -o $@ $(OIIO_LIBS)

$(call GEN_WRITERS,$(BUILD)) $(call GEN_WRITERS,build/fuzz): $(WRITERS_TOOL)
	@mkdir -p $(dir $@)
	$(WRITERS_TOOL) $@

$(BUILD)/obj/gen/%.o: $(BUILD)/gen/%.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) -c $< -o $@

$(BUILD)/obj/%.o: %.cpp
	@mkdir -p $(dir $@)
	$(CXX) $(CPPFLAGS) $(CXXFLAGS) -c $< -o $@

$(LIBA): $(LIB_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@
	ar rcs $@ $^

$(LIBSO): $(LIB_OBJ) lib/libgeneric.map
	@mkdir -p $(dir $@)
	$(CC) -shared -Wl,-soname,libgeneric.so.$(SOVER) -Wl,--version-script=lib/libgeneric.map -o $@ $(filter %.o,$^) \
	    $(LDFLAGS) $(DEPLIBS)
	ln -sf libgeneric.so.$(SOVER) $(BUILD)/lib/libgeneric.so

$(OCIO_CONFIG): share/ocio/config.ocio
	@mkdir -p $(dir $@)
	cp $< $@

# Linked with OpenImageIO only (-z defs: every symbol it uses resolves there; the library's functions come in the
# host table), exporting its one entry.
$(OIIO_SO): $(OIIO_OBJ) lib/image/oiio_module.map
	@mkdir -p $(dir $@)
	$(CXX) -shared -Wl,-z,defs -Wl,--version-script=lib/image/oiio_module.map -o $@ $(filter %.o,$^) $(LDFLAGS) $(OIIO_LIBS)

# Tools and tests link the static library so they run from the build tree without LD_LIBRARY_PATH;
# -rdynamic lets plug-ins resolve the library's symbols from the executable.
.SECONDEXPANSION:
$(BUILD)/bin/%: $$(addsuffix .o,$$(addprefix $(BUILD)/obj/,$$(basename $$(wildcard examples/$$*/*.c)))) $(LIBA) | $(OIIO_SO) $(OCIO_CONFIG)
	@mkdir -p $(dir $@)
	$(CC) -rdynamic -o $@ $(filter %.o,$^) -Wl,--whole-archive $(LIBA) -Wl,--no-whole-archive $(LDFLAGS) $(EXTRA_LIBS_$*) $(DEPLIBS)

ifneq ($(LTO),)
# Objects compiled for link-time optimisation (LTO above): gtrace links them (examples/gtrace/build.mk).
$(BUILD)/obj-lto/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(LTO) -c $< -o $@

$(BUILD)/obj-lto/gen/%.o: $(BUILD)/gen/%.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(LTO) -c $< -o $@
endif

# Tests of a tool's own code link its objects too (TEST_OBJ_<test>).
TEST_OBJ_test_fluorescent := $(BUILD)/obj/examples/gmat/laser_experiment.o
TEST_OBJ_test_fluorescent_laser := $(BUILD)/obj/examples/gmat/laser_experiment.o
$(BUILD)/tests/%: $(BUILD)/obj/tests/%.o $$(TEST_OBJ_$$*) $(LIBA) | $(OIIO_SO) $(OCIO_CONFIG)
	@mkdir -p $(dir $@)
	$(CC) -rdynamic -o $@ $< $(TEST_OBJ_$*) -Wl,--whole-archive $(LIBA) -Wl,--no-whole-archive $(LDFLAGS) $(TESTLIBS) $(DEPLIBS)

# The benchmarks call the GENERIC_NODISCARD operations in their timed loops without looking at the status (a
# branch there would be timed too); until their set-up calls check theirs, unused results are not errors here.
$(BUILD)/obj/bench/%.o: CFLAGS += -Wno-unused-result
$(BUILD)/bench/%: $(BUILD)/obj/bench/%.o $(LIBA) | $(OIIO_SO)
	@mkdir -p $(dir $@)
	$(CC) -o $@ $< $(LIBA) $(LDFLAGS) $(DEPLIBS)

test: deps
	@$(MAKE) --no-print-directory all
	@scripts/run_tests.sh $(BUILD)

# The demo needs the library and the tools only (examples/scenes/demo.scene loads no plug-in).
demo: deps
	@$(MAKE) --no-print-directory lib tools
	@scripts/demo.sh $(BUILD)

# Objects that only a pattern rule names (the tools', the tests', the benchmarks') are intermediate to make, which
# would delete them after linking and compile them again on the next goal (`make demo` then `make test`).
.SECONDARY: $(foreach t,$(TOOLS),$(patsubst %.c,$(BUILD)/obj/%.o,$(wildcard examples/$(t)/*.c))) \
            $(TEST_SRC:%.c=$(BUILD)/obj/%.o) $(BENCH_SRC:%.c=$(BUILD)/obj/%.o)

bench: deps
	@$(MAKE) --no-print-directory all $(BENCH_BIN)
	@for b in $(BENCH_BIN); do echo "== $$b"; $$b || exit 1; done

# install: headers, both libraries, the OpenImageIO module, the OpenColorIO config, generic.pc, the tools (bin/), the example plug-ins
# (PLUGIN_DIR) and, when help2man is installed, a man page per tool made from its --help and --version.
# uninstall removes exactly these files, and the directories that are libgeneric's own once they are empty.
INST := $(DESTDIR)$(PREFIX)
EXAMPLE_PLUGIN_SO := $(patsubst examples/plugins/%.c,$(BUILD)/plugins/%.so,$(wildcard examples/plugins/*.c))
MAN_DIR := $(PREFIX)/share/man/man1
# the NAME line of each tool's man page
MAN_NAME_gcolor := sample colours in every colour model of libgeneric
MAN_NAME_gmat   := evaluate, check, list and plot the materials and texture trees of a libgeneric file
MAN_NAME_gprobe := approximate an HDR light probe by lights and compare the techniques
MAN_NAME_gtrace := render a libgeneric scene file
.PHONY: uninstall
install: lib tools $(EXAMPLE_PLUGIN_SO)
	install -d $(INST)/include/generic/kit $(INST)/include/generic/services $(INST)/lib/pkgconfig $(INST)/bin \
	    $(DESTDIR)$(PLUGIN_DIR)
	install -m 644 include/generic/*.h $(INST)/include/generic/
	install -m 644 include/generic/kit/*.h $(INST)/include/generic/kit/
	install -m 644 include/generic/services/*.h $(INST)/include/generic/services/
	install -m 644 $(LIBA) $(INST)/lib/
	install -m 755 $(LIBSO) $(INST)/lib/
	install -d $(INST)/lib/generic
	install -m 755 $(OIIO_SO) $(INST)/lib/generic/
	install -d $(INST)/share/generic/ocio
	install -m 644 share/ocio/config.ocio $(INST)/share/generic/ocio/
	ln -sf libgeneric.so.$(SOVER) $(INST)/lib/libgeneric.so
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|$(VERSION)|' generic.pc.in > $(INST)/lib/pkgconfig/generic.pc
	install -m 755 $(TOOL_BIN) $(INST)/bin/
	install -m 755 $(EXAMPLE_PLUGIN_SO) $(DESTDIR)$(PLUGIN_DIR)/
	@if command -v help2man >/dev/null 2>&1; then \
	    install -d $(DESTDIR)$(MAN_DIR) && \
	    $(foreach t,$(TOOLS),echo "help2man $(BUILD)/bin/$(t) > $(DESTDIR)$(MAN_DIR)/$(t).1" && \
	    help2man -N -n "$(or $(MAN_NAME_$(t)),a libgeneric tool)" -o $(DESTDIR)$(MAN_DIR)/$(t).1 $(BUILD)/bin/$(t) &&) \
	    true; \
	else echo "install: help2man not found: no man pages written (Debian package help2man)"; fi

uninstall:
	rm -f $(patsubst include/%,$(INST)/include/%,$(PUBLIC_HDR))
	rm -f $(INST)/lib/libgeneric.a $(INST)/lib/libgeneric.so $(INST)/lib/libgeneric.so.$(SOVER)
	rm -f $(INST)/lib/generic/$(notdir $(OIIO_SO)) $(INST)/lib/pkgconfig/generic.pc
	rm -f $(INST)/share/generic/ocio/config.ocio
	rm -f $(addprefix $(INST)/bin/,$(TOOLS)) $(addprefix $(DESTDIR)$(MAN_DIR)/,$(TOOLS:=.1))
	rm -f $(addprefix $(DESTDIR)$(PLUGIN_DIR)/,$(notdir $(EXAMPLE_PLUGIN_SO)))
	rmdir $(INST)/include/generic/kit $(INST)/include/generic/services 2>/dev/null || true
	rmdir $(INST)/include/generic $(DESTDIR)$(PLUGIN_DIR) $(INST)/lib/generic 2>/dev/null || true
	rmdir $(INST)/share/generic/ocio $(INST)/share/generic 2>/dev/null || true

clean:
	rm -rf build

-include $(shell find $(BUILD)/obj $(BUILD)/obj-lto -name '*.d' 2>/dev/null)

# gtrace's rules (a copy of the tree without examples/, as tests/scripts/readme_examples.sh builds the library in,
# has none)
-include examples/gtrace/build.mk

# ---- run-time plug-in modules (examples/plugins/, tests/plugins/) ----
# Each examples/plugins/*.c is one module, built as its own .so into $(BUILD)/plugins/ against the public
# headers as `make install` installs them (copied to $(BUILD)/plugins/include), never against the source tree.
# Modules are not linked with libgeneric: the program that loads them provides the library's symbols.
# tests/plugins/bad_module.c is built three ways (wrong interface version, failing init, no entry point)
# for tests/test_plugin.c; tests/plugins/nonconforming.c fourteen ways (albedo above 1, not reciprocal, a sampler
# that disagrees with its pdf, a glow hidden by a wrong GMAT_NO_EMISSION, a transparency hidden by a wrong
# GMAT_OPAQUE, a tilted normal hidden by a wrong GMAT_GEOMETRIC_NORMAL, a diffuse colour that a wrong
# GMAT_LAMBERTIAN renders in place of the reflection, a reflection that reads u under a wrong GMAT_NO_UV, a grey
# response to coloured light under a wrong GMAT_DIAGONAL, a wrong colour add, overlapping wavelength bands) for
# tests/scripts/conformance.sh, and (a mirror reflecting 1.2 times the light, a glass refracting about the
# geometric normal, a mirror reflecting light from inside the body) for tests/scripts/bump_ideal_conformance.sh.
PLUGIN_SRC := $(wildcard examples/plugins/*.c)
PLUGIN_INC := $(BUILD)/plugins/include
PLUGIN_HDR := $(patsubst include/generic/%,$(PLUGIN_INC)/generic/%,$(PUBLIC_HDR))
PLUGIN_SO  := $(PLUGIN_SRC:examples/plugins/%.c=$(BUILD)/plugins/%.so) \
              $(BUILD)/plugins/bad_abi.so $(BUILD)/plugins/failing_init.so $(BUILD)/plugins/no_init.so \
              $(BUILD)/plugins/constructor_only.so \
              $(BUILD)/plugins/gain.so $(BUILD)/plugins/skewed.so $(BUILD)/plugins/bad_add.so \
              $(BUILD)/plugins/bad_bands.so $(BUILD)/plugins/misdrawn.so $(BUILD)/plugins/misflagged.so \
              $(BUILD)/plugins/misopaque.so $(BUILD)/plugins/misnormal.so $(BUILD)/plugins/misdiffuse.so \
              $(BUILD)/plugins/misuv.so $(BUILD)/plugins/misdiag.so $(BUILD)/plugins/gain_mirror.so \
              $(BUILD)/plugins/misbent.so $(BUILD)/plugins/leaky.so
# -fvisibility=hidden: a module's own symbols never bind to the program's copies (only the two GENERIC_MODULE_EXPORT
# symbols are exported).
PLUGIN_CFLAGS := -std=c11 -D_GNU_SOURCE $(OPT) -g -fPIC -shared -fvisibility=hidden $(WARN) $(SANFLAGS) -I$(PLUGIN_INC)

.PHONY: plugins
all: plugins
plugins: $(PLUGIN_SO)

$(PLUGIN_INC)/generic/%.h: include/generic/%.h
	@mkdir -p $(dir $@)
	install -m 644 $< $@

$(BUILD)/plugins/%.so: examples/plugins/%.c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -o $@ $< -lm

$(BUILD)/plugins/bad_abi.so: tests/plugins/bad_module.c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -DBAD_ABI -o $@ $<

$(BUILD)/plugins/failing_init.so: tests/plugins/bad_module.c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -DFAIL_INIT -o $@ $<

$(BUILD)/plugins/no_init.so: tests/plugins/bad_module.c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -DNO_INIT -o $@ $<

$(BUILD)/plugins/constructor_only.so: tests/plugins/bad_module.c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -DNOT_A_MODULE -o $@ $<

# ---- built-in files as run-time modules: the proof that a type's file is self-contained ----
# Each file of BUILTIN_MODULES is compiled as it is in the tree, plus the one line `GENERIC_MODULE(&gtype_NAME);`
# (NAME: the file's base name), into $(BUILD)/modules/NAME.so: against the installed headers only, not linked with
# libgeneric, its own symbols hidden (PLUGIN_CFLAGS) so that none binds to the program's built-in copy.
# tests/test_builtin_modules.c loads them into a registry that lacks those built-ins.
BUILTIN_MODULES := materials/lambert.c colormodels/rgb.c
MODULE_SO := $(patsubst %.c,$(BUILD)/modules/%.so,$(notdir $(BUILTIN_MODULES)))
.SECONDARY: $(MODULE_SO:%.so=%_module.c)

all: modules
plugins: modules
.PHONY: modules
modules: $(MODULE_SO)

MODULE_PCT := %
$(BUILD)/modules/%_module.c: $$(filter $$(MODULE_PCT)/$$*.c,$(BUILTIN_MODULES))
	@mkdir -p $(dir $@)
	{ cat $<; echo; echo 'GENERIC_MODULE(&gtype_$*);'; } > $@

$(BUILD)/modules/%.so: $(BUILD)/modules/%_module.c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -o $@ $< -lm

$(BUILD)/plugins/gain.so: tests/plugins/nonconforming.c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -DGAIN -o $@ $< -lm

$(BUILD)/plugins/skewed.so: tests/plugins/nonconforming.c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -DSKEWED -o $@ $< -lm

$(BUILD)/plugins/misdrawn.so: tests/plugins/nonconforming.c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -DMISDRAWN -o $@ $< -lm

$(BUILD)/plugins/misflagged.so: tests/plugins/nonconforming.c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -DMISFLAGGED -o $@ $< -lm

$(BUILD)/plugins/misopaque.so: tests/plugins/nonconforming.c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -DMISOPAQUE -o $@ $< -lm

$(BUILD)/plugins/misnormal.so: tests/plugins/nonconforming.c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -DMISNORMAL -o $@ $< -lm

$(BUILD)/plugins/misdiffuse.so: tests/plugins/nonconforming.c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -DMISDIFFUSE -o $@ $< -lm

$(BUILD)/plugins/misuv.so: tests/plugins/nonconforming.c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -DMISUV -o $@ $< -lm

$(BUILD)/plugins/misdiag.so: tests/plugins/nonconforming.c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -DMISDIAG -o $@ $< -lm

$(BUILD)/plugins/gain_mirror.so: tests/plugins/nonconforming.c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -DGAIN_MIRROR -o $@ $< -lm

$(BUILD)/plugins/misbent.so: tests/plugins/nonconforming.c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -DMISBENT -o $@ $< -lm

$(BUILD)/plugins/leaky.so: tests/plugins/nonconforming.c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -DLEAKY -o $@ $< -lm

$(BUILD)/plugins/bad_add.so: tests/plugins/nonconforming.c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -DBAD_ADD -o $@ $< -lm
$(BUILD)/plugins/bad_bands.so: tests/plugins/nonconforming.c $(PLUGIN_HDR)
	$(CC) $(PLUGIN_CFLAGS) -DBAD_BANDS -o $@ $< -lm

# ---- fuzzing (tests/fuzz/): libFuzzer targets built with clang, -fsanitize=fuzzer,address,undefined ----
# make fuzz [FUZZ_SECONDS=30] [FUZZ_TARGETS="reader bfc"] [FUZZ_SEED=N] builds the library's sources with clang
# into build/fuzz/ (without OpenMP: one thread keeps a run reproducible) and runs each target
# tests/fuzz/fuzz_<target>.c for FUZZ_SECONDS seconds. Inputs: tests/fuzz/corpus/<target>/ (small, committed), the example files fuzz-seed copies
# into build/fuzz/seed/<target>/ at run time, and tests/regress/<target>/ (every crasher found so far, replayed by
# tests/test_regress.c in the normal suite). New inputs go to build/fuzz/corpus/<target>/, a crasher to
# build/fuzz/crashes/<target>/ and the run fails; fix it and keep the input in tests/regress/<target>/.
# Then the structure-aware generator (tests/fuzz/gen/, fuzz_gen) writes FUZZ_GEN_COUNT inputs per target of up to
# FUZZ_GEN_BUDGET bytes (long operand lists, reference chains, lying image headers, ...: sizes libFuzzer never
# reaches), seeded by FUZZ_SEED, and tests/fuzz/run_generated.sh runs them through the same entry points with
# FUZZ_GEN_TIMEOUT seconds and FUZZ_GEN_MB megabytes per input; a crash, timeout or out-of-memory is reported
# with the input kept in build/fuzz/crashes/<target>/. Every stage runs; `make fuzz` fails if any failed.
# `make fuzz-gen` runs the generated inputs only.
FUZZ_BUILD    := build/fuzz
FUZZ_SECONDS  ?= 30
# libFuzzer's seed: 0 draws a new one each run (exploration); CI passes a fixed one, so that a red smoke run
# means a regression that the same command reproduces, not a lucky draw.
FUZZ_SEED     ?= 0
FUZZ_CC       ?= clang
FUZZ_CXX      ?= clang++
FUZZ_SAN      := -fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=undefined,float-cast-overflow \
                 -fno-omit-frame-pointer
# GENERIC_OIIO_STATIC: the OpenImageIO shims are linked into the fuzzing library, not loaded as the module.
FUZZ_CPPFLAGS := -Iinclude -Ilib -I. -D_GNU_SOURCE -DGENERIC_OIIO_STATIC -MMD -MP
FUZZ_CFLAGS   := -std=c11 -O1 -g -Wall -Wextra -Wno-unknown-pragmas $(FUZZ_SAN) -fsanitize=fuzzer-no-link
FUZZ_CXXFLAGS := -std=c++17 -O1 -g -Wall -Wextra -Wno-unknown-pragmas $(FUZZ_SAN) -fsanitize=fuzzer-no-link \
                 $(shell pkg-config --cflags OpenImageIO 2>/dev/null)
FUZZ_LIBS     := $(shell pkg-config --libs OpenImageIO OpenColorIO 2>/dev/null) -lpng -ldl -lpthread -lm
FUZZ_NAMES    := $(patsubst tests/fuzz/fuzz_%.c,%,$(wildcard tests/fuzz/fuzz_*.c))
FUZZ_TARGETS  ?= $(FUZZ_NAMES)
FUZZ_BIN      := $(FUZZ_NAMES:%=$(FUZZ_BUILD)/fuzz_%)
FUZZ_C_OBJ    := $(LIB_SRC:%.c=$(FUZZ_BUILD)/obj/%.o)
FUZZ_CXX_OBJ  := $(LIB_CXX:%.cpp=$(FUZZ_BUILD)/obj/%.o)
FUZZ_GEN_OBJ  := $(FUZZ_BUILD)/obj/gen/builtin_types.o
FUZZ_WRITERS_OBJ := $(FUZZ_BUILD)/obj/gen/image_writers.o
FUZZ_LIBA     := $(FUZZ_BUILD)/libgeneric.a
# What fuzz-seed copies (the examples of each input kind; tests/bad/*.mat are broken on purpose, good seeds too).
FUZZ_SEED_reader := examples/materials/*.mat examples/textures/*.txt tests/good/*.mat tests/bad/*.mat
FUZZ_SEED_bfc    := tests/bad/*.BFC tests/bad/*.bfc
FUZZ_SEED_probe  := tests/bad/*.hdr tests/bad/*.pfm
FUZZ_SEED_image  := examples/textures/*.png examples/scenes/*.png tests/bad/*.hdr tests/bad/*.pfm
# Per-target libFuzzer options. The image readers keep OpenImageIO's file cache between inputs, which grows, so
# the per-input leak check would run (and cost more than the input) every time: leaks show at exit instead.
FUZZ_OPTS_image  := -detect_leaks=0
FUZZ_OPTS_probe  := -detect_leaks=0
# The reader's inputs may grow to 64 KiB, so that structure (nesting, lists, chains) can appear.
FUZZ_OPTS_reader := -max_len=65536
FUZZ_GEN_COUNT   ?= 24
FUZZ_GEN_BUDGET  ?= 4194304
FUZZ_GEN_TIMEOUT ?= 10
FUZZ_GEN_MB      ?= 2048
FUZZ_GEN_SRC     := $(wildcard tests/fuzz/gen/*.c)
FUZZ_GEN_BIN     := $(FUZZ_BUILD)/fuzz_gen

.PHONY: fuzz fuzz-build fuzz-seed fuzz-gen
fuzz-build: $(FUZZ_BIN) $(FUZZ_GEN_BIN)

# The generator is an ordinary program (no sanitizers: it only writes files).
$(FUZZ_GEN_BIN): $(FUZZ_GEN_SRC) tests/fuzz/gen/gen.h
	@mkdir -p $(dir $@)
	$(FUZZ_CC) -std=c11 -O2 -g -Wall -Wextra -Werror -D_GNU_SOURCE -o $@ $(FUZZ_GEN_SRC) -lm

$(FUZZ_C_OBJ): $(FUZZ_BUILD)/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CPPFLAGS) $(FUZZ_CFLAGS) -c $< -o $@

$(FUZZ_CXX_OBJ): $(FUZZ_BUILD)/obj/%.o: %.cpp
	@mkdir -p $(dir $@)
	$(FUZZ_CXX) $(FUZZ_CPPFLAGS) $(FUZZ_CXXFLAGS) -c $< -o $@

$(FUZZ_GEN_OBJ): $(call GEN_BUILTINS,$(FUZZ_BUILD))
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CPPFLAGS) $(FUZZ_CFLAGS) -c $< -o $@

$(FUZZ_WRITERS_OBJ): $(call GEN_WRITERS,$(FUZZ_BUILD))
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CPPFLAGS) $(FUZZ_CFLAGS) -c $< -o $@

$(FUZZ_BUILD)/obj/tests/fuzz/%.o: tests/fuzz/%.c
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CPPFLAGS) $(FUZZ_CFLAGS) -c $< -o $@

$(FUZZ_LIBA): $(FUZZ_C_OBJ) $(FUZZ_CXX_OBJ) $(FUZZ_GEN_OBJ) $(FUZZ_WRITERS_OBJ)
	rm -f $@
	ar rcs $@ $^

.SECONDARY: $(FUZZ_NAMES:%=$(FUZZ_BUILD)/obj/tests/fuzz/fuzz_%.o)
$(FUZZ_BUILD)/fuzz_%: $(FUZZ_BUILD)/obj/tests/fuzz/fuzz_%.o $(FUZZ_LIBA)
	$(FUZZ_CXX) $(FUZZ_SAN) -fsanitize=fuzzer -o $@ $< -Wl,--whole-archive $(FUZZ_LIBA) -Wl,--no-whole-archive \
	    $(FUZZ_LIBS)

fuzz-seed:
	@rm -rf $(FUZZ_BUILD)/seed
	@$(foreach t,$(FUZZ_NAMES),mkdir -p $(FUZZ_BUILD)/seed/$(t) && \
	    for f in $(wildcard $(FUZZ_SEED_$(t))) ''; do [ -z "$$f" ] || cp "$$f" $(FUZZ_BUILD)/seed/$(t)/; done;)

# The targets run FUZZ_JOBS at a time (default: the processors; each run is one process on one core, so a target
# gets the same FUZZ_SECONDS of a core as alone), each printing its lines as it ends; a failed one is named in
# FUZZ_BUILD/failed and the others still run.
FUZZ_JOBS ?= $(shell nproc 2>/dev/null || echo 1)
fuzz_each = printf '%s\n' $(FUZZ_TARGETS) | xargs -P $(FUZZ_JOBS) -I{} sh -c \
    '$(MAKE) --no-print-directory $(1){} || echo "$(2){}" >> $(FUZZ_BUILD)/failed'

fuzz: fuzz-build fuzz-seed
	+@rm -f $(FUZZ_BUILD)/failed; $(call fuzz_each,fuzz-run-,); $(call fuzz_each,fuzz-gen-,gen-); \
	if [ -s $(FUZZ_BUILD)/failed ]; then echo "fuzz: FAILED: $$(cat $(FUZZ_BUILD)/failed | tr '\n' ' ')(inputs in $(FUZZ_BUILD)/crashes/)"; exit 1; fi

fuzz-gen: fuzz-build
	+@rm -f $(FUZZ_BUILD)/failed; $(call fuzz_each,fuzz-gen-,); \
	if [ -s $(FUZZ_BUILD)/failed ]; then echo "fuzz-gen: FAILED: $$(cat $(FUZZ_BUILD)/failed | tr '\n' ' ')(inputs in $(FUZZ_BUILD)/crashes/)"; exit 1; fi

fuzz-gen-%:
	@tests/fuzz/run_generated.sh $* $(FUZZ_SEED) $(FUZZ_GEN_COUNT) $(FUZZ_GEN_BUDGET) $(FUZZ_GEN_TIMEOUT) \
	    $(FUZZ_GEN_MB) $(FUZZ_BUILD)

# One target's run: its corpus directories (those that exist), its options; the executions at the end.
# Inputs are named by their magic bytes, so OpenImageIO tries only the reader of that extension
# (try_all_readers=0): otherwise every corrupt input is probed by every reader, LibRaw's costly constructor
# included (the image target ran about 1.6x slower so).
fuzz-run-%:
	@mkdir -p $(FUZZ_BUILD)/corpus/$* $(FUZZ_BUILD)/crashes/$*
	@dirs="$(FUZZ_BUILD)/corpus/$*"; \
	for d in tests/fuzz/corpus/$* $(FUZZ_BUILD)/seed/$* tests/regress/$*; do [ -d $$d ] && dirs="$$dirs $$d"; done; \
	log=$(FUZZ_BUILD)/fuzz_$*.log; \
	echo "fuzz $*: $(FUZZ_SECONDS) s over $$dirs"; \
	if ! OPENIMAGEIO_OPTIONS=try_all_readers=0 $(FUZZ_BUILD)/fuzz_$* -seed=$(FUZZ_SEED) -max_total_time=$(FUZZ_SECONDS) -timeout=20 -rss_limit_mb=2560 $(FUZZ_OPTS_$*) \
	        -print_final_stats=1 -artifact_prefix=$(FUZZ_BUILD)/crashes/$*/ $$dirs > $$log 2>&1; then \
	    tail -n 80 $$log; echo "fuzz $*: FAILED (input in $(FUZZ_BUILD)/crashes/$*/, log $$log)"; exit 1; \
	fi; \
	echo "fuzz $*: $$(grep -E '^stat::(number_of_executed_units|new_units_added|peak_rss_mb)' $$log | tr -s ' \n' ' ')"
-include $(shell find $(FUZZ_BUILD)/obj -name '*.d' 2>/dev/null)
# (end of fuzzing)
