/* fuzz_probe.c - libFuzzer target: light probes: the bytes as an .hdr or .pfm file loaded with gprobe_load and
 * approximated by lights. The entry point is shared with tests/test_regress.c (fuzz_entry.h); `make fuzz` builds
 * and runs it. */
/* Its allocations are unwound by the fast unwinder, as fuzz_image's: OpenImageIO's known PNG-reader leak (fuzz_entry.h)
 * is then suppressed by the frame where that unwinder stops (seen at exit after 30,943 inputs without it). */
#define GFUZZ_FAST_UNWIND
#define GFUZZ_TARGET probe
#include "fuzz_target.h"
