/* test_file.c - inputs that are not regular files, refused by every reader of the library; outputs written
 * through a temporary (kept files on failure, symbolic links written through, temporaries removed on
 * SIGINT, SIGTERM and SIGHUP). */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "generic/services/bfc.h"
#include "generic/builtins.h"
#include "generic/services/file.h"
#include "generic/services/image.h"
#include "generic/plugin.h"
#include "generic/services/probe.h"
#include "generic/reader.h"
#include "test_util.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

static char dir[256];

static int setup(void **state)
{
    (void)state;
    if (tu_tempdir(dir, sizeof dir, "test_file") != 0)
        return -1;
    GError err;
    return generic_register_builtins(&err) == G_OK ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    return tu_rmtree(dir);
}

/* ---- inputs: every kind of non-regular file against every reader ---- */

typedef struct Kind {
    const char *name; /* what the message says */
    char path[300];
} Kind;

/* Makes one file of each kind that is not a regular file. */
static int make_kinds(Kind *k)
{
    int n = 0;
    snprintf(k[n].path, sizeof k[n].path, "%s/fifo.png", dir);
    unlink(k[n].path);
    assert_int_equal(mkfifo(k[n].path, 0600), 0);
    k[n++].name = "a FIFO";
    snprintf(k[n].path, sizeof k[n].path, "%s/dir.png", dir);
    mkdir(k[n].path, 0700);
    k[n++].name = "a directory";
    const char *devices[] = {"/dev/zero", "/dev/urandom", "/dev/null"};
    for (int i = 0; i < 3; i++) {
        snprintf(k[n].path, sizeof k[n].path, "%s", devices[i]);
        k[n++].name = "a character device";
    }
    snprintf(k[n].path, sizeof k[n].path, "%s/socket.png", dir);
    unlink(k[n].path);
    int s = socket(AF_UNIX, SOCK_STREAM, 0);
    struct sockaddr_un a = {.sun_family = AF_UNIX};
    snprintf(a.sun_path, sizeof a.sun_path, "%.100s", k[n].path);
    assert_int_equal(bind(s, (struct sockaddr *)&a, sizeof a), 0);
    close(s);
    k[n++].name = "not a regular file"; /* a socket cannot be opened: ENXIO */
    return n;
}

/* The message must name what the file is: the reader refused it by its kind before reading from it, so it
 * neither blocked (a FIFO without a writer) nor read forever (/dev/zero). */
static void expect_refusal(int rc, const GError *err, const Kind *k, const char *reader)
{
    if (rc >= 0)
        fail_msg("%s accepted %s (%s)", reader, k->path, k->name);
    char want[400];
    snprintf(want, sizeof want, "\"%s\": it is %s", k->path, k->name);
    if (!strstr(err->message, want))
        fail_msg("%s on %s: expected '%s' in '%s'", reader, k->path, want, err->message);
}

static void test_non_regular_inputs_are_refused_everywhere(void **state)
{
    (void)state;
    Kind kinds[8];
    int n = make_kinds(kinds);
    for (int i = 0; i < n; i++) {
        const Kind *k = &kinds[i];
        GError err;
        int fd = gfile_open_input(k->path, &err);
        if (fd >= 0)
            close(fd);
        expect_refusal(fd, &err, k, "gfile_open_input");
        expect_refusal(gfile_check_input(k->path, &err), &err, k, "gfile_check_input");

        GLibrary *lib = NULL;
        expect_refusal(greader_load_file(k->path, NULL, &lib, &err), &err, k, "greader_load_file");
        char text[600];
        snprintf(text, sizeof text, "include \"%s\"\n", k->path);
        expect_refusal(greader_load_string(text, "inc.mat", NULL, &lib, &err), &err, k, "include");
        snprintf(text, sizeof text, "node n image { child lambert file \"%s\" }\n", k->path);
        expect_refusal(greader_load_string(text, "img.mat", NULL, &lib, &err), &err, k, "image node");
        snprintf(text, sizeof text, "color c bfc \"%s\"\n", k->path);
        expect_refusal(greader_load_string(text, "bfc.mat", NULL, &lib, &err), &err, k, "bfc colour");

        GBfcData bfc;
        expect_refusal(gbfc_read(k->path, &bfc, &err), &err, k, "gbfc_read");
        GImage img;
        expect_refusal(gimage_read(k->path, 0, &img, &err), &err, k, "gimage_read");
        int w, h, c;
        expect_refusal(gimage_info(k->path, &w, &h, &c, &err), &err, k, "gimage_info");
        GProbe *p = NULL;
        expect_refusal(gprobe_load(k->path, GPROBE_AUTO, 0, &p, &err), &err, k, "gprobe_load");
        assert_null(p);
        expect_refusal(gplugin_load(k->path, &err), &err, k, "gplugin_load");
    }
}

