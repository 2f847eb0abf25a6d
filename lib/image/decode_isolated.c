/* decode_isolated.c - untrusted images decoded in a separate process (decode_isolated.h, decode_protocol.h).
 *
 * The decoder, generic-decode, is found like the OpenImageIO module beside which it is installed: $GENERIC_DECODER
 * (a path; then nowhere else), the directory of $GENERIC_OIIO_MODULE, DIR/generic/ and DIR/../lib/generic/ for the
 * object holding this code and for the executable, then GENERIC_LIBDIR/generic/. It is started on first use with
 * posix_spawn (no fork of this process, whose threads and locks stay its own), on one end of a socket pair that is
 * its standard input and output, with /dev/null as its standard error, and serves this process's decodes one at a
 * time (a lock) until this process ends; one that ended (a crash, a limit) is started again for the next file. Its
 * limits: an address space of GDECODE_BASE_MB MiB, and during a decode that plus 1.5 times the decode's charge (at
 * most 1.5 times the memory budget's limit when it started: a higher limit set later starts a new one);
 * GDECODE_CPU_SECONDS seconds of CPU time for a header, and for a decode as many plus one a megapixel. The files of one
 * process share a decoder: a file that subverts the decoder can change the pixels of the files decoded after it in the
 * same process, never this process. A process forked from this one starts its own. */
#include "decode_isolated.h"
#include "decode_protocol.h"
#include "image_format.h"

#include "generic/memory.h"
#include "generic/services/file.h"
#include "generic/services/spawn.h"

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
#include <sys/resource.h>
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

double gdecode_charge(int width, int height, int channels)
{
    return (double)width * height * ((channels > 0 ? channels : 1) + 4) * sizeof(float);
}

/* ---- finding the decoder ---- */

static pthread_once_t find_once = PTHREAD_ONCE_INIT;
static char decoder[PATH_MAX];

/* The decoder: $GENERIC_DECODER, else beside $GENERIC_OIIO_MODULE (a path), else where gspawn_find looks. */
static void find(void)
{
    const char *named = secure_getenv("GENERIC_DECODER"), *module = secure_getenv("GENERIC_OIIO_MODULE");
    if (!(named && *named) && module && *module && strchr(module, '/')) {
        char cand[PATH_MAX + 64];
        snprintf(cand, sizeof cand, "%.*s/%s", (int)(strrchr(module, '/') - module), module, GDECODE_PROGRAM);
        if (access(cand, X_OK) == 0 && realpath(cand, decoder))
            return;
    }
    gspawn_find(GDECODE_PROGRAM, "GENERIC_DECODER", (const void *)&gdecode_run, GENERIC_LIBDIR, decoder);
}

/* ---- the decoder process: one for this process, started on first use ---- */

static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static pid_t server_pid;   /* 0: none */
static pid_t server_owner; /* the process that started it */
static int server_sock = -1;
static uint64_t server_max;   /* its hard address space limit */
static uint64_t server_limit; /* its address space limit now: the base, or the decode's */

static uint64_t base_bytes(void) { return (uint64_t)GDECODE_BASE_MB << 20; }

/* Reads one record of the given phase, and its message: 0, or -1 when the decoder stopped or broke the protocol. */
static int recv_record(int fd, int phase, GDecodeRecord *r, char message[GDECODE_MESSAGE_MAX + 1])
{
    message[0] = 0;
    if (gfile_read_exact(fd, r, sizeof *r) != 0 || r->magic != GDECODE_MAGIC || r->phase != phase ||
        r->message_length > GDECODE_MESSAGE_MAX || gfile_read_exact(fd, message, r->message_length) != 0)
        return -1;
    message[r->message_length] = 0;
    return 0;
}

/* Ends the decoder (kill: it is still running) and says why it ended when err is given. G_ERR_IO. */
static int stop(const char *path, int kill_it, unsigned long cpu, GError *err)
{
    if (server_sock >= 0)
        close(server_sock);
    server_sock = -1;
    if (!server_pid)
        return G_ERR_IO;
    if (kill_it)
        kill(server_pid, SIGKILL);
    int status = 0;
    while (waitpid(server_pid, &status, 0) < 0 && errno == EINTR)
        ;
    server_pid = 0;
    if (!err || kill_it)
        return G_ERR_IO;
    if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU)
        return gerror_set(err, G_ERR_IO, "%s: cannot read image: its decoder took more than its %lu s of CPU time",
                          path, cpu);
    if (WIFSIGNALED(status))
        return gerror_set(err, G_ERR_IO, "%s: cannot read image: its decoder crashed (%s) within its limits of %.0f MiB"
                          " of address space and %lu s of CPU time", path, strsignal(WTERMSIG(status)),
                          (double)server_limit / 1048576.0, cpu);
    return gerror_set(err, G_ERR_IO, "%s: cannot read image: its decoder ended (exit status %d) without an answer",
                      path, WIFEXITED(status) ? WEXITSTATUS(status) : -1);
}

