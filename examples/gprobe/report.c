/* report.c - `gprobe report`: one HTML page (and a markdown table) per probe with, for every technique and
 * size, the reconstructed radiance, the irradiance map and a false-colour map of the irradiance error, as
 * lat-long PNG images (OpenImageIO), beside the error figures and the Fig. 6 plot (gnuplot).
 *
 * Images: H x 2H lat-long (--size H). The reference row shows the probe (each pixel the mean of 4 x 4 samples)
 * and its ground-truth irradiance (every probe pixel summed, for the normal of each image pixel). A light
 * technique's radiance shows each light's power in the pixel it falls in; a basis shows its own radiance
 * (negative values, SH's ringing, are black). All radiance images share one exposure (the probe's mean
 * luminance maps to 0.18) and all irradiance maps another (the largest true irradiance maps to 0.8). The
 * error map is |E' - E| / E per pixel (averaged over R, G, B) in a five-colour ramp from 0 to the page's
 * --error-scale, drawn beside it as a bar; larger errors saturate. */
#include "gprobe.h"

#include <generic/services/image.h>
#include <generic/memory.h>

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static void report_usage(FILE *f)
{
    fprintf(f,
            "usage: gprobe report --probe FILE -o DIR [--counts LIST] [--techniques LIST] [--size H]\n"
            "                     [--normals M] [--fit-normals N] [--error-scale PCT] [--title TEXT]\n"
            "Writes DIR/index.html, a page with every technique's reconstructed radiance, irradiance map and\n"
            "false-colour irradiance error map (lat-long PNGs in DIR/images/), the error figures and the Fig. 6\n"
            "plot (DIR/fig6.png, needs gnuplot), and the same figures as DIR/report.md and DIR/errors.csv.\n"
            "%s"
            "  -o DIR            output directory (made when missing)\n"
            "  --counts LIST     light and lobe counts (default 8,16,32); SH always at 4, 9, 16, 25\n"
            "  --techniques LIST comma separated from %s (default: all but sh9)\n"
            "  --size H          image height in pixels, the width is 2 H (default 64)\n"
            "  --normals M       normals for the error figures (default 20000)\n"
            "  --fit-normals N   normals the irradiance optimisation fits (default 2000)\n"
            "  --error-scale PCT relative error at the top of the error maps' colour ramp (default 25)\n"
            "  --title TEXT      page title (default: the probe's file name)\n"
            "Every option value may also be written --option=value.\n" CLI_EXIT_STATUS_HELP,
            probe_args_help, methods_names);
}

/* The error ramp's colours (sRGB display values), from no error to the scale's top. */
static const double ramp[5][3] = {{0.05, 0.05, 0.35}, {0.0, 0.45, 0.95}, {0.2, 0.8, 0.3}, {1.0, 0.85, 0.0},
                                  {0.85, 0.05, 0.05}};

static double srgb_to_linear(double c) { return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4); }

static void ramp_colour(double t, float out[3])
{
    t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
    double x = t * 4.0;
    int i = x >= 4.0 ? 3 : (int)x;
    double f = x - i;
    for (int c = 0; c < 3; c++) /* written linear: the PNG writer encodes to sRGB */
        out[c] = (float)srgb_to_linear(ramp[i][c] + f * (ramp[i + 1][c] - ramp[i][c]));
}

typedef struct Page {
    const char *dir;
    int w, h;
    GVec3 *dirs;      /* w * h pixel directions */
    double *truth;    /* true irradiance per pixel */
    double *approx;   /* scratch: approximate irradiance per pixel */
    double kr, ke;    /* exposures of radiance and irradiance */
    double scale;     /* error at the ramp's top, as a fraction */
} Page;