static void test_regular_input_opens_blocking(void **state)
{
    (void)state;
    char path[300];
    snprintf(path, sizeof path, "%s/plain.txt", dir);
    FILE *f = fopen(path, "w");
    fputs("hello\n", f);
    fclose(f);
    GError err;
    int fd = gfile_open_input(path, &err);
    assert_true(fd >= 0);
    assert_int_equal(fcntl(fd, F_GETFL) & O_NONBLOCK, 0);
    assert_true(fcntl(fd, F_GETFD) & FD_CLOEXEC);
    char buf[16];
    assert_int_equal(read(fd, buf, sizeof buf), 6);
    close(fd);
    /* a symbolic link to a regular file is followed; a loop of links is reported as such */
    char link[300], loop[300];
    snprintf(link, sizeof link, "%s/link.txt", dir);
    snprintf(loop, sizeof loop, "%s/loop.txt", dir);
    assert_int_equal(symlink(path, link), 0);
    assert_int_equal(symlink(loop, loop), 0);
    assert_int_equal(gfile_check_input(link, &err), G_OK);
    assert_int_equal(gfile_check_input(loop, &err), G_ERR_IO);
    assert_non_null(strstr(err.message, strerror(ELOOP)));
    snprintf(link, sizeof link, "%s/missing.txt", dir);
    assert_int_equal(gfile_check_input(link, &err), G_ERR_IO);
    assert_non_null(strstr(err.message, "No such file or directory"));
}

/* ---- outputs ---- */

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    assert_int_equal(fclose(f), 0);
}

static void expect_text(const char *path, const char *text)
{
    char buf[256] = {0};
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    assert_string_equal(buf, text);
}

/* The number of entries in dir whose name starts with prefix (temporaries start with "."). */
static int count_entries(const char *prefix)
{
    DIR *d = opendir(dir);
    assert_non_null(d);
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)))
        n += strncmp(e->d_name, prefix, strlen(prefix)) == 0 && strcmp(e->d_name, ".") && strcmp(e->d_name, "..");
    closedir(d);
    return n;
}

