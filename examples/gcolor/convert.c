/* convert.c - `gcolor convert [--colormodel M] [--role reflectance|light] [--samples] LITERAL...`: what each colour
 * literal is in a colour model, one machine-readable line per literal:
 *
 *     LITERAL: XYZ X Y Z xy x y sRGB r g b brightness B[ samples NM:VALUE ...]
 *
 * The literal is read by the library's own reader (anything the text format accepts as a colour), converted into
 * the model in the role, and reported through the public conversions. Built only on the public API. */
#include "gcolor.h"
#include "../common/cli.h"

#include <generic/color.h>
#include <generic/reader.h>
#include <generic/registry.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CONVERT_MAX_LITERAL 65536

static void convert_usage(FILE *f)
{
    fprintf(f,
            "usage: gcolor convert [--colormodel M] [--step NM] [--role reflectance|light] [--illuminant N]\n"
            "                      [--samples] [--plugin FILE.so]... LITERAL...\n"
            "Prints, for each colour literal (anything a file accepts as a colour: 'rgb 1 0 0', 'illuminant F11',\n"
            "'blackbody 2856', 'line 550', 'spectrum { ... }'), one line:\n"
            "  LITERAL: XYZ X Y Z xy x y sRGB r g b brightness B\n"
            "the literal (its white space made single spaces), its CIE 1931 XYZ, chromaticity, linear sRGB and the\n"
            "model's brightness, in the role (a reflectance is seen under D65 of Y = 1; a light is its own spectrum).\n"
            "  --colormodel M  the colour model (default spectrum)\n"
            "  --step NM       the model's sample spacing in nm (a spectral model; default its own)\n"
            "  --role R        reflectance (default) or light\n"
            "  --illuminant N  a reflectance seen under the named illuminant N (gcolor list --illuminants) of Y = 1\n"
            "                  instead of D65: its XYZ and xy under N, and sRGB of that XYZ (not adapted)\n"
            "  --samples       then ' samples NM:VALUE ...': the model's own values at its wavelengths (a\n"
            "                  re-radiation matrix: its diagonal); refused for a model without wavelengths\n"
            "  -h, --help      this text\n" CLI_EXIT_STATUS_HELP);
}

typedef struct ConvertArgs {
    const char *model;
    const char *illuminant; /**< a reflectance's viewing illuminant (NULL: D65, the library's) */
    double step;
    GColorRole role;
    int samples;
    const GSpectrumNM *viewing; /**< the viewing illuminant's spectrum (Y = 1), or NULL */
} ConvertArgs;

/* The literal with every run of white space made one space and the ends trimmed, into out (size n). */
static void one_line(const char *literal, char *out, size_t n)
{
    size_t k = 0;
    int space = 0;
    for (const char *p = literal; *p && k + 1 < n; p++) {
        if (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r') {
            space = k > 0;
            continue;
        }
        if (space && k + 2 < n)
            out[k++] = ' ';
        space = 0;
        out[k++] = *p;
    }
    out[k] = '\0';
}

/* Reads the literal as the one entry of a text `color c LITERAL` into a library of model m. */
static int read_literal(const char *literal, const GColorModel *m, GLibrary **lib, GError *err)
{
    size_t len = strlen(literal);
    if (len > CONVERT_MAX_LITERAL)
        return gerror_set(err, G_ERR_INVALID, "the literal is longer than %d characters", CONVERT_MAX_LITERAL);
    char *text = malloc(len + 16);
    if (!text)
        return gerror_set(err, G_ERR_NOMEM, "out of memory");
    snprintf(text, len + 16, "color c\n%s\n", literal);
    GReaderOptions opt = {0};
    opt.model = m;
    opt.no_plugins = 1;
    int rc = greader_load_string(text, "literal", &opt, lib, err);
    free(text);
    if (rc != G_OK)
        return rc;
    int entries = 0;
    for (int k = 0; k < GKIND_MAX; k++)
        entries += glibrary_count(*lib, (GKind)k);
    if (entries != 1 || glibrary_count(*lib, GKIND_COLOR) != 1) {
        glibrary_destroy(*lib);
        *lib = NULL;
        return gerror_set(err, G_ERR_INVALID, "not one colour literal (it reads as %d entries)", entries);
    }
    return G_OK;
}