/* A running decoder whose hard limit allows max_bytes: the one there is, else a new one. */
static int ensure(const char *path, uint64_t max_bytes, GError *err)
{
    if (server_pid && server_owner != getpid()) { /* inherited through a fork: the parent's, not ours */
        if (server_sock >= 0)
            close(server_sock);
        server_sock = -1;
        server_pid = 0;
    }
    if (server_pid && server_max >= max_bytes)
        return G_OK;
    if (server_pid)
        stop(path, 1, 0, NULL);
    pthread_once(&find_once, find);
    if (!decoder[0])
        return gerror_set(err, G_ERR_IO, "%s: cannot read image: the image decoder %s is not found (looked in "
                          "generic/ and ../lib/generic/ beside the library and the program, and in " GENERIC_LIBDIR
                          "/generic/; GENERIC_DECODER may name it, GENERIC_DECODE=inprocess decodes trusted files "
                          "without it)", path, GDECODE_PROGRAM);
    int sv[2];
    if (gspawn_socketpair(sv, 2) != 0)
        return gerror_set(err, G_ERR_IO, "%s: cannot start the image decoder: %s", path, strerror(errno));
    char base_text[32], max_text[32];
    snprintf(base_text, sizeof base_text, "%llu", (unsigned long long)base_bytes());
    snprintf(max_text, sizeof max_text, "%llu", (unsigned long long)max_bytes);
    char *const argv[] = {(char *)GDECODE_PROGRAM, base_text, max_text, NULL};
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_adddup2(&fa, sv[1], 0);
    posix_spawn_file_actions_adddup2(&fa, sv[1], 1);
    posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addclosefrom_np(&fa, 3); /* none of this process's other files */
    pid_t pid;
    int rc = posix_spawn(&pid, decoder, &fa, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    close(sv[1]);
    if (rc != 0) {
        close(sv[0]);
        return gerror_set(err, G_ERR_IO, "%s: cannot start the image decoder %s: %s", path, decoder, strerror(rc));
    }
    server_pid = pid;
    server_owner = getpid();
    server_sock = sv[0];
    server_max = max_bytes;
    server_limit = base_bytes();
    return G_OK;
}

/* The status a decoder reported, kept when it is one of the library's. */
static int reported(int status) { return status < 0 && status >= G_ERR_UNSUPPORTED ? status : G_ERR_IO; }

/* The file's content is of a format the library reads (image_format.h): checked here, so that other content never
 * reaches a decoder. G_OK, or G_ERR_IO naming the file and the format found. */
static int check_format(const char *path, GError *err)
{
    int fd = gfile_open_input(path, err);
    if (fd < 0)
        return fd;
    unsigned char head[GIMAGE_SNIFF_BYTES];
    ssize_t got = pread(fd, head, sizeof head, 0);
    close(fd);
    const GImageFormat f = gimage_sniff(head, got > 0 ? (size_t)got : 0);
    if (f.oiio)
        return G_OK;
    if (strcmp(f.name, "unknown") == 0)
        return gerror_set(err, G_ERR_IO, "%s: cannot read image: its content is not one of the formats read (%s)", path,
                          GIMAGE_READ_FORMATS);
    return gerror_set(err, G_ERR_IO, "%s: cannot read image: its content is %s, not one of the formats read (%s)", path,
                      f.name, GIMAGE_READ_FORMATS);
}

static int run_locked(const char *path, GDecodeMode mode, unsigned flags, GImage *img, int *width, int *height,
                      int *channels, GError *err)
{
    const size_t limit = gmem_budget_limit();
    const uint64_t max_bytes = base_bytes() + (uint64_t)(1.5 * (double)limit);
    int rc = ensure(path, max_bytes, err);
    if (rc != G_OK)
        return rc;
    size_t len = strlen(path);
    if (len < 1 || len > GDECODE_PATH_MAX)
        return gerror_set(err, G_ERR_IO, "%s: cannot read image: a path of %zu bytes is too long", path, len);
    GDecodeRequest q = {GDECODE_MAGIC, mode == GDECODE_READ ? GDECODE_MODE_READ
                                       : mode == GDECODE_CHECK ? GDECODE_MODE_CHECK : GDECODE_MODE_INFO,
                        flags, (uint32_t)len};
    GDecodeRecord head, r;
    char message[GDECODE_MESSAGE_MAX + 1];
    unsigned long cpu = GDECODE_CPU_SECONDS;
    if (gfile_send_exact(server_sock, &q, sizeof q) != 0 || gfile_send_exact(server_sock, path, len) != 0 ||
        recv_record(server_sock, GDECODE_HEADER, &head, message) != 0)
        return stop(path, 0, cpu, err);
    if (head.status != G_OK)
        return gerror_set(err, reported(head.status), "%s", message);
    if (head.width < 1 || head.height < 1 || head.channels < 1 || (long long)head.width * head.height > (1LL << 29)) {
        if (mode != GDECODE_INFO)
            stop(path, 1, cpu, NULL);
        return gerror_set(err, G_ERR_IO, "%s: cannot read image: its decoder answered an impossible size", path);
    }
    if (width)
        *width = head.width;
    if (height)
        *height = head.height;
    if (channels)
        *channels = head.channels;
    if (mode == GDECODE_INFO)
        return G_OK;

    const double pixels = (double)head.width * head.height;
    const double charge = gdecode_charge(head.width, head.height, head.channels) +
                          (mode == GDECODE_READ ? pixels * 4 * sizeof(float) : 0.0);
    char what[PATH_MAX + 96];
    snprintf(what, sizeof what, "%s: decoding a %dx%d image with %d channels", path, head.width, head.height,
             head.channels);
    rc = gmem_budget_reserve((size_t)charge, what, err);
    cpu = GDECODE_CPU_SECONDS + (unsigned long)(pixels / 1e6);
    GDecodeGo go = {GDECODE_MAGIC, rc == G_OK ? 'g' : 'n', base_bytes() + (uint64_t)(1.5 * charge), cpu};
    server_limit = go.address_space < server_max ? go.address_space : server_max;
    if (gfile_send_exact(server_sock, &go, sizeof go) != 0) {
        if (rc == G_OK)
            gmem_budget_release((size_t)charge);
        return rc != G_OK ? (stop(path, 1, cpu, NULL), rc) : stop(path, 0, cpu, err);
    }
    if (rc != G_OK)
        return rc;
    if (recv_record(server_sock, GDECODE_PIXELS, &r, message) != 0) {
        rc = stop(path, 0, cpu, err);
    } else if (r.status != G_OK && mode == GDECODE_CHECK && reported(r.status) == G_ERR_IO) {
        /* a texture whose header reads and whose pixels do not: said as the texture node says it */
        const char *why = message;
        size_t plen = strlen(path);
        if (strncmp(why, path, plen) == 0 && strncmp(why + plen, ": ", 2) == 0)
            why += plen + 2;
        if (strncmp(why, "cannot decode image: ", 21) == 0)
            why += 21;
        rc = gerror_set(err, G_ERR_IO, "%s: cannot read image: its pixels cannot be decoded (a truncated or damaged "
                        "file): %s", path, why);
    } else if (r.status != G_OK) {
        rc = gerror_set(err, reported(r.status), "%s", message);
    } else if (r.width != head.width || r.height != head.height || r.channels < 3 || r.channels > 4) {
        rc = gerror_set(err, G_ERR_IO, "%s: cannot read image: its decoder answered an impossible image", path);
        stop(path, 1, cpu, NULL);
    } else if (mode == GDECODE_READ) {
        size_t n = (size_t)r.width * r.height * r.channels;
        float *pix = gmem_alloc(n * sizeof(float));
        if (!pix) {
            rc = gerror_set(err, G_ERR_NOMEM, "%s: out of memory for a %dx%d image", path, r.width, r.height);
            stop(path, 1, cpu, NULL);
        } else if (gfile_read_exact(server_sock, pix, n * sizeof(float)) != 0) {
            gmem_free(pix);
            rc = stop(path, 0, cpu, err);
        } else {
            *img = (GImage){r.width, r.height, r.channels, pix};
        }
    }
    gmem_budget_release((size_t)charge);
    server_limit = base_bytes();
    return rc;
}

int gdecode_run(const char *path, GDecodeMode mode, unsigned flags, GImage *img, int *width, int *height, int *channels,
                GError *err)
{
    if (img)
        *img = (GImage){0};
    int rc = check_format(path, err);
    if (rc != G_OK)
        return rc;
    pthread_mutex_lock(&lock);
    rc = run_locked(path, mode, flags, img, width, height, channels, err);
    pthread_mutex_unlock(&lock);
    return rc;
}
