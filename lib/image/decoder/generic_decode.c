/* generic_decode.c - the image decoder process, generic-decode (lib/image/decode_protocol.h): decodes one untrusted
 * image with the library's in-process reader under resource limits, so that a crash, a hang or a memory blow-up of
 * a third-party decoder ends this process only. Installed beside the OpenImageIO module (PREFIX/lib/generic/), which
 * it loads from its own directory. Not a program for users: it talks the protocol on its standard input and
 * output. */
#include "generic/memory.h"
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

/* Writes all of buf to standard output; 0, or -1 when the library went away. */
static int send_all(const void *buf, size_t n)
{
    const char *p = buf;
    while (n > 0) {
        ssize_t w = write(1, p, n);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            return -1;
        p += w;
        n -= (size_t)w;
    }
    return 0;
}

static int send_record(int phase, int status, int width, int height, int channels, const char *message)
{
    GDecodeRecord r = {GDECODE_MAGIC, phase, status, width, height, channels, 0};
    size_t len = status != G_OK && message ? strlen(message) : 0;
    r.message_length = (uint32_t)(len < GDECODE_MESSAGE_MAX ? len : GDECODE_MESSAGE_MAX);
    if (send_all(&r, sizeof r) != 0 || send_all(message, r.message_length) != 0)
        return -1;
    return 0;
}

/* The limits on this process: address space and CPU time from the library, no core file, no file written. */
static void limit_self(unsigned long long as_bytes, const char *cpu_text)
{
    struct rlimit none = {0, 0};
    setrlimit(RLIMIT_CORE, &none);
    setrlimit(RLIMIT_FSIZE, &none);
    char *colon;
    unsigned long long cpu_seconds = strtoull(cpu_text, &colon, 10);
    unsigned long long cpu_max = *colon == ':' ? strtoull(colon + 1, NULL, 10) : cpu_seconds;
    struct rlimit cpu = {(rlim_t)cpu_seconds, (rlim_t)(cpu_max > cpu_seconds ? cpu_max : cpu_seconds) + 1};
    setrlimit(RLIMIT_CPU, &cpu);
#if !defined(__SANITIZE_ADDRESS__) /* the sanitizer's shadow memory needs terabytes of address space */
    struct rlimit as = {(rlim_t)as_bytes, (rlim_t)as_bytes};
    setrlimit(RLIMIT_AS, &as);
#else
    (void)as_bytes;
#endif
}

/* The decode's own limits once the header is known: a lower address space, the CPU time its size needs. */
static void set_decode_limits(uint64_t as_bytes, uint64_t cpu_seconds)
{
    struct rlimit cpu;
    if (getrlimit(RLIMIT_CPU, &cpu) == 0 && cpu_seconds < cpu.rlim_max) {
        cpu.rlim_cur = (rlim_t)cpu_seconds;
        setrlimit(RLIMIT_CPU, &cpu);
    }
#if !defined(__SANITIZE_ADDRESS__)
    struct rlimit as;
    if (getrlimit(RLIMIT_AS, &as) == 0 && (as.rlim_cur == RLIM_INFINITY || as_bytes < as.rlim_cur)) {
        as.rlim_cur = as.rlim_max = (rlim_t)as_bytes;
        setrlimit(RLIMIT_AS, &as);
    }
#else
    (void)as_bytes;
#endif
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

int main(int argc, char **argv)
{
    if (argc != 6 || isatty(0)) {
        fprintf(stderr, "%s is the library's image decoder process; it is not run by hand\n", GDECODE_PROGRAM);
        return 2;
    }
    const char *mode = argv[1], *path = argv[5];
    unsigned flags = (unsigned)strtoul(argv[2], NULL, 10);
    limit_self(strtoull(argv[3], NULL, 10), argv[4]);
    setenv("GENERIC_DECODE", "inprocess", 1);   /* this process is the isolation */
    setenv("OPENIMAGEIO_THREADS", "1", 1);      /* one thread: a small, predictable address space */
    setenv("MALLOC_ARENA_MAX", "1", 1);
    gmem_budget_set_limit((size_t)GMEM_BUDGET_MAX_MB << 20); /* the library charged the decode to its budget */
    module_beside_self();

    GError err;
    int width = 0, height = 0, channels = 0;
    int rc = gimage_info(path, &width, &height, &channels, &err);
    if (send_record(GDECODE_HEADER, rc, width, height, channels, err.message) != 0 || rc != G_OK)
        return 0;
    if (strcmp(mode, "info") == 0)
        return 0;
    unsigned char go[1 + 2 * sizeof(uint64_t)];
    size_t got = 0;
    while (got < sizeof go) {
        ssize_t n = read(0, go + got, sizeof go - got);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return 0;
        got += (size_t)n;
    }
    if (go[0] != 'g')
        return 0;
    uint64_t limits[2];
    memcpy(limits, go + 1, sizeof limits);
    set_decode_limits(limits[0], limits[1]);
    GImage img;
    rc = gimage_read(path, flags, &img, &err);
    if (rc != G_OK)
        return send_record(GDECODE_PIXELS, rc, 0, 0, 0, err.message) != 0;
    int failed;
    if (strcmp(mode, "read") == 0)
        failed = send_record(GDECODE_PIXELS, G_OK, img.width, img.height, img.channels, NULL) != 0 ||
                 send_all(img.pixels, (size_t)img.width * img.height * img.channels * sizeof(float)) != 0;
    else
        failed = send_record(GDECODE_PIXELS, G_OK, img.width, img.height, img.channels, NULL) != 0;
    gimage_free(&img);
    return failed;
}
