/* fuzz_reader.c - libFuzzer target: the text format loaded from a string (every registered entry kind, four colour
 * models), then evaluated. The entry point is shared with tests/test_regress.c (fuzz_entry.h); `make fuzz` builds
 * and runs it. */
#define GFUZZ_TARGET reader
#include "fuzz_target.h"
