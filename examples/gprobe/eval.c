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

int parse_count_list(const char *s, int *counts, int max)
{
    int n = 0;
    char buf[512];
    snprintf(buf, sizeof buf, "%s", s);
    for (char *save = NULL, *tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        if (n >= max) {
            fprintf(stderr, "gprobe: --counts: at most %d counts\n", max);
            return -1;
        }
        if (parse_int("--counts", tok, 1, 4096, &counts[n]) != 0)
            return -1;
        n++;
    }
    if (n == 0)
        fprintf(stderr, "gprobe: --counts: no counts given\n");
    return n > 0 ? n : -1;
}

void methods_default(int *use)
{
    for (int k = 0; k < method_count(); k++)
        use[k] = !method_is_sh9(k);
}

int parse_method_list(const char *s, int *use)
{
    char buf[512];
    snprintf(buf, sizeof buf, "%s", s);
    memset(use, 0, sizeof(int) * method_count());
    int any = 0;
    for (char *save = NULL, *tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        int t = method_find(tok);
        if (t < 0) {
            fprintf(stderr, "gprobe: unknown technique '%s' (expected %s)\n", tok, methods_names);
            return -1;
        }
        use[t] = any = 1;
    }
    if (!any)
        fprintf(stderr, "gprobe: --techniques: none given\n");
    return any ? 0 : -1;
}

void rows_csv(FILE *f, const Row *rows, int n)
{
    fprintf(f, "technique,count,unit,mean_rel,max_rel,mean_norm,max_norm,smape,seconds\n");
    for (int i = 0; i < n; i++) {
        const Method *m = method_get(rows[i].method);
        fprintf(f, "%s,%d,%s,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", m->name, rows[i].count, m->unit, rows[i].e.mean_rel,
                rows[i].e.max_rel, rows[i].e.mean_norm, rows[i].e.max_norm, rows[i].e.smape, rows[i].seconds);
    }
}

int eval_one(const GProbe *p, int method, int n, const GProbeOptions *opt, const GVec3 *normals, int m,
             const double *truth, double *approx, Row *row, Approx *keep, int quiet)
{
    GError err;
    GProbeFitReport rep;
    Approx a;
    double s = now_seconds();
    if (approx_make(p, method, n, opt, &a, &rep, &err) != G_OK) {
        fprintf(stderr, "\ngprobe: %s N=%d: %s\n", method_get(method)->name, n, err.message);
        return -1;
    }
    row->seconds = now_seconds() - s;
    row->method = method;
    row->count = n;
    approx_irradiance(&a, normals, m, approx);
    gprobe_compare(truth, approx, m, &row->e);
    if (!quiet) {
        const Method *me = method_get(method);
        fprintf(stderr, "\r  %-12s N=%-4d mean %7.3f%%  max %8.3f%%  %7.3f s", me->name, n, row->e.mean_rel,
                row->e.max_rel, row->seconds);
        if (me->light == GPROBE_IRRADIANCE) {
            fprintf(stderr, "  (objective %.4g -> %.4g, %d iterations%s", rep.initial, rep.final, rep.iterations,
                    rep.converged ? "" : ", iteration limit");
            if (rep.revived)
                fprintf(stderr, ", %d unused lights moved", rep.revived);
            fputc(')', stderr);
        }
        fputc('\n', stderr);
    }
    if (keep)
        *keep = a;
    else
        approx_free(&a);
    return 0;
}

