/* fuzz_image.c - libFuzzer target: images: the bytes as an image file read with gimage_read and through the image texture node.
 * The entry point is shared with tests/test_regress.c (fuzz_entry.h); `make fuzz` builds and runs it. */
/* OpenImageIO's TextureSystem frees its implementation with a sized delete of the wrong size (see
 * lib/image/image_basic.c); that mismatch is inside the system library, not ours. Allocation stacks by the fast
 * unwinder (full ones cost 60% of the run), so the suppressions name the frame where it stops. */
#define GFUZZ_FAST_UNWIND
#include "fuzz_entry.h"

const char *__asan_default_options(void);
const char *__asan_default_options(void) { return "new_delete_type_mismatch=0"; }

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    if (gfuzz_setup() != 0) {
        fprintf(stderr, "fuzz_image: cannot set up the private directory\n");
        abort();
    }
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (gfuzz_image(data, size) != 0) {
        fprintf(stderr, "fuzz_image: %s\n", gfuzz_why);
        abort();
    }
    return 0;
}
