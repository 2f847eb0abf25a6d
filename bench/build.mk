# bench/build.mk - the benchmarks (bench/bench_*.c: build/bench/bench_*). `make bench` builds everything and runs
# them; they print figures and never fail on time. (gtrace's own benchmarks join the goal from its section.)

.PHONY: bench
BENCH_SRC := $(wildcard bench/bench_*.c)
BENCH_BIN := $(BENCH_SRC:bench/%.c=$(BUILD)/bench/%)

# The benchmarks call the GENERIC_NODISCARD operations in their timed loops without looking at the status (a
# branch there would be timed too); until their set-up calls check theirs, unused results are not errors here.
$(BUILD)/obj/bench/%.o: CFLAGS += -Wno-unused-result
$(BUILD)/bench/%: $(BUILD)/obj/bench/%.o $(LIBA) | $(OIIO_SO)
	@mkdir -p $(dir $@)
	$(CC) -o $@ $< $(LIBA) $(LDFLAGS) $(DEPLIBS)
.SECONDARY: $(BENCH_SRC:%.c=$(BUILD)/obj/%.o)

bench: deps
	+@$(BUILD_STEP) all $(BENCH_BIN)
	@for b in $(BENCH_BIN); do echo "== $$b"; $$b || exit 1; done

# Benchmarks that read images start the image decoder process (lib/build.mk).
$(BENCH_BIN): | $(DECODER)

# the material preview path-traced per material against lambert (bench/materials.sh)
.PHONY: bench-materials
bench-materials: $(BUILD)/bin/gtrace
	@bench/materials.sh $(BUILD)
bench: bench-materials
