/* plot.c - the Fig. 6 plot of `gprobe eval`: error against the number of lights, drawn by gnuplot. */
#include "gprobe.h"
#include "../common/gnuplot.h"

#include <generic/services/file.h>
#include <generic/services/image.h>
#include <generic/memory.h>

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

int plot_check_gnuplot(void)
{
    if (gnuplot_found())
        return 0;
    fprintf(stderr, "gprobe: --plot needs gnuplot, which is not installed (Debian: apt-get install gnuplot-nox)\n");
    return -1;
}

/* Most series a plot draws (one per method). */
#define MAX_SERIES 16

typedef struct Series {
    char name[32];
    int method; /* index in methods.c's list: it picks the colour */
    int n;
    double x[64], y[64][4];
} Series;

static int read_csv(const char *csv, Series *series, int *nseries, double sh9[4], int *have_sh9)
{
    GError err;
    int fd = gfile_open_input(csv, &err);
    FILE *f = fd >= 0 ? fdopen(fd, "r") : NULL;
    if (!f) {
        if (fd >= 0) {
            close(fd);
            fprintf(stderr, "gprobe: cannot read %s: %s\n", csv, strerror(errno));
        } else {
            fprintf(stderr, "gprobe: %s\n", err.message);
        }
        return -1;
    }
    char line[512];
    *nseries = 0;
    *have_sh9 = 0;
    while (fgets(line, sizeof line, f)) {
        char name[32], unit[32];
        int count;
        double v[6];
        if (sscanf(line, "%31[^,],%d,%31[^,],%lf,%lf,%lf,%lf,%lf,%lf", name, &count, unit, &v[0], &v[1], &v[2], &v[3],
                   &v[4], &v[5]) != 9)
            continue; /* the header */
        if (strcmp(name, "sh9") == 0) {
            memcpy(sh9, v, 4 * sizeof(double));
            *have_sh9 = 1;
            continue;
        }
        int k = 0;
        while (k < *nseries && strcmp(series[k].name, name) != 0)
            k++;
        if (k == *nseries) {
            if (k == MAX_SERIES || method_find(name) < 0)
                continue;
            snprintf(series[k].name, sizeof series[k].name, "%s", name);
            series[k].method = method_find(name);
            series[k].n = 0;
            (*nseries)++;
        }
        Series *s = &series[k];
        if (s->n < 64) {
            s->x[s->n] = count;
            memcpy(s->y[s->n], v, 4 * sizeof(double));
            s->n++;
        }
    }
    fclose(f);
    return 0;
}

/* One colour per method of methods.c's list, whatever methods the CSV has. */
static const char *const colours[MAX_SERIES] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b",
                                                "#e377c2", "#17becf", "#bcbd22", "#7f7f7f", "#393b79", "#e7969c",
                                                "#000000", "#637939", "#843c39", "#3182bd"};

/* The figure: 1500 x 760 pixels, Sans 11 (pngcairo: a line 17 pixels high, the legend sized by characters 9
 * pixels wide). */
enum { FIG_W = 1500, FIG_H = 760, FIG_FONT = 11 };
#define FIG_LINE (1.55 * FIG_FONT)
#define FIG_CHAR (0.82 * FIG_FONT)

/* The data blocks, one per series: N, then mean and max of each measure. */
static void write_series(FILE *g, const Series *series, int ns)
{
    for (int k = 0; k < ns; k++) {
        fprintf(g, "$s%d << EOD\n", k);
        for (int i = 0; i < series[k].n; i++)
            fprintf(g, "%g %g %g %g %g\n", series[k].x[i], series[k].y[i][0], series[k].y[i][1], series[k].y[i][2],
                    series[k].y[i][3]);
        fprintf(g, "EOD\n");
    }
}

/* The layout, in screen fractions: the title on top, the two panels side by side, under them the legend across
 * the figure (as many columns as fit, the rows it takes), so that it covers neither axis label. */
typedef struct Layout {
    int cols, rows;
    double key_top;      /* the legend's area is [0, key_top] */
    double panel_bottom; /* above the legend: room for the tic labels and the x label */
} Layout;

static Layout layout_of(int entries, int longest)
{
    Layout t;
    t.cols = (int)((FIG_W - 4 * FIG_CHAR) / ((longest + 10) * FIG_CHAR)); /* text, sample, gaps */
    t.cols = t.cols < 1 ? 1 : t.cols > entries ? entries : t.cols;
    t.rows = (entries + t.cols - 1) / t.cols;
    t.key_top = (t.rows + 1.0) * FIG_LINE / FIG_H;
    t.panel_bottom = t.key_top + 3.0 * FIG_LINE / FIG_H;
    return t;
}

/* The logarithmic axes: N at powers of two from xmin to xmax, the error in percent. */
static void write_axes(FILE *g, double xmin, double xmax)
{
    fprintf(g, "set logscale xy\nset grid xtics ytics mytics\nset xrange [%g:%g]\nset xtics (", xmin / 1.25,
            xmax * 1.25);
    for (double x = 1; x <= xmax * 1.01; x *= 2)
        if (x >= xmin * 0.99)
            fprintf(g, "%s%g", x > xmin * 1.01 ? "," : "", x);
    fprintf(g, ")\nset xlabel 'N: lights, coefficients or lobes (solid: mean, dashed: max)'\n"
               "set ylabel 'irradiance error (%%)'\nunset key\n");
}

