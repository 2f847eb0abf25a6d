/* plot.c - the Fig. 6 plot of `gprobe eval`: error against the number of lights, drawn by gnuplot. */
#include "gprobe.h"

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
    const char *path = getenv("PATH");
    char buf[4096];
    for (const char *p = path ? path : "/usr/bin:/bin"; *p;) {
        const char *e = strchr(p, ':');
        size_t n = e ? (size_t)(e - p) : strlen(p);
        snprintf(buf, sizeof buf, "%.*s/gnuplot", (int)n, n ? p : ".");
        if (access(buf, X_OK) == 0)
            return 0;
        p += n + (e ? 1 : 0);
    }
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

/* Writes s single-quoted for gnuplot ('' escapes a quote). */
static void put_quoted(FILE *f, const char *s)
{
    fputc('\'', f);
    for (; *s; s++) {
        if (*s == '\'')
            fputc('\'', f);
        if (*s != '\n')
            fputc(*s, f);
    }
    fputc('\'', f);
}

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

int plot_errors(const char *csv, const char *png, const char *title)
{
    /* one colour per method of methods.c's list, whatever methods the CSV has */
    static const char *const colours[MAX_SERIES] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                                                    "#8c564b", "#e377c2", "#17becf", "#bcbd22", "#7f7f7f",
                                                    "#393b79", "#e7969c", "#000000", "#637939", "#843c39",
                                                    "#3182bd"};
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
    for (int k = 0; k < ns; k++)
        for (int i = 0; i < series[k].n; i++) {
            xmin = series[k].x[i] < xmin ? series[k].x[i] : xmin;
            xmax = series[k].x[i] > xmax ? series[k].x[i] : xmax;
        }
    if (xmax <= 0.0)
        xmin = 1.0, xmax = 128.0;

    GFileOutput out; /* gnuplot writes the temporary by name; it is checked and renamed here */
    GError err;
    if (gfile_output_begin(&out, png, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        return -1;
    }
    const char *tmp = out.temp;
    FILE *g = popen("gnuplot", "w");
    if (!g) {
        fprintf(stderr, "gprobe: cannot run gnuplot: %s\n", strerror(errno));
        gfile_output_abort(&out);
        return -1;
    }
    fprintf(g, "set terminal pngcairo size 1500,760 font 'Sans,11'\nset output ");
    put_quoted(g, tmp);
    fputc('\n', g);
    for (int k = 0; k < ns; k++) {
        fprintf(g, "$s%d << EOD\n", k);
        for (int i = 0; i < series[k].n; i++)
            fprintf(g, "%g %g %g %g %g\n", series[k].x[i], series[k].y[i][0], series[k].y[i][1], series[k].y[i][2],
                    series[k].y[i][3]);
        fprintf(g, "EOD\n");
    }
    fprintf(g, "set multiplot layout 1,2 title ");
    put_quoted(g, title);
    fprintf(g, " font 'Sans,13'\n"
               "set logscale xy\nset grid xtics ytics mytics\n"
               "set key outside below center horizontal maxrows 4 box\n" /* beside the data, never over it */
               "set xrange [%g:%g]\nset xtics (",
            xmin / 1.25, xmax * 1.25);
    for (double x = 1; x <= xmax * 1.01; x *= 2)
        if (x >= xmin * 0.99)
            fprintf(g, "%s%g", x > xmin * 1.01 ? "," : "", x);
    fprintf(g, ")\nset xlabel 'N: lights, coefficients or lobes (solid: mean, dashed: max)'\n"
               "set ylabel 'irradiance error (%%)'\n");
    for (int panel = 0; panel < 2; panel++) {
        fprintf(g, "set title '%s'\nplot ", panel == 0 ? "relative to the true irradiance (the paper''s Fig. 6 measure)"
                                                       : "normalised by the largest irradiance");
        int first = 1;
        for (int k = 0; k < ns; k++) {
            const char *c = colours[series[k].method % MAX_SERIES];
            fprintf(g, "%s$s%d using 1:%d with linespoints lw 2 pt 7 lc rgb '%s' title '%s', "
                       "$s%d using 1:%d with linespoints lw 2 dt 2 pt 6 lc rgb '%s' notitle",
                    first ? "" : ", ", k, 2 + 2 * panel, c, series[k].name, k, 3 + 2 * panel, c);
            first = 0;
        }
        if (have_sh9) {
            double mean = sh9[2 * panel], max = sh9[2 * panel + 1];
            if (mean > 0.0)
                fprintf(g, "%s%g with lines lw 2 lc rgb 'gray40' title 'sh9 (9 coefficients)', "
                           "%g with lines lw 2 dt 2 lc rgb 'gray40' notitle",
                        first ? "" : ", ", mean, max);
        }
        fputc('\n', g);
    }
    fprintf(g, "unset multiplot\nset output\n");
    int st = pclose(g);
    int ok = st != -1 && WIFEXITED(st) && WEXITSTATUS(st) == 0;
    GImage check = {0}; /* the picture must decode whole: a full disk would have cut it short */
    if (ok && gimage_read(tmp, GIMAGE_READ_RGB, &check, &err) != G_OK) {
        fprintf(stderr, "gprobe: gnuplot's picture %s is not readable: %s\n", png, err.message);
        ok = 0;
    }
    gimage_free(&check);
    if (!ok) {
        fprintf(stderr, "gprobe: gnuplot failed to draw %s\n", png);
        gfile_output_abort(&out);
        return -1;
    }
    if (gfile_output_commit(&out, -1, png, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        return -1;
    }

    return ok ? 0 : -1;
}
