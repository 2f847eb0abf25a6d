/* check.c - `gcolor check MODEL`: conformance checks any colour model's author can run, built-in or plug-in.
 *
 * Each property is measured over a set of test colours (a 5x5x5 grid of linear sRGB values in [0, 1], as
 * reflectances and as lights, and the six report colours) and printed as one line: the property, its worst
 * error, the tolerance, PASS or FAIL. Errors are relative to the largest magnitude of the value compared
 * (max-norm over the model's values), so they do not depend on a model's units. a + black and pow(a, 1)
 * allow float rounding (1e-5); whatever goes through a conversion (white from rgb 1 1 1, the round trips)
 * allows 1e-3 (the built-in spectral models' white reflectance is 1 within 1.5e-4, from the exact 3x3
 * correction of their basis; measured errors are printed, so tighter models show it). */
#include "gcolor.h"
#include "../common/cli.h"

#include <generic/color.h>
#include <generic/registry.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define GRID 5
#define NTEST (2 * GRID * GRID * GRID)
#define TOL_IDENTITY 1e-5
#define TOL_CONVERT 1e-3
#define TOL_NM 0.1

typedef struct Check {
    const GColorModel *m;
    GColor test[NTEST];
    double rgb[NTEST][3];
    GColorRole role[NTEST];
    int n;
    GColor tmp, clamped, black, white_refl, white_light;
    int failures;
} Check;

/* max |a - b| / max(|a|, tiny) over the model's values */
static double rel_diff(const GColor *a, const GColor *b)
{
    int n = a->model->nvalues;
    double big = 0.0, d = 0.0;
    for (int i = 0; i < n; i++) {
        big = fmax(big, fabs(a->v[i]));
        d = fmax(d, fabs((double)a->v[i] - b->v[i]));
    }
    if (!isfinite(d))
        return INFINITY;
    return big > 0.0 ? d / big : d;
}

static void report(Check *c, const char *property, double worst, double tol, const char *note)
{
    int pass = worst <= tol; /* NaN fails */
    if (!pass)
        c->failures++;
    printf("%-44s worst %-11.3g tolerance %-8.2g %s%s%s\n", property, worst, tol, pass ? "PASS" : "FAIL",
           note ? "  " : "", note ? note : "");
}

static int make_tests(Check *c)
{
    for (int role = 0; role < 2; role++)
        for (int r = 0; r < GRID; r++)
            for (int g = 0; g < GRID; g++)
                for (int b = 0; b < GRID; b++) {
                    double rgb[3] = {r / (GRID - 1.0), g / (GRID - 1.0), b / (GRID - 1.0)};
                    if (rgb[0] + rgb[1] + rgb[2] == 0.0)
                        continue; /* black is checked on its own */
                    int k = c->n;
                    if (gcolor_alloc(&c->test[k], c->m) != G_OK ||
                        gcolor_from_rgb(&c->test[k], rgb, role ? GCOLOR_LIGHT : GCOLOR_REFLECTANCE) != G_OK)
                        return -1;
                    memcpy(c->rgb[k], rgb, sizeof rgb);
                    c->role[k] = role ? GCOLOR_LIGHT : GCOLOR_REFLECTANCE;
                    c->n++;
                }
    return 0;
}

static void check_identities(Check *c)
{
    double add = 0, mul = 0, pw = 0;
    for (int k = 0; k < c->n; k++) {
        const GColor *a = &c->test[k];
        add = fmax(add, gcolor_add(&c->tmp, a, &c->black) == G_OK ? rel_diff(a, &c->tmp) : INFINITY);
        mul = fmax(mul, gcolor_mul(&c->tmp, &c->white_refl, a) == G_OK ? rel_diff(a, &c->tmp) : INFINITY);
        /* pow is for transmittances: on the value with negative samples set to 0 */
        if (gcolor_copy(&c->clamped, a) != G_OK) {
            pw = INFINITY;
            continue;
        }
        for (int i = 0; i < c->m->nvalues; i++)
            c->clamped.v[i] = fmaxf(c->clamped.v[i], 0.0f);
        pw = fmax(pw, gcolor_pow(&c->tmp, &c->clamped, 1.0) == G_OK ? rel_diff(&c->clamped, &c->tmp) : INFINITY);
    }
    report(c, "a + black = a", add, TOL_IDENTITY, NULL);
    report(c, "white * a = a (white from rgb 1 1 1)", mul, TOL_CONVERT, NULL);
    report(c, "pow(a, 1) = a (a >= 0)", pw, TOL_IDENTITY, NULL);
}