/* Prints " samples NM:VALUE ..." for c at the model's wavelengths; a re-radiation matrix by its diagonal (its
 * pow 1, which the interface defines as the diagonal). */
static int print_samples(const GColor *c, GColorRole role)
{
    const GColorModel *m = c->model;
    int n = gcolormodel_wavelengths(m, NULL, 0);
    double *nm = malloc(sizeof *nm * (size_t)n);
    float *v = malloc(sizeof *v * (size_t)n);
    GColor diag = {0};
    int rc = nm && v ? gcolor_alloc(&diag, m) : G_ERR_NOMEM;
    if (rc == G_OK && c->kind == GCOLOR_MATRIX)
        rc = gcolor_pow(&diag, c, 1.0);
    if (rc == G_OK) {
        gcolormodel_wavelengths(m, nm, n);
        rc = gcolor_at_wavelengths(c->kind == GCOLOR_MATRIX ? &diag : c, role, v, n);
    }
    if (rc == G_OK) {
        printf(" samples");
        for (int i = 0; i < n; i++)
            printf(" %.9g:%.9g", nm[i], (double)v[i]);
    }
    gcolor_free(&diag);
    free(nm);
    free(v);
    return rc;
}

/* The XYZ of reflectance c seen under the illuminant `light` (Y = 1): the reflectance's spectrum times the light's,
 * as a light (so white gives the illuminant's own XYZ, Y = 1), and the sRGB of that XYZ (no chromatic adaptation). */
static int seen_under(const GColor *c, const GSpectrumNM *light, double xyz[3], double rgb[3], GError *err)
{
    static GSpectrumNM s;
    int rc = gcolor_to_nm(c, GCOLOR_REFLECTANCE, &s);
    if (rc != G_OK)
        return gerror_set(err, rc, "the reflectance's spectrum cannot be had: %s", gstatus_string(rc));
    for (int i = 0; i < GNM_COUNT; i++)
        s.v[i] *= light->v[i];
    gcie_nm_to_xyz(&s, GCOLOR_LIGHT, xyz);
    gcie_xyz_to_rgb(xyz, rgb);
    return G_OK;
}

/* One literal's line; 0, or 1 after a message on stderr. */
static int convert_one(const char *literal, const GColorModel *m, const ConvertArgs *a)
{
    GError err = {0};
    GLibrary *lib = NULL;
    GColor c;
    if (gcolor_alloc(&c, m) != G_OK) {
        fprintf(stderr, "gcolor convert: out of memory\n");
        return 1;
    }
    double xyz[3], rgb[3];
    int rc = read_literal(literal, m, &lib, &err);
    if (rc == G_OK)
        rc = glibrary_color(lib, "c", a->role, &c, &err);
    if (rc == G_OK && a->viewing)
        rc = seen_under(&c, a->viewing, xyz, rgb, &err);
    else if (rc == G_OK && ((rc = gcolor_to_xyz(&c, a->role, xyz)) != G_OK || (rc = gcolor_to_rgb(&c, a->role, rgb))))
        gerror_set(&err, rc, "the conversion to XYZ or sRGB failed: %s", gstatus_string(rc));
    double bright = rc == G_OK ? gcolor_brightness(&c) : 0.0;
    if (rc == G_OK && !isfinite(xyz[0] + xyz[1] + xyz[2] + rgb[0] + rgb[1] + rgb[2] + bright))
        rc = gerror_set(&err, G_ERR_INVALID, "the result is not finite (the value is out of the model's range)");
    if (rc == G_OK) {
        static char line[CONVERT_MAX_LITERAL + 1];
        one_line(literal, line, sizeof line);
        double sum = xyz[0] + xyz[1] + xyz[2];
        double x = sum != 0.0 ? xyz[0] / sum : 0.0, y = sum != 0.0 ? xyz[1] / sum : 0.0;
        printf("%s: XYZ %.9g %.9g %.9g xy %.9g %.9g sRGB %.9g %.9g %.9g brightness %.9g", line, xyz[0], xyz[1],
               xyz[2], x, y, rgb[0], rgb[1], rgb[2], bright);
        if (a->samples && (rc = print_samples(&c, a->role)) != G_OK)
            gerror_set(&err, rc, "its samples cannot be read: %s", gstatus_string(rc));
        printf("\n");
    }
    if (rc != G_OK)
        fprintf(stderr, "gcolor convert: '%s': %s\n", literal, err.message);
    gcolor_free(&c);
    glibrary_destroy(lib);
    return rc != G_OK;
}

