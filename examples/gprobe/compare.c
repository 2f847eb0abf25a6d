/* compare.c - `gprobe compare`: the RMSE of a render against a reference, over the whole image and inside
 * the cast shadows, so the approximation techniques can be compared where irradiance alone cannot tell them
 * apart (Madsen & Laursen's future work: "the reflected radiance in and around cast shadows").
 *
 * RMSE = sqrt(sum over the pixels and the three channels of (a - r)^2 / (3 * pixels)) on the linear float
 * values; "relative" divides it by the mean of the reference over the same pixels and channels.
 *
 * The shadow mask is either given (--mask: a pixel is in the shadows where the mean of its channels is above
 * 0.5, so a white-on-black PNG works), or found from an unshadowed render of the same scene (--unshadowed:
 * gtrace ... --probe-technique reference --probe-shadows off, with the same samples, so both renders draw the
 * same directions per pixel and their ratio is the visibility-weighted share of the light): a pixel is in the
 * shadows where the reference's luminance is below (1 - T) times the unshadowed one's (T = --threshold,
 * default 0.1: at least a tenth of the direct light is blocked). */
#include "gprobe.h"

#include <generic/services/image.h>
#include <generic/memory.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

static void compare_usage(FILE *f)
{
    fprintf(f, "usage: gprobe compare IMAGE REFERENCE [--mask MASK | --unshadowed IMAGE [--threshold T]]\n"
               "                      [--write-mask OUT]\n"
               "Prints the RMSE of IMAGE against REFERENCE (linear float images of one size, e.g. gtrace's .exr),\n"
               "over the whole image and inside the cast shadows:\n"
               "    whole  pixels N rmse X relative X/mean(reference)\n"
               "    shadow pixels N rmse X relative X/mean(reference in the shadows)\n"
               "RMSE is over pixels and the three channels. The shadows are a given mask or are found from an\n"
               "unshadowed render of the same scene with the same samples (see examples/gprobe/compare.c).\n"
               "  --mask MASK        shadow pixels: where the mean of MASK's channels is above 0.5\n"
               "  --unshadowed IMG   shadow pixels: where the reference's luminance is below (1 - T) times IMG's\n"
               "  --threshold T      the share of blocked light that makes a shadow (default 0.1)\n"
               "  --write-mask OUT   write the shadow mask (white in the shadows) as an image\n"
               "  -h, --help         this text\n"
               "  --version          the version\n" CLI_EXIT_STATUS_HELP);
}

