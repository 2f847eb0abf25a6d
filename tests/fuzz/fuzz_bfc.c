/* fuzz_bfc.c - libFuzzer target: Labsphere BFC-450 matrices: gbfc_parse on the bytes, the matrix converted into three colour models.
 * The entry point is shared with tests/test_regress.c (fuzz_entry.h); `make fuzz` builds and runs it. */
#include "fuzz_entry.h"

/* OpenImageIO's TextureSystem frees its implementation with a sized delete of the wrong size (see
 * lib/image/texture_oiio.cpp); that mismatch is inside the system library, not ours. */
const char *__asan_default_options(void);
const char *__asan_default_options(void) { return "new_delete_type_mismatch=0"; }

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    if (gfuzz_setup() != 0) {
        fprintf(stderr, "fuzz_bfc: cannot set up the private directory\n");
        abort();
    }
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (gfuzz_bfc(data, size) != 0) {
        fprintf(stderr, "fuzz_bfc: %s\n", gfuzz_why);
        abort();
    }
    return 0;
}
