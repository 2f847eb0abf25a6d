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

/* getopt_long codes of report's own long options. */
enum { OPT_SIZE = PLAN_OPT_OWN, OPT_SCALE, OPT_TITLE };

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

/* The command line of report. */
typedef struct ReportArgs {
    ProbeArgs probe;
    EvalPlan plan;
    const char *dir, *title; /* -o, --title */
    int size;                /* --size H: image height */
    double scale_pct;        /* --error-scale */
} ReportArgs;

/* Handles one of report's own options: 0, or -1 on a usage error (message printed). */
static int report_option(ReportArgs *a, int c, const char *v)
{
    if (c == 'o') {
        a->dir = v;
    } else if (c == OPT_SIZE) {
        return cli_int("gprobe", "--size", v, 4, 1024, &a->size);
    } else if (c == OPT_SCALE) {
        char *end;
        a->scale_pct = strtod(v, &end);
        if (end == v || *end || !(a->scale_pct > 0.0 && a->scale_pct <= 1e6)) {
            fprintf(stderr, "gprobe report: --error-scale expects a percentage above 0, got '%s'\n", v);
            return -1;
        }
    } else if (c == OPT_TITLE) {
        a->title = v;
    } else {
        return -1;
    }
    return 0;
}

/* Reads the command line into a: -1 to go on, else the exit status to end with. */
static int report_args(int argc, char **argv, ReportArgs *a)
{
    static const int counts[] = {8, 16, 32};
    static const struct option longopts[] = {
        CLI_COMMON_OPTIONS, PROBE_ARGS_OPTIONS, EVAL_PLAN_OPTIONS,
        {"output", required_argument, NULL, 'o'}, {"size", required_argument, NULL, OPT_SIZE},
        {"error-scale", required_argument, NULL, OPT_SCALE}, {"title", required_argument, NULL, OPT_TITLE},
        {NULL, 0, NULL, 0},
    };
    memset(a, 0, sizeof *a);
    eval_plan_init(&a->plan, counts, (int)(sizeof counts / sizeof *counts));
    a->size = 64;
    a->scale_pct = 25.0;
    CliParser cp;
    cli_begin(&cp, "gprobe report", argc, argv, "hqo:", longopts);
    int c, status = CLI_OK;
    while ((c = probe_next_option(&cp, &a->probe, report_usage, &status)) != -1) {
        if (c == CLI_EXIT)
            return status;
        int r = eval_plan_option(&a->plan, c, optarg);
        if (r < 0 || (r == 0 && report_option(a, c, optarg) != 0))
            return CLI_USAGE;
    }
    if (no_operands(&cp))
        return CLI_USAGE;
    if (!a->dir) {
        fprintf(stderr, "gprobe report: -o DIR is required (gprobe report --help)\n");
        return CLI_USAGE;
    }
    return -1;
}

/* DIR and DIR/images, made when missing, and a writer for the PNG images: 0, or -1 with a message. */
static int make_dirs(const char *dir)
{
    char sub[4096];
    snprintf(sub, sizeof sub, "%s/images", dir);
    if (make_dir(dir) != 0 || make_dir(sub) != 0)
        return -1;
    snprintf(sub, sizeof sub, "%s/images/error-scale.png", dir);
    return output_check(sub, 1);
}

/* One run of the report: the page's images, the ground truth at the normals, and a row per technique and size. */
typedef struct Report {
    const ReportArgs *args;
    const GProbe *probe;
    Page page;
    GProbe *grid; /* a black probe of the page's size: its pixels' directions */
    Truth truth;
    double *rad;  /* scratch: a radiance image */
    Entry *entries;
    int n;
} Report;

