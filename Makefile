# libgeneric - one build for the library, the tools, the tests and the benchmarks. This file holds what the build
# is (version, install locations, compilers and flags, the library's sources) and the goals; each folder's rules
# are in its build.mk: lib/ (the library, its OpenImageIO module, generated sources, generic.pc, modules' headers),
# examples/ (the tools, the example plug-ins), tests/ (test programs, test plug-ins, built-ins as modules),
# tests/fuzz/ (libFuzzer targets), bench/ (benchmarks).
# make                 library (build/lib, build/pkgconfig/generic.pc), tools (build/bin), plug-ins, tests
# make test            install missing packages, build on every processor, run the test suite
# make test SANITIZE=1 the same built with -fsanitize=address,undefined,float-cast-overflow (in build/san)
# make demo            install missing packages, build on every processor, run the default demo
# make bench           benchmarks (print figures; never fail on time)
# make fuzz            libFuzzer targets and generated inputs (tests/fuzz/build.mk)
# make python         the Python package in build/python (python/build.mk; part of make)
# make install PREFIX=/usr/local DESTDIR=    (make uninstall removes the same files)

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
# An object's own defines, in both object trees (BUILD/obj, and BUILD/obj-lto for gtrace's optimised link).
objs_of = $(BUILD)/obj/$(1) $(BUILD)/obj-lto/$(1)
# -fvisibility=hidden: only declarations marked GENERIC_API (include/generic/export.h) are exported; the version
# scripts say the same to the linker (lib/libgeneric.map; lib/image/oiio_module.map keeps the OpenImageIO module's
# inline instantiations of OpenImageIO templates out of its dynamic symbol table).
VISIBILITY := -fvisibility=hidden
CFLAGS  += -std=c11 $(OPT) -g -fPIC -fopenmp $(WARN) $(SANFLAGS) $(VISIBILITY)
CXXFLAGS += -std=c++17 $(OPT) -g -fPIC $(WARN) $(SANFLAGS) $(VISIBILITY) -fvisibility-inlines-hidden \
            $(shell pkg-config --cflags OpenImageIO 2>/dev/null)
# The library itself needs no C++ and no OpenImageIO: the OpenImageIO shims (LIB_CXX) are the module OIIO_SO,
# which the library dlopens on the first image read or write other than PNG and OpenEXR output
# (lib/image/oiio_module.h); PNG output goes through libpng, OpenEXR output through OpenEXRCore, which it dlopens on
# the first EXR written (lib/image/exr_core_lib.c).
DEPLIBS := -lpng -fopenmp -ldl -lpthread -lm
# OpenColorIO (display transforms, lib/image/ocio_display.cpp) is part of the module: OpenImageIO links it already.
OIIO_LIBS := $(shell pkg-config --libs OpenImageIO OpenColorIO 2>/dev/null) -lstdc++
LDFLAGS += $(SANFLAGS)
# Run-time modules (plug-ins) are built against the public headers as `make install` lays them out (PLUGIN_HDR,
# lib/build.mk), never against the source tree, and are not linked with libgeneric: the program that loads them
# provides the library's symbols. -fvisibility=hidden: a module's own symbols never bind to the program's copies
# (only the two GENERIC_MODULE_EXPORT symbols are exported).
PLUGIN_INC := $(BUILD)/plugins/include
PLUGIN_CFLAGS := -std=c11 -D_GNU_SOURCE $(OPT) -g -fPIC -shared -fvisibility=hidden $(WARN) $(SANFLAGS) -I$(PLUGIN_INC)

# Where `make install` puts things (INST: the staged PREFIX).
INST       := $(DESTDIR)$(PREFIX)
# the example plug-ins: the last directory searched for a bare module name (lib/module/plugin.c)
PLUGIN_DIR := $(PREFIX)/lib/generic/plugins
MAN_DIR    := $(PREFIX)/share/man/man1

