/* probe.c - light probe creation, loading, pixel weights, directions and lookups. */
#include "probe_internal.h"
#include "generic/memory.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static void probe_free_tables(GProbe *p)
{
    gmem_free(p->rgb);
    gmem_free(p->q);
    gmem_free(p->sat);
    gmem_free(p->cos_phi);
    gmem_free(p->sin_phi);
    gmem_free(p->cos_theta);
    gmem_free(p->sin_theta);
}

void gprobe_destroy(GProbe *p)
{
    if (!p)
        return;
    probe_free_tables(p);
    gmem_budget_release(p->charged);
    gmem_free(p);
}

/* Weights Q and the summed-area table of energy and energy-weighted direction. */
static void probe_prepare(GProbe *p)
{
    const int w = p->w, h = p->h;
    const double k = 2.0 * M_PI * M_PI / ((double)w * h);
    for (int u = 0; u < w; u++) {
        double phi = M_PI - 2.0 * M_PI * (u + 0.5) / w; /* see probe.h */
        p->cos_phi[u] = cos(phi);
        p->sin_phi[u] = sin(phi);
    }
    for (int v = 0; v < h; v++) {
        double theta = M_PI * (v + 0.5) / h;
        p->cos_theta[v] = cos(theta);
        p->sin_theta[v] = sin(theta);
    }
    #pragma omp parallel for schedule(static)
    for (int v = 0; v < h; v++) {
        const float s = (float)(k * p->sin_theta[v]);
        const float *src = p->rgb + (size_t)v * w * 3;
        float *dst = p->q + (size_t)v * w * 3;
        for (int i = 0; i < w * 3; i++)
            dst[i] = s * src[i];
    }
    const size_t stride = (size_t)(w + 1) * PROBE_SAT;
    memset(p->sat, 0, stride * sizeof(double)); /* row 0 */
    for (int v = 0; v < h; v++) {
        double *prev = p->sat + (size_t)v * stride, *row = prev + stride;
        double acc[PROBE_SAT] = {0};
        for (int c = 0; c < PROBE_SAT; c++)
            row[c] = 0.0;
        for (int u = 0; u < w; u++) {
            const float *q = p->q + ((size_t)v * w + u) * 3;
            double e = probe_lum(q);
            GVec3 d = probe_pixel_dir(p, u, v);
            acc[0] += e;
            acc[1] += e * d.x;
            acc[2] += e * d.y;
            acc[3] += e * d.z;
            acc[4] += q[0];
            acc[5] += q[1];
            acc[6] += q[2];
            for (int c = 0; c < PROBE_SAT; c++)
                row[(u + 1) * PROBE_SAT + c] = prev[(u + 1) * PROBE_SAT + c] + acc[c];
        }
    }
}

double probe_bytes(int width, int height)
{
    /* the pixels and their weights (3 floats each) and the summed-area table (PROBE_SAT doubles a corner) */
    return (double)width * height * 6 * sizeof(float) +
           ((double)width + 1) * ((double)height + 1) * PROBE_SAT * sizeof(double);
}

int probe_check_budget(int width, int height, GError *err)
{
    const double bytes = probe_bytes(width, height);
    const size_t limit = gmem_budget_limit(), used = gmem_budget_used();
    if (bytes > (double)(limit > used ? limit - used : 0)) {
        char what[64];
        snprintf(what, sizeof what, "a %dx%d probe", width, height);
        return gmem_budget_reserve((size_t)(bytes < (double)SIZE_MAX ? bytes : (double)SIZE_MAX), what, err);
    }
    return G_OK;
}

