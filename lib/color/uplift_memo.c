/* uplift_memo.c - each thread's memo of uplifted spectra (uplift_memo.h): a direct-mapped table of the last
 * results, indexed by a hash of the model's address, the role and the colour's bits, created on a thread's first
 * use and freed when the thread ends (as the scratch arena, lib/core/memory.c). An entry matches only the exact
 * bits it was made from, so a hit gives what the fit would give. A global epoch, advanced whenever a model goes
 * away, makes every older entry stale: a model made later at the same address never sees another's values. */
#include "uplift_memo.h"
#include "generic/memory.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <string.h>

enum { MEMO_SLOTS = 64 };

typedef struct MemoEntry {
    const void *model;
    unsigned long epoch; /* 0: empty (the epoch starts at 1) */
    int role, n;
    double rgb[3];
    float v[GUPLIFT_MEMO_MAX_VALUES];
} MemoEntry;

typedef struct Memo {
    MemoEntry slot[MEMO_SLOTS];
} Memo;

static atomic_ulong memo_epoch = 1;
static pthread_key_t memo_key;
static int memo_key_ok;
static pthread_once_t memo_once = PTHREAD_ONCE_INIT;
static _Thread_local Memo *memo_of_thread;

static void memo_destroy(void *memo) { gmem_free(memo); }

static void memo_key_create(void) { memo_key_ok = pthread_key_create(&memo_key, memo_destroy) == 0; }

static Memo *thread_memo(void)
{
    if (memo_of_thread)
        return memo_of_thread;
    pthread_once(&memo_once, memo_key_create);
    if (!memo_key_ok)
        return NULL;
    Memo *m = gmem_calloc(1, sizeof *m);
    if (m && pthread_setspecific(memo_key, m) != 0) {
        gmem_free(m);
        m = NULL;
    }
    return memo_of_thread = m;
}

static unsigned slot_of(const void *model, int role, const double rgb[3])
{
    uint64_t h = (uint64_t)(uintptr_t)model * 0x9e3779b97f4a7c15u ^ (uint64_t)role;
    for (int c = 0; c < 3; c++) {
        uint64_t bits;
        memcpy(&bits, &rgb[c], sizeof bits);
        h = (h ^ bits) * 0xff51afd7ed558ccdu;
        h ^= h >> 29;
    }
    return (unsigned)(h >> 40) % MEMO_SLOTS;
}

const float *guplift_memo_find(const void *model, int role, const double rgb[3], int n, unsigned long *epoch)
{
    *epoch = atomic_load_explicit(&memo_epoch, memory_order_acquire);
    if (n > GUPLIFT_MEMO_MAX_VALUES)
        return NULL;
    Memo *m = thread_memo();
    if (!m)
        return NULL;
    const MemoEntry *e = &m->slot[slot_of(model, role, rgb)];
    if (e->epoch != *epoch || e->model != model || e->role != role || e->n != n ||
        memcmp(e->rgb, rgb, sizeof e->rgb) != 0)
        return NULL;
    return e->v;
}

void guplift_memo_store(const void *model, int role, const double rgb[3], int n, const float *v,
                        unsigned long epoch)
{
    Memo *m = n <= GUPLIFT_MEMO_MAX_VALUES ? thread_memo() : NULL;
    if (!m || epoch != atomic_load_explicit(&memo_epoch, memory_order_acquire))
        return;
    MemoEntry *e = &m->slot[slot_of(model, role, rgb)];
    e->model = model;
    e->epoch = epoch;
    e->role = role;
    e->n = n;
    memcpy(e->rgb, rgb, sizeof e->rgb);
    memcpy(e->v, v, (size_t)n * sizeof *v);
}

void guplift_memo_forget_all(void) { atomic_fetch_add_explicit(&memo_epoch, 1, memory_order_acq_rel); }
