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
#include "../common/gnuplot.h"

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
    double ymax; /* the largest luminance */
    int peak;    /* the direction of ymax: the lobe is filled with its colour */
} Lobe;

/* The ideal specular ray, when the material has one: its angle from the normal, luminance and colour. */
typedef struct Specular {
    int drawn;
    double angle, y;
    float rgb[3];
} Specular;

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


/* The lobe for light from theta_in degrees on the left (phi = 180; signed angle a: < 0 on the light's side) and
 * the ideal specular ray. */
static int measure(GmatContext *ctx, double theta_in, Lobe *l, Specular *spec, GError *err)
{
    GVec3 in = gmat_direction(theta_in, 180.0);
    l->ymax = 0.0;
    l->peak = 0;
    for (int i = 0; i < ANGLES; i++) {
        double a = -90.0 + 0.5 * i;
        l->angle[i] = a;
        int rc = gmat_reflect(ctx, in, gmat_direction(fabs(a), a < 0 ? 180.0 : 0.0));
        if (rc != G_OK)
            return gerror_set(err, rc, "evaluating the material failed (%s)", gstatus_string(rc));
        display(&ctx->result, l->rgb[i], &l->y[i]);
        l->ymax = fmax(l->ymax, l->y[i]);
        l->peak = l->y[i] > l->y[l->peak] ? i : l->peak;
    }
    GVec3 dir;
    spec->drawn = gmat_specular(ctx, in, &dir) == 1;
    if (spec->drawn) {
        display(&ctx->result, spec->rgb, &spec->y);
        spec->angle = atan2(dir.x, dir.z) * 180.0 / M_PI;
    }
    return G_OK;
}

/* The plot's radial scale: radius R in plot units; on a logarithmic radius a luminance y is drawn at
 * log10(y / rmin), rmin GMAT_PLOT_DECADES decades below the top. */
typedef struct Scale {
    int log;
    double top, rmin, R;
} Scale;

static Scale scale_of(const Lobe *l, int log_radius)
{
    Scale s = {.log = log_radius, .top = l->ymax > 0 ? l->ymax * 1.05 : 1.0};
    s.rmin = s.top * pow(10.0, -GMAT_PLOT_DECADES);
    s.R = log_radius ? GMAT_PLOT_DECADES : s.top;
    return s;
}

static double radius(const Scale *s, double y)
{
    if (!s->log)
        return y;
    return y > s->rmin ? log10(y / s->rmin) : 0.0;
}

/* The data blocks: the lobe (gnuplot's polar angle: 90 along the normal, 180 on the light's side), the incident
 * light and the specular ray as lines from the origin to the rim. */
static void write_data(FILE *g, const Lobe *l, const Specular *spec, const Scale *s, double theta_in)
{
    fprintf(g, "$lobe << EOD\n");
    for (int i = 0; i < ANGLES; i++)
        fprintf(g, "%.2f %.9g\n", 90.0 - l->angle[i], radius(s, l->y[i]));
    fprintf(g, "EOD\n$in << EOD\n%g 0\n%g %g\nEOD\n", 90.0 + theta_in, 90.0 + theta_in, s->R);
    if (spec->drawn)
        fprintf(g, "$spec << EOD\n%g 0\n%g %g\nEOD\n", 90.0 - spec->angle, 90.0 - spec->angle, s->R);
}

/* Where the texts and the plot go in a w x h picture whose font is `font` points, from w / 46.5 (11 at the
 * default 512) down to 5. pngcairo's line is 1.55 times the size in pixels; gnuplot sizes the legend by
 * characters 0.82 of it wide, text runs about 0.68 of it a character. From the top: the title (two lines when one
 * is too wide), the legend (as many columns as fit; none when not one does), the half disc with its angle
 * labels; at the bottom the radius labels and the two lines that describe the axes. The half disc is as large as
 * the room left allows and centred in it, so that the legend covers nothing. */
typedef struct Layout {
    int w, h;
    double font, line, chr, text; /* points; a line's height, a legend character's and a text character's width */
    int title_lines, key_rows, key_cols;
    double left, right, bottom, top; /* the plot's box, in pixels from the lower left corner */
} Layout;

