/* generic_decode.c - the image decoder process, generic-decode (lib/image/decode_protocol.h): decodes untrusted
 * images with the library's in-process reader under resource limits, so that a crash, a hang or a memory blow-up of
 * a third-party decoder ends this process only. Installed beside the OpenImageIO module (PREFIX/lib/generic/), which
 * it loads from its own directory. Not a program for users: it talks the protocol on its standard input and
 * output. */
#include "generic/memory.h"
#include "generic/services/file.h"
#include "generic/services/image.h"

#include "../decode_protocol.h"

#include <errno.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

/* The decoder's pipe: requests on standard input, answers on standard output. */
static int recv_all(void *buf, size_t n) { return gfile_read_exact(0, buf, n); }
static int send_all(const void *buf, size_t n) { return gfile_write_exact(1, buf, n); }

static int send_record(int phase, int status, int width, int height, int channels, const char *message)
{
    GDecodeRecord r = {GDECODE_MAGIC, phase, status, width, height, channels, 0};
    size_t len = status != G_OK && message ? strlen(message) : 0;
    r.message_length = (uint32_t)(len < GDECODE_MESSAGE_MAX ? len : GDECODE_MESSAGE_MAX);
    if (send_all(&r, sizeof r) != 0 || send_all(message, r.message_length) != 0)
        return -1;
    return 0;
}

/* The address space limit: soft at bytes (at most the hard limit set at the start). The sanitizers' shadow memory
 * needs terabytes of address space, so a sanitizer build sets none. */
static void address_space(uint64_t bytes, uint64_t max_bytes)
{
#if !defined(__SANITIZE_ADDRESS__)
    struct rlimit as = {(rlim_t)(bytes < max_bytes ? bytes : max_bytes), (rlim_t)max_bytes};
    setrlimit(RLIMIT_AS, &as);
#else
    (void)bytes;
    (void)max_bytes;
#endif
}

/* CPU time: seconds more than this process has used so far. */
static void cpu_time(uint64_t seconds)
{
    struct rusage ru;
    uint64_t used = getrusage(RUSAGE_SELF, &ru) == 0 ? (uint64_t)(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) : 0;
    struct rlimit cpu = {(rlim_t)(used + seconds), RLIM_INFINITY};
    setrlimit(RLIMIT_CPU, &cpu);
}

/* Loads the OpenImageIO module from this program's directory unless the environment names one. */
static void module_beside_self(void)
{
    if (getenv("GENERIC_OIIO_MODULE"))
        return;
    char self[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0)
        return;
    self[n] = 0;
    char *slash = strrchr(self, '/');
    if (!slash)
        return;
    char module[PATH_MAX + 32];
    snprintf(module, sizeof module, "%.*s/libgeneric_oiio.so", (int)(slash - self), self);
    if (access(module, R_OK) == 0)
        setenv("GENERIC_OIIO_MODULE", module, 1);
}

/* GENERIC_DECODE_FAULT=by-name, for the tests of the isolation (tests/test_image_isolation.c): the decode of a file
 * named fault-crash.*, fault-spin.* or fault-grow.* crashes, spins until its CPU time ends (a limit of 1 s) or
 * allocates and touches memory until its address space ends, as a defective decoder would. */
static void fault(const char *path)
{
    const char *f = getenv("GENERIC_DECODE_FAULT"), *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    if (!f || strcmp(f, "by-name") != 0 || strncmp(base, "fault-", 6) != 0)
        return;
    if (strncmp(base + 6, "crash.", 6) == 0) {
        volatile int *nowhere = NULL;
        *nowhere = 1;
    } else if (strncmp(base + 6, "spin.", 5) == 0) {
        cpu_time(1);
        for (volatile unsigned long i = 0;; i++)
            ;
    } else if (strncmp(base + 6, "grow.", 5) == 0) {
        for (;;) {
            char *p = malloc(64u << 20);
            if (!p)
                abort(); /* what a decoder does when an allocation fails: std::bad_alloc, an assertion */
            memset(p, 1, 64u << 20);
        }
    }
}

/* One request; 0 to go on, -1 when the library went away. */
static int serve(const GDecodeRequest *q, const char *path, uint64_t base, uint64_t max_bytes)
{
    GError err;
    int width = 0, height = 0, channels = 0;
    cpu_time(30);
    int rc = gimage_info(path, &width, &height, &channels, &err);
    if (send_record(GDECODE_HEADER, rc, width, height, channels, err.message) != 0)
        return -1;
    if (rc != G_OK || q->mode == GDECODE_MODE_INFO)
        return 0;
    GDecodeGo go;
    if (recv_all(&go, sizeof go) != 0 || go.magic != GDECODE_MAGIC)
        return -1;
    if (go.go != 'g')
        return 0;
    address_space(go.address_space, max_bytes);
    cpu_time(go.cpu_seconds);
    fault(path);
    GImage img;
    rc = gimage_read(path, q->flags, &img, &err);
    int failed;
    if (rc != G_OK)
        failed = send_record(GDECODE_PIXELS, rc, 0, 0, 0, err.message);
    else if (q->mode == GDECODE_MODE_READ)
        failed = send_record(GDECODE_PIXELS, G_OK, img.width, img.height, img.channels, NULL) != 0 ||
                 send_all(img.pixels, (size_t)img.width * img.height * img.channels * sizeof(float)) != 0;
    else
        failed = send_record(GDECODE_PIXELS, G_OK, img.width, img.height, img.channels, NULL);
    gimage_free(&img);
    address_space(base, max_bytes);
    return failed ? -1 : 0;
}

int main(int argc, char **argv)
{
    if (argc != 3 || isatty(0)) {
        fprintf(stderr, "%s is the library's image decoder process; it is not run by hand\n", GDECODE_PROGRAM);
        return 2;
    }
    const uint64_t base = strtoull(argv[1], NULL, 10), max_bytes = strtoull(argv[2], NULL, 10);
    struct rlimit none = {0, 0};
    setrlimit(RLIMIT_CORE, &none);
    address_space(base, max_bytes);
    setenv("GENERIC_DECODE", "inprocess", 1); /* this process is the isolation */
    setenv("OPENIMAGEIO_THREADS", "1", 1);    /* one thread: a small, predictable address space */
    gmem_budget_set_limit((size_t)GMEM_BUDGET_MAX_MB << 20); /* the library charged the decode to its budget */
    module_beside_self();
    /* OpenImageIO loaded now, before any file is read (the header of no file loads it), so that what the dynamic
     * loader writes when asked (LD_DEBUG_OUTPUT) is written; from here on this process writes no file */
    GError ignored;
    int w, h, c;
    if (gimage_info("/", &w, &h, &c, &ignored) == G_OK) /* a directory: refused after the module is loaded */
        return 1;
    setrlimit(RLIMIT_FSIZE, &none);
    for (;;) {
        GDecodeRequest q;
        char path[GDECODE_PATH_MAX + 1];
        if (recv_all(&q, sizeof q) != 0 || q.magic != GDECODE_MAGIC || q.path_length < 1 ||
            q.path_length > GDECODE_PATH_MAX || recv_all(path, q.path_length) != 0)
            return 0;
        path[q.path_length] = 0;
        if (serve(&q, path, base, max_bytes) != 0)
            return 0;
    }
}