static void check_brightness(Check *c)
{
    /* brightness(black) must be exactly 0 and every test colour (none is black) must be brighter */
    double b0 = gcolor_brightness(&c->black), smallest = INFINITY;
    for (int k = 0; k < c->n; k++) {
        double b = gcolor_brightness(&c->test[k]);
        smallest = isfinite(b) ? fmin(smallest, b) : -1.0;
    }
    char note[96];
    snprintf(note, sizeof note, "(brightness of black %g, least of the others %.3g)", b0, smallest);
    report(c, "brightness 0 iff black", b0 == 0.0 && smallest > 0.0 ? 0.0 : 1.0, 0.0, note);
}

static void check_rgb_round_trip(Check *c)
{
    double grey = 0, colour = 0;
    for (int k = 0; k < c->n; k++) {
        double back[3], e = 0.0, big = fmax(c->rgb[k][0], fmax(c->rgb[k][1], c->rgb[k][2]));
        if (gcolor_to_rgb(&c->test[k], c->role[k], back) != G_OK)
            e = INFINITY;
        for (int i = 0; i < 3; i++)
            e = fmax(e, fabs(back[i] - c->rgb[k][i]) / big);
        if (!isfinite(e))
            e = INFINITY;
        if (c->rgb[k][0] == c->rgb[k][1] && c->rgb[k][1] == c->rgb[k][2])
            grey = fmax(grey, e);
        else
            colour = fmax(colour, e);
    }
    report(c, "rgb -> model -> rgb, greys", grey, TOL_CONVERT, NULL);
    if (c->m->nvalues < 3) {
        char note[96];
        snprintf(note, sizeof note, "(not required: %d value%s cannot hold three channels)", c->m->nvalues,
                 c->m->nvalues == 1 ? "" : "s");
        printf("%-44s worst %-11.3g tolerance %-8.2g SKIP  %s\n", "rgb -> model -> rgb, colours", colour,
               TOL_CONVERT, note);
    } else {
        report(c, "rgb -> model -> rgb, colours", colour, TOL_CONVERT, NULL);
    }
}

static void check_white(Check *c)
{
    double rgb[3] = {0, 0, 0}, e = 0.0;
    if (gcolor_mul(&c->tmp, &c->white_refl, &c->white_light) != G_OK ||
        gcolor_to_rgb(&c->tmp, GCOLOR_LIGHT, rgb) != G_OK)
        e = INFINITY;
    for (int i = 0; i < 3; i++)
        e = fmax(e, fabs(rgb[i] - 1.0));
    char note[96];
    snprintf(note, sizeof note, "(sRGB %.6f %.6f %.6f)", rgb[0], rgb[1], rgb[2]);
    report(c, "white light on white surface = white", isfinite(e) ? e : INFINITY, TOL_CONVERT, note);
}

/* model -> nm -> model: the value itself need not come back (a model's from_nm may filter, e.g. with hat
 * weights that keep a line's energy, and a coarse model's reconstruction is not the inverse of its sampling),
 * but its colour must, within TOL_NM of its largest XYZ component. TOL_NM catches a wrong scale or role (a
 * factor or a D65 too many), not sampling quality: measured worst errors are rgb 5e-9, spectrum (5 nm)
 * 1.7e-3, bispectral (10 nm) 7.2e-3, spectrum9 (50 nm, spline) 8.2e-2. The largest change of a value is
 * printed too. */
