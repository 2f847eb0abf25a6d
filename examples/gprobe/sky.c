/* sky.c - `gprobe sky`: writes a small synthetic outdoor probe (a clear sky, a sun disc and a ground), so
 * scenes and tests can be lit by a probe the repository makes itself (examples/scenes/sky.hdr is one).
 *
 * Not a physical sky model, a plausible and fully specified one (linear Rec.709 RGB, z up):
 *   sky (above the horizon)  zenith colour blended to the horizon colour by 1 - cos(theta), plus a
 *                            circumsolar glow exp(-gamma / 0.2) (gamma: angle to the sun) in the sun's colour;
 *                            the sky is scaled so that it alone gives a horizontal surface the irradiance
 *                            --sky-irradiance;
 *   sun                      a disc of --sun-radius degrees, anti-aliased (each pixel's covered fraction from
 *                            8 x 8 sub-samples), of uniform radiance chosen so that the disc's pixels give a
 *                            surface facing the sun the irradiance --sun-irradiance (summed as the
 *                            library's weights Q, the paper's Eq. 4);
 *   ground (below)           Lambertian with albedo (0.30, 0.26, 0.21) lit by the sky and the sun.
 * Every irradiance is the luminance (Rec. 709 weights) of the RGB irradiance. */
#include "gprobe.h"

#include <generic/memory.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define SKY_SUB 8

static const double sky_zenith[3] = {0.16, 0.30, 0.75};
static const double sky_horizon[3] = {0.62, 0.72, 0.90};
static const double sun_colour[3] = {1.0, 0.90, 0.76};
static const double ground_albedo[3] = {0.30, 0.26, 0.21};

static double lum3(const double c[3]) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }

static void sky_usage(FILE *f)
{
    fprintf(f, "usage: gprobe sky -o FILE [--height H] [--sun-elevation DEG] [--sun-azimuth DEG]\n"
               "                  [--sun-radius DEG] [--sun-irradiance E] [--sky-irradiance E]\n"
               "Writes a synthetic lat-long probe: a clear sky blended from zenith to horizon with a glow around\n"
               "the sun, an anti-aliased sun disc, and a Lambertian ground lit by both (see examples/gprobe/sky.c).\n"
               "Directions as everywhere in gprobe: z up, azimuth from +x towards +y.\n"
               "  -o FILE              output (.hdr, .exr, .pfm: linear float)\n"
               "  --height H           rows of the lat-long image, width 2 H (default 64)\n"
               "  --sun-elevation DEG  sun above the horizon (default 40)\n"
               "  --sun-azimuth DEG    sun azimuth from +x towards +y (default 130)\n"
               "  --sun-radius DEG     angular radius of the disc (default 3)\n"
               "  --sun-irradiance E   irradiance of the sun on a surface facing it (default 3)\n"
               "  --sky-irradiance E   irradiance of the sky alone on a horizontal surface (default 1)\n"
               "  -h, --help           this text\n"
               "  --version            the version\n" CLI_EXIT_STATUS_HELP);
}

static int parse_double(const char *opt, const char *s, double lo, double hi, double *out)
{
    char *end;
    double v = strtod(s, &end);
    if (end == s || *end || !(v >= lo && v <= hi)) {
        fprintf(stderr, "gprobe: %s expects a number in [%g, %g], got '%s'\n", opt, lo, hi, s);
        return -1;
    }
    *out = v;
    return 0;
}

