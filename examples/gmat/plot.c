/* plot.c - gmat plot: a polar plot of the reflected light in the plane of incidence, drawn by gnuplot.
 *
 * For each outgoing direction in the plane of incidence (from grazing on the light's side, -90 degrees, through
 * the normal, 0, to grazing on the far side, +90) the lobe reaches out to the reflected luminance for unit white
 * light, on a linear radius or, with --log-radius, a logarithmic one over GMAT_PLOT_DECADES decades below the
 * maximum (a diffuse lobe beside a specular one). The lobe is filled with the reflected colour of its brightest
 * direction; the incoming light and the ideal specular ray (when the material has one) are drawn as lines.
 * gnuplot draws a PNG into a temporary directory; it is read back and written to the destination through the
 * library's image writer (so any format OpenImageIO writes, whole or not at all). --data writes the table the
 * plot is drawn from. */
#include "gmat.h"

#include <generic/services/file.h>
#include <generic/services/image.h>
#include <generic/memory.h>

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#define ANGLES 361 /* -90 .. 90 degrees in 0.5 degree steps */

typedef struct Lobe {
    double angle[ANGLES], y[ANGLES];
    float rgb[ANGLES][3];
} Lobe;

/* The reflected colour of one direction as a display colour: largest channel 1, negatives clipped. */
static void display(const GColor *c, float out[3], double *y)
{
    double xyz[3] = {0, 0, 0}, rgb[3];
    if (gcolor_to_xyz(c, GCOLOR_LIGHT, xyz) != G_OK)
        xyz[0] = xyz[1] = xyz[2] = 0.0; /* shown black */
    gcie_xyz_to_rgb(xyz, rgb);
    double mx = fmax(rgb[0], fmax(rgb[1], rgb[2]));
    for (int k = 0; k < 3; k++)
        out[k] = mx > 0 ? (float)fmax(0.0, rgb[k] / mx) : 0.0f;
    *y = fmax(0.0, xyz[1]);
}

/* A display colour as gnuplot's 0xRRGGBB, sRGB encoded and darkened by `shade`. */
static unsigned hex_colour(const float c[3], double shade)
{
    unsigned v = 0;
    for (int k = 0; k < 3; k++)
        v = v << 8 | (unsigned)lround(255.0 * fmin(1.0, gimage_srgb_encode(shade * c[k])));
    return v;
}

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

static int gnuplot_found(void)
{
    const char *path = getenv("PATH");
    char buf[4096];
    for (const char *p = path ? path : "/usr/bin:/bin"; *p;) {
        const char *e = strchr(p, ':');
        size_t n = e ? (size_t)(e - p) : strlen(p);
        snprintf(buf, sizeof buf, "%.*s/gnuplot", (int)n, n ? p : ".");
        if (access(buf, X_OK) == 0)
            return 1;
        p += n + (e ? 1 : 0);
    }
    return 0;
}

/* The table: angle (degrees from the normal, negative towards the light), luminance, display colour. */
static void write_table(FILE *f, const Lobe *l)
{
    for (int i = 0; i < ANGLES; i++)
        fprintf(f, "%.1f %.9g %.4f %.4f %.4f\n", l->angle[i], l->y[i], l->rgb[i][0], l->rgb[i][1], l->rgb[i][2]);
}

static int write_data_file(const char *path, const GmatContext *ctx, double theta_in, const Lobe *l, GError *err)
{
    GFileOutput out;
    int rc = gfile_output_begin(&out, path, err);
    if (rc != G_OK)
        return rc;
    int fd = dup(out.fd);
    FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
    if (!f) {
        if (fd >= 0)
            close(fd);
        gfile_output_abort(&out);
        return gerror_set(err, G_ERR_IO, "cannot write %s: %s", path, strerror(errno));
    }
    fprintf(f, "# gmat plot: material %s, light from theta %g degrees (the left)\n"
               "# angle_deg luminance r g b   (angle from the normal, negative towards the light; luminance\n"
               "# reflected for unit white light; r g b the colour normalised to its largest channel)\n",
            ctx->material_name, theta_in);
    write_table(f, l);
    int failed = ferror(f);
    if (fclose(f) != 0 || failed) {
        gfile_output_abort(&out);
        return gerror_set(err, G_ERR_IO, "cannot write %s: write error", path);
    }
    return gfile_output_commit(&out, -1, path, err);
}

