/* gprobe.h - the gprobe tool's shared pieces: options common to every command, probe loading, output. */
#ifndef GPROBE_TOOL_H
#define GPROBE_TOOL_H

#include <generic/services/file.h>
#include <generic/services/probe.h>

#include "../common/cli.h"

#include <stdio.h>

/** Options every command that reads a probe understands. */
typedef struct ProbeArgs {
    const char *path;    /* --probe */
    GProbeFormat format; /* --format */
    double rot[3];       /* --rotate X,Y,Z in degrees */
    int rotate;          /* --rotate given */
    int quiet;           /* -q */
} ProbeArgs;

/** getopt_long codes of --probe, --format and --rotate (-q is 'q'); a command's own codes start at PROBE_OPT_OWN. */
enum { PROBE_OPT_PROBE = CLI_FIRST_OWN, PROBE_OPT_FORMAT, PROBE_OPT_ROTATE, PROBE_OPT_OWN };
/** The option table entries of those options (-q, --quiet too). */
#define PROBE_ARGS_OPTIONS                                                                                           \
    {"probe", required_argument, NULL, PROBE_OPT_PROBE}, {"format", required_argument, NULL, PROBE_OPT_FORMAT},     \
        {"rotate", required_argument, NULL, PROBE_OPT_ROTATE}, {"quiet", no_argument, NULL, 'q'}
/** Handles the option of code c (value v) when it is one of those; 1 when handled, 0 when it is not one of them,
 * -1 on a bad value (message printed). */
int probe_args_option(ProbeArgs *a, int c, const char *v);
/** The help lines for those options. */
extern const char probe_args_help[];
/** Loads (and rotates) the probe; prints the error or the clamping warning. NULL on failure. */
GProbe *probe_args_load(const ProbeArgs *a);

/** The next option of a command's own, after -h/--help (prints usage(stdout)), --version and the probe options
 * (--probe, --format, --rotate, -q, into a): as cli_next_own, CLI_EXIT with *status CLI_USAGE after a bad value
 * of a probe option too. */
int probe_next_option(CliParser *p, ProbeArgs *a, void (*usage)(FILE *), int *status);

/** Parses "x,y,z"; -1 with a message when malformed. */
int parse_vec3(const char *opt, const char *s, double v[3]);

/** Seconds on a monotonic clock. */
double now_seconds(void);

/** A text file written to a temporary next to `path` and renamed into place by text_close (generic/services/file.h). */
typedef struct TextOut {
    FILE *f;
    char *path;
    GFileOutput out;
} TextOut;
/** Checks before any work that path can be written (generic/services/file.h), and, when image is set, that this
 * OpenImageIO has a writer for its extension; -1 with a message when not. NULL passes. */
int output_check(const char *path, int image);
/** Opens the temporary; -1 with a message on failure. */
int text_open(TextOut *t, const char *path);
/** Closes and renames (ok != 0) or removes (ok == 0) the temporary; -1 with a message when the write failed. */
int text_close(TextOut *t, int ok);

/** Progress reporter for the library's callback: a percentage on stderr when it is a terminal. */
void progress_print(void *user, const char *stage, double fraction);
/** The library's options for a command: the irradiance fit's normals (0: its default), progress unless quiet. */
GProbeOptions probe_options(int fit_normals, int quiet);

/* ---- the approximations compared (methods.c) ---- */

/** One approximation method: a light technique (light >= 0) or a basis (basis >= 0). */
typedef struct Method {
    const char *name;
    int light;        /* GProbeTechnique or -1 */
    int basis;        /* GProbeBasisKind or -1 */
    const char *unit; /* what N counts: lights, coefficients, lobes */
} Method;
/** The names, comma separated, for messages. */
extern const char methods_names[];
int method_count(void);
const Method *method_get(int i);
/** Index of a name, -1 when unknown. */
int method_find(const char *name);
/** 1 for the legacy sh9 entry (the nine-coefficient reference line; not in the default list). */
int method_is_sh9(int i);
/** The sizes a method is tried at for the given light counts: SH always at 4, 9, 16, 25 coefficients, the
 * ambient cube at 6, the others at the counts they can make (skipped ones reported unless quiet). */
int method_sizes(int i, const int *counts, int ncounts, int fit_normals, int *out, int quiet);