static void check_nm_round_trip(Check *c)
{
    double e = 0.0, samples = 0.0;
    for (int k = 0; k < c->n; k++) {
        GSpectrumNM s;
        double a[3], b[3];
        if (gcolor_to_nm(&c->test[k], c->role[k], &s) != G_OK || gcolor_from_nm(&c->tmp, &s, c->role[k]) != G_OK ||
            gcolor_to_xyz(&c->test[k], c->role[k], a) != G_OK || gcolor_to_xyz(&c->tmp, c->role[k], b) != G_OK) {
            e = INFINITY;
            break;
        }
        double d = fmax(fabs(a[0] - b[0]), fmax(fabs(a[1] - b[1]), fabs(a[2] - b[2]))) /
                   fmax(fmax(a[0], a[1]), fmax(a[2], 1e-12));
        e = fmax(e, isfinite(d) ? d : INFINITY);
        samples = fmax(samples, rel_diff(&c->test[k], &c->tmp));
    }
    char note[96];
    snprintf(note, sizeof note, "(largest change of a value %.3g)", samples);
    report(c, "model -> nm -> model keeps XYZ", e, TOL_NM, note);
}

/* The wavelength bands (dispersion): the bands partition every value, sum over bands of mask * a = a; a band's
 * mask has the value 1 in its own band and 0 in the others; every test colour has a finite value in every
 * band. A model without band slots has one band, its mask white, and passes trivially. */
static void check_bands(Check *c)
{
    int nb = gcolormodel_band_count(c->m);
    double part = 0.0, unit = 0.0, finite = 0.0;
    GColor mask = {0}, sum = {0};
    if (gcolor_alloc(&mask, c->m) != G_OK || gcolor_alloc(&sum, c->m) != G_OK) {
        part = unit = finite = INFINITY;
        goto done;
    }
    for (int b = 0; b < nb && isfinite(unit); b++) {
        if (gcolor_band_mask(&mask, b) != G_OK) {
            unit = INFINITY;
            break;
        }
        for (int j = 0; j < nb; j++) {
            double v = gcolor_band_value(&mask, j) - (j == b);
            unit = fmax(unit, isfinite(v) ? fabs(v) : INFINITY);
        }
    }
    for (int k = 0; k < c->n && isfinite(part); k++) {
        gcolor_black(&sum);
        for (int b = 0; b < nb; b++)
            if (gcolor_band_mask(&mask, b) != G_OK || gcolor_mul(&c->tmp, &mask, &c->test[k]) != G_OK ||
                gcolor_add(&sum, &sum, &c->tmp) != G_OK || !isfinite(gcolor_band_value(&c->test[k], b)))
                finite = INFINITY;
        part = fmax(part, rel_diff(&c->test[k], &sum));
    }
done:
    gcolor_free(&mask);
    gcolor_free(&sum);
    char note[96];
    snprintf(note, sizeof note, "(%d band%s)", nb, nb == 1 ? "" : "s");
    report(c, "bands partition a (disjoint unit masks)", fmax(fmax(part, finite), unit), TOL_IDENTITY, note);
}

/* Information, not a property: how far below 0 from_rgb goes for colours in [0, 1] (a model whose basis
 * cannot hold every in-gamut colour without negative samples shows it here). */
static void report_negative(Check *c)
{
    double least = 0.0;
    for (int k = 0; k < c->n; k++)
        for (int i = 0; i < c->m->nvalues; i++)
            least = fmin(least, c->test[k].v[i]);
    printf("%-44s %-11.3g %s\n", "least value from_rgb gives in [0,1]^3", least, "(information)");
}