static double luminance(const float *p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

/* Reads an RGB image and checks its size against the first one read (w, h start at 0). */
static int read_rgb(const char *path, int *w, int *h, GImage *img)
{
    GError err;
    if (gimage_read(path, GIMAGE_READ_RGB, img, &err) != G_OK) {
        fprintf(stderr, "gprobe: %s\n", err.message);
        return -1;
    }
    if (*w && (img->width != *w || img->height != *h)) {
        fprintf(stderr, "gprobe compare: %s is %dx%d, the other images %dx%d\n", path, img->width, img->height,
                *w, *h);
        gimage_free(img);
        return -1;
    }
    *w = img->width;
    *h = img->height;
    return 0;
}

/* RMSE and reference mean over the pixels where mask is non-zero (mask NULL: all). */
static void rmse(const GImage *a, const GImage *r, const unsigned char *mask, long *count, double *err,
                 double *mean)
{
    long n = 0;
    double se = 0.0, sum = 0.0;
    size_t npix = (size_t)a->width * a->height;
    for (size_t i = 0; i < npix; i++) {
        if (mask && !mask[i])
            continue;
        n++;
        for (int c = 0; c < 3; c++) {
            double d = (double)a->pixels[3 * i + c] - r->pixels[3 * i + c];
            se += d * d;
            sum += r->pixels[3 * i + c];
        }
    }
    *count = n;
    *err = n ? sqrt(se / (3.0 * n)) : 0.0;
    *mean = n ? sum / (3.0 * n) : 0.0;
}

static void report(const char *what, long n, double e, double mean)
{
    printf("%-6s pixels %ld rmse %.6g relative %.6g\n", what, n, e, mean > 0.0 ? e / mean : 0.0);
}

/* The command line of compare. */
typedef struct CompareArgs {
    const char *files[2];                      /* IMAGE REFERENCE */
    const char *mask, *unshadowed, *write_mask; /* --mask, --unshadowed, --write-mask */
    double threshold;                          /* --threshold */
} CompareArgs;

/* getopt_long codes of compare's options. */
enum { OPT_MASK = CLI_FIRST_OWN, OPT_UNSHADOWED, OPT_WRITE_MASK, OPT_THRESHOLD };

/* Handles one of compare's options: 0, or -1 on a usage error (message printed). */
static int compare_option(CompareArgs *a, int c, const char *v)
{
    if (c == OPT_MASK) {
        a->mask = v;
    } else if (c == OPT_UNSHADOWED) {
        a->unshadowed = v;
    } else if (c == OPT_WRITE_MASK) {
        a->write_mask = v;
    } else if (c == OPT_THRESHOLD) {
        char *end;
        a->threshold = strtod(v, &end);
        if (end == v || *end || !(a->threshold > 0.0 && a->threshold < 1.0)) {
            fprintf(stderr, "gprobe compare: --threshold expects a number in (0, 1), got '%s'\n", v);
            return -1;
        }
    } else {
        return -1;
    }
    return 0;
}

/* Reads the command line into a: -1 to go on, else the exit status to end with. */
static int compare_args(int argc, char **argv, CompareArgs *a)
{
    static const struct option longopts[] = {
        CLI_COMMON_OPTIONS, {"mask", required_argument, NULL, OPT_MASK},
        {"unshadowed", required_argument, NULL, OPT_UNSHADOWED},
        {"write-mask", required_argument, NULL, OPT_WRITE_MASK}, {"threshold", required_argument, NULL, OPT_THRESHOLD},
        {NULL, 0, NULL, 0},
    };
    *a = (CompareArgs){{NULL, NULL}, NULL, NULL, NULL, 0.1};
    CliParser cp;
    cli_begin(&cp, "gprobe compare", argc, argv, "h", longopts);
    int c, status = CLI_OK, nfiles;
    while ((c = cli_next_own(&cp, "gprobe", compare_usage, &status)) != -1) {
        if (c == CLI_EXIT)
            return status;
        if (compare_option(a, c, optarg) != 0)
            return CLI_USAGE;
    }
    char **rest = cli_operands(&cp, &nfiles);
    if (nfiles > 2) {
        fprintf(stderr, "gprobe compare: more than two images given ('%s')\n", rest[2]);
        return CLI_USAGE;
    }
    for (int i = 0; i < nfiles; i++)
        a->files[i] = rest[i];
    const char *wrong = NULL;
    if (nfiles != 2)
        wrong = "give an image and its reference (gprobe compare --help)";
    else if (a->mask && a->unshadowed)
        wrong = "give either --mask or --unshadowed, not both";
    else if (a->write_mask && !a->mask && !a->unshadowed)
        wrong = "--write-mask needs --mask or --unshadowed";
    if (wrong) {
        fprintf(stderr, "gprobe compare: %s\n", wrong);
        return CLI_USAGE;
    }
    return -1;
}

/* The shadow mask (1 in the shadows) from aux, read from --mask or --unshadowed: NULL when out of memory. */
static unsigned char *shadow_mask(const CompareArgs *a, const GImage *ref, const GImage *aux)
{
    size_t npix = (size_t)ref->width * ref->height;
    unsigned char *mask = gmem_calloc(npix, 1);
    if (!mask) {
        fprintf(stderr, "gprobe: out of memory\n");
        return NULL;
    }
    for (size_t i = 0; i < npix; i++) {
        const float *m = aux->pixels + 3 * i;
        if (a->mask) {
            mask[i] = (m[0] + m[1] + m[2]) / 3.0 > 0.5;
        } else {
            double open = luminance(m);
            mask[i] = open > 0.0 && luminance(ref->pixels + 3 * i) < (1.0 - a->threshold) * open;
        }
    }
    return mask;
}

/* The mask as an image, white in the shadows: 0, or -1 with a message. */
static int write_mask(const char *path, const unsigned char *mask, int w, int h)
{
    GImage out = {0};
    GError err;
    int rc = gimage_create(&out, w, h, 3, &err);
    if (rc == G_OK) {
        for (size_t i = 0; i < (size_t)w * h; i++)
            out.pixels[3 * i] = out.pixels[3 * i + 1] = out.pixels[3 * i + 2] = mask[i] ? 1.0f : 0.0f;
        rc = gimage_write(path, &out, NULL, &err);
    }
    if (rc != G_OK)
        fprintf(stderr, "gprobe: %s\n", err.message);
    gimage_free(&out);
    return rc == G_OK ? 0 : -1;
}

int cmd_compare(int argc, char **argv)
{
    CompareArgs a;
    int status = compare_args(argc, argv, &a);
    if (status >= 0)
        return status;
    if (output_check(a.write_mask, 1) != 0)
        return 1;
    int w = 0, h = 0;
    GImage img = {0}, ref = {0}, aux = {0};
    unsigned char *mask = NULL;
    const char *aux_path = a.mask ? a.mask : a.unshadowed;
    status = 1;
    if (read_rgb(a.files[0], &w, &h, &img) || read_rgb(a.files[1], &w, &h, &ref) ||
        (aux_path && (read_rgb(aux_path, &w, &h, &aux) || !(mask = shadow_mask(&a, &ref, &aux)))))
        goto done;
    long n;
    double e, mean;
    rmse(&img, &ref, NULL, &n, &e, &mean);
    report("whole", n, e, mean);
    if (mask) {
        rmse(&img, &ref, mask, &n, &e, &mean);
        report("shadow", n, e, mean);
    }
    if (!a.write_mask || write_mask(a.write_mask, mask, w, h) == 0)
        status = 0;
done:
    gimage_free(&img);
    gimage_free(&ref);
    gimage_free(&aux);
    gmem_free(mask);
    return status;
}