/* The gnuplot program drawing the lobe into png. On a logarithmic radius the plot's radius is
 * log10(luminance / rmin), rmin GMAT_PLOT_DECADES decades below the maximum, and the rings are labelled with
 * the luminance they stand for. */
static void write_script(FILE *g, const char *png, const GmatPlotOptions *o, const GmatContext *ctx,
                         double theta_in, const Lobe *l, double ymax, int spec, double spec_angle, double spec_y,
                         const float spec_rgb[3])
{
    const int w = o->size, h = o->size * 3 / 4, font = w >= 512 ? 11 : w >= 256 ? 8 : 5;
    const double top = ymax > 0 ? ymax * 1.05 : 1.0, rmin = top * pow(10.0, -GMAT_PLOT_DECADES);
    const double R = o->log_radius ? GMAT_PLOT_DECADES : top; /* the outer radius in plot units */
    int peak = 0;
    for (int i = 0; i < ANGLES; i++)
        peak = l->y[i] > l->y[peak] ? i : peak;
    fprintf(g, "set terminal pngcairo size %d,%d font 'Sans,%d'\nset output ", w, h, font);
    put_quoted(g, png);
    fprintf(g, "\n$lobe << EOD\n");
    for (int i = 0; i < ANGLES; i++) /* gnuplot's polar angle: 90 along the normal, 180 on the light's side */
        fprintf(g, "%.2f %.9g\n", 90.0 - l->angle[i],
                o->log_radius ? (l->y[i] > rmin ? log10(l->y[i] / rmin) : 0.0) : l->y[i]);
    fprintf(g, "EOD\n$in << EOD\n%g 0\n%g %g\nEOD\n", 90.0 + theta_in, 90.0 + theta_in, R);
    if (spec)
        fprintf(g, "$spec << EOD\n%g 0\n%g %g\nEOD\n", 90.0 - spec_angle, 90.0 - spec_angle, R);
    fprintf(g, "set polar\nset angles degrees\nset size ratio -1\nunset border\nunset xtics\nunset ytics\n"
               "set trange [0:180]\nset rrange [0:%g]\nset xrange [%g:%g]\nset yrange [%g:%g]\n",
            R, -1.1 * R, 1.1 * R, -0.06 * R, 1.3 * R);
    if (o->log_radius) {
        fprintf(g, "set rtics (");
        for (int k = 0; k <= GMAT_PLOT_DECADES; k++)
            fprintf(g, "%s'%.0e' %d", k ? ", " : "", rmin * pow(10.0, k), k);
        fprintf(g, ")\n");
    } else {
        fprintf(g, "set rtics format '%%.2g'\n");
    }
    fprintf(g, "set grid polar 30 front lc rgb 'gray40'\n"
               "set ttics ('+90' 0, '+60' 30, '+30' 60, '0' 90, '-30' 120, '-60' 150, '-90' 180)\n"
               "set xlabel \"outgoing angle from the normal, degrees (negative: light side)\\n"
               "radius: reflected luminance for unit white light%s\"\n",
            o->log_radius ? " (logarithmic)" : "");
    char title[512];
    snprintf(title, sizeof title, "%s (%s, %s): light from %g degrees on the left", ctx->material_name,
             gmaterial_name(ctx->material), gcolormodel_name(ctx->model), theta_in);
    fprintf(g, "set title ");
    put_quoted(g, title);
    fprintf(g, "\nset key top right opaque box\n"
               "plot $lobe using 1:2 with filledcurves closed fs transparent solid 0.6 lc rgb '#%06x' title 'reflected light', "
               "$lobe using 1:2 with lines lw 2 lc rgb 'black' notitle, "
               "$in using 1:2 with lines lw 2 dt 2 lc rgb '#e08000' title 'incident light'",
            hex_colour(l->rgb[peak], 0.75));
    if (spec)
        fprintf(g, ", $spec using 1:2 with lines lw 3 lc rgb '#%06x' title 'ideal specular ray, reflectance Y %.3g'",
                hex_colour(spec_rgb, 0.8), spec_y);
    fprintf(g, "\nset output\n");
}