static Layout layout_of(int w, int h, int title_len, int entries, int longest)
{
    Layout t = {.w = w, .h = h, .font = fmax(5.0, fmin(11.0, round(w / 46.5 * 10.0) / 10.0))};
    t.line = 1.55 * t.font;
    t.chr = 0.82 * t.font;
    t.text = 0.68 * t.font;
    t.title_lines = title_len * t.text > w - 2 * t.chr ? 2 : 1;
    int fit = (int)((w - 2 * t.chr) / ((longest + 6) * t.chr)); /* a column: text, sample, gaps */
    if ((longest + 11) * t.chr > w - 2 * t.chr) /* and the box around one */
        fit = 0;
    t.key_cols = fit > entries ? entries : fit;
    t.key_rows = fit > 0 ? (entries + t.key_cols - 1) / t.key_cols : 0;
    /* the half disc spans 2 R across and 1.02 R up, its angle tics reach 0.05 R further, their labels a few
     * characters beside (+90, -90) and a line and a half above (0) */
    double x0 = 5.0 * t.chr, x1 = w - 5.0 * t.chr;
    double y0 = 3.9 * t.line, y1 = h - (t.title_lines + t.key_rows + 2.5) * t.line;
    double unit = fmax(1.0, fmin((x1 - x0) / 2.1, (y1 - y0) / 1.07)); /* R in pixels */
    t.left = 0.5 * (x0 + x1) - unit;
    t.right = 0.5 * (x0 + x1) + unit;
    t.bottom = y0 + 0.5 * (y1 - y0 - 1.07 * unit);
    t.top = t.bottom + 1.02 * unit;
    return t;
}

/* The radius labels, at least five text characters apart: on a logarithmic radius a ring at each power of ten
 * the plot spans, every one or every other labelled with its luminance as briefly as it reads ("0.01" .. "1000",
 * else "1e-5", "1e4"); on a linear one a ring every 1, 2 or 5 times a power of ten. */
static void write_rtics(FILE *g, const Scale *s, const Layout *t)
{
    const double room = (t->right - t->left) / 2.0 / (5.0 * t->text); /* labels R can hold */
    if (!s->log) {
        double want = s->R / fmax(1.0, room), step = pow(10.0, floor(log10(want)));
        for (int k = 0; step < want; k++)
            step *= k % 3 == 1 ? 2.5 : 2.0; /* 1, 2, 5, 10, 20, 50, ... times a power of ten */
        fprintf(g, "set rtics %g format '%%g'\n", step);
        return;
    }
    const int every = GMAT_PLOT_DECADES <= room ? 1 : 2;
    fprintf(g, "set rtics (");
    int first = 1;
    for (int e = (int)ceil(log10(s->rmin) - 1e-9); e <= (int)floor(log10(s->top) + 1e-9); e++) {
        double at = e - log10(s->rmin);
        if (e % every != 0)
            fprintf(g, "%s'' %.4f", first ? "" : ", ", at);
        else if (e >= -2 && e <= 3)
            fprintf(g, "%s'%g' %.4f", first ? "" : ", ", pow(10.0, e), at);
        else
            fprintf(g, "%s'1e%d' %.4f", first ? "" : ", ", e, at);
        first = 0;
    }
    fprintf(g, ")\n");
}

/* The half disc: the plot spans [-R, R] x [0, R] with a ring at R, where gnuplot puts the angle labels (at the
 * outermost ring); they sit half a line above their spokes, so that +90 and -90 stand clear of the radius labels
 * under the axis. */
static void write_frame(FILE *g, const Scale *s, const Layout *t)
{
    fprintf(g, "set polar\nset angles degrees\nset size ratio -1\nunset border\nunset xtics\nunset ytics\n"
               "set trange [0:180]\nset rrange [0:%g]\nset xrange [%g:%g]\nset yrange [%g:%g]\n",
            s->R, -s->R, s->R, -0.02 * s->R, s->R);
    write_rtics(g, s, t);
    fprintf(g, "set rtics add ('' %g)\nset grid polar 30 front lc rgb 'gray40'\n"
               "set ttics ('+90' 0, '+60' 30, '+30' 60, '0' 90, '-30' 120, '-60' 150, '-90' 180) offset 0,0.5\n",
            s->R);
}

/* A height given in lines from the top of the picture, as gnuplot's screen coordinate. */
static double from_top(const Layout *t, double lines) { return 1.0 - lines * t->line / t->h; }

static void write_texts(FILE *g, const Layout *t, const char *title, const Scale *s)
{
    const char *split = t->title_lines == 2 ? strstr(title, ": ") : NULL;
    if (split) {
        fprintf(g, "set label 1 '%.*s' at screen 0.5, screen %.4f center\n", (int)(split + 1 - title), title,
                from_top(t, 1.0));
        title = split + 2;
    }
    fprintf(g, "set label 2 ");
    gnuplot_put_quoted(g, title);
    fprintf(g, " at screen 0.5, screen %.4f center\n", from_top(t, split ? 2.0 : 1.0));
    if (t->key_rows > 0)
        fprintf(g, "set key at screen 0.5, screen %.4f center top vertical maxcols %d maxrows %d box samplen 2\n",
                from_top(t, (split ? 2.0 : 1.0) + 0.7), t->key_cols, t->key_rows);
    else
        fprintf(g, "unset key\n"); /* a thumbnail: no room for one */
    fprintf(g, "set label 3 'outgoing angle from the normal, degrees (negative: light side)' at screen 0.5, "
               "screen %.4f center\n", 2.0 * t->line / t->h);
    fprintf(g, "set label 4 'radius: reflected luminance for unit white light%s' at screen 0.5, screen %.4f center\n",
            s->log ? " (logarithmic)" : "", t->line / t->h);
    fprintf(g, "set lmargin at screen %.4f\nset rmargin at screen %.4f\nset bmargin at screen %.4f\n"
               "set tmargin at screen %.4f\n",
            t->left / t->w, t->right / t->w, t->bottom / t->h, t->top / t->h);
}