static void check_usage(FILE *f)
{
    fprintf(f, "usage: gcolor check MODEL [--step NM] [--plugin FILE.so]...\n"
               "Checks the colour model MODEL (built-in or from a module): a + black = a, white * a = a,\n"
               "pow(a, 1) = a, brightness 0 exactly for black, rgb -> model -> rgb, white light on a white\n"
               "surface, model -> nm -> model, the wavelength bands partitioning every value, each with its\n"
               "worst error over a grid of test colours.\n"
               "  --step NM     sample spacing in nm for a spectral model (0.1..400)\n"
               "  -h, --help    this text\n"
               "  --version     the version\n"
               "Exit status: 0 when every property passes, 1 when one fails, 2 for a usage error (an unknown\n"
               "option or model, a bad value).\n");
}

/* Reads the command line into *name and *step: -1 to go on, else the exit status to end with. */
static int check_args(int argc, char **argv, const char **name, double *step)
{
    static const struct option longopts[] = {CLI_COMMON_OPTIONS, {"step", required_argument, NULL, 's'}, {0}};
    CliParser p;
    cli_begin(&p, "gcolor check", argc, argv, "h", longopts);
    int opt, n, status = CLI_OK;
    while ((opt = cli_next_own(&p, "gcolor", check_usage, &status)) != -1) {
        if (opt == CLI_EXIT)
            return status;
        if (opt != 's' || cli_double("gcolor check", "--step", optarg, 0.1, 400.0, step) != 0)
            return CLI_USAGE;
    }
    char **rest = cli_operands(&p, &n);
    if (n > 1)
        return cli_usage_error("gcolor check", "unexpected argument '%s'", rest[1]);
    if (n == 0) {
        fprintf(stderr, "gcolor check: no MODEL given (gcolor list shows the registered ones)\n");
        return CLI_USAGE;
    }
    *name = rest[0];
    if (!gregistry_find(GKIND_COLORMODEL, *name)) {
        char names[512];
        gregistry_names(GKIND_COLORMODEL, names, sizeof names);
        fprintf(stderr, "gcolor check: unknown colour model '%s' (registered: %s)\n", *name, names);
        return CLI_USAGE;
    }
    return -1;
}

/* The checks of model m (named name) on c's test colours: the exit status. */
static int check_model(Check *c, const char *name, const GColorModel *m)
{
    double one[3] = {1, 1, 1};
    c->m = m;
    if (gcolor_alloc(&c->tmp, m) || gcolor_alloc(&c->clamped, m) || gcolor_alloc(&c->black, m) ||
        gcolor_alloc(&c->white_refl, m) || gcolor_alloc(&c->white_light, m) ||
        gcolor_from_rgb(&c->white_refl, one, GCOLOR_REFLECTANCE) ||
        gcolor_from_rgb(&c->white_light, one, GCOLOR_LIGHT) || make_tests(c)) {
        fprintf(stderr, "gcolor check: %s: creating the test colours failed\n", name);
        return 1;
    }
    printf("colour model %s (%d values, %d test colours)\n", name, m->nvalues, c->n);
    report_negative(c);
    check_identities(c);
    check_brightness(c);
    check_rgb_round_trip(c);
    check_white(c);
    check_nm_round_trip(c);
    check_bands(c);
    printf("%s: %s\n", name, c->failures ? "FAIL" : "PASS");
    return c->failures ? 1 : 0;
}

int gcolor_check(int argc, char **argv)
{
    const char *name = NULL;
    double step = 0.0;
    int rc = check_args(argc, argv, &name, &step);
    if (rc >= 0)
        return rc;
    GError err;
    GColorModel *m = NULL;
    GColorModelOptions mo = {.step_nm = step};
    if (gcolormodel_create(name, &mo, &m, &err) != G_OK) {
        fprintf(stderr, "gcolor check: %s\n", err.message);
        return 1;
    }
    static Check c; /* large: keep it off the stack */
    memset(&c, 0, sizeof c);
    rc = check_model(&c, name, m);
    for (int k = 0; k < c.n; k++)
        gcolor_free(&c.test[k]);
    gcolor_free(&c.tmp);
    gcolor_free(&c.clamped);
    gcolor_free(&c.black);
    gcolor_free(&c.white_refl);
    gcolor_free(&c.white_light);
    gcolormodel_destroy(m);
    return rc;
}