int gcolor_convert_command(int argc, char **argv)
{
    static const struct option longopts[] = {CLI_COMMON_OPTIONS,
                                             {"colormodel", required_argument, NULL, 'm'},
                                             {"role", required_argument, NULL, 'r'},
                                             {"samples", no_argument, NULL, 's'},
                                             {"step", required_argument, NULL, 't'},
                                             {"illuminant", required_argument, NULL, 'i'},
                                             {0}};
    ConvertArgs a = {.model = "spectrum", .role = GCOLOR_REFLECTANCE};
    CliParser p;
    cli_begin(&p, "gcolor convert", argc, argv, "h", longopts);
    int c, n, status = CLI_OK;
    while ((c = cli_next_own(&p, "gcolor", convert_usage, &status)) != -1) {
        if (c == CLI_EXIT)
            return status;
        if (c == 'm')
            a.model = optarg;
        else if (c == 's')
            a.samples = 1;
        else if (c == 'i')
            a.illuminant = optarg;
        else if (c == 't' && cli_double("gcolor convert", "--step", optarg, 0.1, 400.0, &a.step) != 0)
            return CLI_USAGE;
        else if (c == 't')
            continue;
        else if (c == 'r' && (strcmp(optarg, "reflectance") == 0 || strcmp(optarg, "light") == 0))
            a.role = strcmp(optarg, "light") == 0 ? GCOLOR_LIGHT : GCOLOR_REFLECTANCE;
        else if (c == 'r')
            return cli_usage_error("gcolor convert", "--role expects reflectance or light, got '%s'", optarg);
        else
            return CLI_USAGE;
    }
    static GSpectrumNM viewing;
    if (a.illuminant && gcie_illuminant_nm(a.illuminant, &viewing) != G_OK)
        return cli_usage_error("gcolor convert", "--illuminant: unknown illuminant '%s' (gcolor list --illuminants)",
                               a.illuminant);
    if (a.illuminant && a.role != GCOLOR_REFLECTANCE)
        return cli_usage_error("gcolor convert", "--illuminant %s: only a reflectance is seen under an illuminant",
                               a.illuminant);
    a.viewing = a.illuminant ? &viewing : NULL;
    char **literals = cli_operands(&p, &n);
    if (n == 0)
        return cli_usage_error("gcolor convert", "no colour literal given%s", "");
    if (!gregistry_find(GKIND_COLORMODEL, a.model)) {
        char names[512];
        gregistry_names(GKIND_COLORMODEL, names, sizeof names);
        fprintf(stderr, "gcolor convert: --colormodel: unknown colour model '%s' (registered: %s)\n", a.model, names);
        return CLI_USAGE;
    }
    GError err;
    GColorModel *m = NULL;
    GColorModelOptions mopt = {.step_nm = a.step};
    if (gcolormodel_create(a.model, &mopt, &m, &err) != G_OK) {
        fprintf(stderr, "gcolor convert: %s\n", err.message);
        return a.step > 0.0 ? CLI_USAGE : 1;
    }
    if (a.samples && gcolormodel_wavelengths(m, NULL, 0) == 0) {
        gcolormodel_destroy(m);
        return cli_usage_error("gcolor convert", "--samples: the model '%s' has no wavelength samples", a.model);
    }
    int failed = 0;
    for (int i = 0; i < n; i++)
        failed |= convert_one(literals[i], m, &a);
    gcolormodel_destroy(m);
    return failed;
}
