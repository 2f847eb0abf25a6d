/* decode_isolated.c - untrusted images decoded in a separate process (decode_isolated.h, decode_protocol.h).
 *
 * The decoder, generic-decode, is found like the OpenImageIO module beside which it is installed: $GENERIC_DECODER
 * (a path; then nowhere else), DIR/generic/ and DIR/../lib/generic/ for the object holding this code and for the
 * executable, then GENERIC_LIBDIR/generic/. It is started with posix_spawn (no fork of this process, whose threads
 * and locks stay its own), on one end of a socket pair that is its standard input and output, with /dev/null as its
 * standard error. Its limits: an address space of GDECODE_BASE_MB MiB plus 1.5 times what the memory budget has left
 * while it reads the header, then plus 1.5 times the decode's charge; GDECODE_CPU_SECONDS seconds of CPU time for
 * the header, then as many plus one a megapixel. */
#include "decode_isolated.h"
#include "decode_protocol.h"

#include "generic/memory.h"

#include <dlfcn.h>
#include <errno.h>
#include <limits.h>
#include <pthread.h>
#include <signal.h>
#include <fcntl.h>
#include <stdint.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#ifndef GENERIC_LIBDIR
#define GENERIC_LIBDIR "/usr/local/lib"
#endif

/** The decoder's address space beyond the decode: its program, OpenImageIO and its libraries, one thread. */
#define GDECODE_BASE_MB 1024
/** The decoder's CPU time beyond one second a megapixel. */
#define GDECODE_CPU_SECONDS 30

extern char **environ;

int gdecode_isolated(GError *err)
{
    const char *v = getenv("GENERIC_DECODE");
    if (!v || !*v || strcmp(v, "isolated") == 0)
        return 1;
    if (strcmp(v, "inprocess") == 0)
        return 0;
    return gerror_set(err, G_ERR_INVALID, "GENERIC_DECODE is '%s': it must be 'isolated' (the default: images are "
                      "decoded in a separate process) or 'inprocess' (for trusted files)", v);
}

double gdecode_charge(int width, int height, int channels)
{
    return (double)width * height * ((channels > 0 ? channels : 1) + 4) * sizeof(float);
}

/* ---- finding the decoder ---- */

static pthread_once_t find_once = PTHREAD_ONCE_INIT;
static char decoder[PATH_MAX];

static int try_dir(const char *dir, const char *sub)
{
    char cand[PATH_MAX + 64];
    snprintf(cand, sizeof cand, "%s%s/%s", dir, sub, GDECODE_PROGRAM);
    if (access(cand, X_OK) != 0 || !realpath(cand, decoder)) {
        decoder[0] = 0;
        return 0;
    }
    return 1;
}

static int try_beside(const char *file)
{
    char real[PATH_MAX];
    if (!file || !realpath(file, real))
        return 0;
    char *slash = strrchr(real, '/');
    if (!slash)
        return 0;
    *slash = 0;
    return try_dir(real, "/generic") || try_dir(real, "/../lib/generic");
}

static void find(void)
{
    const char *named = secure_getenv("GENERIC_DECODER");
    if (named && *named) {
        snprintf(decoder, sizeof decoder, "%s", named);
        return;
    }
    Dl_info self;
    if (dladdr((void *)&gdecode_run, &self) && self.dli_fname && strchr(self.dli_fname, '/') &&
        try_beside(self.dli_fname))
        return;
    if (try_beside("/proc/self/exe"))
        return;
    try_dir(GENERIC_LIBDIR, "/generic");
}

/* ---- talking to it ---- */

static int recv_all(int fd, void *buf, size_t n)
{
    char *p = buf;
    while (n > 0) {
        ssize_t r = read(fd, p, n);
        if (r < 0 && errno == EINTR)
            continue;
        if (r <= 0)
            return -1;
        p += r;
        n -= (size_t)r;
    }
    return 0;
}

