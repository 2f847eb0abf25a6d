/* plot.c - gmat plot: a polar plot of the reflected light in the plane of incidence.
 *
 * The surface is the horizontal line near the bottom; the point of reflection is its centre. For each
 * outgoing direction in the plane (from grazing on the light's side, through the normal, to grazing on the
 * far side) the lobe reaches out to a distance proportional to the reflected luminance, filled with the
 * reflected colour (normalised so its largest sRGB channel is 1, so hue shows at every brightness). Grey
 * rings mark 25, 50, 75 and 100 % of the largest value. The incoming direction is drawn in white; the ideal
 * specular ray, if the material has one, is a coloured line whose length is its reflectance (the whole
 * radius = 1). */
#include "gmat.h"

#include <generic/image.h>
#include <generic/memory.h>

#include <math.h>
#include <stdio.h>

#define ANGLES 1801 /* -90 .. 90 degrees in 0.1 degree steps */

typedef struct Lobe {
    float y[ANGLES];
    float rgb[ANGLES][3];
} Lobe;

static void put(GImage *img, int x, int y, const float c[3])
{
    if (x < 0 || y < 0 || x >= img->width || y >= img->height)
        return;
    float *p = img->pixels + ((size_t)y * img->width + x) * 3;
    p[0] = c[0];
    p[1] = c[1];
    p[2] = c[2];
}

static void line(GImage *img, double x0, double y0, double x1, double y1, const float c[3])
{
    const double far = 1e6; /* far outside any image: not drawn, and kept away from the integer casts below */
    if (!(fabs(x0) < far && fabs(y0) < far && fabs(x1) < far && fabs(y1) < far))
        return;
    int n = (int)(fmax(fabs(x1 - x0), fabs(y1 - y0)) * 2) + 1;
    for (int i = 0; i <= n; i++) {
        double t = (double)i / n;
        int x = (int)lround(x0 + (x1 - x0) * t), y = (int)lround(y0 + (y1 - y0) * t);
        for (int d = 0; d < 2; d++)
            put(img, x + d, y, c);
    }
}

/* The reflected colour of one direction as a display colour: largest channel 1, negatives clipped. */
static void display(const GColor *c, float out[3], float *y)
{
    double xyz[3] = {0, 0, 0}, rgb[3];
    if (gcolor_to_xyz(c, GCOLOR_LIGHT, xyz) != G_OK)
        xyz[0] = xyz[1] = xyz[2] = 0.0; /* shown black */
    gcie_xyz_to_rgb(xyz, rgb);
    double mx = fmax(rgb[0], fmax(rgb[1], rgb[2]));
    for (int k = 0; k < 3; k++)
        out[k] = mx > 0 ? (float)fmax(0.0, rgb[k] / mx) : 0.0f;
    *y = (float)fmax(0.0, xyz[1]);
}

int gmat_plot(GmatContext *ctx, double theta_in, int size, const char *path, GError *err)
{
    int check = gimage_check_output(path, err); /* before any work */
    if (check != G_OK)
        return check;
    Lobe *lobe = gmem_calloc(1, sizeof *lobe);
    if (!lobe)
        return gerror_set(err, G_ERR_NOMEM, "out of memory");
    /* the light comes from phi = 180 degrees (the left); signed angle a: < 0 on the light's side */
    GVec3 in = gmat_direction(theta_in, 180.0);
    double ymax = 0.0;
    for (int i = 0; i < ANGLES; i++) {
        double a = -90.0 + 0.1 * i;
        int rc = gmat_reflect(ctx, in, gmat_direction(fabs(a), a < 0 ? 180.0 : 0.0));
        if (rc != G_OK) {
            gmem_free(lobe);
            return gerror_set(err, rc, "evaluating the material failed (%s)", gstatus_string(rc));
        }
        display(&ctx->result, lobe->rgb[i], &lobe->y[i]);
        ymax = fmax(ymax, lobe->y[i]);
    }
    GImage img = {0};
    int rc = gimage_create(&img, size, size * 3 / 4, 3, err);
    if (rc != G_OK) {
        gmem_free(lobe);
        return rc;
    }
    double cx = size / 2.0, cy = img.height - size * 0.08, radius = size * 0.44;
    static const float bg[3] = {0.02f, 0.02f, 0.025f}, ring[3] = {0.12f, 0.12f, 0.12f};
    for (int y = 0; y < img.height; y++)
        for (int x = 0; x < img.width; x++) {
            double dx = x + 0.5 - cx, dy = cy - (y + 0.5), d = sqrt(dx * dx + dy * dy);
            put(&img, x, y, bg);
            if (dy < 0)
                continue;
            double a = atan2(dx, dy) * 180.0 / M_PI; /* 0 along the normal, negative to the left */
            double f = (a + 90.0) / 0.1;
            int i = (int)floor(f);
            if (i < 0 || i >= ANGLES - 1)
                continue;
            double t = f - i, yv = (1 - t) * lobe->y[i] + t * lobe->y[i + 1];
            double r = ymax > 0 ? radius * yv / ymax : 0.0;
            double rr = d / radius * 4.0;
            if (fabs(rr - lround(rr)) * radius / 4.0 < 0.6 && lround(rr) >= 1 && lround(rr) <= 4)
                put(&img, x, y, ring);
            if (d <= r) {
                const float *c = lobe->rgb[t < 0.5 ? i : i + 1];
                float shade[3] = {0.85f * c[0], 0.85f * c[1], 0.85f * c[2]};
                put(&img, x, y, shade);
            }
        }
    static const float surface[3] = {0.5f, 0.5f, 0.5f}, white[3] = {1, 1, 1};
    line(&img, cx - radius * 1.05, cy, cx + radius * 1.05, cy, surface);
    line(&img, cx, cy, cx + in.x * radius, cy - in.z * radius, white);
    GVec3 dir;
    int spec = gmat_specular(ctx, in, &dir);
    if (spec == 1) {
        float c[3], y;
        display(&ctx->result, c, &y);
        line(&img, cx, cy, cx + dir.x * radius * fmin(1.0, y), cy - dir.z * radius * fmin(1.0, y), c);
    }
    rc = gimage_write(path, &img, NULL, err);
    gimage_free(&img);
    gmem_free(lobe);
    if (rc == G_OK)
        printf("wrote %s: %dx%d, lobe maximum %.6g (reflected luminance for unit white light), specular %s\n", path,
               size, size * 3 / 4, ymax, spec == 1 ? "ray drawn" : "none");
    return rc;
}
