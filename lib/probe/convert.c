/* convert.c - lat-long <-> angular map conversion, rotation and saving of probes. */
#include "probe_internal.h"
#include "generic/memory.h"

#include <math.h>
#include <string.h>

/* Angular map coordinates (a right, b up, both in [-1, 1], r <= 1 inside the disc) to a direction: the
 * centre looks along +x, right is -y, up is +z (probe.h). */
static GVec3 angular_to_dir(double a, double b)
{
    double r = sqrt(a * a + b * b);
    if (r < 1e-12)
        return gvec3(1.0, 0.0, 0.0);
    double psi = M_PI * r, s = sin(psi) / r;
    return gvec3(cos(psi), -a * s, b * s);
}

/* Direction (unit) to angular map coordinates. */
static void dir_to_angular(GVec3 d, double *a, double *b)
{
    double c = d.x;
    if (c > 1.0)
        c = 1.0;
    if (c < -1.0)
        c = -1.0;
    double r = acos(c) / M_PI, m = sqrt(d.y * d.y + d.z * d.z);
    if (m < 1e-15) {
        *a = r;
        *b = 0.0;
        return;
    }
    *a = -r * d.y / m;
    *b = r * d.z / m;
}

static int supersampling(double src_per_dst)
{
    int ss = (int)ceil(src_per_dst - 1e-9);
    return ss < 1 ? 1 : ss > 4 ? 4 : ss;
}

int gprobe_to_angular(const GProbe *p, int size, GImage *out, GError *err)
{
    if (size < 2 || size > (1 << 15))
        return gerror_set(err, G_ERR_INVALID, "angular map size %d out of range", size);
    int rc = gimage_create(out, size, size, 3, err);
    if (rc != G_OK)
        return rc;
    /* the disc spans 2 pi radians over `size` pixels; the probe has h pixels over pi */
    const int ss = supersampling(2.0 * p->h / size);
    #pragma omp parallel for schedule(dynamic, 8)
    for (int j = 0; j < size; j++) {
        for (int i = 0; i < size; i++) {
            double acc[3] = {0, 0, 0};
            int n = 0;
            for (int sj = 0; sj < ss; sj++)
                for (int si = 0; si < ss; si++) {
                    double a = 2.0 * (i + (si + 0.5) / ss) / size - 1.0;
                    double b = 1.0 - 2.0 * (j + (sj + 0.5) / ss) / size;
                    if (a * a + b * b > 1.0)
                        continue;
                    float rgb[3];
                    gprobe_radiance(p, angular_to_dir(a, b), rgb);
                    for (int c = 0; c < 3; c++)
                        acc[c] += rgb[c];
                    n++;
                }
            float *px = out->pixels + ((size_t)j * size + i) * 3;
            for (int c = 0; c < 3; c++)
                px[c] = n ? (float)(acc[c] / n) : 0.0f;
        }
    }
    return G_OK;
}

/* Bilinear lookup in an angular map using only pixels whose centres lie inside the disc. */
static void angular_lookup(const GImage *m, double a, double b, double rgb[3])
{
    const int d = m->width, ch = m->channels;
    double fx = (a + 1.0) * 0.5 * d - 0.5, fy = (1.0 - b) * 0.5 * d - 0.5;
    int x0 = (int)floor(fx), y0 = (int)floor(fy);
    double tx = fx - x0, ty = fy - y0, wsum = 0.0;
    rgb[0] = rgb[1] = rgb[2] = 0.0;
    double best = 1e300;
    int bx = -1, by = -1;
    for (int k = 0; k < 4; k++) {
        int x = x0 + (k & 1), y = y0 + (k >> 1);
        if (x < 0 || y < 0 || x >= d || y >= d)
            continue;
        double pa = 2.0 * (x + 0.5) / d - 1.0, pb = 1.0 - 2.0 * (y + 0.5) / d, r2 = pa * pa + pb * pb;
        if (r2 > 1.0) {
            if (r2 < best) {
                best = r2;
                bx = x;
                by = y;
            }
            continue;
        }
        double w = ((k & 1) ? tx : 1.0 - tx) * ((k >> 1) ? ty : 1.0 - ty);
        const float *px = m->pixels + ((size_t)y * d + x) * ch;
        for (int c = 0; c < 3; c++)
            rgb[c] += w * px[c];
        wsum += w;
    }
    if (wsum > 1e-12) {
        for (int c = 0; c < 3; c++)
            rgb[c] /= wsum;
    } else if (bx >= 0) { /* on the rim between pixel centres: the nearest pixel */
        const float *px = m->pixels + ((size_t)by * d + bx) * ch;
        for (int c = 0; c < 3; c++)
            rgb[c] = px[c];
    }
}