/* Panel 0 (relative to the true irradiance, on the left) or 1 (normalised by the largest, on the right). */
static void write_panel(FILE *g, const Layout *t, int panel, const Series *series, int ns, const double sh9[4],
                        int have_sh9)
{
    fprintf(g, "set lmargin at screen %.2f\nset rmargin at screen %.2f\nset bmargin at screen %.4f\n"
               "set tmargin at screen 0.9\n",
            panel == 0 ? 0.06 : 0.56, panel == 0 ? 0.48 : 0.98, t->panel_bottom);
    fprintf(g, "set title '%s'\nplot ", panel == 0 ? "relative to the true irradiance (the paper''s Fig. 6 measure)"
                                                   : "normalised by the largest irradiance");
    int first = 1;
    for (int k = 0; k < ns; k++) {
        const char *c = colours[series[k].method % MAX_SERIES];
        fprintf(g, "%s$s%d using 1:%d with linespoints lw 2 pt 7 lc rgb '%s' notitle, "
                   "$s%d using 1:%d with linespoints lw 2 dt 2 pt 6 lc rgb '%s' notitle",
                first ? "" : ", ", k, 2 + 2 * panel, c, k, 3 + 2 * panel, c);
        first = 0;
    }
    if (have_sh9) {
        double mean = sh9[2 * panel], max = sh9[2 * panel + 1];
        if (mean > 0.0)
            fprintf(g, "%s%g with lines lw 2 lc rgb 'gray40' notitle, %g with lines lw 2 dt 2 lc rgb 'gray40' notitle",
                    first ? "" : ", ", mean, max);
    }
    fputc('\n', g);
}

/* The legend of both panels: a plot of nothing across the bottom of the figure whose only mark is its key. */
static void write_legend(FILE *g, const Layout *t, const Series *series, int ns, int have_sh9)
{
    fprintf(g, "unset title\nunset xlabel\nunset ylabel\nunset logscale\nunset grid\nunset border\nunset tics\n"
               "set xrange [0:1]\nset yrange [0:1]\n"
               "set lmargin at screen 0.02\nset rmargin at screen 0.98\nset bmargin at screen 0\n"
               "set tmargin at screen %.4f\n"
               "set key inside center center horizontal maxcols %d maxrows %d box\nplot ",
            t->key_top, t->cols, t->rows);
    for (int k = 0; k < ns; k++)
        fprintf(g, "%sNaN with linespoints lw 2 pt 7 lc rgb '%s' title '%s'", k ? ", " : "",
                colours[series[k].method % MAX_SERIES], series[k].name);
    if (have_sh9)
        fprintf(g, "%sNaN with lines lw 2 lc rgb 'gray40' title 'sh9 (9 coefficients)'", ns ? ", " : "");
    fputc('\n', g);
}

/* Ends gnuplot's run: its picture (the temporary of out) must decode whole, a full disk would have cut it short;
 * then it is renamed into place. 0, or -1 with a message. */
static int finish(FILE *g, GFileOutput *out, const char *png)
{
    int st = pclose(g);
    int ok = st != -1 && WIFEXITED(st) && WEXITSTATUS(st) == 0;
    GError err;
    GImage check = {0};
    if (ok && gimage_read(out->temp, GIMAGE_READ_RGB, &check, &err) != G_OK) {
        fprintf(stderr, "gprobe: gnuplot's picture %s is not readable: %s\n", png, err.message);
        ok = 0;
    }
    gimage_free(&check);
    if (!ok) {
        fprintf(stderr, "gprobe: gnuplot failed to draw %s\n", png);
        gfile_output_abort(out);
        return -1;
    }
    if (gfile_output_commit(out, -1, png, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        return -1;
    }
    return 0;
}

int plot_errors(const char *csv, const char *png, const char *title)
{
    static Series series[MAX_SERIES];
    int ns, have_sh9;
    double sh9[4];
    if (read_csv(csv, series, &ns, sh9, &have_sh9) != 0)
        return -1;
    if (ns == 0 && !have_sh9) {
        fprintf(stderr, "gprobe: nothing to plot\n");
        return -1;
    }
    double xmin = 1e9, xmax = 0.0;
    int longest = have_sh9 ? (int)strlen("sh9 (9 coefficients)") : 0;
    for (int k = 0; k < ns; k++) {
        for (int i = 0; i < series[k].n; i++) {
            xmin = series[k].x[i] < xmin ? series[k].x[i] : xmin;
            xmax = series[k].x[i] > xmax ? series[k].x[i] : xmax;
        }
        longest = (int)strlen(series[k].name) > longest ? (int)strlen(series[k].name) : longest;
    }
    if (xmax <= 0.0)
        xmin = 1.0, xmax = 128.0;

    GFileOutput out; /* gnuplot writes the temporary by name; finish() checks and renames it */
    GError err;
    if (gfile_output_begin(&out, png, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        return -1;
    }
    FILE *g = popen("gnuplot", "w");
    if (!g) {
        fprintf(stderr, "gprobe: cannot run gnuplot: %s\n", strerror(errno));
        gfile_output_abort(&out);
        return -1;
    }
    const Layout t = layout_of(ns + have_sh9, longest);
    gnuplot_begin_png(g, FIG_W, FIG_H, FIG_FONT, out.temp);
    write_series(g, series, ns);
    fprintf(g, "set multiplot title ");
    gnuplot_put_quoted(g, title);
    fprintf(g, " font 'Sans,13'\n");
    write_axes(g, xmin, xmax);
    for (int panel = 0; panel < 2; panel++)
        write_panel(g, &t, panel, series, ns, sh9, have_sh9);
    write_legend(g, &t, series, ns, have_sh9);
    fprintf(g, "unset multiplot\nset output\n");
    return finish(g, &out, png);
}
