/* fuzz_target.h - the libFuzzer entry points of one target: a target file (tests/fuzz/fuzz_<name>.c) defines
 * GFUZZ_TARGET as its name and includes this header once. LLVMFuzzerInitialize makes the private directory
 * (gfuzz_setup); LLVMFuzzerTestOneInput runs each input through the entry point gfuzz_<name> of fuzz_entry.h, and
 * a broken promise aborts with the line "fuzz_<name>: reason" (which tests/fuzz/run_generated.sh looks for), so
 * that libFuzzer keeps the input. */
#ifndef GENERIC_TESTS_FUZZ_TARGET_H
#define GENERIC_TESTS_FUZZ_TARGET_H

#include "fuzz_entry.h"

#ifndef GFUZZ_TARGET
#error "define GFUZZ_TARGET (the target's name: reader, bfc, ...) before including fuzz_target.h"
#endif

#define GFUZZ_PASTE(a, b) GFUZZ_PASTE_(a, b)
#define GFUZZ_PASTE_(a, b) a##b
#define GFUZZ_STRING(x) GFUZZ_STRING_(x)
#define GFUZZ_STRING_(x) #x
#define GFUZZ_ENTRY GFUZZ_PASTE(gfuzz_, GFUZZ_TARGET)
#define GFUZZ_NAME "fuzz_" GFUZZ_STRING(GFUZZ_TARGET)

/* OpenImageIO's TextureSystem frees its implementation with a sized delete of the wrong size (see
 * lib/image/image_basic.c); that mismatch is inside the system library, not ours. */
const char *__asan_default_options(void);
const char *__asan_default_options(void) { return "new_delete_type_mismatch=0"; }

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    if (gfuzz_setup() != 0) {
        fprintf(stderr, GFUZZ_NAME ": cannot set up the private directory\n");
        abort();
    }
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (GFUZZ_ENTRY(data, size) != 0) {
        fprintf(stderr, GFUZZ_NAME ": %s\n", gfuzz_why);
        abort();
    }
    return 0;
}

#endif
