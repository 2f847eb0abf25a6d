/* fuzz_image.c - libFuzzer target: images: the bytes as an image file read with gimage_read and through the image
 * texture node. The entry point is shared with tests/test_regress.c (fuzz_entry.h); `make fuzz` builds and runs
 * it. Allocation stacks by the fast unwinder (full ones cost 60% of the run), so the suppressions name the frame
 * where it stops (GFUZZ_FAST_UNWIND, fuzz_entry.h). */
#define GFUZZ_FAST_UNWIND
#define GFUZZ_TARGET image
#include "fuzz_target.h"