/* The page's pixel directions and the true irradiance at them and at the normals: 0, or -1 with a message. */
static int report_start(Report *r)
{
    Page *pg = &r->page;
    const size_t npix = (size_t)pg->w * pg->h;
    int oom = truth_alloc(&r->truth, r->args->plan.normals) != 0;
    r->rad = gmem_calloc(npix * 3, sizeof(double));
    r->entries = gmem_calloc((size_t)eval_plan_max_rows(&r->args->plan), sizeof *r->entries);
    pg->dirs = gmem_calloc(npix, sizeof *pg->dirs);
    pg->truth = gmem_calloc(npix * 3, sizeof(double));
    pg->approx = gmem_calloc(npix * 3, sizeof(double));
    if (oom || !r->rad || !r->entries || !pg->dirs || !pg->truth || !pg->approx) {
        fprintf(stderr, "gprobe: out of memory\n");
        return -1;
    }
    GError err;
    if (gprobe_create(pg->w, pg->h, NULL, &r->grid, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        return -1;
    }
    for (int v = 0; v < pg->h; v++)
        for (int u = 0; u < pg->w; u++)
            pg->dirs[(size_t)v * pg->w + u] = gprobe_direction(r->grid, u + 0.5, v + 0.5);
    if (truth_compute(&r->truth, r->probe, &err) != G_OK ||
        gprobe_irradiance(r->probe, pg->dirs, (int)npix, pg->truth, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        return -1;
    }
    return 0;
}

/* The reference row (the probe, 4 x 4 samples a pixel, and its irradiance), the exposures they set, and the
 * error ramp's bar: 0, or -1 with a message. */
static int write_reference(Report *r)
{
    Page *pg = &r->page;
    double lum_sum = 0.0, omega_sum = 0.0, emax = 0.0;
    for (int v = 0; v < pg->h; v++)
        for (int u = 0; u < pg->w; u++) {
            double *o = r->rad + 3 * ((size_t)v * pg->w + u);
            for (int s = 0; s < 16; s++) {
                float c[3];
                gprobe_radiance(r->probe, gprobe_direction(r->grid, u + (s % 4 + 0.5) / 4.0, v + (s / 4 + 0.5) / 4.0),
                                c);
                for (int k = 0; k < 3; k++)
                    o[k] += c[k] / 16.0;
            }
            double omega = sin(M_PI * (v + 0.5) / pg->h);
            lum_sum += luminance(o) * omega;
            omega_sum += omega;
        }
    for (size_t i = 0; i < (size_t)pg->w * pg->h; i++)
        emax = fmax(emax, luminance(pg->truth + 3 * i));
    pg->kr = lum_sum > 0.0 ? 0.18 * omega_sum / lum_sum : 1.0;
    pg->ke = emax > 0.0 ? 0.8 / emax : 1.0;
    if (write_scaled(pg, "reference-radiance.png", r->rad, pg->kr) ||
        write_scaled(pg, "reference-irradiance.png", pg->truth, pg->ke))
        return -1;
    GImage bar;
    GError err;
    if (gimage_create(&bar, 256, 16, 3, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        return -1;
    }
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 256; x++)
            ramp_colour((x + 0.5) / 256.0, bar.pixels + 3 * (y * 256 + x));
    int rc = write_image(pg, "error-scale.png", &bar);
    gimage_free(&bar);
    return rc;
}

/* One technique and size: its radiance, irradiance and error images, and its entry. */
static int report_row(void *user, const Row *row, const Approx *a)
{
    Report *r = user;
    Page *pg = &r->page;
    Entry *e = &r->entries[r->n];
    const char *mn = method_get(row->method)->name;
    char name[160];
    int rc = 0;
    e->row = *row;
    approx_irradiance(a, pg->dirs, pg->w * pg->h, pg->approx);
    approx_radiance(pg, r->probe, a, r->rad);
    snprintf(name, sizeof name, "%s-%d-radiance.png", mn, row->count);
    rc |= write_scaled(pg, name, r->rad, pg->kr);
    snprintf(name, sizeof name, "%s-%d-irradiance.png", mn, row->count);
    rc |= write_scaled(pg, name, pg->approx, pg->ke);
    snprintf(name, sizeof name, "%s-%d-error.png", mn, row->count);
    rc |= write_error_map(pg, name, &e->worst);
    if (rc == 0)
        r->n++;
    return rc;
}

/* DIR/errors.csv, the plot (when gnuplot is there) and the pages: 0, or -1 with a message. */
static int report_finish(const Report *r, int have_gnuplot)
{
    const ReportArgs *a = r->args;
    Row *rows = gmem_calloc((size_t)r->n + 1, sizeof *rows);
    if (!rows) {
        fprintf(stderr, "gprobe: out of memory\n");
        return -1;
    }
    for (int i = 0; i < r->n; i++)
        rows[i] = r->entries[i].row;
    char path[4096];
    snprintf(path, sizeof path, "%s/errors.csv", a->dir);
    TextOut csv;
    int ok = text_open(&csv, path) == 0;
    if (ok) {
        rows_csv(csv.f, rows, r->n);
        ok = text_close(&csv, 1) == 0;
    }
    gmem_free(rows);
    if (!ok)
        return -1;
    const char *base = strrchr(a->probe.path, '/');
    const char *shown = a->title ? a->title : base ? base + 1 : a->probe.path;
    if (have_gnuplot) {
        char png[4096];
        snprintf(png, sizeof png, "%s/fig6.png", a->dir);
        if (plot_errors(path, png, shown) != 0)
            return -1;
    }
    return write_pages(&r->page, shown, a->probe.path, gprobe_width(r->probe), gprobe_height(r->probe), r->entries,
                       r->n, have_gnuplot, a->plan.normals);
}

int cmd_report(int argc, char **argv)
{
    ReportArgs a;
    int status = report_args(argc, argv, &a);
    if (status >= 0)
        return status;
    if (make_dirs(a.dir) != 0)
        return 1;
    int have_gnuplot = plot_check_gnuplot() == 0;
    if (!have_gnuplot)
        fprintf(stderr, "gprobe report: the page will have no plot\n");
    GProbe *p = probe_args_load(&a.probe);
    if (!p)
        return 1;
    Report r = {.args = &a, .probe = p, .page = {a.dir, 2 * a.size, a.size, NULL, NULL, NULL, 0.0, 0.0,
                                                 a.scale_pct / 100.0}};
    if (report_start(&r) == 0 && write_reference(&r) == 0 &&
        eval_plan_run(&a.plan, p, &r.truth, a.probe.quiet, report_row, &r) == 0 &&
        report_finish(&r, have_gnuplot) == 0) {
        if (!a.probe.quiet)
            fprintf(stderr, "gprobe: %s/index.html: %d rows\n", a.dir, r.n);
        status = 0;
    } else {
        status = 1;
    }
    gprobe_destroy(r.grid);
    truth_free(&r.truth);
    gmem_free(r.rad);
    gmem_free(r.entries);
    gmem_free(r.page.dirs);
    gmem_free(r.page.truth);
    gmem_free(r.page.approx);
    gprobe_destroy(p);
    return status;
}
