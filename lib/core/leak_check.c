/* leak_check.c - sanitizer builds only: LeakSanitizer's check at exit, run once no thread is exiting (leak_check.h).
 * A handler registered by the library's constructor runs before the sanitizer's own check (registered earlier, at
 * the run-time's start); the own check is then skipped, since the check runs once. */
#include "leak_check.h"

#if defined(__SANITIZE_ADDRESS__) && !defined(GENERIC_OIIO_STATIC)
#include <dirent.h>
#include <sanitizer/lsan_interface.h>
#include <stdlib.h>
#include <time.h>

/* Threads of this process, from /proc/self/task; -1 when it cannot be read. */
static int thread_count(void)
{
    DIR *d = opendir("/proc/self/task");
    if (!d)
        return -1;
    int n = 0;
    for (struct dirent *e; (e = readdir(d));)
        n += e->d_name[0] != '.';
    closedir(d);
    return n;
}

void gleak_check_when_threads_settle(void)
{
    const struct timespec ms = {0, 1000000};
    int last = thread_count(), steady = 0;
    for (int i = 0; i < 2000 && steady < 20; i++) { /* 20 ms without change, at most about 2 s */
        nanosleep(&ms, NULL);
        int now = thread_count();
        steady = now == last ? steady + 1 : 0;
        last = now;
    }
    __lsan_do_leak_check();
}

__attribute__((constructor)) static void register_leak_check(void) { atexit(gleak_check_when_threads_settle); }
#else
void gleak_check_when_threads_settle(void) {}
#endif
