/* memory.c - allocator hook and the scratch arena. */
#include "generic/memory.h"

#include <pthread.h>

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static void *libc_alloc(size_t n, void *u) { (void)u; return malloc(n); }
static void *libc_realloc(void *p, size_t n, void *u) { (void)u; return realloc(p, n); }
static void libc_free(void *p, void *u) { (void)u; free(p); }

static GAllocator current = {libc_alloc, libc_realloc, libc_free, NULL};

void gmem_set_allocator(const GAllocator *a)
{
    if (a)
        current = *a;
    else
        current = (GAllocator){libc_alloc, libc_realloc, libc_free, NULL};
}

void *gmem_alloc(size_t size) { return size ? current.alloc(size, current.user) : NULL; }

void *gmem_calloc(size_t n, size_t size)
{
    if (n == 0 || size == 0 || n > SIZE_MAX / size)
        return NULL;
    void *p = gmem_alloc(n * size);
    if (p)
        memset(p, 0, n * size);
    return p;
}

void *gmem_realloc(void *ptr, size_t size) { return current.realloc(ptr, size, current.user); }

void gmem_free(void *ptr)
{
    if (ptr)
        current.free(ptr, current.user);
}

char *gmem_strdup(const char *s)
{
    if (!s)
        return NULL;
    size_t n = strlen(s) + 1;
    char *d = gmem_alloc(n);
    if (d)
        memcpy(d, s, n);
    return d;
}

/* ---- scratch arena: a list of blocks; allocation bumps within the current block ---- */

typedef struct Block {
    struct Block *next;
    size_t size, used;
    unsigned char *data;
} Block;

struct GScratch {
    Block *first, *cur;
    size_t block_size;
    void *raw; /* the allocation holding this header and the first block */
};

/* ALIGN: of every allocation from the arena. LINE: a cache line. An arena is one thread's, and its header and
 * current block are written at every allocation and release: they sit in an allocation of their own, a line
 * apart from anything else, so that two threads' arenas never share a cache line (two 24-byte headers from
 * malloc did, side by side, and cost the spectral models 10% of a 2-thread render). */
enum { ALIGN = 32, LINE = 64 };

static void block_init(Block *b, size_t size)
{
    b->next = NULL;
    b->size = size;
    b->used = 0;
    uintptr_t p = (uintptr_t)(b + 1);
    b->data = (unsigned char *)((p + ALIGN - 1) & ~(uintptr_t)(ALIGN - 1));
}

static Block *block_new(size_t size)
{
    Block *b = size <= SIZE_MAX - sizeof *b - ALIGN ? gmem_alloc(sizeof *b + size + ALIGN) : NULL;
    if (b)
        block_init(b, size);
    return b;
}

GScratch *gscratch_create(size_t bytes)
{
    size_t size = bytes ? bytes : 256 * 1024;
    size_t head = (sizeof(GScratch) + sizeof(Block) + LINE - 1) & ~(size_t)(LINE - 1);
    if (size > SIZE_MAX - head - 3 * LINE)
        return NULL;
    /* a line of slack to align the header, the header with the first block's, the data, a line after it */
    unsigned char *raw = gmem_alloc(LINE + head + size + LINE);
    if (!raw)
        return NULL;
    GScratch *s = (GScratch *)(((uintptr_t)raw + LINE - 1) & ~(uintptr_t)(LINE - 1));
    Block *b = (Block *)(s + 1);
    block_init(b, size);
    *s = (GScratch){.first = b, .cur = b, .block_size = size, .raw = raw};
    return s;
}

void gscratch_destroy(GScratch *s)
{
    if (!s)
        return;
    for (Block *b = s->first->next; b;) { /* the first block is in the header's allocation */
        Block *n = b->next;
        gmem_free(b);
        b = n;
    }
    gmem_free(s->raw);
}

/* gscratch_alloc when the current block is full (bytes rounded): the next kept block, or a new one. Apart, so that
 * the common case saves no registers. */
__attribute__((noinline)) static void *alloc_grow(GScratch *s, size_t bytes)
{
    for (;;) {
        Block *b = s->cur;
        if (b->size - b->used >= bytes) {
            void *p = b->data + b->used;
            b->used += bytes;
            return p;
        }
        if (b->next) { /* reuse a block kept from earlier growth */
            s->cur = b->next;
            s->cur->used = 0;
            continue;
        }
        size_t size = bytes > s->block_size ? bytes : s->block_size;
        Block *nb = block_new(size);
        if (!nb)
            return NULL;
        b->next = nb;
        s->cur = nb;
    }
}

void *gscratch_alloc(GScratch *s, size_t bytes)
{
    bytes = (bytes + ALIGN - 1) & ~(size_t)(ALIGN - 1);
    Block *b = s->cur;
    if (b->size - b->used >= bytes) {
        void *p = b->data + b->used;
        b->used += bytes;
        return p;
    }
    return alloc_grow(s, bytes);
}

GScratchMark gscratch_mark(const GScratch *s)
{
    GScratchMark m = {s->cur, s->cur->used};
    return m;
}

void gscratch_release(GScratch *s, GScratchMark mark)
{
    s->cur = mark.block;
    s->cur->used = mark.used;
}

void gscratch_reset(GScratch *s)
{
    s->cur = s->first;
    s->cur->used = 0;
}

/* The per-thread arena of gscratch_thread: created on a thread's first use and grown to the largest temporary
 * asked for, so later calls do not allocate; the key's destructor frees it when the thread ends (the
 * thread-local pointer keeps it reachable until then). */
static pthread_key_t thread_key;
static int thread_key_ok;
static pthread_once_t thread_once = PTHREAD_ONCE_INIT;
static _Thread_local GScratch *arena_of_thread;

static void thread_arena_destroy(void *arena) { gscratch_destroy(arena); }

static void thread_key_create(void) { thread_key_ok = pthread_key_create(&thread_key, thread_arena_destroy) == 0; }

GScratch *gscratch_thread(void)
{
    if (arena_of_thread)
        return arena_of_thread;
    pthread_once(&thread_once, thread_key_create);
    if (!thread_key_ok)
        return NULL;
    GScratch *s = gscratch_create(0);
    if (s && pthread_setspecific(thread_key, s) != 0) {
        gscratch_destroy(s);
        s = NULL;
    }
    return arena_of_thread = s;
}