static void test_output_commit_abort_and_links(void **state)
{
    (void)state;
    char target[300], link[300], link2[300];
    snprintf(target, sizeof target, "%s/out.txt", dir);
    snprintf(link, sizeof link, "%s/out_link.txt", dir);
    snprintf(link2, sizeof link2, "%s/out_link2.txt", dir);
    write_text(target, "old");
    chmod(target, 0640);
    GError err;
    GFileOutput o;
    /* abort keeps the existing file and leaves no temporary */
    assert_int_equal(gfile_output_begin(&o, target, &err), G_OK);
    assert_int_equal(write(o.fd, "new", 3), 3);
    gfile_output_abort(&o);
    expect_text(target, "old");
    assert_int_equal(count_entries(".out"), 0);
    /* a wrong size is a failure: the target is kept */
    assert_int_equal(gfile_output_begin(&o, target, &err), G_OK);
    assert_int_equal(write(o.fd, "new", 3), 3);
    assert_int_equal(gfile_output_commit(&o, 4, target, &err), G_ERR_IO);
    assert_non_null(strstr(err.message, "3 of 4 bytes"));
    expect_text(target, "old");
    assert_int_equal(count_entries(".out"), 0);
    /* written through a chain of two links: the target is replaced, its mode kept, the links stay links */
    assert_int_equal(symlink("out.txt", link), 0);
    assert_int_equal(symlink(link, link2), 0);
    assert_int_equal(gfile_output_begin(&o, link2, &err), G_OK);
    assert_int_equal(write(o.fd, "new", 3), 3);
    assert_int_equal(gfile_output_commit(&o, 3, link2, &err), G_OK);
    expect_text(target, "new");
    struct stat st;
    assert_int_equal(lstat(link2, &st), 0);
    assert_true(S_ISLNK(st.st_mode));
    assert_int_equal(lstat(link, &st), 0);
    assert_true(S_ISLNK(st.st_mode));
    assert_int_equal(stat(target, &st), 0);
    assert_int_equal(st.st_mode & 0777, 0640);
    assert_int_equal(count_entries(".out"), 0);
    /* the longest name a directory takes (255 bytes) has a temporary that fits: its base is cut, not the write */
    char name[256], longest[600];
    memset(name, 'n', 251);
    memcpy(name + 251, ".png", 5);
    snprintf(longest, sizeof longest, "%s/%s", dir, name);
    assert_int_equal(gfile_check_output(longest, &err), G_OK);
    assert_int_equal(gfile_output_begin(&o, longest, &err), G_OK);
    assert_non_null(strstr(o.temp, ".png"));
    assert_true(strlen(strrchr(o.temp, '/') + 1) <= 255);
    assert_int_equal(write(o.fd, "new", 3), 3);
    assert_int_equal(gfile_output_commit(&o, 3, longest, &err), G_OK);
    expect_text(longest, "new");
    unlink(longest);
}

static void test_output_destinations_checked(void **state)
{
    (void)state;
    GError err;
    char path[300];
    snprintf(path, sizeof path, "%s/no/such/dir/x.png", dir);
    assert_int_equal(gfile_check_output(path, &err), G_ERR_IO);
    assert_non_null(strstr(err.message, "No such file or directory"));
    assert_int_equal(gimage_check_output(path, &err), G_ERR_IO);
    assert_int_equal(gfile_check_output("/dev/full", &err), G_ERR_IO);
    assert_non_null(strstr(err.message, "it is a character device"));
    assert_int_equal(gfile_check_output(dir, &err), G_ERR_IO);
    assert_non_null(strstr(err.message, "it is a directory"));
    snprintf(path, sizeof path, "%s/x.png", dir);
    assert_int_equal(gimage_check_output(path, &err), G_OK);
    /* a format without a writer in this OpenImageIO, and a name without a format */
    snprintf(path, sizeof path, "%s/x.unknownformat", dir);
    assert_int_equal(gimage_check_output(path, &err), G_ERR_IO);
    assert_non_null(strstr(err.message, "no writer for '.unknownformat'"));
    /* a file's directory that is a file */
    char file[300];
    snprintf(file, sizeof file, "%s/plainfile", dir);
    write_text(file, "x");
    snprintf(path, sizeof path, "%s/plainfile/x.png", dir);
    assert_int_equal(gfile_check_output(path, &err), G_ERR_IO);
    /* gimage_write refuses them too and creates nothing */
    GImage img;
    assert_int_equal(gimage_create(&img, 4, 4, 3, &err), G_OK);
    assert_int_equal(gimage_write("/dev/full", &img, NULL, &err), G_ERR_IO);
    snprintf(path, sizeof path, "%s/x.unknownformat", dir);
    assert_int_equal(gimage_write(path, &img, NULL, &err), G_ERR_IO);
    assert_int_equal(access(path, F_OK), -1);
    gimage_free(&img);
}