# The public headers: for applications (generic/), for type writers (generic/kit/), the tools' services
# (generic/services/).
PUBLIC_HDR := $(wildcard include/generic/*.h include/generic/kit/*.h include/generic/services/*.h)
# The library: the sources of lib/'s folders and of the type folders (one type a file, ending in its GENERIC_TYPE
# record), the generated list of built-in types and the extensions OpenImageIO writes (lib/build.mk).
LIB_DIRS  := $(sort $(dir $(wildcard lib/*/)))
TYPE_DIRS := colormodels/ colors/ materials/ materials/*/ textures/
LIB_SRC   := $(foreach d,$(LIB_DIRS) $(TYPE_DIRS),$(sort $(wildcard $(d)*.c)))
LIB_CXX   := $(wildcard lib/*/*.cpp)
LIB_OBJ := $(LIB_SRC:%.c=$(BUILD)/obj/%.o) $(BUILD)/obj/gen/builtin_types.o $(BUILD)/obj/gen/image_writers.o \
           $(BUILD)/obj/gen/uplift_tables.o
LIBA    := $(BUILD)/lib/libgeneric.a
LIBSO   := $(BUILD)/lib/libgeneric.so.$(SOVER)
# The OpenImageIO module, found beside libgeneric.so (lib/generic/) or the program (../lib/generic/).
OIIO_OBJ := $(LIB_CXX:%.cpp=$(BUILD)/obj/%.o)
OIIO_SO  := $(BUILD)/lib/generic/libgeneric_oiio.so
OCIO_CONFIG := $(BUILD)/share/generic/ocio/config.ocio

# The default goal; each folder's build.mk gives lib, tools, plugins and tests their prerequisites.
.PHONY: all test demo install uninstall clean deps
all: lib tools plugins tests

# Every object of the tree, compiled alike (the generated sources from BUILD/gen).
$(BUILD)/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) -c $< -o $@

$(BUILD)/obj/gen/%.o: $(BUILD)/gen/%.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) -c $< -o $@

$(BUILD)/obj/%.o: %.cpp
	@mkdir -p $(dir $@)
	$(CXX) $(CPPFLAGS) $(CXXFLAGS) -c $< -o $@

# A rule's prerequisites may name its stem ($$*: a tool's sources, a test plug-in's variant).
.SECONDEXPANSION:
include lib/build.mk
include examples/build.mk
include tests/build.mk
include tests/fuzz/build.mk
include bench/build.mk

ifneq ($(LTO),)
# Objects compiled for link-time optimisation (LTO above): gtrace links them (examples/gtrace/build.mk).
$(BUILD)/obj-lto/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(LTO) -c $< -o $@

$(BUILD)/obj-lto/gen/%.o: $(BUILD)/gen/%.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(CFLAGS) $(LTO) -c $< -o $@
endif

deps:
	@scripts/deps.sh

# The goals that build and then run build on every processor unless the command line chose a number of jobs
# (-j), each command's output kept together.
BUILD_STEP = $(MAKE) --no-print-directory --output-sync=target \
             $(if $(filter -j%,$(MAKEFLAGS)),,-j$$(nproc 2>/dev/null || echo 1))

test: deps
	+@$(BUILD_STEP) all
	@scripts/run_tests.sh $(BUILD)

# The demo needs the library and the tools only (examples/scenes/demo.scene loads no plug-in).
demo: deps
	+@$(BUILD_STEP) lib tools
	@scripts/demo.sh $(BUILD)

# install and uninstall: each folder adds its part (install-lib, install-tools, ...); uninstall then removes the
# directories that are libgeneric's own once they are empty.
uninstall:
	rmdir $(INST)/include/generic/kit $(INST)/include/generic/services 2>/dev/null || true
	rmdir $(INST)/include/generic $(DESTDIR)$(PLUGIN_DIR) $(INST)/lib/generic 2>/dev/null || true
	rmdir $(INST)/share/generic/ocio $(INST)/share/generic 2>/dev/null || true

clean:
	rm -rf build

-include $(shell find $(BUILD)/obj $(BUILD)/obj-lto -name '*.d' 2>/dev/null)

# gtrace's rules (a copy of the tree without examples/, as tests/scripts/readme_examples.sh builds the library in,
# has none)
-include examples/gtrace/build.mk
# the Python package (python/build.mk; after gtrace's rules, whose libgtrace.so it opens)
-include python/build.mk

