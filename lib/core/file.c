/* file.c - opening inputs (regular files only) and writing outputs through a temporary that is renamed into
 * place, with a registry of pending temporaries removed on exit and on SIGINT, SIGTERM, SIGHUP
 * (generic/services/file.h). */
#include "generic/services/file.h"
#include "generic/memory.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- inputs ---- */

static const char *kind_of(mode_t m)
{
    if (S_ISDIR(m))
        return "a directory";
    if (S_ISFIFO(m))
        return "a FIFO";
    if (S_ISCHR(m))
        return "a character device";
    if (S_ISBLK(m))
        return "a block device";
    if (S_ISSOCK(m))
        return "a socket";
    return "not a regular file";
}

static int not_regular(const char *path, mode_t m, GError *err)
{
    const char *kind = kind_of(m);
    return gerror_set(err, G_ERR_IO, "cannot read \"%s\": it is %s%s", path, kind,
                      strcmp(kind, "not a regular file") ? ", not a regular file" : "");
}

int gfile_open_input(const char *path, GError *err)
{
    if (!path || !path[0])
        return gerror_set(err, G_ERR_INVALID, "no file name given");
    int fd = open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
    if (fd < 0) {
        if (errno == ENXIO) /* a socket, or a device without a driver */
            return gerror_set(err, G_ERR_IO, "cannot read \"%s\": it is not a regular file", path);
        return gerror_set(err, G_ERR_IO, "cannot open \"%s\": %s", path, strerror(errno));
    }
    struct stat st;
    if (fstat(fd, &st) != 0) {
        int e = errno;
        close(fd);
        return gerror_set(err, G_ERR_IO, "cannot open \"%s\": %s", path, strerror(e));
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        return not_regular(path, st.st_mode, err);
    }
    int fl = fcntl(fd, F_GETFL);
    if (fl < 0 || fcntl(fd, F_SETFL, fl & ~O_NONBLOCK) != 0) {
        int e = errno;
        close(fd);
        return gerror_set(err, G_ERR_IO, "cannot open \"%s\": %s", path, strerror(e));
    }
    return fd;
}

int gfile_read_exact(int fd, void *buf, size_t n)
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

int gfile_write_exact(int fd, const void *buf, size_t n)
{
    const char *p = buf;
    while (n > 0) {
        ssize_t w = write(fd, p, n);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            return -1;
        p += w;
        n -= (size_t)w;
    }
    return 0;
}

int gfile_send_exact(int fd, const void *buf, size_t n)
{
    const char *p = buf;
    while (n > 0) {
        ssize_t w = send(fd, p, n, MSG_NOSIGNAL);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            return -1;
        p += w;
        n -= (size_t)w;
    }
    return 0;
}

int gfile_check_input(const char *path, GError *err)
{
    int fd = gfile_open_input(path, err);
    if (fd < 0)
        return fd;
    close(fd);
    return G_OK;
}

/* ---- the registry of pending temporaries ---- */

#define SLOTS 64
#define SLOT_PATH 4096

static char slot_path[SLOTS][SLOT_PATH];
static atomic_int slot_used[SLOTS]; /* 0 free, 1 being filled, 2 pending (path valid) */
static pthread_mutex_t install_lock = PTHREAD_MUTEX_INITIALIZER;
static int installed;
static const int cleanup_signals[] = {SIGINT, SIGTERM, SIGHUP};
#define NSIG_CLEANUP ((int)(sizeof cleanup_signals / sizeof cleanup_signals[0]))
static struct sigaction previous[NSIG_CLEANUP];

static void remove_pending(void)
{
    for (int i = 0; i < SLOTS; i++)
        if (atomic_load(&slot_used[i]) == 2)
            unlink(slot_path[i]); /* async-signal-safe */
}

static void on_signal(int sig, siginfo_t *info, void *ctx)
{
    int saved = errno;
    remove_pending();
    for (int k = 0; k < NSIG_CLEANUP; k++) {
        if (cleanup_signals[k] != sig)
            continue;
        const struct sigaction *p = &previous[k];
        if ((p->sa_flags & SA_SIGINFO) && p->sa_sigaction) {
            p->sa_sigaction(sig, info, ctx);
        } else if (p->sa_handler != SIG_DFL && p->sa_handler != SIG_IGN) {
            p->sa_handler(sig);
        } else { /* the default: end the process by the same signal */
            struct sigaction dfl;
            memset(&dfl, 0, sizeof dfl);
            dfl.sa_handler = SIG_DFL;
            sigemptyset(&dfl.sa_mask);
            sigaction(sig, &dfl, NULL);
            sigset_t s;
            sigemptyset(&s);
            sigaddset(&s, sig);
            pthread_sigmask(SIG_UNBLOCK, &s, NULL);
            raise(sig);
        }
    }
    errno = saved;
}

