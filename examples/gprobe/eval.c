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
            "Approximates the probe with each technique and light count and compares the irradiance of the\n"
            "lights with the ground truth (every pixel summed, Eq. 4) at M normals spread evenly over the\n"
            "sphere. Errors in percent: for each channel the mean and the max over the normals of\n"
            "|E' - E| / E (the paper's measure) and of |E' - E| / max E (normalised by the largest\n"
            "irradiance), averaged over R, G, B. Prints a table; --csv and --plot write it and its Fig. 6.\n"
            "%s"
            "  --normals M       normals for the evaluation (default 20000)\n"
            "  --counts LIST     light counts, comma separated (default 2,4,8,16,32,64,128; median cut\n"
            "                    skips counts that are not powers of two)\n"
            "  --techniques LIST comma separated from mediancut, adaptive, kmeans, irradiance, sh9\n"
            "                    (default: all; sh9 is the 9-coefficient reference, drawn as a line)\n"
            "  --fit-normals N   normals the irradiance optimisation fits (default 2000)\n"
            "  --csv OUT.csv     technique,count,mean_rel,max_rel,mean_norm,max_norm,seconds\n"
            "  --plot OUT.png    error against the number of lights, drawn with gnuplot (pngcairo)\n"
            "  --title TEXT      plot title (default: the probe's file name)\n" CLI_EXIT_STATUS_HELP,
            probe_args_help);
}

enum { SH9 = GPROBE_TECHNIQUE_COUNT, NTECH };
static const char *tech_name(int t) { return t == SH9 ? "sh9" : gprobe_technique_name((GProbeTechnique)t); }

typedef struct Row {
    int tech, count;
    GProbeErrors e;
    double seconds;
} Row;

static int parse_list_counts(const char *s, int *counts, int max)
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

static int parse_list_techniques(const char *s, int *use)
{
    char buf[512];
    snprintf(buf, sizeof buf, "%s", s);
    memset(use, 0, sizeof(int) * NTECH);
    int any = 0;
    for (char *save = NULL, *tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        int t = -1;
        for (int k = 0; k < NTECH; k++)
            if (strcmp(tok, tech_name(k)) == 0)
                t = k;
        if (t < 0) {
            fprintf(stderr, "gprobe: unknown technique '%s' (expected mediancut, adaptive, kmeans, irradiance or sh9)\n",
                    tok);
            return -1;
        }
        use[t] = any = 1;
    }
    if (!any)
        fprintf(stderr, "gprobe: --techniques: none given\n");
    return any ? 0 : -1;
}

static void put_csv(FILE *f, const Row *rows, int n)
{
    fprintf(f, "technique,count,mean_rel,max_rel,mean_norm,max_norm,seconds\n");
    for (int i = 0; i < n; i++)
        fprintf(f, "%s,%d,%.6g,%.6g,%.6g,%.6g,%.6g\n", tech_name(rows[i].tech), rows[i].count, rows[i].e.mean_rel,
                rows[i].e.max_rel, rows[i].e.mean_norm, rows[i].e.max_norm, rows[i].seconds);
}

/* 0 when the directory of path can take a new file (checked before the long work starts). */
int cmd_eval(int argc, char **argv)
{
    ProbeArgs pa = {0};
    int m = 20000, fit = 0, counts[64], ncounts = 7, use[NTECH];
    const int defaults[7] = {2, 4, 8, 16, 32, 64, 128};
    memcpy(counts, defaults, sizeof defaults);
    for (int k = 0; k < NTECH; k++)
        use[k] = 1;
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
            if ((ncounts = parse_list_counts(v, counts, 64)) < 0)
                return CLI_USAGE;
        } else if (c == OPT_TECHNIQUES) {
            if (parse_list_techniques(v, use) != 0)
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
    Row *rows = gmem_calloc((size_t)NTECH * ncounts, sizeof *rows);
    GProbeLight *lights = NULL;
    int maxn = 1, nrows = 0, status = 1;
    for (int c = 0; c < ncounts; c++)
        maxn = counts[c] > maxn ? counts[c] : maxn;
    lights = gmem_calloc((size_t)maxn, sizeof *lights);
    if (!normals || !truth || !approx || !rows || !lights) {
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
    for (int t = 0; t < NTECH; t++) {
        if (!use[t])
            continue;
        if (t == SH9) {
            double s = now_seconds();
            GProbeSH9 sh;
            gprobe_sh9_project(p, &sh);
            double dt = now_seconds() - s;
            gprobe_sh9_irradiance(&sh, normals, m, approx);
            Row *r = &rows[nrows++];
            r->tech = t;
            r->count = 9;
            r->seconds = dt;
            gprobe_compare(truth, approx, m, &r->e);
            continue;
        }
        for (int c = 0; c < ncounts; c++) {
            int n = counts[c];
            if (t == GPROBE_MEDIANCUT && (n & (n - 1)) != 0) {
                if (!pa.quiet)
                    fprintf(stderr, "  mediancut    N=%-4d skipped (median cut makes powers of two)\n", n);
                continue;
            }
            if (t == GPROBE_IRRADIANCE && 2 * n > (fit > 0 ? fit : 2000)) {
                fprintf(stderr, "  irradiance   N=%-4d skipped (needs at least %d fit normals: --fit-normals)\n", n, 2 * n);
                continue;
            }
            GProbeFitReport rep;
            double s = now_seconds();
            int rc = t == GPROBE_IRRADIANCE ? gprobe_irradiance_fit(p, n, &opt, lights, &rep, &err)
                                            : gprobe_approximate(p, (GProbeTechnique)t, n, &opt, lights, &err);
            double dt = now_seconds() - s;
            if (rc != G_OK) {
                fprintf(stderr, "\ngprobe: %s N=%d: %s\n", tech_name(t), n, err.message);
                goto done;
            }
            gprobe_lights_irradiance(lights, n, normals, m, approx);
            Row *r = &rows[nrows++];
            r->tech = t;
            r->count = n;
            r->seconds = dt;
            gprobe_compare(truth, approx, m, &r->e);
            if (!pa.quiet) {
                fprintf(stderr, "\r  %-12s N=%-4d mean %7.3f%%  max %8.3f%%  %7.3f s", tech_name(t), n, r->e.mean_rel,
                        r->e.max_rel, dt);
                if (t == GPROBE_IRRADIANCE)
                    fprintf(stderr, "  (objective %.4g -> %.4g, %d iterations%s", rep.initial, rep.final, rep.iterations,
                            rep.converged ? "" : ", iteration limit");
                if (t == GPROBE_IRRADIANCE && rep.revived)
                    fprintf(stderr, ", %d unused lights moved", rep.revived);
                if (t == GPROBE_IRRADIANCE)
                    fputc(')', stderr);
                fputc('\n', stderr);
            }
        }
    }

    printf("%-11s %6s %10s %10s %10s %10s %9s\n", "technique", "lights", "mean_rel%", "max_rel%", "mean_norm%",
           "max_norm%", "seconds");
    for (int i = 0; i < nrows; i++)
        printf("%-11s %6d %10.3f %10.3f %10.4f %10.4f %9.3f\n", tech_name(rows[i].tech), rows[i].count,
               rows[i].e.mean_rel, rows[i].e.max_rel, rows[i].e.mean_norm, rows[i].e.max_norm, rows[i].seconds);
    status = 0;
    if (csv) {
        put_csv(csv_out.f, rows, nrows);
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
            put_csv(f, rows, nrows);
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
    gmem_free(lights);
    gprobe_destroy(p);
    return status;
}
