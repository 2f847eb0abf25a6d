/* cli.h - the command-line conventions every tool of examples/ shares, on top of getopt_long: `--opt value`
 * and `--opt=value`, --help and --version, one message naming the option that is wrong, and the exit status
 * (0 success, 1 the work failed, 2 a usage error). Header only (static functions), so a tool needs no more
 * than this include; it uses nothing outside libc. */
#ifndef EXAMPLES_CLI_H
#define EXAMPLES_CLI_H

#include <errno.h>
#include <fcntl.h>
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdio_ext.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifndef GENERIC_VERSION
#define GENERIC_VERSION "unknown"
#endif

/** Exit statuses of every tool. */
enum { CLI_OK = 0, CLI_FAILED = 1, CLI_USAGE = 2 };

/** getopt_long codes of the long-only options every tool takes (above any character). */
enum { CLI_VERSION = 0x100, CLI_FIRST_OWN = 0x101 };

/** The two entries every option table has: -h/--help and --version. */
#define CLI_COMMON_OPTIONS {"help", no_argument, NULL, 'h'}, {"version", no_argument, NULL, CLI_VERSION}

/** The exit-status paragraph of every --help. */
#define CLI_EXIT_STATUS_HELP                                                                                       \
    "Exit status: 0 on success, 1 when the work failed (an unreadable or bad input file, a failed\n"                  \
    "write), 2 for a usage error (an unknown option, a bad value, a missing argument).\n"

/** One parse of argv with a table of options; prog is the name in messages ("gtrace", "gmat plot"). */
typedef struct CliParser {
    const char *prog;
    int argc;
    char **argv;
    const char *shortopts; /* without the leading ':' */
    const struct option *longopts;
    char optstring[64];
} CliParser;

/** Starts a parse of argv[1..argc) (argv[0] is the program or the subcommand's name). */
static inline void cli_begin(CliParser *p, const char *prog, int argc, char **argv, const char *shortopts,
                             const struct option *longopts)
{
    p->prog = prog;
    p->argc = argc;
    p->argv = argv;
    p->shortopts = shortopts;
    p->longopts = longopts;
    snprintf(p->optstring, sizeof p->optstring, ":%s", shortopts);
    optind = 0; /* glibc: start again from argv[1], forgetting any earlier parse */
    opterr = 0;
}

/* The long option `text` (after "--", up to any '=') names: how many entries it is a prefix of, and whether
 * one matches it exactly. */
static inline int cli_matches_(const CliParser *p, const char *text, int *exact)
{
    size_t len = strcspn(text, "=");
    int n = 0;
    *exact = 0;
    for (const struct option *o = p->longopts; o->name; o++)
        if (strncmp(o->name, text, len) == 0) {
            n++;
            if (strlen(o->name) == len)
                *exact = 1;
        }
    return n;
}

/** The next option's code (its short character or long code), -1 after the last. On a mistake (an unknown or
 * ambiguous option, a missing value, a value given to an option that takes none) it prints one line naming the
 * option, "PROG: unknown option '--x' (see PROG --help)", and returns '?': the caller exits with CLI_USAGE. */
static inline int cli_next(CliParser *p)
{
    int c = getopt_long(p->argc, p->argv, p->optstring, p->longopts, NULL);
    if (c != '?' && c != ':')
        return c;
    const char *arg = optind > 0 && optind <= p->argc ? p->argv[optind - 1] : "";
    int is_long = arg[0] == '-' && arg[1] == '-';
    if (c == ':') {
        if (is_long)
            fprintf(stderr, "%s: option '%s' needs a value", p->prog, arg);
        else
            fprintf(stderr, "%s: option '-%c' needs a value", p->prog, optopt);
    } else if (is_long) {
        int exact, n = cli_matches_(p, arg + 2, &exact);
        int len = (int)strcspn(arg, "=");
        if (n == 0)
            fprintf(stderr, "%s: unknown option '%.*s'", p->prog, len, arg);
        else if (n > 1 && !exact)
            fprintf(stderr, "%s: option '%.*s' is ambiguous (it begins several options)", p->prog, len, arg);
        else
            fprintf(stderr, "%s: option '%.*s' takes no value", p->prog, len, arg);
    } else {
        fprintf(stderr, "%s: unknown option '-%c'", p->prog, optopt);
    }
    fprintf(stderr, " (see %s --help)\n", p->prog);
    return '?';
}

/** The arguments that are not options, after the parse (getopt_long moved them to the end). */
static inline char **cli_operands(const CliParser *p, int *count)
{
    *count = p->argc - optind;
    return p->argv + optind;
}