int gprobe_create(int width, int height, const float *rgb, GProbe **out, GError *err)
{
    if (!out)
        return gerror_set(err, G_ERR_INVALID, "gprobe_create: no output given");
    *out = NULL;
    if (height < 2 || width != 2 * height || height > (1 << 14))
        return gerror_set(err, G_ERR_INVALID,
                          "a latitude-longitude probe must be twice as wide as high (got %dx%d)", width, height);
    char what[64];
    snprintf(what, sizeof what, "a %dx%d probe", width, height);
    const size_t charge = (size_t)probe_bytes(width, height);
    int rc = gmem_budget_reserve(charge, what, err);
    if (rc != G_OK)
        return rc;
    GProbe *p = gmem_calloc(1, sizeof *p);
    if (!p) {
        gmem_budget_release(charge);
        return gerror_set(err, G_ERR_NOMEM, "out of memory for a %dx%d probe", width, height);
    }
    p->charged = charge;
    const size_t n = (size_t)width * height;
    p->w = width;
    p->h = height;
    p->rgb = gmem_calloc(n * 3, sizeof(float));
    p->q = gmem_calloc(n * 3, sizeof(float));
    p->sat = gmem_calloc((size_t)(width + 1) * (height + 1) * PROBE_SAT, sizeof(double));
    p->cos_phi = gmem_calloc(width, sizeof(double));
    p->sin_phi = gmem_calloc(width, sizeof(double));
    p->cos_theta = gmem_calloc(height, sizeof(double));
    p->sin_theta = gmem_calloc(height, sizeof(double));
    if (!p->rgb || !p->q || !p->sat || !p->cos_phi || !p->sin_phi || !p->cos_theta || !p->sin_theta) {
        gprobe_destroy(p);
        return gerror_set(err, G_ERR_NOMEM, "out of memory for a %dx%d probe", width, height);
    }
    if (rgb) {
        long bad = 0;
        for (size_t i = 0; i < n; i++) {
            int pixel_bad = 0;
            for (int c = 0; c < 3; c++) {
                float v = rgb[i * 3 + c];
                if (!(v >= 0.0f) || isinf(v)) { /* negative, NaN or infinite */
                    v = 0.0f;
                    pixel_bad = 1;
                } else if (v > GPROBE_MAX_RADIANCE) { /* sums of such values would overflow the weights */
                    v = GPROBE_MAX_RADIANCE;
                    pixel_bad = 1;
                }
                p->rgb[i * 3 + c] = v;
            }
            bad += pixel_bad;
        }
        p->clamped = bad;
    }
    probe_prepare(p);
    *out = p;
    return G_OK;
}

int gprobe_load(const char *path, GProbeFormat format, int height, GProbe **out, GError *err)
{
    if (!out)
        return gerror_set(err, G_ERR_INVALID, "gprobe_load: no output given");
    *out = NULL;
    if (format != GPROBE_AUTO && format != GPROBE_LATLONG && format != GPROBE_ANGULAR)
        return gerror_set(err, G_ERR_INVALID, "gprobe_load: unknown probe format %d", (int)format);
    if (height < 0)
        return gerror_set(err, G_ERR_INVALID, "gprobe_load: negative height %d", height);
    /* The header first: a probe whose tables do not fit in the memory budget is refused before its decode. */
    int hw, hh;
    int rc = gimage_info(path, &hw, &hh, NULL, err);
    if (rc == G_OK) {
        const int ph = format == GPROBE_ANGULAR || (format == GPROBE_AUTO && hw == hh) ? (height > 0 ? height : hw / 2)
                                                                                        : hh;
        rc = probe_check_budget(2 * (ph > 2 ? ph : 2), ph > 2 ? ph : 2, err);
        if (rc != G_OK && err && !strstr(err->message, path)) {
            char msg[sizeof err->message];
            snprintf(msg, sizeof msg, "%s", err->message);
            gerror_set(err, rc, "%s: %s", path, msg);
        }
    }
    if (rc != G_OK)
        return rc;
    GImage img;
    rc = gimage_read(path, GIMAGE_READ_RGB, &img, err);
    if (rc != G_OK)
        return rc;
    const int w = img.width, h = img.height;
    if (format == GPROBE_AUTO) {
        if (w == 2 * h)
            format = GPROBE_LATLONG;
        else if (w == h)
            format = GPROBE_ANGULAR;
        else {
            gimage_free(&img);
            return gerror_set(err, G_ERR_INVALID,
                              "%s is %dx%d: a light probe must be a latitude-longitude image twice as wide as high "
                              "or a square angular map", path, w, h);
        }
    }
    if (format == GPROBE_LATLONG) {
        if (w != 2 * h)
            rc = gerror_set(err, G_ERR_INVALID,
                            "%s is %dx%d: a latitude-longitude probe must be twice as wide as high", path, w, h);
        else if (h < 2)
            rc = gerror_set(err, G_ERR_INVALID, "%s is %dx%d: a latitude-longitude probe needs at least 2 rows", path,
                            w, h);
        else if (height && height != h)
            rc = gerror_set(err, G_ERR_INVALID, "%s: resizing a latitude-longitude probe is not supported", path);
        else
            rc = gprobe_create(w, h, img.pixels, out, err);
    } else {
        if (w != h)
            rc = gerror_set(err, G_ERR_INVALID, "%s is %dx%d: an angular map must be square", path, w, h);
        else if (w < 2)
            rc = gerror_set(err, G_ERR_INVALID, "%s is %dx%d: an angular map needs at least 2x2 pixels", path, w, h);
        else
            rc = gprobe_from_angular(&img, height, out, err);
    }
    gimage_free(&img);
    if (rc != G_OK && err && !strstr(err->message, path)) {
        char msg[sizeof err->message];
        snprintf(msg, sizeof msg, "%s", err->message);
        gerror_set(err, rc, "%s: %s", path, msg);
    }
    return rc;
}