/* The gnuplot program drawing the lobe into png. */
static void write_script(FILE *g, const char *png, const GmatPlotOptions *o, const GmatContext *ctx,
                         double theta_in, const Lobe *l, const Specular *spec)
{
    const Scale s = scale_of(l, o->log_radius);
    char title[512], spec_title[64];
    snprintf(title, sizeof title, "%s (%s, %s): light from %g degrees on the left", ctx->material_name,
             gmaterial_name(ctx->material), gcolormodel_name(ctx->model), theta_in);
    snprintf(spec_title, sizeof spec_title, "specular ray, Y %.3g", spec->y);
    int longest = spec->drawn ? (int)strlen(spec_title) : (int)strlen("reflected light");
    const Layout t = layout_of(o->size, o->size * 3 / 4, (int)strlen(title), spec->drawn ? 3 : 2,
                               longest > 15 ? longest : 15);
    gnuplot_begin_png(g, t.w, t.h, t.font, png);
    write_data(g, l, spec, &s, theta_in);
    write_frame(g, &s, &t);
    write_texts(g, &t, title, &s);
    fprintf(g, "plot $lobe using 1:2 with filledcurves closed fs transparent solid 0.6 lc rgb '#%06x' "
               "title 'reflected light', $lobe using 1:2 with lines lw 2 lc rgb 'black' notitle, "
               "$in using 1:2 with lines lw 2 dt 2 lc rgb '#e08000' title 'incident light'",
            hex_colour(l->rgb[l->peak], 0.75));
    if (spec->drawn) {
        fprintf(g, ", $spec using 1:2 with lines lw 3 lc rgb '#%06x' title ", hex_colour(spec->rgb, 0.8));
        gnuplot_put_quoted(g, spec_title);
    }
    fprintf(g, "\nset output\n");
}

/* Runs gnuplot on the script into a temporary directory and reads its picture into img. */
static int draw(const GmatPlotOptions *o, const GmatContext *ctx, double theta_in, const Lobe *l,
                const Specular *spec, GImage *img, GError *err)
{
    const char *base = getenv("TMPDIR");
    char dir[4096], png[4200];
    snprintf(dir, sizeof dir, "%s/gmat_plot_XXXXXX", base && *base ? base : "/tmp");
    if (!mkdtemp(dir))
        return gerror_set(err, G_ERR_IO, "cannot make a temporary directory for gnuplot: %s", strerror(errno));
    snprintf(png, sizeof png, "%s/plot.png", dir);
    FILE *g = popen("gnuplot", "w");
    if (!g) {
        rmdir(dir);
        return gerror_set(err, G_ERR_IO, "cannot run gnuplot: %s", strerror(errno));
    }
    write_script(g, png, o, ctx, theta_in, l, spec);
    int st = pclose(g), rc = G_OK;
    if (st == -1 || !WIFEXITED(st) || WEXITSTATUS(st) != 0)
        rc = gerror_set(err, G_ERR_IO, "gnuplot failed to draw the plot");
    else if (gimage_read(png, GIMAGE_READ_RGB, img, err) != G_OK)
        rc = gerror_set(err, G_ERR_IO, "gnuplot's picture is not readable: %s", err ? err->message : "");
    unlink(png);
    rmdir(dir);
    return rc;
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
    Specular spec = {0};
    GImage img = {0};
    rc = measure(ctx, theta_in, lobe, &spec, err);
    if (rc == G_OK)
        rc = draw(o, ctx, theta_in, lobe, &spec, &img, err);
    if (rc == G_OK)
        rc = gimage_write(path, &img, NULL, err);
    if (rc == G_OK && o->data)
        rc = write_data_file(o->data, ctx, theta_in, lobe, err);
    if (rc == G_OK)
        printf("wrote %s: %dx%d, lobe maximum %.6g (reflected luminance for unit white light), %s radius, specular "
               "%s\n", path, img.width, img.height, lobe->ymax, o->log_radius ? "logarithmic" : "linear",
               spec.drawn ? "ray drawn" : "none");
    gimage_free(&img);
    gmem_free(lobe);
    return rc;
}
