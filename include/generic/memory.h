/* memory.h - the library's allocator hook, the per-thread scratch arena and the memory budget.
 *
 * Every allocation the library makes goes through gmem_alloc/gmem_realloc/gmem_free, which call the
 * functions installed with gmem_set_allocator (the C library's by default). Tests install counting or
 * failing allocators through it.
 *
 * A GScratch is a bump allocator for short-lived values (colours on the per-ray path): allocation moves
 * a pointer, gscratch_mark/gscratch_release return to an earlier point, and memory is only requested
 * from the allocator when the arena grows past what it ever needed before. One arena per thread. */
#ifndef GENERIC_MEMORY_H
#define GENERIC_MEMORY_H

#include "error.h"
#include "export.h"
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/** Allocator functions installed with gmem_set_allocator. */
typedef struct GAllocator {
    void *(*alloc)(size_t size, void *user);
    void *(*realloc)(void *ptr, size_t size, void *user);
    void (*free)(void *ptr, void *user);
    void *user;
} GAllocator;

/** Installs an allocator for all later library allocations; NULL restores the C library's. Not thread safe:
 * call it before other threads use the library. */
GENERIC_API void gmem_set_allocator(const GAllocator *allocator);
/** Allocates size bytes (never returns a pointer for size 0 requests of 0: returns NULL). */
GENERIC_API void *gmem_alloc(size_t size);
/** Allocates n * size zeroed bytes, checking the multiplication for overflow. */
GENERIC_API void *gmem_calloc(size_t n, size_t size);
/** Resizes a block from gmem_alloc; NULL ptr allocates. */
GENERIC_API void *gmem_realloc(void *ptr, size_t size);
/** Frees a block from gmem_alloc; NULL is a no-op. */
GENERIC_API void gmem_free(void *ptr);
/** Duplicates a string with gmem_alloc; NULL gives NULL. */
GENERIC_API char *gmem_strdup(const char *s);

/** Bump arena for per-ray temporaries. */
typedef struct GScratch GScratch;

/** Creates an arena whose first block holds `bytes` (0 picks 256 KiB); NULL when out of memory. */
GENERIC_API GScratch *gscratch_create(size_t bytes);
/** Frees the arena and all its blocks; NULL is a no-op. */
GENERIC_API void gscratch_destroy(GScratch *s);
/** Returns `bytes` of 32-byte aligned storage, or NULL when the allocator fails. */
GENERIC_API void *gscratch_alloc(GScratch *s, size_t bytes);
/** A position in the arena to return to. */
typedef struct GScratchMark {
    void *block;
    size_t used;
} GScratchMark;
/** Remembers the current position. */
GENERIC_API GScratchMark gscratch_mark(const GScratch *s);
/** Returns to a position from gscratch_mark; everything allocated after it is released. */
GENERIC_API void gscratch_release(GScratch *s, GScratchMark mark);
/** The calling thread's own arena, for library code that needs temporaries when its caller gave no arena (the
 * defaults of optional colour operations, texture nodes called without sp->scratch): created on first use,
 * freed when the thread ends; NULL when out of memory. Users take a mark and release it, like any arena. */
GENERIC_API GScratch *gscratch_thread(void);
/** Releases everything (keeps the blocks for reuse). */
GENERIC_API void gscratch_reset(GScratch *s);

/* ---- the memory budget: one process-wide limit on memory whose size comes from input ----
 *
 * Everything the library or a tool allocates in proportion to what a file asks for (decoded images and their
 * decode, light probe tables, texture caches, meshes, instances, colours and matrices, acceleration structures,
 * framebuffers) is reserved against one budget before it is allocated, and released when it is freed; a
 * reservation that would take the total above the limit is refused before any memory is touched.
 * The limit: what gmem_budget_set_limit set, else the environment's GENERIC_MEMORY_LIMIT_MB (read once), else
 * GMEM_BUDGET_DEFAULT_MB MiB. GENERIC_IMAGE_BUDGET_MB is accepted as another name for GENERIC_MEMORY_LIMIT_MB (the
 * whole scene's limit, not one image's); set to different values, the two are an error. An environment value that
 * gmem_budget_parse refuses is never replaced by the default: every reservation fails with the parse error until a
 * limit is set, and gmem_budget_check_env reports it at start-up. All functions are thread safe (atomics). */

/** The default memory budget, in MiB. */
#define GMEM_BUDGET_DEFAULT_MB 4096

/** Reserves `bytes` against the budget for `what` (a short noun phrase: "a 4096x2048 light probe"). G_OK, or
 * G_ERR_NOMEM when used + bytes would exceed the limit (nothing is reserved; the message names `what`, the bytes
 * requested, used and the limit, and how to raise it: --memory-limit or GENERIC_MEMORY_LIMIT_MB), or
 * G_ERR_INVALID when the environment's limit is malformed. Callers put the entry's FILE:LINE:COL in front. */
GENERIC_API GENERIC_NODISCARD int gmem_budget_reserve(size_t bytes, const char *what, GError *err);
/** Returns `bytes` from an earlier gmem_budget_reserve; releasing more than is reserved is a programming error
 * (the count stops at 0). */
GENERIC_API void gmem_budget_release(size_t bytes);
/** The limit in bytes (see above; the default when the environment's value is malformed). */
GENERIC_API size_t gmem_budget_limit(void);
/** The bytes reserved now. */
GENERIC_API size_t gmem_budget_used(void);
/** Sets the limit in bytes for the whole process, over the environment; 0 returns to the environment's value or
 * the default. Reservations already made are kept, even above a lower limit. */
GENERIC_API void gmem_budget_set_limit(size_t bytes);
/** Parses a limit as a user writes it: a whole number of MiB ("512"), or a whole number with one of the suffixes
 * M, G, T (binary multiples, upper or lower case, optionally followed by "B" or "iB": "2G", "512MiB", "1t").
 * The value must be at least 1 MiB and at most GMEM_BUDGET_MAX_MB MiB. G_OK with *bytes set, or G_ERR_INVALID
 * (0, negative numbers, fractions, exponents, other suffixes, out of range) with a message quoting the text and
 * the bounds. */
GENERIC_API GENERIC_NODISCARD int gmem_budget_parse(const char *text, size_t *bytes, GError *err);
/** Checks the environment's limit (GENERIC_MEMORY_LIMIT_MB, GENERIC_IMAGE_BUDGET_MB): G_OK when unset or valid,
 * else G_ERR_INVALID with gmem_budget_parse's message naming the variable. Tools call it at start-up. */
GENERIC_API GENERIC_NODISCARD int gmem_budget_check_env(GError *err);

/** The largest limit gmem_budget_parse accepts, in MiB (1 TiB). */
#define GMEM_BUDGET_MAX_MB (1024 * 1024)

#ifdef __cplusplus
}
#endif
#endif
