/* test_budget.c - the process-wide memory budget (generic/memory.h): the parsing of limits as users write them
 * (accepted forms give exact byte counts, malformed and out-of-range ones are refused with a message), the
 * environment (refused, never defaulted), reservations up to the limit and not a byte beyond, the refusal's
 * figures, releases, and reservations from several threads adding up exactly. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "generic/memory.h"

#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void test_parse_accepts(void **state)
{
    (void)state;
    static const struct {
        const char *text;
        unsigned long long bytes;
    } cases[] = {
        {"512", 512ULL << 20},   {"1", 1ULL << 20},         {"2G", 2ULL << 30},     {"2g", 2ULL << 30},
        {"512M", 512ULL << 20},  {"512MiB", 512ULL << 20},  {"512MB", 512ULL << 20}, {"1T", 1ULL << 40},
        {" 64 ", 64ULL << 20},   {"1048576", 1ULL << 40},   {"3GiB", 3ULL << 30},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        size_t bytes = 0;
        GError err;
        int rc = gmem_budget_parse(cases[i].text, &bytes, &err);
        if (rc != G_OK)
            fail_msg("'%s' refused: %s", cases[i].text, err.message);
        assert_true((unsigned long long)bytes == cases[i].bytes);
    }
}

static void test_parse_refuses(void **state)
{
    (void)state;
    static const char *const bad[] = {"0", "-5", "abc", "1e30", "", "  ", "1.5G", "2K", "2GG", "2 G x", "0G",
                                      "1048577", "2T", "99999999999999999999999", "+5", "5X", "0x10", "G"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        size_t bytes = 12345;
        GError err;
        int rc = gmem_budget_parse(bad[i], &bytes, &err);
        if (rc != G_ERR_INVALID)
            fail_msg("'%s' accepted as %zu bytes", bad[i], bytes);
        assert_int_equal(bytes, 12345);
        assert_non_null(strstr(err.message, "memory limit"));
    }
}

static void test_reserve_up_to_limit(void **state)
{
    (void)state;
    const size_t base = gmem_budget_used();
    gmem_budget_set_limit(base + (8u << 20));
    GError err;
    assert_int_equal(gmem_budget_reserve(6u << 20, "a first image", &err), G_OK);
    assert_int_equal(gmem_budget_reserve(2u << 20, "a second image", &err), G_OK); /* exactly the limit */
    assert_int_equal(gmem_budget_used(), base + (8u << 20));
    assert_int_equal(gmem_budget_reserve(1, "one byte more", &err), G_ERR_NOMEM);
    assert_int_equal(gmem_budget_used(), base + (8u << 20)); /* a refusal reserves nothing */
    assert_non_null(strstr(err.message, "one byte more"));
    assert_non_null(strstr(err.message, "--memory-limit"));
    assert_non_null(strstr(err.message, "GENERIC_MEMORY_LIMIT_MB"));
    gmem_budget_release(2u << 20);
    assert_int_equal(gmem_budget_reserve(3u << 20, "a third image", &err), G_ERR_NOMEM);
    char figures[64];
    snprintf(figures, sizeof figures, "needs 3.0 MiB");
    assert_non_null(strstr(err.message, figures));
    assert_int_equal(gmem_budget_reserve(SIZE_MAX, "everything", &err), G_ERR_NOMEM); /* no overflow */
    assert_int_equal(gmem_budget_reserve(2u << 20, "a third image", &err), G_OK);
    gmem_budget_release(8u << 20);
    assert_int_equal(gmem_budget_used(), base);
    gmem_budget_set_limit(0);
    assert_int_equal(gmem_budget_limit(), (size_t)GMEM_BUDGET_DEFAULT_MB << 20);
}

enum { THREADS = 4, ROUNDS = 20000 };

static void *reserve_many(void *arg)
{
    size_t *granted = arg;
    GError err;
    for (int i = 0; i < ROUNDS; i++)
        if (gmem_budget_reserve(4096, "a block", &err) == G_OK)
            (*granted)++;
    return NULL;
}

static void test_threads_add_up(void **state)
{
    (void)state;
    const size_t base = gmem_budget_used();
    const size_t room = 4096u * (ROUNDS * THREADS / 2); /* half the requests fit */
    gmem_budget_set_limit(base + room);
    pthread_t t[THREADS];
    size_t granted[THREADS] = {0};
    for (int i = 0; i < THREADS; i++)
        assert_int_equal(pthread_create(&t[i], NULL, reserve_many, &granted[i]), 0);
    size_t total = 0;
    for (int i = 0; i < THREADS; i++) {
        pthread_join(t[i], NULL);
        total += granted[i];
    }
    assert_int_equal(total, ROUNDS * THREADS / 2);
    assert_int_equal(gmem_budget_used(), base + room);
    gmem_budget_release(room);
    gmem_budget_set_limit(0);
}

int main(int argc, char **argv)
{
    /* The environment is read once, at the first use: a malformed value there is refused, not defaulted. This
     * process sets it before anything reads it, then checks the limit from a child's point of view by re-running
     * itself (argv[1] "env VALUE": exit 0 when refused, 1 when accepted). */
    if (argc == 3 && strcmp(argv[1], "env") == 0) {
        setenv("GENERIC_MEMORY_LIMIT_MB", argv[2], 1);
        GError err;
        int refused = gmem_budget_check_env(&err) == G_ERR_INVALID &&
                      strstr(err.message, "GENERIC_MEMORY_LIMIT_MB") &&
                      gmem_budget_reserve(1, "a byte", &err) == G_ERR_INVALID;
        return refused ? 0 : 1;
    }
    if (argc == 2 && strcmp(argv[1], "env-alias") == 0) {
        setenv("GENERIC_IMAGE_BUDGET_MB", "64", 1);
        unsetenv("GENERIC_MEMORY_LIMIT_MB");
        GError err;
        return gmem_budget_check_env(&err) == G_OK && gmem_budget_limit() == (64u << 20) ? 0 : 1;
    }
    unsetenv("GENERIC_MEMORY_LIMIT_MB");
    unsetenv("GENERIC_IMAGE_BUDGET_MB");
    static const char *const bad_env[] = {"0", "-5", "abc", "1e30", "512KB"};
    for (size_t i = 0; i < sizeof bad_env / sizeof bad_env[0]; i++) {
        char cmd[4096];
        snprintf(cmd, sizeof cmd, "'%s' env '%s'", argv[0], bad_env[i]);
        if (system(cmd) != 0) {
            fprintf(stderr, "GENERIC_MEMORY_LIMIT_MB=%s was not refused\n", bad_env[i]);
            return 1;
        }
    }
    char cmd[4096];
    snprintf(cmd, sizeof cmd, "'%s' env-alias", argv[0]);
    if (system(cmd) != 0) {
        fprintf(stderr, "GENERIC_IMAGE_BUDGET_MB=64 was not taken as the limit\n");
        return 1;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_parse_accepts),
        cmocka_unit_test(test_parse_refuses),
        cmocka_unit_test(test_reserve_up_to_limit),
        cmocka_unit_test(test_threads_add_up),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