static void install_handlers(void)
{
    pthread_mutex_lock(&install_lock);
    if (!installed) {
        installed = 1;
        atexit(remove_pending);
        for (int k = 0; k < NSIG_CLEANUP; k++) {
            struct sigaction now;
            if (sigaction(cleanup_signals[k], NULL, &now) != 0 ||
                (!(now.sa_flags & SA_SIGINFO) && now.sa_handler == SIG_IGN))
                continue; /* ignored: nothing will end the process by it */
            struct sigaction sa;
            memset(&sa, 0, sizeof sa);
            sa.sa_sigaction = on_signal;
            sa.sa_flags = SA_SIGINFO | SA_RESTART;
            sigfillset(&sa.sa_mask);
            previous[k] = now;
            sigaction(cleanup_signals[k], &sa, NULL);
        }
    }
    pthread_mutex_unlock(&install_lock);
}

static int register_temp(const char *path)
{
    if (strlen(path) >= SLOT_PATH)
        return -1;
    install_handlers();
    for (int i = 0; i < SLOTS; i++) {
        int expect = 0;
        if (atomic_compare_exchange_strong(&slot_used[i], &expect, 1)) {
            memcpy(slot_path[i], path, strlen(path) + 1);
            atomic_store(&slot_used[i], 2);
            return i;
        }
    }
    return -1;
}

static void unregister_temp(int slot)
{
    if (slot >= 0 && slot < SLOTS)
        atomic_store(&slot_used[slot], 0);
}

/* ---- outputs ---- */

char *gfile_dir_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    if (!slash)
        return gmem_strdup(".");
    size_t n = slash == path ? 1 : (size_t)(slash - path);
    char *d = gmem_alloc(n + 1);
    if (d) {
        memcpy(d, path, n);
        d[n] = '\0';
    }
    return d;
}

/* Follows symbolic links from path to the file that is to be replaced (which need not exist). */
static int resolve_target(const char *path, char **out, GError *err)
{
    *out = NULL;
    char *cur = gmem_strdup(path);
    if (!cur)
        return gerror_set(err, G_ERR_NOMEM, "out of memory");
    for (int hops = 0;; hops++) {
        struct stat st;
        if (lstat(cur, &st) != 0 || !S_ISLNK(st.st_mode))
            break;
        if (hops == 40) {
            gmem_free(cur);
            return gerror_set(err, G_ERR_IO, "cannot write \"%s\": %s", path, strerror(ELOOP));
        }
        char link[PATH_MAX];
        ssize_t n = readlink(cur, link, sizeof link - 1);
        if (n < 0) {
            int e = errno;
            gmem_free(cur);
            return gerror_set(err, G_ERR_IO, "cannot write \"%s\": %s", path, strerror(e));
        }
        link[n] = '\0';
        char *next;
        if (link[0] == '/' || !strchr(cur, '/')) {
            next = gmem_strdup(link);
        } else {
            char *dir = gfile_dir_of(cur);
            size_t len = dir ? strlen(dir) + 1 + strlen(link) + 1 : 0;
            next = dir ? gmem_alloc(len) : NULL;
            if (next)
                snprintf(next, len, "%s/%s", dir, link);
            gmem_free(dir);
        }
        gmem_free(cur);
        if (!next)
            return gerror_set(err, G_ERR_NOMEM, "out of memory");
        cur = next;
    }
    *out = cur;
    return G_OK;
}

