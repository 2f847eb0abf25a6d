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

int cmd_compare(int argc, char **argv)
{
    const char *files[2] = {NULL, NULL}, *mask_path = NULL, *unshadowed = NULL, *write_mask = NULL;
    double threshold = 0.1;
    int nfiles = 0;
    enum { OPT_MASK = CLI_FIRST_OWN, OPT_UNSHADOWED, OPT_WRITE_MASK, OPT_THRESHOLD };
    static const struct option longopts[] = {
        CLI_COMMON_OPTIONS, {"mask", required_argument, NULL, OPT_MASK},
        {"unshadowed", required_argument, NULL, OPT_UNSHADOWED}, {"write-mask", required_argument, NULL, OPT_WRITE_MASK},
        {"threshold", required_argument, NULL, OPT_THRESHOLD}, {NULL, 0, NULL, 0},
    };
    CliParser cp;
    cli_begin(&cp, "gprobe compare", argc, argv, "h", longopts);
    int c;
    while ((c = cli_next(&cp)) != -1) {
        const char *v = optarg;
        if (c == 'h') {
            compare_usage(stdout);
            return CLI_OK;
        } else if (c == CLI_VERSION) {
            return cli_version("gprobe");
        } else if (c == OPT_MASK) {
            mask_path = v;
        } else if (c == OPT_UNSHADOWED) {
            unshadowed = v;
        } else if (c == OPT_WRITE_MASK) {
            write_mask = v;
        } else if (c == OPT_THRESHOLD) {
            char *end;
            threshold = strtod(v, &end);
            if (end == v || *end || !(threshold > 0.0 && threshold < 1.0)) {
                fprintf(stderr, "gprobe compare: --threshold expects a number in (0, 1), got '%s'\n", v);
                return CLI_USAGE;
            }
        } else {
            return CLI_USAGE;
        }
    }
    char **rest = cli_operands(&cp, &nfiles);
    if (nfiles > 2) {
        fprintf(stderr, "gprobe compare: more than two images given ('%s')\n", rest[2]);
        return CLI_USAGE;
    }
    for (int i = 0; i < nfiles; i++)
        files[i] = rest[i];
    if (nfiles != 2) {
        fprintf(stderr, "gprobe compare: give an image and its reference (gprobe compare --help)\n");
        return 2;
    }
    if (mask_path && unshadowed) {
        fprintf(stderr, "gprobe compare: give either --mask or --unshadowed, not both\n");
        return 2;
    }
    if (write_mask && !mask_path && !unshadowed) {
        fprintf(stderr, "gprobe compare: --write-mask needs --mask or --unshadowed\n");
        return 2;
    }
    if (output_check(write_mask, 1) != 0)
        return 1;
    int w = 0, h = 0, status = 1;
    GImage img = {0}, ref = {0}, aux = {0}, out = {0};
    unsigned char *mask = NULL;
    if (read_rgb(files[0], &w, &h, &img) || read_rgb(files[1], &w, &h, &ref))
        goto done;
    size_t npix = (size_t)w * h;
    if (mask_path || unshadowed) {
        if (read_rgb(mask_path ? mask_path : unshadowed, &w, &h, &aux))
            goto done;
        if (!(mask = gmem_calloc(npix, 1))) {
            fprintf(stderr, "gprobe: out of memory\n");
            goto done;
        }
        for (size_t i = 0; i < npix; i++) {
            const float *m = aux.pixels + 3 * i;
            if (mask_path) {
                mask[i] = (m[0] + m[1] + m[2]) / 3.0 > 0.5;
            } else {
                double open = luminance(m);
                mask[i] = open > 0.0 && luminance(ref.pixels + 3 * i) < (1.0 - threshold) * open;
            }
        }
    }
    long n;
    double e, mean;
    rmse(&img, &ref, NULL, &n, &e, &mean);
    report("whole", n, e, mean);
    if (mask) {
        rmse(&img, &ref, mask, &n, &e, &mean);
        report("shadow", n, e, mean);
    }
    if (write_mask) {
        GError err;
        if (gimage_create(&out, w, h, 3, &err) != G_OK) {
            fprintf(stderr, "gprobe: %s\n", err.message);
            goto done;
        }
        for (size_t i = 0; i < npix; i++)
            out.pixels[3 * i] = out.pixels[3 * i + 1] = out.pixels[3 * i + 2] = mask[i] ? 1.0f : 0.0f;
        if (gimage_write(write_mask, &out, NULL, &err) != G_OK) {
            fprintf(stderr, "gprobe: %s\n", err.message);
            goto done;
        }
    }
    status = 0;
done:
    gimage_free(&img);
    gimage_free(&ref);
    gimage_free(&aux);
    gimage_free(&out);
    gmem_free(mask);
    return status;
}