static int write_image(const Page *pg, const char *name, GImage *img)
{
    char path[4096];
    GError err;
    snprintf(path, sizeof path, "%s/images/%s", pg->dir, name);
    if (gimage_write(path, img, NULL, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        return -1;
    }
    return 0;
}

/* Writes an image whose pixel i is rgb[3 i] * k (doubles). */
static int write_scaled(const Page *pg, const char *name, const double *rgb, double k)
{
    GImage img;
    GError err;
    if (gimage_create(&img, pg->w, pg->h, 3, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        return -1;
    }
    for (size_t i = 0; i < (size_t)pg->w * pg->h * 3; i++)
        img.pixels[i] = (float)fmax(0.0, rgb[i] * k);
    int rc = write_image(pg, name, &img);
    gimage_free(&img);
    return rc;
}

/* The error map of pg->approx against pg->truth; *worst gets the largest relative error. */
static int write_error_map(const Page *pg, const char *name, double *worst)
{
    GImage img;
    GError err;
    if (gimage_create(&img, pg->w, pg->h, 3, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        return -1;
    }
    double emax = 0.0;
    for (size_t i = 0; i < (size_t)pg->w * pg->h * 3; i++)
        emax = fmax(emax, pg->truth[i]);
    *worst = 0.0;
    for (size_t i = 0; i < (size_t)pg->w * pg->h; i++) {
        double r = 0.0;
        for (int c = 0; c < 3; c++) {
            double t = pg->truth[3 * i + c], d = fabs(pg->approx[3 * i + c] - t);
            r += (t > 1e-6 * emax && t > 0.0 ? d / t : 0.0) / 3.0;
        }
        *worst = fmax(*worst, r);
        ramp_colour(r / pg->scale, img.pixels + 3 * i);
    }
    int rc = write_image(pg, name, &img);
    gimage_free(&img);
    return rc;
}

static double luminance(const double *c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }

/* Radiance image of an approximation: a basis's radiance, or each light's power in its pixel. */
static void approx_radiance(const Page *pg, const GProbe *probe, const Approx *a, double *rgb)
{
    memset(rgb, 0, sizeof(double) * 3 * pg->w * pg->h);
    if (!a->lights) {
        for (int i = 0; i < pg->w * pg->h; i++)
            gprobe_basis_radiance(&a->basis, pg->dirs[i], rgb + 3 * i);
        return;
    }
    GProbe *grid = NULL; /* a black probe of the report's size maps directions to its pixels */
    if (gprobe_create(pg->w, pg->h, NULL, &grid, NULL) != G_OK)
        return;
    (void)probe;
    for (int k = 0; k < a->n; k++) {
        double x, y;
        gprobe_position(grid, a->lights[k].dir, &x, &y);
        int u = (int)x, v = (int)y;
        u = u < 0 ? 0 : u >= pg->w ? pg->w - 1 : u;
        v = v < 0 ? 0 : v >= pg->h ? pg->h - 1 : v;
        double omega = 2.0 * M_PI / pg->w * (cos(M_PI * v / pg->h) - cos(M_PI * (v + 1) / pg->h));
        for (int c = 0; c < 3; c++)
            rgb[3 * ((size_t)v * pg->w + u) + c] += a->lights[k].rgb[c] / omega;
    }
    gprobe_destroy(grid);
}

static int make_dir(const char *path)
{
    if (mkdir(path, 0777) == 0 || errno == EEXIST) {
        struct stat st;
        if (stat(path, &st) == 0 && S_ISDIR(st.st_mode))
            return 0;
        fprintf(stderr, "gprobe report: %s exists and is not a directory\n", path);
        return -1;
    }
    fprintf(stderr, "gprobe report: cannot make the directory %s: %s\n", path, strerror(errno));
    return -1;
}

static void html_escape(FILE *f, const char *s)
{
    for (; *s; s++) {
        if (*s == '<')
            fputs("&lt;", f);
        else if (*s == '>')
            fputs("&gt;", f);
        else if (*s == '&')
            fputs("&amp;", f);
        else if (*s == '"')
            fputs("&quot;", f);
        else
            fputc(*s, f);
    }
}

typedef struct Entry {
    Row row;
    double worst; /* largest relative error of the error map */
} Entry;

static int write_pages(const Page *pg, const char *title, const char *probe_path, int pw, int ph, const Entry *e,
                       int n, int have_plot, int m)
{
    char path[4096];
    TextOut t;
    snprintf(path, sizeof path, "%s/index.html", pg->dir);
    if (text_open(&t, path) != 0)
        return -1;
    FILE *f = t.f;
    fprintf(f, "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>");
    html_escape(f, title);
    fprintf(f, "</title>\n<style>body{font-family:sans-serif;margin:1em}table{border-collapse:collapse}"
               "td,th{border:1px solid #ccc;padding:4px;text-align:right;vertical-align:middle}"
               "img{image-rendering:pixelated}</style></head><body>\n<h1>");
    html_escape(f, title);
    fprintf(f, "</h1>\n<p>Probe <code>");
    html_escape(f, probe_path);
    fprintf(f, "</code> (%dx%d). Errors in percent at %d normals (mean and max of |E'-E|/E, mean of |E'-E|/max E, "
               "sMAPE), averaged over R, G, B. Images %dx%d lat-long (row 0 the zenith); radiance and irradiance "
               "each share one exposure; light techniques show each light's power in its pixel.</p>\n",
            pw, ph, m, pg->w, pg->h);
    if (have_plot)
        fprintf(f, "<p><img src=\"fig6.png\" alt=\"error against N\" style=\"max-width:100%%\"></p>\n");
    fprintf(f, "<p>Error maps: |E'-E|/E from 0 <img src=\"images/error-scale.png\" alt=\"colour ramp\" "
               "width=\"256\" height=\"16\"> %.0f%% (and above).</p>\n",
            100.0 * pg->scale);
    fprintf(f, "<table>\n<tr><th>technique</th><th>N</th><th>mean rel</th><th>max rel</th><th>mean norm</th>"
               "<th>sMAPE</th><th>s</th><th>radiance</th><th>irradiance</th><th>error (largest)</th></tr>\n"
               "<tr><td>reference</td><td></td><td></td><td></td><td></td><td></td><td></td>"
               "<td><img src=\"images/reference-radiance.png\"></td><td><img src=\"images/reference-irradiance.png\">"
               "</td><td></td></tr>\n");
    for (int i = 0; i < n; i++) {
        const Method *me = method_get(e[i].row.method);
        const GProbeErrors *x = &e[i].row.e;
        fprintf(f, "<tr><td>%s</td><td>%d %s</td><td>%.3f</td><td>%.3f</td><td>%.4f</td><td>%.3f</td><td>%.3f</td>",
                me->name, e[i].row.count, me->unit, x->mean_rel, x->max_rel, x->mean_norm, x->smape, e[i].row.seconds);
        fprintf(f, "<td><img src=\"images/%s-%d-radiance.png\"></td><td><img src=\"images/%s-%d-irradiance.png\"></td>"
                   "<td><img src=\"images/%s-%d-error.png\"><br>%.1f%%</td></tr>\n",
                me->name, e[i].row.count, me->name, e[i].row.count, me->name, e[i].row.count, 100.0 * e[i].worst);
    }
    fprintf(f, "</table>\n</body></html>\n");
    if (text_close(&t, 1) != 0)
        return -1;

    snprintf(path, sizeof path, "%s/report.md", pg->dir);
    if (text_open(&t, path) != 0)
        return -1;
    f = t.f;
    fprintf(f, "| technique | N | mean rel %% | max rel %% | mean norm %% | sMAPE %% | seconds |\n"
               "|---|---|---:|---:|---:|---:|---:|\n");
    for (int i = 0; i < n; i++) {
        const Method *me = method_get(e[i].row.method);
        const GProbeErrors *x = &e[i].row.e;
        fprintf(f, "| %s | %d %s | %.3f | %.3f | %.4f | %.3f | %.3f |\n", me->name, e[i].row.count, me->unit,
                x->mean_rel, x->max_rel, x->mean_norm, x->smape, e[i].row.seconds);
    }
    return text_close(&t, 1);
}

int cmd_report(int argc, char **argv)
{
    ProbeArgs pa = {0};
    const char *dir = NULL, *title = NULL;
    int counts[64] = {8, 16, 32}, ncounts = 3, size = 64, m = 20000, fit = 0, use[64];
    double scale_pct = 25.0;
    methods_default(use);
    enum { OPT_OUTPUT = PROBE_OPT_OWN, OPT_COUNTS, OPT_TECHNIQUES, OPT_SIZE, OPT_NORMALS, OPT_FIT, OPT_SCALE,
           OPT_TITLE };
    static const struct option longopts[] = {
        CLI_COMMON_OPTIONS, PROBE_ARGS_OPTIONS,
        {"output", required_argument, NULL, 'o'}, {"counts", required_argument, NULL, OPT_COUNTS},
        {"techniques", required_argument, NULL, OPT_TECHNIQUES}, {"size", required_argument, NULL, OPT_SIZE},
        {"normals", required_argument, NULL, OPT_NORMALS}, {"fit-normals", required_argument, NULL, OPT_FIT},
        {"error-scale", required_argument, NULL, OPT_SCALE}, {"title", required_argument, NULL, OPT_TITLE},
        {NULL, 0, NULL, 0},
    };
    CliParser cp;
    cli_begin(&cp, "gprobe report", argc, argv, "hqo:", longopts);
    int c;
    while ((c = cli_next(&cp)) != -1) {
        const char *v = optarg;
        int r = probe_args_option(&pa, c, v);
        if (r < 0)
            return CLI_USAGE;
        if (r > 0)
            continue;
        if (c == 'h') {
            report_usage(stdout);
            return CLI_OK;
        } else if (c == CLI_VERSION) {
            return cli_version("gprobe");
        } else if (c == 'o') {
            dir = v;
        } else if (c == OPT_COUNTS) {
            if ((ncounts = parse_count_list(v, counts, 64)) < 0)
                return CLI_USAGE;
        } else if (c == OPT_TECHNIQUES) {
            if (parse_method_list(v, use) != 0)
                return CLI_USAGE;
        } else if (c == OPT_SIZE) {
            if (parse_int("--size", v, 4, 1024, &size) != 0)
                return CLI_USAGE;
        } else if (c == OPT_NORMALS) {
            if (parse_int("--normals", v, 1, 10000000, &m) != 0)
                return CLI_USAGE;
        } else if (c == OPT_FIT) {
            if (parse_int("--fit-normals", v, 2, 1000000, &fit) != 0)
                return CLI_USAGE;
        } else if (c == OPT_SCALE) {
            char *end;
            scale_pct = strtod(v, &end);
            if (end == v || *end || !(scale_pct > 0.0 && scale_pct <= 1e6)) {
                fprintf(stderr, "gprobe report: --error-scale expects a percentage above 0, got '%s'\n", v);
                return CLI_USAGE;
            }
        } else if (c == OPT_TITLE) {
            title = v;
        } else {
            return CLI_USAGE;
        }
    }
    if (no_operands(&cp))
        return CLI_USAGE;
    if (!dir) {
        fprintf(stderr, "gprobe report: -o DIR is required (gprobe report --help)\n");
        return 2;
    }
    char sub[4096];
    snprintf(sub, sizeof sub, "%s/images", dir);
    if (make_dir(dir) != 0 || make_dir(sub) != 0)
        return 1;
    snprintf(sub, sizeof sub, "%s/images/error-scale.png", dir);
    if (output_check(sub, 1) != 0)
        return 1;
    int have_gnuplot = plot_check_gnuplot() == 0;
    if (!have_gnuplot)
        fprintf(stderr, "gprobe report: the page will have no plot\n");
    GProbe *p = probe_args_load(&pa);
    if (!p)
        return 1;

    Page pg = {dir, 2 * size, size, NULL, NULL, NULL, 0.0, 0.0, scale_pct / 100.0};
    const size_t npix = (size_t)pg.w * pg.h;
    int status = 1, nent = 0;
    GVec3 *normals = gmem_calloc((size_t)m, sizeof *normals);
    double *truth = gmem_calloc((size_t)m * 3, sizeof(double)), *approx = gmem_calloc((size_t)m * 3, sizeof(double));
    double *rad = gmem_calloc(npix * 3, sizeof(double));
    Entry *ent = gmem_calloc((size_t)method_count() * (ncounts + GPROBE_SH_MAX_ORDER), sizeof *ent);
    pg.dirs = gmem_calloc(npix, sizeof *pg.dirs);
    pg.truth = gmem_calloc(npix * 3, sizeof(double));
    pg.approx = gmem_calloc(npix * 3, sizeof(double));
    GProbe *grid = NULL;
    GError err;
    if (!normals || !truth || !approx || !rad || !ent || !pg.dirs || !pg.truth || !pg.approx) {
        fprintf(stderr, "gprobe: out of memory\n");
        goto done;
    }
    if (gprobe_create(pg.w, pg.h, NULL, &grid, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        goto done;
    }
    for (int v2 = 0; v2 < pg.h; v2++)
        for (int u = 0; u < pg.w; u++)
            pg.dirs[(size_t)v2 * pg.w + u] = gprobe_direction(grid, u + 0.5, v2 + 0.5);
    gprobe_fibonacci(m, normals);
    if (gprobe_irradiance(p, normals, m, truth, &err) != G_OK || gprobe_irradiance(p, pg.dirs, (int)npix, pg.truth, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        goto done;
    }
    /* the reference: the probe (4 x 4 samples a pixel) and its irradiance; the exposures */
    double lum_sum = 0.0, omega_sum = 0.0, emax = 0.0;
    for (int v2 = 0; v2 < pg.h; v2++)
        for (int u = 0; u < pg.w; u++) {
            double *o = rad + 3 * ((size_t)v2 * pg.w + u);
            for (int s = 0; s < 16; s++) {
                float c[3];
                gprobe_radiance(p, gprobe_direction(grid, u + (s % 4 + 0.5) / 4.0, v2 + (s / 4 + 0.5) / 4.0), c);
                for (int k = 0; k < 3; k++)
                    o[k] += c[k] / 16.0;
            }
            double omega = sin(M_PI * (v2 + 0.5) / pg.h);
            lum_sum += luminance(o) * omega;
            omega_sum += omega;
        }
    for (size_t i = 0; i < npix; i++)
        emax = fmax(emax, luminance(pg.truth + 3 * i));
    pg.kr = lum_sum > 0.0 ? 0.18 * omega_sum / lum_sum : 1.0;
    pg.ke = emax > 0.0 ? 0.8 / emax : 1.0;
    if (write_scaled(&pg, "reference-radiance.png", rad, pg.kr) || write_scaled(&pg, "reference-irradiance.png", pg.truth, pg.ke))
        goto done;
    GImage bar;
    if (gimage_create(&bar, 256, 16, 3, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        goto done;
    }
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 256; x++)
            ramp_colour((x + 0.5) / 256.0, bar.pixels + 3 * (y * 256 + x));
    int brc = write_image(&pg, "error-scale.png", &bar);
    gimage_free(&bar);
    if (brc)
        goto done;

    GProbeOptions opt = {0};
    opt.fit_normals = fit;
    if (!pa.quiet)
        opt.progress = progress_print;
    for (int t = 0; t < method_count(); t++) {
        if (!use[t])
            continue;
        int sizes[64 + GPROBE_SH_MAX_ORDER];
        int ns = method_sizes(t, counts, ncounts, fit, sizes, pa.quiet);
        for (int c = 0; c < ns; c++) {
            Approx a;
            Entry *e = &ent[nent];
            if (eval_one(p, t, sizes[c], &opt, normals, m, truth, approx, &e->row, &a, pa.quiet) != 0)
                goto done;
            char name[160];
            const char *mn = method_get(t)->name;
            approx_irradiance(&a, pg.dirs, (int)npix, pg.approx);
            approx_radiance(&pg, p, &a, rad);
            int rc = 0;
            snprintf(name, sizeof name, "%s-%d-radiance.png", mn, sizes[c]);
            rc |= write_scaled(&pg, name, rad, pg.kr);
            snprintf(name, sizeof name, "%s-%d-irradiance.png", mn, sizes[c]);
            rc |= write_scaled(&pg, name, pg.approx, pg.ke);
            snprintf(name, sizeof name, "%s-%d-error.png", mn, sizes[c]);
            rc |= write_error_map(&pg, name, &e->worst);
            approx_free(&a);
            if (rc)
                goto done;
            nent++;
        }
    }

    /* the CSV, the plot and the pages */
    Row *rows = gmem_calloc((size_t)nent + 1, sizeof *rows);
    if (!rows) {
        fprintf(stderr, "gprobe: out of memory\n");
        goto done;
    }
    for (int i = 0; i < nent; i++)
        rows[i] = ent[i].row;
    char path[4096];
    snprintf(path, sizeof path, "%s/errors.csv", dir);
    TextOut csv;
    int ok = text_open(&csv, path) == 0;
    if (ok) {
        rows_csv(csv.f, rows, nent);
        ok = text_close(&csv, 1) == 0;
    }
    gmem_free(rows);
    if (!ok)
        goto done;
    const char *base = strrchr(pa.path, '/');
    const char *shown = title ? title : base ? base + 1 : pa.path;
    int have_plot = 0;
    if (have_gnuplot) {
        char png[4096];
        snprintf(png, sizeof png, "%s/fig6.png", dir);
        if (plot_errors(path, png, shown) != 0)
            goto done;
        have_plot = 1;
    }
    if (write_pages(&pg, shown, pa.path, gprobe_width(p), gprobe_height(p), ent, nent, have_plot, m) != 0)
        goto done;
    if (!pa.quiet)
        fprintf(stderr, "gprobe: %s/index.html: %d rows\n", dir, nent);
    status = 0;
done:
    gprobe_destroy(grid);
    gmem_free(normals);
    gmem_free(truth);
    gmem_free(approx);
    gmem_free(rad);
    gmem_free(ent);
    gmem_free(pg.dirs);
    gmem_free(pg.truth);
    gmem_free(pg.approx);
    gprobe_destroy(p);
    return status;
}
