/* eval.c - `gprobe eval`: every technique at every light count against the ground-truth irradiance. */
#include "gprobe.h"

#include <generic/memory.h>

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static void usage(FILE *f)
{
    fprintf(f,
            "usage: gprobe eval --probe FILE [--normals M] [--counts LIST] [--techniques LIST]\n"
            "                   [--fit-normals N] [--csv OUT.csv] [--plot OUT.png] [--title TEXT]\n"
            "Approximates the probe with each technique and size and compares the irradiance of the\n"
            "approximation with the ground truth (every pixel summed, Eq. 4) at M normals spread evenly over\n"
            "the sphere. Errors in percent: for each channel the mean and the max over the normals of\n"
            "|E' - E| / E (the paper's measure) and of |E' - E| / max E (normalised by the largest\n"
            "irradiance), and sMAPE, 100 mean 2 |E' - E| / (|E'| + |E|), averaged over R, G, B. Prints a\n"
            "table; --csv and --plot write it and its Fig. 6.\n"
            "%s"
            "  --normals M       normals for the evaluation (default 20000)\n"
            "  --counts LIST     light and lobe counts, comma separated (default 2,4,8,16,32,64,128; median\n"
            "                    cut skips counts that are not powers of two). SH is always tried at 4, 9, 16\n"
            "                    and 25 coefficients (orders 1..4), the ambient cube at its 6\n"
            "  --techniques LIST comma separated from %s\n"
            "                    (default: all but sh9, the 9-coefficient reference drawn as a line)\n"
            "  --fit-normals N   normals the irradiance optimisation fits (default 2000)\n"
            "  --csv OUT.csv     technique,count,unit,mean_rel,max_rel,mean_norm,max_norm,smape,seconds\n"
            "                    (unit: what count counts, lights, coefficients or lobes)\n"
            "  --plot OUT.png    error against N, drawn with gnuplot (pngcairo)\n"
            "  --title TEXT      plot title (default: the probe's file name)\n" CLI_EXIT_STATUS_HELP,
            probe_args_help, methods_names);
}

/* The command line of eval. */
typedef struct EvalArgs {
    ProbeArgs probe;
    EvalPlan plan;
    const char *csv, *png, *title; /* --csv, --plot, --title */
} EvalArgs;

/* Reads the command line into a: -1 to go on, else the exit status to end with. */
static int eval_args(int argc, char **argv, EvalArgs *a)
{
    static const int counts[] = {2, 4, 8, 16, 32, 64, 128};
    enum { OPT_CSV = PLAN_OPT_OWN, OPT_PLOT, OPT_TITLE };
    static const struct option longopts[] = {
        CLI_COMMON_OPTIONS, PROBE_ARGS_OPTIONS, EVAL_PLAN_OPTIONS,
        {"csv", required_argument, NULL, OPT_CSV}, {"plot", required_argument, NULL, OPT_PLOT},
        {"title", required_argument, NULL, OPT_TITLE}, {NULL, 0, NULL, 0},
    };
    memset(a, 0, sizeof *a);
    eval_plan_init(&a->plan, counts, (int)(sizeof counts / sizeof *counts));
    CliParser cp;
    cli_begin(&cp, "gprobe eval", argc, argv, "hq", longopts);
    int c, status = CLI_OK;
    while ((c = probe_next_option(&cp, &a->probe, usage, &status)) != -1) {
        if (c == CLI_EXIT)
            return status;
        int r = eval_plan_option(&a->plan, c, optarg);
        if (r < 0)
            return CLI_USAGE;
        if (r > 0)
            continue;
        if (c == OPT_CSV)
            a->csv = optarg;
        else if (c == OPT_PLOT)
            a->png = optarg;
        else if (c == OPT_TITLE)
            a->title = optarg;
        else
            return CLI_USAGE;
    }
    return no_operands(&cp) ? CLI_USAGE : -1;
}

/* The rows measured so far. */
typedef struct Rows {
    Row *row;
    int n;
} Rows;

static int keep_row(void *user, const Row *row, const Approx *a)
{
    (void)a;
    Rows *rows = user;
    rows->row[rows->n++] = *row;
    return 0;
}

