/* test_alloc.h - the test allocator (static inline): installed with gmem_set_allocator, it counts the library's
 * allocations, frees and live blocks and fails the calls a test chooses (one numbered call, every call from it
 * on, or every block of at least a size). The counters are atomic: rendering and the probe's sums allocate in
 * threads. */
#ifndef GENERIC_TEST_ALLOC_H
#define GENERIC_TEST_ALLOC_H

#include <stdlib.h>

#include "generic/memory.h"

/** What the test allocator fails (set by the test before tu_alloc_install; all zero: nothing) and what it counted
 * since. */
typedef struct TuAlloc {
    long fail_call;   /**< the alloc or realloc call that fails, counted from 1; 0: none */
    int fail_after;   /**< with fail_call: every later call fails too */
    size_t max_bytes; /**< 0, or every request of at least this many bytes fails */
    int tagged;       /**< blocks carry a header, so that one freed by another allocator, or another's freed by
                       * this one, is a crash (install it only around code that frees nothing allocated before) */
    long calls;       /**< alloc and realloc calls */
    long frees;       /**< blocks freed */
    long live;        /**< blocks allocated and not freed */
    int failed;       /**< a call failed */
} TuAlloc;

/* the header of a tagged block: a 16-byte slot keeps the caller's block aligned as malloc's */
#define TU_ALLOC_TAG 16

/* Counts a call; whether it fails. */
static inline int tu_alloc_fails(TuAlloc *a, size_t size)
{
    long n = __atomic_add_fetch(&a->calls, 1, __ATOMIC_SEQ_CST);
    int fail = (a->fail_call > 0 && (n == a->fail_call || (a->fail_after && n > a->fail_call))) ||
               (a->max_bytes && size >= a->max_bytes);
    if (fail)
        __atomic_store_n(&a->failed, 1, __ATOMIC_SEQ_CST);
    return fail;
}

static inline void *tu_alloc_alloc(size_t size, void *user)
{
    TuAlloc *a = user;
    if (tu_alloc_fails(a, size))
        return NULL;
    size_t tag = a->tagged ? TU_ALLOC_TAG : 0;
    char *p = malloc(size + tag);
    if (!p)
        return NULL;
    __atomic_fetch_add(&a->live, 1, __ATOMIC_SEQ_CST);
    return p + tag;
}

static inline void *tu_alloc_realloc(void *ptr, size_t size, void *user)
{
    TuAlloc *a = user;
    if (!ptr)
        return tu_alloc_alloc(size, user);
    if (tu_alloc_fails(a, size))
        return NULL;
    size_t tag = a->tagged ? TU_ALLOC_TAG : 0;
    char *p = realloc((char *)ptr - tag, size + tag);
    return p ? p + tag : NULL;
}

static inline void tu_alloc_free(void *ptr, void *user)
{
    TuAlloc *a = user;
    if (!ptr)
        return;
    __atomic_fetch_add(&a->frees, 1, __ATOMIC_SEQ_CST);
    __atomic_fetch_sub(&a->live, 1, __ATOMIC_SEQ_CST);
    free((char *)ptr - (a->tagged ? TU_ALLOC_TAG : 0));
}

/** Installs the test allocator a (gmem_set_allocator) with its counters zeroed; gmem_set_allocator(NULL) restores
 * the C library's. a must outlive the installation: give it static storage, so that an assertion failing in
 * between does not leave the allocator on a dead stack frame. */
static inline void tu_alloc_install(TuAlloc *a)
{
    a->calls = a->frees = a->live = 0;
    a->failed = 0;
    GAllocator g = {tu_alloc_alloc, tu_alloc_realloc, tu_alloc_free, a};
    gmem_set_allocator(&g);
}

#endif
