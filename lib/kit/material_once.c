/* material_once.c - work a material does on first use instead of at creation (generic/kit/material_kit.h,
 * gmaterial_once): one process-wide lock, taken only until the work has run, recursive so that the work may use
 * other materials' (a layer's base, a film's base) on the same thread. */
#include "generic/kit/material_kit.h"

#include <pthread.h>

static pthread_mutex_t once_lock;
static pthread_once_t once_lock_made = PTHREAD_ONCE_INIT;

static void make_lock(void)
{
    pthread_mutexattr_t attr;
    pthread_mutexattr_init(&attr);
    pthread_mutexattr_settype(&attr, PTHREAD_MUTEX_RECURSIVE);
    pthread_mutex_init(&once_lock, &attr);
    pthread_mutexattr_destroy(&attr);
}

int gmaterial_once(GMaterialOnce *once, int (*work)(void *arg), void *arg)
{
    if (__atomic_load_n(&once->state, __ATOMIC_ACQUIRE))
        return once->status;
    pthread_once(&once_lock_made, make_lock);
    pthread_mutex_lock(&once_lock);
    if (!__atomic_load_n(&once->state, __ATOMIC_RELAXED)) {
        once->status = work(arg);
        __atomic_store_n(&once->state, 1, __ATOMIC_RELEASE);
    }
    pthread_mutex_unlock(&once_lock);
    return once->status;
}