int cmd_eval(int argc, char **argv)
{
    ProbeArgs pa = {0};
    int m = 20000, fit = 0, counts[64], ncounts = 7, use[64];
    const int defaults[7] = {2, 4, 8, 16, 32, 64, 128};
    memcpy(counts, defaults, sizeof defaults);
    methods_default(use);
    const char *csv = NULL, *png = NULL, *title = NULL;
    enum { OPT_NORMALS = PROBE_OPT_OWN, OPT_FIT, OPT_COUNTS, OPT_TECHNIQUES, OPT_CSV, OPT_PLOT, OPT_TITLE };
    static const struct option longopts[] = {
        CLI_COMMON_OPTIONS, PROBE_ARGS_OPTIONS,
        {"normals", required_argument, NULL, OPT_NORMALS}, {"fit-normals", required_argument, NULL, OPT_FIT},
        {"counts", required_argument, NULL, OPT_COUNTS}, {"techniques", required_argument, NULL, OPT_TECHNIQUES},
        {"csv", required_argument, NULL, OPT_CSV}, {"plot", required_argument, NULL, OPT_PLOT},
        {"title", required_argument, NULL, OPT_TITLE}, {NULL, 0, NULL, 0},
    };
    CliParser cp;
    cli_begin(&cp, "gprobe eval", argc, argv, "hq", longopts);
    int c;
    while ((c = cli_next(&cp)) != -1) {
        const char *v = optarg;
        int r = probe_args_option(&pa, c, v);
        if (r < 0)
            return CLI_USAGE;
        if (r > 0)
            continue;
        if (c == 'h') {
            usage(stdout);
            return CLI_OK;
        } else if (c == CLI_VERSION) {
            return cli_version("gprobe");
        } else if (c == OPT_NORMALS) {
            if (parse_int("--normals", v, 1, 10000000, &m) != 0)
                return CLI_USAGE;
        } else if (c == OPT_FIT) {
            if (parse_int("--fit-normals", v, 2, 1000000, &fit) != 0)
                return CLI_USAGE;
        } else if (c == OPT_COUNTS) {
            if ((ncounts = parse_count_list(v, counts, 64)) < 0)
                return CLI_USAGE;
        } else if (c == OPT_TECHNIQUES) {
            if (parse_method_list(v, use) != 0)
                return CLI_USAGE;
        } else if (c == OPT_CSV) {
            csv = v;
        } else if (c == OPT_PLOT) {
            png = v;
        } else if (c == OPT_TITLE) {
            title = v;
        } else {
            return CLI_USAGE;
        }
    }
    if (no_operands(&cp))
        return CLI_USAGE;
    if ((png && plot_check_gnuplot() != 0) || output_check(png, 1) != 0 || output_check(csv, 0) != 0)
        return 1;
    TextOut csv_out = {0};
    if (csv && text_open(&csv_out, csv) != 0)
        return 1;
    GProbe *p = probe_args_load(&pa);
    if (!p) {
        if (csv)
            text_close(&csv_out, 0);
        return 1;
    }

    GVec3 *normals = gmem_calloc((size_t)m, sizeof *normals);
    double *truth = gmem_calloc((size_t)m * 3, sizeof(double)), *approx = gmem_calloc((size_t)m * 3, sizeof(double));
    Row *rows = gmem_calloc((size_t)method_count() * (ncounts + GPROBE_SH_MAX_ORDER), sizeof *rows);
    int nrows = 0, status = 1;
    if (!normals || !truth || !approx || !rows) {
        fprintf(stderr, "gprobe: out of memory for %d normals\n", m);
        goto done;
    }
    GError err;
    gprobe_fibonacci(m, normals);
    double t0 = now_seconds();
    if (gprobe_irradiance(p, normals, m, truth, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        goto done;
    }
    if (!pa.quiet)
        fprintf(stderr, "gprobe: %s: %dx%d, ground truth at %d normals in %.2f s\n", pa.path, gprobe_width(p),
                gprobe_height(p), m, now_seconds() - t0);

    GProbeOptions opt = {0};
    opt.fit_normals = fit;
    if (!pa.quiet) {
        opt.progress = progress_print;
    }
    for (int t = 0; t < method_count(); t++) {
        if (!use[t])
            continue;
        int sizes[64 + GPROBE_SH_MAX_ORDER];
        int ns = method_sizes(t, counts, ncounts, fit, sizes, pa.quiet);
        for (int c = 0; c < ns; c++)
            if (eval_one(p, t, sizes[c], &opt, normals, m, truth, approx, &rows[nrows++], NULL, pa.quiet) != 0)
                goto done;
    }

    printf("%-11s %5s %-12s %10s %10s %10s %10s %8s %9s\n", "technique", "N", "unit", "mean_rel%", "max_rel%",
           "mean_norm%", "max_norm%", "smape%", "seconds");
    for (int i = 0; i < nrows; i++)
        printf("%-11s %5d %-12s %10.3f %10.3f %10.4f %10.4f %8.3f %9.3f\n", method_get(rows[i].method)->name,
               rows[i].count, method_get(rows[i].method)->unit, rows[i].e.mean_rel, rows[i].e.max_rel,
               rows[i].e.mean_norm, rows[i].e.max_norm, rows[i].e.smape, rows[i].seconds);
    status = 0;
    if (csv) {
        rows_csv(csv_out.f, rows, nrows);
        csv = NULL; /* closed here */
        if (text_close(&csv_out, 1) != 0)
            status = 1;
    }
    if (png && status == 0) {
        GFileOutput tmp; /* the plot's data: a temporary (removed on a signal too) that is never renamed */
        GError err;
        FILE *f = NULL;
        int fd = -1;
        if (gfile_output_begin(&tmp, png, &err) != G_OK) /* next to the picture, never renamed over it */
            fprintf(stderr, "gprobe: %s\n", err.message);
        else if ((fd = dup(tmp.fd)) < 0 || !(f = fdopen(fd, "w")))
            perror("gprobe: temporary file");
        if (!f) {
            if (fd >= 0)
                close(fd);
            status = 1;
        } else {
            rows_csv(f, rows, nrows);
            if (ferror(f) | (fclose(f) != 0)) {
                fprintf(stderr, "gprobe: cannot write the temporary %s\n", tmp.temp);
                status = 1;
            }
            const char *base = strrchr(pa.path, '/');
            if (status == 0 && plot_errors(tmp.temp, png, title ? title : base ? base + 1 : pa.path) != 0)
                status = 1;
        }
        gfile_output_abort(&tmp);
    }
done:
    if (csv) /* still open: the work failed */
        text_close(&csv_out, 0);
    gmem_free(normals);
    gmem_free(truth);
    gmem_free(approx);
    gmem_free(rows);
    gprobe_destroy(p);
    return status;
}