/* Reads one record of the given phase, and its message when it carries one: 0, or -1 when the decoder stopped. */
static int recv_record(int fd, int phase, GDecodeRecord *r, char message[GDECODE_MESSAGE_MAX + 1])
{
    message[0] = 0;
    if (recv_all(fd, r, sizeof *r) != 0 || r->magic != GDECODE_MAGIC || r->phase != phase ||
        r->message_length > GDECODE_MESSAGE_MAX || recv_all(fd, message, r->message_length) != 0)
        return -1;
    message[r->message_length] = 0;
    return 0;
}

/* Why the decoder ended without an answer, from its wait status. */
static int ended(const char *path, pid_t pid, int killed, double as_mb, unsigned long cpu, GError *err)
{
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
        ;
    if (killed)
        return G_OK;
    if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU)
        return gerror_set(err, G_ERR_IO, "%s: cannot read image: its decoder took more than its %lu s of CPU time",
                          path, cpu);
    if (WIFSIGNALED(status))
        return gerror_set(err, G_ERR_IO, "%s: cannot read image: its decoder crashed (%s) within its limits of %.0f MiB "
                          "and %lu s of CPU time", path, strsignal(WTERMSIG(status)), as_mb, cpu);
    return gerror_set(err, G_ERR_IO, "%s: cannot read image: its decoder ended (exit status %d) without an answer",
                      path, WIFEXITED(status) ? WEXITSTATUS(status) : -1);
}

