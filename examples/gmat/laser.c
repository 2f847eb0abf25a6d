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

int gmat_laser(int argc, char **argv, const GReaderOptions *base)
{
    const char *file = NULL, *name = NULL, *pattern = NULL, *colormodel = NULL;
    double nm = 532.0, el[MAX_ELEVATIONS] = {5, 20, 60}, extent = 1.5, size = 384, step = 0;
    int nel = 3;
    enum { OPT_WAVELENGTH = CLI_FIRST_OWN, OPT_ELEVATION, OPT_PATTERN, OPT_SIZE, OPT_EXTENT, OPT_COLORMODEL,
           OPT_STEP };
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
    CliParser p;
    cli_begin(&p, "gmat laser", argc - 1, argv + 1, "h", longopts);
    int c;
    while ((c = cli_next(&p)) != -1) {
        const char *v = optarg;
        switch (c) {
        case 'h':
            laser_usage(stdout);
            return CLI_OK;
        case CLI_VERSION:
            return cli_version("gmat");
        case OPT_WAVELENGTH:
            if (gmat_number(v, 200, 2000, &nm))
                return gmat_usage_error("laser", "--wavelength: '%s' is not a wavelength in nm", v);
            break;
        case OPT_ELEVATION:
            if (elevations(v, el, &nel))
                return gmat_usage_error("laser", "--elevation: '%s' is not a list of up to 16 angles in (0, 90] degrees",
                                        v);
            break;
        case OPT_PATTERN:
            pattern = v;
            break;
        case OPT_SIZE:
            if (gmat_number(v, 64, 4096, &size) || size != floor(size))
                return gmat_usage_error("laser", "--size: '%s' is not a whole number in 64..4096", v);
            break;
        case OPT_EXTENT:
            if (gmat_number(v, 0.01, 100, &extent))
                return gmat_usage_error("laser", "--extent: '%s' is not a number in 0.01..100", v);
            break;
        case OPT_COLORMODEL:
            colormodel = v;
            break;
        case OPT_STEP:
            if (gmat_number(v, 0.1, 400, &step))
                return gmat_usage_error("laser", "--step: '%s' is not a spacing in nm", v);
            break;
        default:
            return CLI_USAGE;
        }
    }
    int nrest;
    char **rest = cli_operands(&p, &nrest);
    if (nrest > 2)
        return gmat_usage_error("laser", "unexpected argument '%s'", rest[2]);
    file = nrest > 0 ? rest[0] : NULL;
    name = nrest > 1 ? rest[1] : NULL;
    if (!file || !name)
        return gmat_usage_error("laser", "%s", "FILE and MATERIAL are required");
    GColorModelOptions mo = {.step_nm = step};
    GReaderOptions opt = *base;
    opt.colormodel = colormodel;
    opt.colormodel_options = &mo;
    GLibrary *lib;
    GError err;
    if (pattern && gimage_check_output(pattern, &err) != G_OK) { /* before any work */
        fprintf(stderr, "gmat laser: %s\n", err.message);
        return 1;
    }
    if (greader_load_file(file, &opt, &lib, &err) != G_OK) {
        fprintf(stderr, "gmat laser: %s\n", err.message);
        return 1;
    }
    GMaterial *m = glibrary_material(lib, name);
    GScratch *sc = gscratch_create(0);
    int rc = 0;
    if (!m) {
        fprintf(stderr, "gmat laser: %s defines no material named '%s' (gmat list %s shows them)\n", file, name,
                file);
        rc = 1;
    } else if (!sc) {
        fprintf(stderr, "gmat laser: out of memory\n");
        rc = 1;
    }
    const GColorModel *model = glibrary_colormodel(lib);
    if (rc == 0) {
        printf("material %s (%s), colour model %s\n", name, gmaterial_name(m), gcolormodel_name(model));
        if (model->nsamples == 0)
            printf("(a non-spectral model: nothing can shift, a white beam is used; try --colormodel bispectral)\n");
        printf("  elevation   kept     shifted   total    shifted light: dominant / peak\n");
    }
    for (int k = 0; k < nel && rc == 0; k++) {
        GFluorLaserSplit s;
        if (gfluor_laser_split(m, sc, nm, el[k], NULL, &s, &err) != G_OK) {
            fprintf(stderr, "gmat laser: %s\n", err.message);
            rc = 1;
            break;
        }
        if (k == 0 && s.wavelength > 0)
            printf("  (beam on the %g nm sample)\n", s.wavelength);
        printf("  %6.1f    %7.4f  %7.4f  %7.4f", el[k], s.kept, s.shifted, s.kept + s.shifted);
        if (s.shifted > 0 && s.dominant_nm > 0)
            printf("   %5.0f nm / %5.0f nm\n", s.dominant_nm, s.peak_nm);
        else if (s.shifted > 0)
            printf("   purple, complementary %5.0f nm / %5.0f nm\n", -s.dominant_nm, s.peak_nm);
        else
            printf("   -\n");
    }
    if (rc == 0 && pattern)
        rc = write_pattern(m, sc, nm, el, nel, (int)size, extent, pattern);
    gscratch_destroy(sc);
    glibrary_destroy(lib);
    return rc;
}
