/* laser.c - `gmat laser`: the laser experiment of Wilkie et al. (sections 3 and 6) on a material from a file.
 *
 *   gmat laser FILE MATERIAL [--wavelength NM] [--elevation E1,E2,...] [--pattern OUT.png] [--size PIXELS]
 *              [--extent X] [--colormodel NAME [--step NM]]
 *
 * For each elevation it prints the share of a collimated monochromatic beam's power that the material
 * reflects at the beam's wavelength and the share it shifts to other wavelengths (with the dominant and peak
 * wavelength of the shifted light); with --pattern it draws the reflection pattern on a white diffuse target
 * (one panel per elevation, side by side) and measures the lobe of unshifted light. The computation is the
 * library's (gfluor_laser_split, gfluor_laser_pattern in generic/fluorescent.h). */
#include "gmat.h"
#include "../common/cli.h"

#include "laser_experiment.h"
#include <generic/services/image.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_ELEVATIONS = 16 };

static void laser_usage(FILE *f)
{
    fprintf(f,
            "usage: gmat laser FILE MATERIAL [--wavelength NM] [--elevation E1,E2,...] [--pattern OUT.png]\n"
            "                  [--size PIXELS] [--extent X] [--colormodel NAME [--step NM]]\n\n"
            "The laser experiment of Wilkie et al.: a collimated monochromatic beam hits MATERIAL (a name defined\n"
            "in FILE) at each elevation above the surface (degrees, default 5,20,60). The reflected power is\n"
            "integrated over the hemisphere and split into the share that kept the beam's wavelength and the\n"
            "share shifted to other wavelengths (fractions of the incident power), with the dominant wavelength\n"
            "(against equal-energy white) and the peak of the shifted light. The beam sits on the colour model's\n"
            "sample nearest to --wavelength (default 532 nm). Only the bispectral model shifts wavelengths; in\n"
            "the others the matrix is folded into a reflectance and everything is 'kept'.\n"
            "  --pattern OUT.png   draw the reflection pattern on a white diffuse target perpendicular to the\n"
            "                      beam's mirror direction at distance 1 (one panel per elevation; horizontal is\n"
            "                      across the plane of incidence, up towards the normal; the grid is every 0.1)\n"
            "                      and print the widths at half maximum of the unshifted lobe\n"
            "  --size PIXELS       panel size (64..4096, default 384)\n"
            "  --extent X          the target spans -X..X (default 1.5)\n"
            "  --colormodel NAME   compute in this model instead of the file's; --step NM its spacing\n"
            "  --plugin FILE.so    load a module first (repeatable)\n"
            "  --allow-plugins     let `plugin` statements of FILE load modules; --confine DIR: files under DIR only\n"
            "  -h, --help          this text\n"
            "  --version           the version\n"
            CLI_EXIT_STATUS_HELP);
}

static int elevations(const char *s, double *e, int *n)
{
    char buf[256];
    snprintf(buf, sizeof buf, "%s", s);
    *n = 0;
    for (char *tok = strtok(buf, ","); tok; tok = strtok(NULL, ",")) {
        if (*n == MAX_ELEVATIONS || gmat_number(tok, 0.01, 90.0, &e[*n]))
            return -1;
        (*n)++;
    }
    return *n > 0 ? 0 : -1;
}