static int start(const char *path, GDecodeMode mode, unsigned flags, double charge, double pixels, int *sock,
                 pid_t *pid, double *as_mb, unsigned long *cpu, GError *err)
{
    pthread_once(&find_once, find);
    if (!decoder[0])
        return gerror_set(err, G_ERR_IO, "%s: cannot read image: the image decoder %s is not found (looked in "
                          "generic/ and ../lib/generic/ beside the library and the program, and in " GENERIC_LIBDIR
                          "/generic/; GENERIC_DECODER may name it, GENERIC_DECODE=inprocess decodes trusted files "
                          "without it)", path, GDECODE_PROGRAM);
    int sv[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0)
        return gerror_set(err, G_ERR_IO, "%s: cannot start the image decoder: %s", path, strerror(errno));
    *as_mb = GDECODE_BASE_MB + 1.5 * charge / 1048576.0;
    *cpu = GDECODE_CPU_SECONDS;
    char flag_text[24], as_text[32], cpu_text[48];
    snprintf(flag_text, sizeof flag_text, "%u", flags);
    snprintf(as_text, sizeof as_text, "%.0f", *as_mb * 1048576.0);
    snprintf(cpu_text, sizeof cpu_text, "%lu:%lu", *cpu, GDECODE_CPU_SECONDS + (unsigned long)(pixels / 1e6));
    const char *mode_text = mode == GDECODE_READ ? "read" : mode == GDECODE_CHECK ? "check" : "info";
    char *const argv[] = {(char *)GDECODE_PROGRAM, (char *)mode_text, flag_text, as_text, cpu_text, (char *)path,
                          NULL};
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_adddup2(&fa, sv[1], 0);
    posix_spawn_file_actions_adddup2(&fa, sv[1], 1);
    posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
    int rc = posix_spawn(pid, decoder, &fa, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    close(sv[1]);
    if (rc != 0) {
        close(sv[0]);
        return gerror_set(err, G_ERR_IO, "%s: cannot start the image decoder %s: %s", path, decoder, strerror(rc));
    }
    *sock = sv[0];
    return G_OK;
}

int gdecode_run(const char *path, GDecodeMode mode, unsigned flags, GImage *img, int *width, int *height, int *channels,
                GError *err)
{
    if (img)
        *img = (GImage){0};
    /* The decoder starts limited to what the budget has left, and lowers its limit to the decode's own once the
     * header is known and charged. */
    const size_t limit = gmem_budget_limit(), used = gmem_budget_used();
    const double room = limit > used ? (double)(limit - used) : 0.0;
    int sock = -1;
    pid_t pid = 0;
    double as_mb = 0.0;
    unsigned long cpu = 0;
    int rc = start(path, mode, flags, room, (double)(1 << 29), &sock, &pid, &as_mb, &cpu, err);
    if (rc != G_OK)
        return rc;
    GDecodeRecord head, r;
    char message[GDECODE_MESSAGE_MAX + 1];
    if (recv_record(sock, GDECODE_HEADER, &head, message) != 0) {
        close(sock);
        return ended(path, pid, 0, as_mb, cpu, err);
    }
    rc = G_OK;
    if (head.status != G_OK)
        rc = gerror_set(err, head.status < 0 && head.status >= G_ERR_UNSUPPORTED ? head.status : G_ERR_IO, "%s",
                        message);
    else if (head.width < 1 || head.height < 1 || head.channels < 1 ||
             (long long)head.width * head.height > (1LL << 29))
        rc = gerror_set(err, G_ERR_IO, "%s: cannot read image: its decoder answered an impossible size", path);
    if (rc != G_OK || mode == GDECODE_INFO) {
        close(sock); /* the decoder ends at the end of the socket */
        ended(path, pid, 1, as_mb, cpu, NULL);
        if (rc == G_OK) {
            if (width)
                *width = head.width;
            if (height)
                *height = head.height;
            if (channels)
                *channels = head.channels;
        }
        return rc;
    }

    const double pixels = (double)head.width * head.height;
    const double charge = gdecode_charge(head.width, head.height, head.channels) +
                          (mode == GDECODE_READ ? pixels * 4 * sizeof(float) : 0.0);
    char what[PATH_MAX + 96];
    snprintf(what, sizeof what, "%s: decoding a %dx%d image with %d channels", path, head.width, head.height,
             head.channels);
    if ((rc = gmem_budget_reserve((size_t)charge, what, err)) != G_OK) {
        close(sock);
        ended(path, pid, 1, as_mb, cpu, NULL);
        return rc;
    }
    unsigned char go[1 + 2 * sizeof(uint64_t)] = {'g'};
    as_mb = GDECODE_BASE_MB + 1.5 * charge / 1048576.0;
    cpu = GDECODE_CPU_SECONDS + (unsigned long)(pixels / 1e6);
    const uint64_t limits[2] = {(uint64_t)(as_mb * 1048576.0), cpu};
    memcpy(go + 1, limits, sizeof limits);
    int stopped = 0; /* a decoder whose answer is refused is killed */
    if (send(sock, go, sizeof go, MSG_NOSIGNAL) != (ssize_t)sizeof go || recv_record(sock, GDECODE_PIXELS, &r, message) != 0) {
        rc = ended(path, pid, 0, as_mb, cpu, err);
        pid = 0;
    } else if (r.status != G_OK) {
        rc = gerror_set(err, r.status < 0 && r.status >= G_ERR_UNSUPPORTED ? r.status : G_ERR_IO, "%s", message);
    } else if (r.width != head.width || r.height != head.height || r.channels < 3 || r.channels > 4) {
        rc = gerror_set(err, G_ERR_IO, "%s: cannot read image: its decoder answered an impossible image", path);
        stopped = 1;
    } else if (mode == GDECODE_READ) {
        size_t n = (size_t)r.width * r.height * r.channels;
        float *pix = gmem_alloc(n * sizeof(float));
        if (!pix) {
            rc = gerror_set(err, G_ERR_NOMEM, "%s: out of memory for a %dx%d image", path, r.width, r.height);
            stopped = 1;
        } else if (recv_all(sock, pix, n * sizeof(float)) != 0) {
            gmem_free(pix);
            rc = ended(path, pid, 0, as_mb, cpu, err);
            pid = 0;
        } else {
            *img = (GImage){r.width, r.height, r.channels, pix};
        }
    }
    if (stopped)
        kill(pid, SIGKILL);
    close(sock);
    if (pid)
        ended(path, pid, 1, as_mb, cpu, NULL);
    gmem_budget_release((size_t)charge);
    if (width)
        *width = head.width;
    if (height)
        *height = head.height;
    if (channels)
        *channels = head.channels;
    return rc;
}