/** One method made for one size. */
typedef struct Approx {
    int method, n;
    GProbeLight *lights; /* light methods */
    GProbeBasis basis;   /* basis methods */
} Approx;
/** Makes method `method` with n lights, coefficients or lobes; rep (may be NULL) gets the irradiance fit's report. */
int approx_make(const GProbe *p, int method, int n, const GProbeOptions *opt, Approx *a, GProbeFitReport *rep,
                GError *err);
/** Irradiance at m normals (3 doubles each). */
void approx_irradiance(const Approx *a, const GVec3 *normals, int m, double *E);
void approx_free(Approx *a);

/* ---- what eval and report measure (measure.c) ---- */

/** One result row of eval and report. */
typedef struct Row {
    int method, count;
    GProbeErrors e;
    double seconds;
} Row;
/** The CSV of rows: technique,count,unit,mean_rel,max_rel,mean_norm,max_norm,smape,seconds. */
void rows_csv(FILE *f, const Row *rows, int n);

/** The techniques, their sizes and the normals eval and report measure them at. */
typedef struct EvalPlan {
    int normals;             /* --normals M: the normals of the error figures (default 20000) */
    int fit_normals;         /* --fit-normals N: the normals the irradiance fit fits (0: the library's default) */
    int counts[64], ncounts; /* --counts: light and lobe counts */
    int use[64];             /* --techniques: use[method] */
} EvalPlan;
/** getopt_long codes of the plan's options; a command's own codes start at PLAN_OPT_OWN. */
enum { PLAN_OPT_NORMALS = PROBE_OPT_OWN, PLAN_OPT_FIT, PLAN_OPT_COUNTS, PLAN_OPT_TECHNIQUES, PLAN_OPT_OWN };
/** The option table entries of --normals, --fit-normals, --counts and --techniques. */
#define EVAL_PLAN_OPTIONS                                                                                            \
    {"normals", required_argument, NULL, PLAN_OPT_NORMALS}, {"fit-normals", required_argument, NULL, PLAN_OPT_FIT}, \
        {"counts", required_argument, NULL, PLAN_OPT_COUNTS},                                                        \
        {"techniques", required_argument, NULL, PLAN_OPT_TECHNIQUES}
/** A plan of 20000 normals, the given counts, every technique but sh9 and the fit's default normals. */
void eval_plan_init(EvalPlan *plan, const int *counts, int ncounts);
/** Handles the option of code c (value v) when it is one of the plan's: 1 when handled, 0 when it is not one of
 * them, -1 on a bad value (message printed). */
int eval_plan_option(EvalPlan *plan, int c, const char *v);
/** The most rows a plan makes. */
int eval_plan_max_rows(const EvalPlan *plan);

/** The ground truth at m normals spread evenly over the sphere, and room for an approximation's irradiance
 * there (3 doubles a normal each). */
typedef struct Truth {
    int m;
    GVec3 *normals;
    double *truth, *approx;
} Truth;
/** Allocates for m normals: 0, or -1 when out of memory (nothing printed). */
int truth_alloc(Truth *t, int m);
/** Spreads the normals and sums the probe's irradiance at each (the paper's Eq. 4). */
int truth_compute(Truth *t, const GProbe *p, GError *err);
void truth_free(Truth *t);

/** Receives one measured technique and size with its approximation (freed after the call); 0 to go on. */
typedef int (*EvalRowFn)(void *user, const Row *row, const Approx *a);
/** Makes every technique of the plan at each of its sizes, in the order of methods.c's list, times it and
 * compares its irradiance at the truth's normals (printing a line each unless quiet); each goes to fn. 0, or -1
 * when a technique failed (message printed) or fn returned non-zero. */
int eval_plan_run(const EvalPlan *plan, const GProbe *p, Truth *truth, int quiet, EvalRowFn fn, void *user);

/** The operands after the options: a usage error (2, message printed) when there are any. */
int no_operands(const CliParser *p);

/* the commands: each returns the process exit status */
int cmd_eval(int argc, char **argv);
int cmd_approx(int argc, char **argv);
int cmd_irradiance(int argc, char **argv);
int cmd_convert(int argc, char **argv);
int cmd_compare(int argc, char **argv); /* compare.c */
int cmd_sky(int argc, char **argv);     /* sky.c */
int cmd_report(int argc, char **argv);  /* report.c */

/** Draws the Fig. 6 plot of a CSV written by eval into png with gnuplot; -1 with a message on failure. */
int plot_errors(const char *csv, const char *png, const char *title);
/** 0 when a gnuplot executable is on PATH, -1 with a clear message when not. */
int plot_check_gnuplot(void);

#endif
