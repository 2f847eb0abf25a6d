# tests/fuzz/build.mk - libFuzzer targets built with clang, -fsanitize=fuzzer,address,undefined.
# make fuzz [FUZZ_SECONDS=30] [FUZZ_TARGETS="reader bfc"] [FUZZ_SEED=N] builds the library's sources with clang
# (and gtrace's, for the scene target) into build/fuzz/ (without OpenMP: one thread keeps a run reproducible) and
# runs each target tests/fuzz/fuzz_<target>.c for FUZZ_SECONDS seconds. Inputs: tests/fuzz/corpus/<target>/
# (small, committed), the example files fuzz-seed copies into build/fuzz/seed/<target>/ at run time, and
# tests/regress/<target>/ (every crasher found so far, replayed by tests/test_regress.c in the normal suite). New
# inputs go to build/fuzz/corpus/<target>/, a crasher to build/fuzz/crashes/<target>/ and the run fails; fix it and
# keep the input in tests/regress/<target>/.
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
FUZZ_LIBS     := $(shell pkg-config --libs OpenImageIO OpenColorIO 2>/dev/null) -lpng -lgomp -ldl -lpthread -lm
FUZZ_NAMES    := $(patsubst tests/fuzz/fuzz_%.c,%,$(wildcard tests/fuzz/fuzz_*.c))
FUZZ_TARGETS  ?= $(FUZZ_NAMES)
FUZZ_BIN      := $(FUZZ_NAMES:%=$(FUZZ_BUILD)/fuzz_%)
FUZZ_C_OBJ    := $(LIB_SRC:%.c=$(FUZZ_BUILD)/obj/%.o)
FUZZ_CXX_OBJ  := $(LIB_CXX:%.cpp=$(FUZZ_BUILD)/obj/%.o)
FUZZ_GEN_OBJ  := $(FUZZ_BUILD)/obj/gen/builtin_types.o $(FUZZ_BUILD)/obj/gen/image_writers.o \
                 $(FUZZ_BUILD)/obj/gen/uplift_tables.o
