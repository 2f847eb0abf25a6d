/* test_gtrace_threads.c - the thread count a render is given limits Embree's BVH build too (Scene.accel_threads,
 * which gtrace sets from --threads): a scene of many spheres built with one thread starts no thread, while the
 * same build with every processor starts some on a machine that has more than one (the control that shows the
 * count can see them). Each build runs in a child process, since Embree's thread pool outlives the build. */
#include "generic/builtins.h"
#include "test_gtrace_common.h"

#include <sys/wait.h>
#include <unistd.h>

/* The calling process's thread count, from /proc/self/status; -1 when it cannot be read. */
static int thread_count(void)
{
    FILE *f = fopen("/proc/self/status", "r");
    if (!f)
        return -1;
    char line[256];
    int n = -1;
    while (fgets(line, sizeof line, f))
        if (sscanf(line, "Threads: %d", &n) == 1)
            break;
    fclose(f);
    return n;
}

/* Builds 20000 spheres with `threads` build threads (0: all) in a child; the threads it started, or -1. */
static int threads_started_by_build(int threads)
{
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        Scene *s = new_scene("rgb", gvec3(0, 0, 40), gvec3(0, 0, 0), 40.0);
        GMaterial *m = lambert(s, 0.5);
        unsigned seed = 1;
        for (int i = 0; i < 20000; i++) {
            double c[3];
            for (int k = 0; k < 3; k++) {
                seed = seed * 1103515245u + 12345u;
                c[k] = (seed >> 8) / (double)(1u << 24) * 20.0 - 10.0;
            }
            add_sphere(s, m, gvec3(c[0], c[1], c[2]), 0.05);
        }
        s->accel_threads = threads;
        GError err;
        int before = thread_count();
        if (before < 0 || accel_build(s, &err) != G_OK)
            _exit(255);
        int started = thread_count() - before;
        _exit(started < 0 ? 255 : started > 200 ? 200 : started);
    }
    int status = 0;
    assert_int_equal(waitpid(pid, &status, 0), pid);
    assert_true(WIFEXITED(status));
    return WEXITSTATUS(status) == 255 ? -1 : WEXITSTATUS(status);
}

static void test_build_obeys_thread_count(void **state)
{
    (void)state;
    int one = threads_started_by_build(1), all = threads_started_by_build(0);
    long cpus = sysconf(_SC_NPROCESSORS_ONLN);
    print_message("threads started by the build: %d with 1 thread, %d with all %ld processors\n", one, all, cpus);
    assert_int_equal(one, 0);
    if (cpus > 1)
        assert_true(all > 0);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_build_obeys_thread_count),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