static int write_pattern(const GMaterial *m, GScratch *sc, double nm, const double *el, int n, int size,
                         double extent, const char *path)
{
    const int gap = 6;
    GImage img;
    GError err;
    if (gimage_create(&img, n * size + (n - 1) * gap, size, 3, &err) != G_OK) {
        fprintf(stderr, "gmat laser: %s\n", err.message);
        return 1;
    }
    for (long i = 0; i < (long)img.width * img.height * 3; i++)
        img.pixels[i] = 1.0f; /* white gaps between the panels */
    printf("\nunshifted lobe on the target (widths at half maximum, target units):\n");
    printf("  elevation   across   along   along/across\n");
    int rc = 0;
    for (int k = 0; k < n && rc == 0; k++) {
        GFluorPattern p;
        if (gfluor_laser_pattern(m, sc, nm, el[k], size, size, extent, &p, &err) != G_OK) {
            fprintf(stderr, "gmat laser: %s\n", err.message);
            rc = 1;
            break;
        }
        printf("  %6.1f    %7.3f  %7.3f  %8.2f\n", el[k], p.kept_fwhm_h, p.kept_fwhm_v, p.aspect);
        for (int y = 0; y < size; y++)
            memcpy(img.pixels + ((long)y * img.width + (long)k * (size + gap)) * 3, p.rgb + (long)y * size * 3,
                   (size_t)size * 3 * sizeof(float));
        gfluor_pattern_free(&p);
    }
    if (rc == 0 && gimage_write(path, &img, NULL, &err) != G_OK) {
        fprintf(stderr, "gmat laser: %s\n", err.message);
        rc = 1;
    }
    if (rc == 0)
        printf("pattern: %s (%d panel%s, %d x %d each)\n", path, n, n > 1 ? "s" : "", size, size);
    gimage_free(&img);
    return rc;
}

/* The command line of laser. */
typedef struct LaserArgs {
    const char *file, *name, *pattern, *colormodel;
    double nm, el[MAX_ELEVATIONS], extent, size, step;
    int nel;
} LaserArgs;

enum { OPT_WAVELENGTH = CLI_FIRST_OWN, OPT_ELEVATION, OPT_PATTERN, OPT_SIZE, OPT_EXTENT, OPT_COLORMODEL, OPT_STEP };

/* Handles one of laser's own options: 0, or the usage error's status (message printed). */
static int laser_option(LaserArgs *a, int c, const char *v)
{
    switch (c) {
    case OPT_WAVELENGTH:
        if (gmat_number(v, 200, 2000, &a->nm))
            return gmat_usage_error("laser", "--wavelength: '%s' is not a wavelength in nm", v);
        return 0;
    case OPT_ELEVATION:
        if (elevations(v, a->el, &a->nel))
            return gmat_usage_error("laser", "--elevation: '%s' is not a list of up to 16 angles in (0, 90] degrees",
                                    v);
        return 0;
    case OPT_PATTERN:
        a->pattern = v;
        return 0;
    case OPT_SIZE:
        if (gmat_number(v, 64, 4096, &a->size) || a->size != floor(a->size))
            return gmat_usage_error("laser", "--size: '%s' is not a whole number in 64..4096", v);
        return 0;
    case OPT_EXTENT:
        if (gmat_number(v, 0.01, 100, &a->extent))
            return gmat_usage_error("laser", "--extent: '%s' is not a number in 0.01..100", v);
        return 0;
    case OPT_COLORMODEL:
        a->colormodel = v;
        return 0;
    case OPT_STEP:
        if (gmat_number(v, 0.1, 400, &a->step))
            return gmat_usage_error("laser", "--step: '%s' is not a spacing in nm", v);
        return 0;
    default:
        return CLI_USAGE;
    }
}

