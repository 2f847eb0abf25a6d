/* reader_fixture.h - shared by the text-reader tests (include after <cmocka.h> and generic/reader.h): loading
 * a text that must fail, with the exact message it must give. */
#ifndef GENERIC_TEST_READER_FIXTURE_H
#define GENERIC_TEST_READER_FIXTURE_H

#include <string.h>

/* Loads text as "t.mat"; the load must fail, leave no library and give exactly `message` (printed beside
 * what came when it differs). */
static inline void load_fails(const char *text, const char *message)
{
    GLibrary *lib = (GLibrary *)0x1;
    GError err;
    assert_true(greader_load_string(text, "t.mat", NULL, &lib, &err) < 0);
    assert_null(lib);
    if (strcmp(err.message, message) != 0)
        print_error("got:  %s\nwant: %s\n", err.message, message);
    assert_string_equal(err.message, message);
}

#endif
