/* budget.c - the process-wide memory budget (generic/memory.h): a limit, the bytes reserved against it, and the
 * parsing of the limit as users and the environment write it. */
#include "generic/memory.h"

#include <ctype.h>
#include <errno.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static atomic_size_t limit_set; /* bytes from gmem_budget_set_limit; 0: none */
static atomic_size_t used_bytes;

/* The environment's limit, read once: its bytes (0 when unset) or the error that refuses it. */
static pthread_once_t env_once = PTHREAD_ONCE_INIT;
static size_t env_bytes;
static GError env_error;

int gmem_budget_parse(const char *text, size_t *bytes, GError *err)
{
    const char *p = text ? text : "";
    while (isspace((unsigned char)*p))
        p++;
    unsigned long long value = 0;
    const char *digits = p;
    while (*p >= '0' && *p <= '9') {
        if (value > (unsigned long long)GMEM_BUDGET_MAX_MB << 20)
            break; /* far out of range already; the bound check below refuses it */
        value = value * 10 + (unsigned long long)(*p - '0');
        p++;
    }
    int ndigits = (int)(p - digits);
    while (*p >= '0' && *p <= '9')
        p++;
    unsigned shift = 20; /* no suffix: MiB */
    int suffix = 1;
    switch (*p) {
    case 'm': case 'M': shift = 20; break;
    case 'g': case 'G': shift = 30; break;
    case 't': case 'T': shift = 40; break;
    default: suffix = 0; break;
    }
    if (suffix) {
        p++;
        if (p[0] == 'i' && p[1] == 'B')
            p += 2;
        else if (*p == 'B' || *p == 'b')
            p++;
    }
    while (isspace((unsigned char)*p))
        p++;
    if (ndigits == 0 || *p)
        return gerror_set(err, G_ERR_INVALID,
                          "memory limit '%s' is not a whole number of MiB, optionally with a suffix M, G or T "
                          "(e.g. 512, 2G)", text ? text : "");
    const unsigned long long max_bytes = (unsigned long long)GMEM_BUDGET_MAX_MB << 20;
    if (value == 0 || value > (max_bytes >> shift) || (value << shift) < (1ULL << 20))
        return gerror_set(err, G_ERR_INVALID, "memory limit '%s' is out of range: it must be from 1 MiB to %d MiB",
                          text, GMEM_BUDGET_MAX_MB);
    if ((value << shift) > SIZE_MAX)
        return gerror_set(err, G_ERR_INVALID, "memory limit '%s' does not fit this machine's address space", text);
    if (bytes)
        *bytes = (size_t)(value << shift);
    return G_OK;
}

static void env_read(void)
{
    static const char *const names[] = {"GENERIC_MEMORY_LIMIT_MB", "GENERIC_IMAGE_BUDGET_MB"};
    size_t found[2] = {0, 0};
    for (int i = 0; i < 2; i++) {
        const char *text = getenv(names[i]);
        if (!text)
            continue;
        GError e;
        if (gmem_budget_parse(text, &found[i], &e) != G_OK) {
            gerror_set(&env_error, G_ERR_INVALID, "%s: %s", names[i], e.message);
            return;
        }
    }
    if (found[0] && found[1] && found[0] != found[1]) {
        gerror_set(&env_error, G_ERR_INVALID,
                   "GENERIC_MEMORY_LIMIT_MB (%zu MiB) and GENERIC_IMAGE_BUDGET_MB (%zu MiB, another name for it) "
                   "differ: set only GENERIC_MEMORY_LIMIT_MB", found[0] >> 20, found[1] >> 20);
        return;
    }
    env_bytes = found[0] ? found[0] : found[1];
}

int gmem_budget_check_env(GError *err)
{
    pthread_once(&env_once, env_read);
    if (env_error.code != G_OK)
        return gerror_set(err, env_error.code, "%s", env_error.message);
    return G_OK;
}

size_t gmem_budget_limit(void)
{
    size_t set = atomic_load(&limit_set);
    if (set)
        return set;
    pthread_once(&env_once, env_read);
    return env_bytes ? env_bytes : (size_t)GMEM_BUDGET_DEFAULT_MB << 20;
}

size_t gmem_budget_used(void) { return atomic_load(&used_bytes); }

void gmem_budget_set_limit(size_t bytes) { atomic_store(&limit_set, bytes); }

static double mib(size_t bytes) { return (double)bytes / 1048576.0; }

int gmem_budget_reserve(size_t bytes, const char *what, GError *err)
{
    if (!atomic_load(&limit_set) && gmem_budget_check_env(err) != G_OK)
        return G_ERR_INVALID;
    const size_t limit = gmem_budget_limit();
    size_t cur = atomic_load(&used_bytes);
    do {
        if (bytes > limit || cur > limit - bytes)
            return gerror_set(err, G_ERR_NOMEM,
                              "%s needs %.1f MiB, over the memory budget: %.1f MiB of %.0f MiB are in use "
                              "(raise it with --memory-limit or GENERIC_MEMORY_LIMIT_MB)",
                              what ? what : "this", mib(bytes), mib(cur), mib(limit));
    } while (!atomic_compare_exchange_weak(&used_bytes, &cur, cur + bytes));
    return G_OK;
}

void gmem_budget_release(size_t bytes)
{
    size_t cur = atomic_load(&used_bytes);
    size_t next;
    do
        next = cur >= bytes ? cur - bytes : 0;
    while (!atomic_compare_exchange_weak(&used_bytes, &cur, next));
}