int gprobe_from_angular(const GImage *map, int height, GProbe **out, GError *err)
{
    if (!out)
        return gerror_set(err, G_ERR_INVALID, "gprobe_from_angular: no output given");
    *out = NULL;
    if (!map || !map->pixels || map->width != map->height || map->width < 2 || map->channels < 3)
        return gerror_set(err, G_ERR_INVALID, "an angular map must be a square RGB image");
    const int h = height > 0 ? height : (map->width / 2 > 2 ? map->width / 2 : 2), w = 2 * h;
    if (h > (1 << 14))
        return gerror_set(err, G_ERR_INVALID, "probe height %d out of range", h);
    int rc = probe_check_budget(w, h, err);
    if (rc != G_OK)
        return rc;
    float *buf = gmem_calloc((size_t)w * h * 3, sizeof(float));
    if (!buf)
        return gerror_set(err, G_ERR_NOMEM, "out of memory converting an angular map");
    const int ss = supersampling(map->width / (2.0 * h));
    #pragma omp parallel for schedule(dynamic, 4)
    for (int v = 0; v < h; v++) {
        for (int u = 0; u < w; u++) {
            double acc[3] = {0, 0, 0};
            for (int sv = 0; sv < ss; sv++)
                for (int su = 0; su < ss; su++) {
                    GVec3 d = probe_latlong_dir(u + (su + 0.5) / ss, v + (sv + 0.5) / ss, w, h);
                    double a, b, rgb[3];
                    dir_to_angular(d, &a, &b);
                    angular_lookup(map, a, b, rgb);
                    for (int c = 0; c < 3; c++)
                        acc[c] += rgb[c];
                }
            for (int c = 0; c < 3; c++)
                buf[((size_t)v * w + u) * 3 + c] = (float)(acc[c] / (ss * ss));
        }
    }
    rc = gprobe_create(w, h, buf, out, err);
    gmem_free(buf);
    return rc;
}

int gprobe_to_image(const GProbe *p, GImage *out, GError *err)
{
    int rc = gimage_create(out, p->w, p->h, 3, err);
    if (rc == G_OK)
        memcpy(out->pixels, p->rgb, sizeof(float) * 3 * (size_t)p->w * p->h);
    return rc;
}

int gprobe_save(const GProbe *p, const char *path, GProbeFormat format, GError *err)
{
    GImage img;
    int rc = format == GPROBE_ANGULAR ? gprobe_to_angular(p, p->h, &img, err) : gprobe_to_image(p, &img, err);
    if (rc != G_OK)
        return rc;
    rc = gimage_write(path, &img, NULL, err);
    gimage_free(&img);
    return rc;
}

void gprobe_rotation_xyz(double x_deg, double y_deg, double z_deg, double R[9])
{
    double a = x_deg * M_PI / 180.0, b = y_deg * M_PI / 180.0, c = z_deg * M_PI / 180.0;
    double ca = cos(a), sa = sin(a), cb = cos(b), sb = sin(b), cc = cos(c), sc = sin(c);
    /* Rz(c) Ry(b) Rx(a) */
    R[0] = cc * cb; R[1] = cc * sb * sa - sc * ca; R[2] = cc * sb * ca + sc * sa;
    R[3] = sc * cb; R[4] = sc * sb * sa + cc * ca; R[5] = sc * sb * ca - cc * sa;
    R[6] = -sb;     R[7] = cb * sa;                R[8] = cb * ca;
}

int gprobe_rotate(const GProbe *p, const double R[9], GProbe **out, GError *err)
{
    if (!out)
        return gerror_set(err, G_ERR_INVALID, "gprobe_rotate: no output given");
    *out = NULL;
    for (int i = 0; i < 9; i++)
        if (!isfinite(R[i]))
            return gerror_set(err, G_ERR_INVALID, "rotation matrix has a non-finite entry");
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) { /* R R^T = I */
            double d = R[i * 3] * R[j * 3] + R[i * 3 + 1] * R[j * 3 + 1] + R[i * 3 + 2] * R[j * 3 + 2];
            if (fabs(d - (i == j)) > 1e-6)
                return gerror_set(err, G_ERR_INVALID, "matrix is not a rotation");
        }
    const int w = p->w, h = p->h;
    float *buf = gmem_calloc((size_t)w * h * 3, sizeof(float));
    if (!buf)
        return gerror_set(err, G_ERR_NOMEM, "out of memory rotating a probe");
    /* a turn about z by a whole number of pixels is a shift of the columns */
    double shift = -atan2(R[3], R[0]) * w / (2.0 * M_PI); /* phi falls to the right (probe.h) */
    int about_z = fabs(R[8] - 1.0) < 1e-12 && fabs(R[2]) < 1e-12 && fabs(R[5]) < 1e-12;
    if (about_z && fabs(shift - round(shift)) < 1e-6) {
        int s = (((int)lround(shift)) % w + w) % w;
        for (int v = 0; v < h; v++)
            for (int u = 0; u < w; u++)
                memcpy(buf + ((size_t)v * w + (u + s) % w) * 3, p->rgb + ((size_t)v * w + u) * 3, 3 * sizeof(float));
    } else {
        #pragma omp parallel for schedule(dynamic, 4)
        for (int v = 0; v < h; v++)
            for (int u = 0; u < w; u++) {
                GVec3 d = probe_pixel_dir(p, u, v);
                GVec3 src = gvec3(R[0] * d.x + R[3] * d.y + R[6] * d.z, R[1] * d.x + R[4] * d.y + R[7] * d.z,
                                  R[2] * d.x + R[5] * d.y + R[8] * d.z); /* R^T d */
                gprobe_radiance(p, src, buf + ((size_t)v * w + u) * 3);
            }
    }
    int rc = gprobe_create(w, h, buf, out, err);
    gmem_free(buf);
    return rc;
}
