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

/* The command line of sky and the sky it describes. */
typedef struct SkyArgs {
    const char *out; /* -o */
    int h;           /* --height */
    double elev, azim, radius, e_sun, e_sky;
} SkyArgs;

/* Reads the command line into a: -1 to go on, else the exit status to end with. */
static int sky_args(int argc, char **argv, SkyArgs *a)
{
    enum { OPT_HEIGHT = CLI_FIRST_OWN, OPT_ELEV, OPT_AZIM, OPT_RADIUS, OPT_SUN, OPT_SKY };
    static const struct option longopts[] = {
        CLI_COMMON_OPTIONS, {"output", required_argument, NULL, 'o'}, {"height", required_argument, NULL, OPT_HEIGHT},
        {"sun-elevation", required_argument, NULL, OPT_ELEV}, {"sun-azimuth", required_argument, NULL, OPT_AZIM},
        {"sun-radius", required_argument, NULL, OPT_RADIUS}, {"sun-irradiance", required_argument, NULL, OPT_SUN},
        {"sky-irradiance", required_argument, NULL, OPT_SKY}, {NULL, 0, NULL, 0},
    };
    *a = (SkyArgs){NULL, 64, 40.0, 130.0, 3.0, 3.0, 1.0};
    CliParser cp;
    cli_begin(&cp, "gprobe sky", argc, argv, "ho:", longopts);
    int c, status = CLI_OK;
    while ((c = cli_next_own(&cp, "gprobe", sky_usage, &status)) != -1) {
        const char *v = optarg;
        int rc;
        switch (c) {
        case CLI_EXIT:
            return status;
        case 'o':
            a->out = v;
            rc = 0;
            break;
        case OPT_HEIGHT:
            rc = cli_int("gprobe", "--height", v, 4, 8192, &a->h);
            break;
        case OPT_ELEV:
            rc = cli_double("gprobe", "--sun-elevation", v, -90.0, 90.0, &a->elev);
            break;
        case OPT_AZIM:
            rc = cli_double("gprobe", "--sun-azimuth", v, -360.0, 360.0, &a->azim);
            break;
        case OPT_RADIUS:
            rc = cli_double("gprobe", "--sun-radius", v, 0.05, 45.0, &a->radius);
            break;
        case OPT_SUN:
            rc = cli_double("gprobe", "--sun-irradiance", v, 0.0, 1e9, &a->e_sun);
            break;
        case OPT_SKY:
            rc = cli_double("gprobe", "--sky-irradiance", v, 0.0, 1e9, &a->e_sky);
            break;
        default:
            rc = -1;
        }
        if (rc)
            return CLI_USAGE;
    }
    if (no_operands(&cp))
        return CLI_USAGE;
    if (!a->out) {
        fprintf(stderr, "gprobe sky: -o FILE is required\n");
        return CLI_USAGE;
    }
    return -1;
}

/* The picture being made: w x h RGB pixels, the share of each pixel the sun's disc covers, and the directions. */
typedef struct Sky {
    int w, h;
    float *px;
    double *sun_cov;
    const GProbe *grid; /* a black probe of the size: only for its directions */
    GVec3 sun;
    double q; /* Q = q sin(theta) P, as the library weighs pixels */
} Sky;

static GVec3 pixel_dir(const Sky *s, int x, int y) { return gprobe_direction(s->grid, x + 0.5, y + 0.5); }

/* The unscaled sky above the horizon and the sun's coverage of every pixel (none in the ground); the sky's
 * irradiance on a horizontal surface into *sky_e and the sun's summed coverage weights into *sun_sum. */
static void sky_fill(Sky *s, double cos_r, double *sky_e, double *sun_sum)
{
    *sky_e = *sun_sum = 0.0;
    for (int y = 0; y < s->h; y++) {
        double sin_t = sin(M_PI * (y + 0.5) / s->h);
        for (int x = 0; x < s->w; x++) {
            GVec3 d = pixel_dir(s, x, y);
            float *p = s->px + ((size_t)y * s->w + x) * 3;
            int covered = 0;
            for (int j = 0; j < SKY_SUB; j++)
                for (int i = 0; i < SKY_SUB; i++)
                    covered += gvec3_dot(gprobe_direction(s->grid, x + (i + 0.5) / SKY_SUB, y + (j + 0.5) / SKY_SUB),
                                         s->sun) >= cos_r;
            double *cov = &s->sun_cov[(size_t)y * s->w + x];
            *cov = d.z > 0.0 ? (double)covered / (SKY_SUB * SKY_SUB) : 0.0;
            *sun_sum += *cov * s->q * sin_t;
            if (d.z <= 0.0)
                continue; /* ground: filled by sky_light */
            double t = 1.0 - d.z, gamma = acos(fmax(-1.0, fmin(1.0, gvec3_dot(d, s->sun))));
            double glow = 0.6 * exp(-gamma / 0.2), c[3];
            for (int k = 0; k < 3; k++) {
                c[k] = (1.0 - t) * sky_zenith[k] + t * sky_horizon[k] + glow * sun_colour[k];
                p[k] = (float)c[k];
            }
            *sky_e += lum3(c) * s->q * sin_t * d.z;
        }
    }
}