FUZZ_LIBA     := $(FUZZ_BUILD)/libgeneric.a
# What fuzz-seed copies (the examples of each input kind; tests/bad/*.mat are broken on purpose, good seeds too).
FUZZ_SEED_reader := examples/materials/*.mat examples/textures/*.txt tests/good/*.mat tests/bad/*.mat
FUZZ_SEED_bfc    := tests/bad/*.BFC tests/bad/*.bfc
FUZZ_SEED_probe  := tests/bad/*.hdr tests/bad/*.pfm
FUZZ_SEED_image  := examples/textures/*.png examples/scenes/*.png tests/bad/*.hdr tests/bad/*.pfm
FUZZ_SEED_scene  := examples/scenes/*.scene tests/bad/*.scene
# Per-target libFuzzer options. The image readers keep OpenImageIO's file cache between inputs, which grows, so
# the per-input leak check would run (and cost more than the input) every time: leaks show at exit instead.
FUZZ_OPTS_image  := -detect_leaks=0
FUZZ_OPTS_probe  := -detect_leaks=0
# The reader's inputs may grow to 64 KiB, so that structure (nesting, lists, chains) can appear.
FUZZ_OPTS_reader := -max_len=65536
# The scene target's dictionary: the keywords of gtrace's scene files and the fixtures' names.
FUZZ_OPTS_scene  := -dict=tests/fuzz/scene.dict
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

# The library's sources, the generated ones and the targets, compiled with FUZZ_CC (lib/build.mk writes the
# generated sources of any build tree).
$(FUZZ_BUILD)/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CPPFLAGS) $(FUZZ_CFLAGS) -c $< -o $@

$(FUZZ_BUILD)/obj/gen/%.o: $(FUZZ_BUILD)/gen/%.c
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CPPFLAGS) $(FUZZ_CFLAGS) -c $< -o $@

$(FUZZ_BUILD)/obj/%.o: %.cpp
	@mkdir -p $(dir $@)
	$(FUZZ_CXX) $(FUZZ_CPPFLAGS) $(FUZZ_CXXFLAGS) -c $< -o $@

$(FUZZ_LIBA): $(FUZZ_C_OBJ) $(FUZZ_CXX_OBJ) $(FUZZ_GEN_OBJ)
	rm -f $@
	ar rcs $@ $^

.SECONDARY: $(FUZZ_NAMES:%=$(FUZZ_BUILD)/obj/tests/fuzz/fuzz_%.o)
# gtrace's media sources name their headers from examples/gtrace/, as gtrace's build does
$(FUZZ_BUILD)/obj/tests/fuzz/fuzz_medium.o: FUZZ_CPPFLAGS += -Iexamples/gtrace
# The scene target (fuzz_scene.c) links gtrace whole: its sources as libgtrace.a has them (examples/gtrace/*/*.c,
# examples/gtrace/build.mk), compiled with FUZZ_CC into FUZZ_BUILD/libgtrace.a, and Embree.
FUZZ_GTRACE_OBJ  := $(patsubst %.c,$(FUZZ_BUILD)/obj/%.o,$(wildcard examples/gtrace/*/*.c))
FUZZ_GTRACE_LIBA := $(FUZZ_BUILD)/libgtrace.a
$(FUZZ_GTRACE_OBJ) $(FUZZ_BUILD)/obj/tests/fuzz/fuzz_scene.o: FUZZ_CPPFLAGS += -Iexamples/gtrace
$(FUZZ_GTRACE_LIBA): $(FUZZ_GTRACE_OBJ)
	rm -f $@
	ar rcs $@ $^
$(FUZZ_BUILD)/fuzz_scene: $(FUZZ_GTRACE_LIBA)
$(FUZZ_BUILD)/fuzz_scene: FUZZ_LIBS := $(FUZZ_GTRACE_LIBA) -lembree3 $(FUZZ_LIBS)
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

# fuzz_failed GOAL: fails, naming the failed targets, when any failed
fuzz_failed = if [ -s $(FUZZ_BUILD)/failed ]; then \
    echo "$(1): FAILED: $$(tr '\n' ' ' < $(FUZZ_BUILD)/failed)(inputs in $(FUZZ_BUILD)/crashes/)"; exit 1; fi

fuzz: fuzz-build fuzz-seed
	+@rm -f $(FUZZ_BUILD)/failed; $(call fuzz_each,fuzz-run-,); $(call fuzz_each,fuzz-gen-,gen-); \
	$(call fuzz_failed,fuzz)

fuzz-gen: fuzz-build
	+@rm -f $(FUZZ_BUILD)/failed; $(call fuzz_each,fuzz-gen-,); $(call fuzz_failed,fuzz-gen)

fuzz-gen-%:
	@tests/fuzz/run_generated.sh $* $(FUZZ_SEED) $(FUZZ_GEN_COUNT) $(FUZZ_GEN_BUDGET) $(FUZZ_GEN_TIMEOUT) \
	    $(FUZZ_GEN_MB) $(FUZZ_BUILD)

# One target's run: its corpus directories (those that exist), its options; the executions at the end. The
# crashers' prefix is absolute: the reader and scene targets run each input inside their private directory, where a
# relative one would name nothing when the input crashes.
# Inputs are named by their magic bytes, so OpenImageIO tries only the reader of that extension
# (try_all_readers=0): otherwise every corrupt input is probed by every reader, LibRaw's costly constructor
# included (the image target ran about 1.6x slower so).
fuzz-run-%:
	@mkdir -p $(FUZZ_BUILD)/corpus/$* $(FUZZ_BUILD)/crashes/$*
	@dirs="$(FUZZ_BUILD)/corpus/$*"; \
	for d in tests/fuzz/corpus/$* $(FUZZ_BUILD)/seed/$* tests/regress/$*; do [ -d $$d ] && dirs="$$dirs $$d"; done; \
	log=$(FUZZ_BUILD)/fuzz_$*.log; \
	echo "fuzz $*: $(FUZZ_SECONDS) s over $$dirs"; \
	if ! OPENIMAGEIO_OPTIONS=try_all_readers=0 $(FUZZ_BUILD)/fuzz_$* -seed=$(FUZZ_SEED) \
	        -max_total_time=$(FUZZ_SECONDS) -timeout=20 -rss_limit_mb=2560 $(FUZZ_OPTS_$*) -print_final_stats=1 \
	        -artifact_prefix=$(abspath $(FUZZ_BUILD))/crashes/$*/ $$dirs > $$log 2>&1; then \
	    tail -n 80 $$log; echo "fuzz $*: FAILED (input in $(FUZZ_BUILD)/crashes/$*/, log $$log)"; exit 1; \
	fi; \
	echo "fuzz $*: $$(grep -E '^stat::(number_of_executed_units|new_units_added|peak_rss_mb)' $$log | tr -s ' \n' ' ')"
-include $(shell find $(FUZZ_BUILD)/obj -name '*.d' 2>/dev/null)