/** Prints "PROG (libgeneric) VERSION" on stdout; returns CLI_OK. */
static inline int cli_version(const char *prog)
{
    printf("%s (libgeneric) %s\n", prog, GENERIC_VERSION);
    return CLI_OK;
}

/** What cli_next_own returns when the tool must end at once. */
enum { CLI_EXIT = -2 };

/** The next option of the tool's own, after those every tool handles alike: -h/--help (prints usage(stdout)),
 * --version (cli_version(tool)) and a mistake (cli_next's message). Returns the option's code (its value in
 * optarg), -1 after the last option, or CLI_EXIT with *status the exit status: CLI_OK after --help or --version,
 * CLI_USAGE after a mistake. */
static inline int cli_next_own(CliParser *p, const char *tool, void (*usage)(FILE *), int *status)
{
    int c = cli_next(p);
    if (c == 'h') {
        usage(stdout);
        *status = CLI_OK;
        return CLI_EXIT;
    }
    if (c == CLI_VERSION || c == '?') {
        *status = c == '?' ? CLI_USAGE : cli_version(tool);
        return CLI_EXIT;
    }
    return c;
}

/** Prints "PROG: MESSAGE (see PROG --help)" on stderr; returns CLI_USAGE. */
static inline int cli_usage_error(const char *prog, const char *message, const char *arg)
{
    fprintf(stderr, "%s: ", prog);
    fprintf(stderr, message, arg);
    fprintf(stderr, " (see %s --help)\n", prog);
    return CLI_USAGE;
}

/** The whole of s as an integer in [lo, hi] into *out; otherwise a message naming opt, and -1. */
static inline int cli_int(const char *prog, const char *opt, const char *s, long lo, long hi, int *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (errno || end == s || *end || v < lo || v > hi) {
        fprintf(stderr, "%s: %s expects a whole number in [%ld, %ld], got '%s'\n", prog, opt, lo, hi, s);
        return -1;
    }
    *out = (int)v;
    return 0;
}

/** The whole of s as a finite number in [lo, hi] into *out; otherwise a message naming opt, and -1. */
static inline int cli_double(const char *prog, const char *opt, const char *s, double lo, double hi, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || *end || !isfinite(v) || v < lo || v > hi) {
        fprintf(stderr, "%s: %s expects a number in [%g, %g], got '%s'\n", prog, opt, lo, hi, s);
        return -1;
    }
    *out = v;
    return 0;
}

/** Ends a tool's use of standard output: flushes and closes it and checks every write it took. When a write failed
 * (a full disk, /dev/full, a closed descriptor that was written to, a broken pipe) it prints "PROG: cannot write
 * the standard output: REASON" on standard error and returns CLI_FAILED for a status that was CLI_OK; else it
 * returns status. A closed standard output that nothing was written to is not an error. Every tool's main returns
 * through it. */
static inline int cli_finish_stdout(const char *prog, int status)
{
    int failed = ferror(stdout) != 0, pending = __fpending(stdout) != 0;
    errno = 0;
    int closed = fclose(stdout) == 0, reason = errno;
    if (!closed && (pending || reason != EBADF))
        failed = 1;
    if (!failed)
        return status;
    fprintf(stderr, "%s: cannot write the standard output: %s\n", prog,
            reason ? strerror(reason) : "a write failed");
    return status == CLI_OK ? CLI_FAILED : status;
}

/** Keeps the standard descriptors 0, 1 and 2 taken for the whole run. One the program was started without is opened
 * on /dev/null the way it cannot be used (standard input for writing, the outputs for reading), so that no file or
 * socket the program opens gets its number (text meant for standard output would go into it) and a write to it
 * fails, which cli_finish_stdout reports. */
static inline void cli_hold_standard_fds(void)
{
    for (int fd = 0; fd <= 2; fd++) {
        if (fcntl(fd, F_GETFD) >= 0 || errno != EBADF)
            continue;
        int got = open("/dev/null", fd == 0 ? O_WRONLY : O_RDONLY); /* the lowest free number: fd itself */
        if (got > fd) {
            dup2(got, fd);
            close(got);
        }
    }
}

/** A tool's whole run: holds the standard descriptors (cli_hold_standard_fds), runs tool_main and ends standard
 * output through cli_finish_stdout. Every tool's main is this call. */
static inline int cli_run(const char *prog, int (*tool_main)(int, char **), int argc, char **argv)
{
    cli_hold_standard_fds();
    return cli_finish_stdout(prog, tool_main(argc, argv));
}

#endif