/* Scales the sky by ks and adds the sun's disc of radiance ls; the horizontal irradiance of both into horiz. */
static void sky_scale(Sky *s, double ks, double ls, double horiz[3])
{
    horiz[0] = horiz[1] = horiz[2] = 0.0;
    for (int y = 0; y < s->h; y++) {
        double sin_t = sin(M_PI * (y + 0.5) / s->h);
        for (int x = 0; x < s->w; x++) {
            GVec3 d = pixel_dir(s, x, y);
            float *p = s->px + ((size_t)y * s->w + x) * 3;
            double cov = s->sun_cov[(size_t)y * s->w + x];
            for (int k = 0; k < 3; k++) {
                p[k] = (float)(d.z > 0.0 ? ks * p[k] : 0.0);
                p[k] += (float)(cov * ls * sun_colour[k]);
                if (d.z > 0.0)
                    horiz[k] += p[k] * s->q * sin_t * d.z;
            }
        }
    }
}

/* The ground: Lambertian, lit by the horizontal irradiance horiz. */
static void sky_ground(Sky *s, const double horiz[3])
{
    for (int y = 0; y < s->h; y++)
        for (int x = 0; x < s->w; x++) {
            float *p = s->px + ((size_t)y * s->w + x) * 3;
            if (pixel_dir(s, x, y).z <= 0.0)
                for (int k = 0; k < 3; k++)
                    p[k] += (float)(ground_albedo[k] / M_PI * horiz[k]);
        }
}

/* The sky of a into px (2 h x h, RGB): the sky scaled to its irradiance, the sun to its own, then the ground lit
 * by both. */
static void sky_render(const SkyArgs *a, const GProbe *grid, float *px, double *sun_cov)
{
    const double el = a->elev * M_PI / 180.0, az = a->azim * M_PI / 180.0;
    Sky s = {2 * a->h, a->h, px, sun_cov, grid, gvec3(cos(el) * cos(az), cos(el) * sin(az), sin(el)), 0.0};
    s.q = 2.0 * M_PI * M_PI / ((double)s.w * s.h);
    double sky_e, sun_sum, horiz[3];
    sky_fill(&s, cos(a->radius * M_PI / 180.0), &sky_e, &sun_sum);
    double ks = sky_e > 0.0 ? a->e_sky / sky_e : 0.0;
    double ls = sun_sum > 0.0 ? a->e_sun / (sun_sum * lum3(sun_colour)) : 0.0;
    sky_scale(&s, ks, ls, horiz);
    sky_ground(&s, horiz);
}

int cmd_sky(int argc, char **argv)
{
    SkyArgs a;
    int status = sky_args(argc, argv, &a);
    if (status >= 0)
        return status;
    if (output_check(a.out, 1) != 0)
        return 1;
    const int w = 2 * a.h, h = a.h;
    GError err;
    GProbe *grid = NULL;
    float *px = gmem_calloc((size_t)w * h * 3, sizeof *px);
    double *sun_cov = gmem_calloc((size_t)w * h, sizeof *sun_cov);
    if (!px || !sun_cov || gprobe_create(w, h, NULL, &grid, &err) != G_OK) {
        fprintf(stderr, "gprobe: out of memory for a %dx%d probe\n", w, h);
        gmem_free(px);
        gmem_free(sun_cov);
        return 1;
    }
    sky_render(&a, grid, px, sun_cov);
    gprobe_destroy(grid);
    gmem_free(sun_cov);
    GProbe *p = NULL;
    int rc = gprobe_create(w, h, px, &p, &err);
    gmem_free(px);
    if (rc == G_OK)
        rc = gprobe_save(p, a.out, GPROBE_LATLONG, &err);
    gprobe_destroy(p);
    if (rc != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        return 1;
    }
    return 0;
}