/* Checks the resolved target and its directory. */
static int check_target(const char *path, const char *target, GError *err)
{
    struct stat st;
    if (stat(target, &st) == 0) {
        if (!S_ISREG(st.st_mode))
            return gerror_set(err, G_ERR_IO, "cannot write \"%s\": it is %s", path, kind_of(st.st_mode));
    } else if (errno != ENOENT) {
        return gerror_set(err, G_ERR_IO, "cannot write \"%s\": %s", path, strerror(errno));
    }
    char *dir = gfile_dir_of(target);
    if (!dir)
        return gerror_set(err, G_ERR_NOMEM, "out of memory");
    int rc = G_OK;
    if (stat(dir, &st) != 0)
        rc = gerror_set(err, G_ERR_IO, "cannot write \"%s\": the directory \"%s\": %s", path, dir, strerror(errno));
    else if (!S_ISDIR(st.st_mode))
        rc = gerror_set(err, G_ERR_IO, "cannot write \"%s\": \"%s\" is not a directory", path, dir);
    else if (access(dir, W_OK | X_OK) != 0)
        rc = gerror_set(err, G_ERR_IO, "cannot write \"%s\": the directory \"%s\": %s", path, dir, strerror(errno));
    gmem_free(dir);
    return rc;
}

/* Longest extension a temporary keeps (".exr", ".tiff"; a longer last part of a name is not an extension). */
#define TEMP_MAX_EXT 32

int gfile_check_output(const char *path, GError *err)
{
    if (!path || !path[0])
        return gerror_set(err, G_ERR_INVALID, "no output file name given");
    char *target;
    int rc = resolve_target(path, &target, err);
    if (rc == G_OK)
        rc = check_target(path, target, err);
    gmem_free(target);
    return rc;
}

/* The process's umask, read without changing it (thread safe). */
static mode_t process_umask(void)
{
    mode_t mask = 022;
    FILE *f = fopen("/proc/self/status", "re");
    if (f) {
        char line[256];
        while (fgets(line, sizeof line, f))
            if (!strncmp(line, "Umask:", 6)) {
                mask = (mode_t)strtol(line + 6, NULL, 8);
                break;
            }
        fclose(f);
    }
    return mask;
}

static void clear_output(GFileOutput *o)
{
    gmem_free(o->target);
    gmem_free(o->temp);
    o->target = o->temp = NULL;
    o->fd = -1;
    o->slot = -1;
}

int gfile_output_begin(GFileOutput *o, const char *path, GError *err)
{
    o->target = o->temp = NULL;
    o->fd = o->slot = -1;
    if (!path || !path[0])
        return gerror_set(err, G_ERR_INVALID, "no output file name given");
    int rc = resolve_target(path, &o->target, err);
    if (rc == G_OK)
        rc = check_target(path, o->target, err);
    if (rc != G_OK) {
        clear_output(o);
        return rc;
    }
    /* .BASE.XXXXXX.EXT next to the target: hidden, and the extension (of at most TEMP_MAX_EXT bytes) kept for
     * writers that look at it; BASE is cut so that the name fits in NAME_MAX bytes, so any name that the
     * destination's directory takes has a temporary that fits too (found before a long render, not after) */
    const char *slash = strrchr(o->target, '/');
    const char *base = slash ? slash + 1 : o->target;
    const char *dot = strrchr(base, '.');
    const char *ext = dot && dot != base && strlen(dot) <= TEMP_MAX_EXT ? dot : "";
    size_t stem = strlen(base) - strlen(ext), room = NAME_MAX - 8 - strlen(ext);
    if (stem > room)
        stem = room;
    size_t dirlen = (size_t)(base - o->target), len = strlen(o->target) + 16 + strlen(ext);
    o->temp = gmem_alloc(len);
    if (!o->temp) {
        clear_output(o);
        return gerror_set(err, G_ERR_NOMEM, "out of memory");
    }
    snprintf(o->temp, len, "%.*s.%.*s.XXXXXX%s", (int)dirlen, o->target, (int)stem, base, ext);
    /* block the cleanup signals while the temporary exists but is not registered */
    sigset_t all, old;
    sigemptyset(&all);
    for (int k = 0; k < NSIG_CLEANUP; k++)
        sigaddset(&all, cleanup_signals[k]);
    install_handlers();
    pthread_sigmask(SIG_BLOCK, &all, &old);
    o->fd = mkostemps(o->temp, (int)strlen(ext), O_CLOEXEC);
    int e = errno;
    if (o->fd >= 0 && (o->slot = register_temp(o->temp)) < 0) {
        close(o->fd);
        unlink(o->temp);
        o->fd = -1;
        e = ENAMETOOLONG;
    }
    pthread_sigmask(SIG_SETMASK, &old, NULL);
    if (o->fd < 0) {
        clear_output(o);
        return gerror_set(err, G_ERR_IO, "cannot write \"%s\": cannot create a temporary file next to it: %s", path,
                          e == ENAMETOOLONG ? "too many pending outputs or too long a name" : strerror(e));
    }
    struct stat st;
    mode_t mode = stat(o->target, &st) == 0 ? (st.st_mode & 07777) : (0666 & ~process_umask());
    if (fchmod(o->fd, mode) != 0)
        mode = 0600; /* the temporary keeps mkstemp's mode: less access, never more */
    return G_OK;
}