/* Reads the command line into a: -1 to go on, else the exit status to end with. */
static int laser_args(int argc, char **argv, LaserArgs *a)
{
    static const struct option longopts[] = {
        CLI_COMMON_OPTIONS,
        {"wavelength", required_argument, NULL, OPT_WAVELENGTH},
        {"elevation", required_argument, NULL, OPT_ELEVATION},
        {"pattern", required_argument, NULL, OPT_PATTERN},
        {"size", required_argument, NULL, OPT_SIZE},
        {"extent", required_argument, NULL, OPT_EXTENT},
        {"colormodel", required_argument, NULL, OPT_COLORMODEL},
        {"step", required_argument, NULL, OPT_STEP},
        {NULL, 0, NULL, 0},
    };
    *a = (LaserArgs){.nm = 532.0, .el = {5, 20, 60}, .extent = 1.5, .size = 384, .nel = 3};
    CliParser p;
    cli_begin(&p, "gmat laser", argc - 1, argv + 1, "h", longopts);
    int c, rc, status = CLI_OK;
    while ((c = cli_next_own(&p, "gmat", laser_usage, &status)) != -1) {
        if (c == CLI_EXIT)
            return status;
        if ((rc = laser_option(a, c, optarg)) != 0)
            return rc;
    }
    if ((rc = gmat_operands("laser", &p, 2, &a->file, &a->name)) != 0)
        return rc;
    if (!a->file || !a->name)
        return gmat_usage_error("laser", "%s", "FILE and MATERIAL are required");
    return -1;
}

/* The table of the shares kept and shifted at each elevation: 0, or 1 with a message. */
static int print_splits(const LaserArgs *a, const GMaterial *m, GScratch *sc)
{
    GError err;
    for (int k = 0; k < a->nel; k++) {
        GFluorLaserSplit s;
        if (gfluor_laser_split(m, sc, a->nm, a->el[k], NULL, &s, &err) != G_OK) {
            fprintf(stderr, "gmat laser: %s\n", err.message);
            return 1;
        }
        if (k == 0 && s.wavelength > 0)
            printf("  (beam on the %g nm sample)\n", s.wavelength);
        printf("  %6.1f    %7.4f  %7.4f  %7.4f", a->el[k], s.kept, s.shifted, s.kept + s.shifted);
        if (s.shifted > 0 && s.dominant_nm > 0)
            printf("   %5.0f nm / %5.0f nm\n", s.dominant_nm, s.peak_nm);
        else if (s.shifted > 0)
            printf("   purple, complementary %5.0f nm / %5.0f nm\n", -s.dominant_nm, s.peak_nm);
        else
            printf("   -\n");
    }
    return 0;
}

/* The experiment on the material of lib: the table, then the pattern when asked. The exit status. */
static int laser_run(const LaserArgs *a, GLibrary *lib)
{
    GMaterial *m = glibrary_material(lib, a->name);
    if (!m) {
        fprintf(stderr, "gmat laser: %s defines no material named '%s' (gmat list %s shows them)\n", a->file, a->name,
                a->file);
        return 1;
    }
    GScratch *sc = gscratch_create(0);
    if (!sc) {
        fprintf(stderr, "gmat laser: out of memory\n");
        return 1;
    }
    const GColorModel *model = glibrary_colormodel(lib);
    printf("material %s (%s), colour model %s\n", a->name, gmaterial_name(m), gcolormodel_name(model));
    if (model->nsamples == 0)
        printf("(a non-spectral model: nothing can shift, a white beam is used; try --colormodel bispectral)\n");
    printf("  elevation   kept     shifted   total    shifted light: dominant / peak\n");
    int rc = print_splits(a, m, sc);
    if (rc == 0 && a->pattern)
        rc = write_pattern(m, sc, a->nm, a->el, a->nel, (int)a->size, a->extent, a->pattern);
    gscratch_destroy(sc);
    return rc;
}

int gmat_laser(int argc, char **argv, const GReaderOptions *base)
{
    LaserArgs a;
    int rc = laser_args(argc, argv, &a);
    if (rc >= 0)
        return rc;
    GLibrary *lib;
    GError err;
    if (a.pattern && gimage_check_output(a.pattern, &err) != G_OK) { /* before any work */
        fprintf(stderr, "gmat laser: %s\n", err.message);
        return 1;
    }
    if (gmat_read(a.file, base, a.colormodel, a.step, 0, &lib, &err) != G_OK) {
        fprintf(stderr, "gmat laser: %s\n", err.message);
        return 1;
    }
    rc = laser_run(&a, lib);
    glibrary_destroy(lib);
    return rc;
}