int cmd_sky(int argc, char **argv)
{
    const char *out = NULL;
    int h = 64;
    double elev = 40.0, azim = 130.0, radius = 3.0, e_sun = 3.0, e_sky = 1.0;
    enum { OPT_HEIGHT = CLI_FIRST_OWN, OPT_ELEV, OPT_AZIM, OPT_RADIUS, OPT_SUN, OPT_SKY };
    static const struct option longopts[] = {
        CLI_COMMON_OPTIONS, {"output", required_argument, NULL, 'o'}, {"height", required_argument, NULL, OPT_HEIGHT},
        {"sun-elevation", required_argument, NULL, OPT_ELEV}, {"sun-azimuth", required_argument, NULL, OPT_AZIM},
        {"sun-radius", required_argument, NULL, OPT_RADIUS}, {"sun-irradiance", required_argument, NULL, OPT_SUN},
        {"sky-irradiance", required_argument, NULL, OPT_SKY}, {NULL, 0, NULL, 0},
    };
    CliParser cp;
    cli_begin(&cp, "gprobe sky", argc, argv, "ho:", longopts);
    int c;
    while ((c = cli_next(&cp)) != -1) {
        const char *v = optarg, *a = c == OPT_ELEV ? "--sun-elevation" : c == OPT_AZIM ? "--sun-azimuth"
                                                  : c == OPT_RADIUS ? "--sun-radius" : c == OPT_SUN ? "--sun-irradiance"
                                                                                                      : "--sky-irradiance";
        int rc = 0;
        if (c == 'h') {
            sky_usage(stdout);
            return CLI_OK;
        } else if (c == CLI_VERSION) {
            return cli_version("gprobe");
        } else if (c == 'o') {
            out = v;
        } else if (c == OPT_HEIGHT) {
            rc = parse_int("--height", v, 4, 8192, &h);
        } else if (c == OPT_ELEV) {
            rc = parse_double(a, v, -90.0, 90.0, &elev);
        } else if (c == OPT_AZIM) {
            rc = parse_double(a, v, -360.0, 360.0, &azim);
        } else if (c == OPT_RADIUS) {
            rc = parse_double(a, v, 0.05, 45.0, &radius);
        } else if (c == OPT_SUN) {
            rc = parse_double(a, v, 0.0, 1e9, &e_sun);
        } else if (c == OPT_SKY) {
            rc = parse_double(a, v, 0.0, 1e9, &e_sky);
        } else {
            return CLI_USAGE;
        }
        if (rc)
            return CLI_USAGE;
    }
    if (no_operands(&cp))
        return CLI_USAGE;
    if (!out) {
        fprintf(stderr, "gprobe sky: -o FILE is required\n");
        return 2;
    }
    if (output_check(out, 1) != 0)
        return 1;
    const int w = 2 * h;
    GError err;
    GProbe *grid = NULL; /* a black probe of the size: only for its directions */
    float *px = gmem_calloc((size_t)w * h * 3, sizeof *px);
    double *sun_cov = gmem_calloc((size_t)w * h, sizeof *sun_cov);
    if (!px || !sun_cov || gprobe_create(w, h, NULL, &grid, &err) != G_OK) {
        fprintf(stderr, "gprobe: out of memory for a %dx%d probe\n", w, h);
        gmem_free(px);
        gmem_free(sun_cov);
        return 1;
    }
    double el = elev * M_PI / 180.0, az = azim * M_PI / 180.0, cos_r = cos(radius * M_PI / 180.0);
    GVec3 sun = gvec3(cos(el) * cos(az), cos(el) * sin(az), sin(el));
    const double q = 2.0 * M_PI * M_PI / ((double)w * h); /* Q = q sin(theta) P, as the library weighs pixels */
    double sky_e = 0.0, sun_sum = 0.0;
    for (int y = 0; y < h; y++) {
        double sin_t = sin(M_PI * (y + 0.5) / h);
        for (int x = 0; x < w; x++) {
            GVec3 d = gprobe_direction(grid, x + 0.5, y + 0.5);
            float *p = px + ((size_t)y * w + x) * 3;
            int covered = 0;
            for (int j = 0; j < SKY_SUB; j++)
                for (int i = 0; i < SKY_SUB; i++)
                    covered += gvec3_dot(gprobe_direction(grid, x + (i + 0.5) / SKY_SUB, y + (j + 0.5) / SKY_SUB),
                                         sun) >= cos_r;
            sun_cov[(size_t)y * w + x] = d.z > 0.0 ? (double)covered / (SKY_SUB * SKY_SUB) : 0.0; /* no sun in the ground */
            sun_sum += sun_cov[(size_t)y * w + x] * q * sin_t;
            if (d.z <= 0.0)
                continue; /* ground: filled below */
            double t = 1.0 - d.z, gamma = acos(fmax(-1.0, fmin(1.0, gvec3_dot(d, sun))));
            double glow = 0.6 * exp(-gamma / 0.2), c[3];
            for (int k = 0; k < 3; k++) {
                c[k] = (1.0 - t) * sky_zenith[k] + t * sky_horizon[k] + glow * sun_colour[k];
                p[k] = (float)c[k];
            }
            sky_e += lum3(c) * q * sin_t * d.z;
        }
    }
    /* scale the sky to its irradiance, the sun to its own, then light the ground with both */
    double ks = sky_e > 0.0 ? e_sky / sky_e : 0.0;
    double ls = sun_sum > 0.0 ? e_sun / (sun_sum * lum3(sun_colour)) : 0.0;
    double horiz[3];
    for (int k = 0; k < 3; k++)
        horiz[k] = 0.0;
    for (int y = 0; y < h; y++) {
        double sin_t = sin(M_PI * (y + 0.5) / h);
        for (int x = 0; x < w; x++) {
            GVec3 d = gprobe_direction(grid, x + 0.5, y + 0.5);
            float *p = px + ((size_t)y * w + x) * 3;
            double cov = sun_cov[(size_t)y * w + x];
            for (int k = 0; k < 3; k++) {
                p[k] = (float)(d.z > 0.0 ? ks * p[k] : 0.0);
                p[k] += (float)(cov * ls * sun_colour[k]);
                if (d.z > 0.0)
                    horiz[k] += p[k] * q * sin_t * d.z;
            }
        }
    }
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            GVec3 d = gprobe_direction(grid, x + 0.5, y + 0.5);
            float *p = px + ((size_t)y * w + x) * 3;
            if (d.z <= 0.0)
                for (int k = 0; k < 3; k++)
                    p[k] += (float)(ground_albedo[k] / M_PI * horiz[k]);
        }
    gprobe_destroy(grid);
    gmem_free(sun_cov);
    GProbe *p = NULL;
    int rc = gprobe_create(w, h, px, &p, &err);
    gmem_free(px);
    if (rc == G_OK)
        rc = gprobe_save(p, out, GPROBE_LATLONG, &err);
    gprobe_destroy(p);
    if (rc != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        return 1;
    }
    return 0;
}