void gfile_output_abort(GFileOutput *o)
{
    if (!o || (!o->temp && o->fd < 0))
        return;
    if (o->fd >= 0)
        close(o->fd);
    if (o->temp)
        unlink(o->temp);
    unregister_temp(o->slot);
    clear_output(o);
}

int gfile_output_commit(GFileOutput *o, long long expected_size, const char *path, GError *err)
{
    if (!o || o->fd < 0 || !o->temp)
        return gerror_set(err, G_ERR_INVALID, "cannot write \"%s\": no output in progress", path ? path : "");
    int rc = G_OK;
    struct stat st;
    if (fsync(o->fd) != 0)
        rc = gerror_set(err, G_ERR_IO, "cannot write \"%s\": %s", path, strerror(errno));
    else if (fstat(o->fd, &st) != 0)
        rc = gerror_set(err, G_ERR_IO, "cannot write \"%s\": %s", path, strerror(errno));
    else if (expected_size >= 0 && (long long)st.st_size != expected_size)
        rc = gerror_set(err, G_ERR_IO, "cannot write \"%s\": %lld of %lld bytes were written", path,
                        (long long)st.st_size, expected_size);
    int fd = o->fd;
    o->fd = -1;
    if (close(fd) != 0 && rc == G_OK)
        rc = gerror_set(err, G_ERR_IO, "cannot write \"%s\": %s", path, strerror(errno));
    if (rc == G_OK && rename(o->temp, o->target) != 0)
        rc = gerror_set(err, G_ERR_IO, "cannot write \"%s\": cannot rename the finished file into place: %s", path,
                        strerror(errno));
    if (rc != G_OK)
        unlink(o->temp);
    unregister_temp(o->slot);
    clear_output(o);
    return rc;
}

int gfile_read_all(const char *path, size_t limit, char **text, size_t *len, GError *err)
{
    *text = NULL;
    int fd = gfile_open_input(path, err); /* a regular file, or a message naming what it is */
    if (fd < 0)
        return fd;
    struct stat st;
    int sized = fstat(fd, &st) == 0;
    if (sized && (unsigned long long)st.st_size > limit) {
        close(fd);
        return gerror_set(err, G_ERR_IO, "\"%s\" is %lld bytes, more than the limit of %zu bytes", path,
                          (long long)st.st_size, limit);
    }
    /* room for the whole file, its NUL and the read that finds its end: no copy while it is read */
    size_t cap = sized && (size_t)st.st_size > 4094 ? (size_t)st.st_size + 2 : 4096, n = 0;
    char *buf = gmem_alloc(cap);
    int rc = buf ? G_OK : gerror_set(err, G_ERR_NOMEM, "out of memory reading \"%s\"", path);
    while (rc == G_OK) {
        if (n + 1 >= cap) {
            char *b = gmem_realloc(buf, cap * 2);
            if (!b) {
                rc = gerror_set(err, G_ERR_NOMEM, "out of memory reading \"%s\"", path);
                break;
            }
            buf = b;
            cap *= 2;
        }
        ssize_t got = read(fd, buf + n, cap - n - 1);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0)
            rc = gerror_set(err, G_ERR_IO, "cannot read \"%s\": %s", path, strerror(errno));
        else if (got == 0)
            break;
        else if ((n += (size_t)got) > limit)
            rc = gerror_set(err, G_ERR_IO, "\"%s\" is more than the limit of %zu bytes", path, limit);
    }
    close(fd);
    if (rc != G_OK) {
        gmem_free(buf);
        return rc;
    }
    buf[n] = '\0';
    *text = buf;
    *len = n;
    return G_OK;
}
