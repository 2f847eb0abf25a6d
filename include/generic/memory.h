/* memory.h - the library's allocator hook and the per-thread scratch arena.
 *
 * Every allocation the library makes goes through gmem_alloc/gmem_realloc/gmem_free, which call the
 * functions installed with gmem_set_allocator (the C library's by default). Tests install counting or
 * failing allocators through it; it is the one piece of process-wide state besides the type registry.
 *
 * A GScratch is a bump allocator for short-lived values (colours on the per-ray path): allocation moves
 * a pointer, gscratch_mark/gscratch_release return to an earlier point, and memory is only requested
 * from the allocator when the arena grows past what it ever needed before. One arena per thread. */
#ifndef GENERIC_MEMORY_H
#define GENERIC_MEMORY_H

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

#ifdef __cplusplus
}
#endif
#endif