static void print_table(const Rows *rows)
{
    printf("%-11s %5s %-12s %10s %10s %10s %10s %8s %9s\n", "technique", "N", "unit", "mean_rel%", "max_rel%",
           "mean_norm%", "max_norm%", "smape%", "seconds");
    for (int i = 0; i < rows->n; i++) {
        const Row *r = &rows->row[i];
        printf("%-11s %5d %-12s %10.3f %10.3f %10.4f %10.4f %8.3f %9.3f\n", method_get(r->method)->name, r->count,
               method_get(r->method)->unit, r->e.mean_rel, r->e.max_rel, r->e.mean_norm, r->e.max_norm, r->e.smape,
               r->seconds);
    }
}

/* Fig. 6 of the rows into png, through their CSV in a temporary beside it (removed on a signal too, never renamed
 * over the picture). 0 or 1, the exit status. */
static int write_plot(const Rows *rows, const char *png, const char *title)
{
    GFileOutput tmp;
    GError err;
    FILE *f = NULL;
    int fd = -1, status = 0;
    if (gfile_output_begin(&tmp, png, &err) != G_OK)
        fprintf(stderr, "gprobe: %s\n", err.message);
    else if ((fd = dup(tmp.fd)) < 0 || !(f = fdopen(fd, "w")))
        perror("gprobe: temporary file");
    if (!f) {
        if (fd >= 0)
            close(fd);
        status = 1;
    } else {
        rows_csv(f, rows->row, rows->n);
        if (ferror(f) | (fclose(f) != 0)) {
            fprintf(stderr, "gprobe: cannot write the temporary %s\n", tmp.temp);
            status = 1;
        }
        if (status == 0 && plot_errors(tmp.temp, png, title) != 0)
            status = 1;
    }
    gfile_output_abort(&tmp);
    return status;
}

/* The ground truth and every row of the plan: 0, or -1 with a message. */
static int measure(const EvalArgs *a, const GProbe *p, Truth *truth, Rows *rows)
{
    if (truth_alloc(truth, a->plan.normals) != 0 || !rows->row) {
        fprintf(stderr, "gprobe: out of memory for %d normals\n", a->plan.normals);
        return -1;
    }
    GError err;
    double t0 = now_seconds();
    if (truth_compute(truth, p, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        return -1;
    }
    if (!a->probe.quiet)
        fprintf(stderr, "gprobe: %s: %dx%d, ground truth at %d normals in %.2f s\n", a->probe.path, gprobe_width(p),
                gprobe_height(p), truth->m, now_seconds() - t0);
    return eval_plan_run(&a->plan, p, truth, a->probe.quiet, keep_row, rows);
}

int cmd_eval(int argc, char **argv)
{
    EvalArgs a;
    int status = eval_args(argc, argv, &a);
    if (status >= 0)
        return status;
    if ((a.png && plot_check_gnuplot() != 0) || output_check(a.png, 1) != 0 || output_check(a.csv, 0) != 0)
        return 1;
    TextOut csv_out = {0};
    if (a.csv && text_open(&csv_out, a.csv) != 0)
        return 1;
    GProbe *p = probe_args_load(&a.probe);
    if (!p) {
        if (a.csv)
            text_close(&csv_out, 0);
        return 1;
    }
    Truth truth = {0};
    Rows rows = {gmem_calloc((size_t)eval_plan_max_rows(&a.plan), sizeof(Row)), 0};
    status = measure(&a, p, &truth, &rows) == 0 ? 0 : 1;
    if (status == 0)
        print_table(&rows);
    if (a.csv) { /* written whole, or removed when the work failed */
        if (status == 0)
            rows_csv(csv_out.f, rows.row, rows.n);
        if (text_close(&csv_out, status == 0) != 0)
            status = 1;
    }
    if (a.png && status == 0) {
        const char *base = strrchr(a.probe.path, '/');
        status = write_plot(&rows, a.png, a.title ? a.title : base ? base + 1 : a.probe.path);
    }
    truth_free(&truth);
    gmem_free(rows.row);
    gprobe_destroy(p);
    return status;
}