int gprobe_width(const GProbe *p) { return p->w; }
int gprobe_height(const GProbe *p) { return p->h; }
const float *gprobe_pixels(const GProbe *p) { return p->rgb; }
const float *gprobe_weights(const GProbe *p) { return p->q; }
long gprobe_clamped_count(const GProbe *p) { return p->clamped; }

GVec3 gprobe_direction(const GProbe *p, double x, double y)
{
    return probe_latlong_dir(x, y, p->w, p->h);
}

void gprobe_position(const GProbe *p, GVec3 dir, double *x, double *y)
{
    double len = gvec3_length(dir);
    double z = len > 0.0 ? dir.z / len : 1.0;
    if (z > 1.0)
        z = 1.0;
    if (z < -1.0)
        z = -1.0;
    double a = M_PI - atan2(dir.y, dir.x); /* pi - phi, in [0, 2 pi] */
    double fx = a * p->w / (2.0 * M_PI);
    if (fx >= p->w)
        fx -= p->w;
    *x = fx;
    *y = acos(z) * p->h / M_PI;
}

void gprobe_radiance(const GProbe *p, GVec3 dir, float rgb[3])
{
    double x, y;
    gprobe_position(p, dir, &x, &y);
    double fx = x - 0.5, fy = y - 0.5;
    double x0 = floor(fx), y0 = floor(fy);
    double tx = fx - x0, ty = fy - y0;
    int u0 = (int)x0, v0 = (int)y0;
    int u1 = u0 + 1, v1 = v0 + 1;
    u0 = ((u0 % p->w) + p->w) % p->w;
    u1 = ((u1 % p->w) + p->w) % p->w;
    if (v0 < 0)
        v0 = 0;
    if (v1 > p->h - 1)
        v1 = p->h - 1;
    const float *a = p->rgb + ((size_t)v0 * p->w + u0) * 3, *b = p->rgb + ((size_t)v0 * p->w + u1) * 3;
    const float *c = p->rgb + ((size_t)v1 * p->w + u0) * 3, *d = p->rgb + ((size_t)v1 * p->w + u1) * 3;
    for (int k = 0; k < 3; k++)
        rgb[k] = (float)((1 - ty) * ((1 - tx) * a[k] + tx * b[k]) + ty * ((1 - tx) * c[k] + tx * d[k]));
}

void gprobe_power(const GProbe *p, double rgb[3])
{
    rgb[0] = rgb[1] = rgb[2] = 0.0;
    const double dphi = 2.0 * M_PI / p->w;
    for (int v = 0; v < p->h; v++) {
        double omega = dphi * (cos(M_PI * v / p->h) - cos(M_PI * (v + 1) / p->h)); /* exact pixel solid angle */
        double row[3] = {0, 0, 0};
        const float *px = p->rgb + (size_t)v * p->w * 3;
        for (int u = 0; u < p->w; u++)
            for (int c = 0; c < 3; c++)
                row[c] += px[u * 3 + c];
        for (int c = 0; c < 3; c++)
            rgb[c] += row[c] * omega;
    }
}

void probe_sat_sum(const GProbe *p, int u0, int v0, int u1, int v1, double out[PROBE_SAT])
{
    const size_t stride = (size_t)(p->w + 1) * PROBE_SAT;
    const double *a = p->sat + v0 * stride + (size_t)u0 * PROBE_SAT, *b = p->sat + v0 * stride + (size_t)u1 * PROBE_SAT;
    const double *c = p->sat + v1 * stride + (size_t)u0 * PROBE_SAT, *d = p->sat + v1 * stride + (size_t)u1 * PROBE_SAT;
    for (int k = 0; k < PROBE_SAT; k++)
        out[k] = (d[k] - b[k]) - (c[k] - a[k]);
    for (int k = 4; k < PROBE_SAT; k++) /* rounding in a region without energy */
        if (out[k] < 0.0)
            out[k] = 0.0;
    if (out[0] < 0.0)
        out[0] = 0.0;
}