int gmat_plot(GmatContext *ctx, double theta_in, const GmatPlotOptions *o, const char *path, GError *err)
{
    int rc = gimage_check_output(path, err); /* before any work */
    if (rc != G_OK)
        return rc;
    if (o->data && (rc = gfile_check_output(o->data, err)) != G_OK)
        return rc;
    if (!gnuplot_found())
        return gerror_set(err, G_ERR_IO, "the plot is drawn by gnuplot, which is not installed (Debian: apt-get "
                                         "install gnuplot-nox)");
    Lobe *lobe = gmem_calloc(1, sizeof *lobe);
    if (!lobe)
        return gerror_set(err, G_ERR_NOMEM, "out of memory");
    /* the light comes from phi = 180 degrees (the left); signed angle a: < 0 on the light's side */
    GVec3 in = gmat_direction(theta_in, 180.0);
    double ymax = 0.0;
    for (int i = 0; i < ANGLES; i++) {
        double a = -90.0 + 0.5 * i;
        lobe->angle[i] = a;
        rc = gmat_reflect(ctx, in, gmat_direction(fabs(a), a < 0 ? 180.0 : 0.0));
        if (rc != G_OK) {
            gmem_free(lobe);
            return gerror_set(err, rc, "evaluating the material failed (%s)", gstatus_string(rc));
        }
        display(&ctx->result, lobe->rgb[i], &lobe->y[i]);
        ymax = fmax(ymax, lobe->y[i]);
    }
    GVec3 dir;
    float spec_rgb[3] = {0, 0, 0};
    double spec_y = 0.0, spec_angle = 0.0;
    int spec = gmat_specular(ctx, in, &dir) == 1;
    if (spec) {
        display(&ctx->result, spec_rgb, &spec_y);
        spec_angle = atan2(dir.x, dir.z) * 180.0 / M_PI;
    }
    const char *base = getenv("TMPDIR");
    char dirbuf[4096], png[4200];
    snprintf(dirbuf, sizeof dirbuf, "%s/gmat_plot_XXXXXX", base && *base ? base : "/tmp");
    if (!mkdtemp(dirbuf)) {
        gmem_free(lobe);
        return gerror_set(err, G_ERR_IO, "cannot make a temporary directory for gnuplot: %s", strerror(errno));
    }
    snprintf(png, sizeof png, "%s/plot.png", dirbuf);
    FILE *g = popen("gnuplot", "w");
    if (!g) {
        rmdir(dirbuf);
        gmem_free(lobe);
        return gerror_set(err, G_ERR_IO, "cannot run gnuplot: %s", strerror(errno));
    }
    write_script(g, png, o, ctx, theta_in, lobe, ymax, spec, spec_angle, spec_y, spec_rgb);
    int st = pclose(g);
    GImage img = {0};
    rc = G_OK;
    if (st == -1 || !WIFEXITED(st) || WEXITSTATUS(st) != 0)
        rc = gerror_set(err, G_ERR_IO, "gnuplot failed to draw the plot");
    else if (gimage_read(png, GIMAGE_READ_RGB, &img, err) != G_OK)
        rc = gerror_set(err, G_ERR_IO, "gnuplot's picture is not readable: %s", err ? err->message : "");
    unlink(png);
    rmdir(dirbuf);
    if (rc == G_OK)
        rc = gimage_write(path, &img, NULL, err);
    if (rc == G_OK && o->data)
        rc = write_data_file(o->data, ctx, theta_in, lobe, err);
    if (rc == G_OK)
        printf("wrote %s: %dx%d, lobe maximum %.6g (reflected luminance for unit white light), %s radius, specular "
               "%s\n", path, img.width, img.height, ymax, o->log_radius ? "logarithmic" : "linear",
               spec ? "ray drawn" : "none");
    gimage_free(&img);
    gmem_free(lobe);
    return rc;
}
