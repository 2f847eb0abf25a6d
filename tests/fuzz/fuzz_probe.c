/* fuzz_probe.c - libFuzzer target: light probes: the bytes as an .hdr or .pfm file loaded with gprobe_load and
 * approximated by lights. The entry point is shared with tests/test_regress.c (fuzz_entry.h); `make fuzz` builds
 * and runs it. */
#define GFUZZ_TARGET probe
#include "fuzz_target.h"
