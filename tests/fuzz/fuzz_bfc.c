/* fuzz_bfc.c - libFuzzer target: Labsphere BFC-450 matrices: gbfc_parse on the bytes, the matrix converted into
 * three colour models. The entry point is shared with tests/test_regress.c (fuzz_entry.h); `make fuzz` builds and
 * runs it. */
#define GFUZZ_TARGET bfc
#include "fuzz_target.h"