static volatile sig_atomic_t handled;
static void own_handler(int sig)
{
    (void)sig;
    handled = 1;
}

/* A child starts an output, reports its temporary, and is ended by sig (or, with its own handler installed
 * before the output began, goes on): the temporary must be gone. */
static void interrupted_output(int sig, int with_own_handler)
{
    int fds[2];
    assert_int_equal(pipe(fds), 0);
    char target[300];
    snprintf(target, sizeof target, "%s/interrupted.exr", dir);
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        close(fds[0]);
        /* the signal as a program started from a terminal gets it (a job started in the background inherits
         * SIGINT ignored, and the library leaves an ignored signal alone) */
        signal(sig, with_own_handler ? own_handler : SIG_DFL);
        GFileOutput o;
        GError err;
        if (gfile_output_begin(&o, target, &err) != G_OK)
            _exit(3);
        if (write(o.fd, "partial", 7) != 7)
            _exit(4);
        if (write(fds[1], o.temp, strlen(o.temp) + 1) < 0)
            _exit(5);
        raise(sig);
        /* with its own handler the program goes on: the temporary is gone all the same */
        _exit(handled ? 7 : 6);
    }
    close(fds[1]);
    char temp[400] = {0};
    ssize_t got = read(fds[0], temp, sizeof temp - 1);
    close(fds[0]);
    int status;
    assert_int_equal(waitpid(pid, &status, 0), pid);
    assert_true(got > 0);
    if (with_own_handler) {
        assert_true(WIFEXITED(status));
        assert_int_equal(WEXITSTATUS(status), 7);
    } else {
        assert_true(WIFSIGNALED(status));
        assert_int_equal(WTERMSIG(status), sig);
    }
    assert_int_equal(access(temp, F_OK), -1);
    assert_int_equal(access(target, F_OK), -1);
}

static void test_temporaries_removed_on_signals(void **state)
{
    (void)state;
    int sigs[] = {SIGINT, SIGTERM, SIGHUP};
    for (int i = 0; i < 3; i++) {
        interrupted_output(sigs[i], 0);
        interrupted_output(sigs[i], 1);
    }
}

static const char *self_path;

/* The program itself, run as `test_file --exit-child TARGET`: starts an output and calls exit(9) (as
 * libjpeg's default error handler would). A fresh process, not a fork of this one: exit() runs the
 * finalizers of the loaded libraries, which wait for threads a forked child does not have. */
static int exit_child(const char *target)
{
    GFileOutput o;
    GError err;
    if (gfile_output_begin(&o, target, &err) != G_OK)
        return 3;
    exit(9);
}

static void test_temporaries_removed_on_exit(void **state)
{
    (void)state;
    char target[300];
    snprintf(target, sizeof target, "%s/exiting.png", dir);
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        execl(self_path, self_path, "--exit-child", target, (char *)NULL);
        _exit(127);
    }
    int status;
    assert_int_equal(waitpid(pid, &status, 0), pid);
    assert_true(WIFEXITED(status));
    assert_int_equal(WEXITSTATUS(status), 9);
    assert_int_equal(count_entries(".exiting"), 0);
}

int main(int argc, char **argv)
{
    if (argc == 3 && strcmp(argv[1], "--exit-child") == 0)
        return exit_child(argv[2]);
    self_path = argv[0];
    const struct CMUnitTest tests[] = {
        /* first: the children must start without the parent's cleanup handlers installed */
        cmocka_unit_test(test_temporaries_removed_on_signals),
        cmocka_unit_test(test_temporaries_removed_on_exit),
        cmocka_unit_test(test_non_regular_inputs_are_refused_everywhere),
        cmocka_unit_test(test_regular_input_opens_blocking),
        cmocka_unit_test(test_output_commit_abort_and_links),
        cmocka_unit_test(test_output_destinations_checked),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
