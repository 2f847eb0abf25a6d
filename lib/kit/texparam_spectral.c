/* texparam_spectral.c - the texels of a spectral OpenEXR (texparam_spectral.h): read once into floats at the file's
 * wavelengths, held against the memory budget, looked up bilinearly and resampled to the nm grid per lookup. */
#include "texparam_spectral.h"
#include "image/decode_isolated.h"
#include "generic/services/file.h"
#include "generic/services/image.h"

#include <math.h>
#include <string.h>
#include <unistd.h>

struct GTexSpectral {
    GImageSpectraBuf buf; /* the texels: width x height x count floats, and the wavelengths */
    GColorRole role;
    int lo[GNM_COUNT];    /* nm GNM_MIN + i is (1 - t[i]) * value[lo[i]] + t[i] * value[hi[i]] */
    int hi[GNM_COUNT];
    float t[GNM_COUNT];
};

/* 1 when the file begins with OpenEXR's magic number (76 2f 31 01); 0 otherwise, or when it cannot be read (the RGB
 * path then reports it). */
static int is_openexr(const char *path)
{
    GError ignored;
    int fd = gfile_open_input(path, &ignored);
    if (fd < 0)
        return 0;
    unsigned char magic[4];
    ssize_t n = read(fd, magic, sizeof magic);
    close(fd);
    return n == 4 && magic[0] == 0x76 && magic[1] == 0x2f && magic[2] == 0x31 && magic[3] == 0x01;
}

/* The resampling weights of the nm grid from the file's wavelengths. */
static void resampling(GTexSpectral *sp)
{
    const double *w = sp->buf.wavelengths;
    const int n = sp->buf.count;
    int k = 0;
    for (int i = 0; i < GNM_COUNT; i++) {
        double nm = GNM_MIN + i;
        while (k + 1 < n && w[k + 1] <= nm)
            k++;
        if (nm <= w[0] || k + 1 >= n) { /* before the first wavelength, or at or after the last */
            sp->lo[i] = sp->hi[i] = nm <= w[0] ? 0 : n - 1;
            sp->t[i] = 0.0f;
        } else {
            sp->lo[i] = k;
            sp->hi[i] = k + 1;
            sp->t[i] = (float)((nm - w[k]) / (w[k + 1] - w[k]));
        }
    }
}

/* G_OK when every value is finite and >= 0, else G_ERR_IO naming the first that is not. */
static int check_values(const char *path, const GImageSpectraBuf *b, GError *err)
{
    const size_t total = (size_t)b->width * (size_t)b->height * (size_t)b->count;
    for (size_t i = 0; i < total; i++) {
        float v = b->values[i];
        if (isfinite(v) && v >= 0.0f)
            continue;
        size_t pixel = i / (size_t)b->count;
        return gerror_set(err, G_ERR_IO, "%s: texel (%zu, %zu) at %g nm is %g: spectral values must be finite and "
                          ">= 0", path, pixel % (size_t)b->width, pixel / (size_t)b->width,
                          b->wavelengths[i % (size_t)b->count], (double)v);
    }
    return G_OK;
}

int gtexparam_spectral_open(const char *path, GColorRole role, GTexSpectral **out, GError *err)
{
    *out = NULL;
    if (!is_openexr(path))
        return G_OK;
    GImageSpectraBuf buf = {0};
    GImageSpectraLayer layer = role == GCOLOR_LIGHT ? GIMAGE_SPECTRA_EMISSIVE : GIMAGE_SPECTRA_REFLECTIVE;
    int rc = gdecode_check_whole(path, err); /* once, before both reads in this process */
    if (rc == G_OK)
        rc = gdecode_read_spectra_checked(path, layer, &buf, err);
    if (rc == G_OK && buf.count == 0) /* values are role free, as an RGB image's: the other layer serves too */
        rc = gdecode_read_spectra_checked(path, layer == GIMAGE_SPECTRA_EMISSIVE ? GIMAGE_SPECTRA_REFLECTIVE
                                                                                 : GIMAGE_SPECTRA_EMISSIVE, &buf, err);
    if (rc != G_OK)
        return rc;
    if (buf.count == 0) {
        gimage_spectra_free(&buf);
        return G_OK;
    }
    if ((long long)buf.width * buf.height > GTEXSYS_MAX_PIXELS)
        rc = gerror_set(err, G_ERR_IO, "%s: %dx%d texels, more than a texture may have (8192 x 8192)", path,
                        buf.width, buf.height);
    if (rc == G_OK)
        rc = check_values(path, &buf, err);
    GTexSpectral *sp = rc == G_OK ? gmem_calloc(1, sizeof *sp) : NULL;
    if (rc == G_OK && !sp)
        rc = gerror_set(err, G_ERR_NOMEM, "%s: out of memory", path);
    if (rc != G_OK) {
        gimage_spectra_free(&buf);
        return rc;
    }
    sp->buf = buf;
    sp->role = role == GCOLOR_LIGHT ? GCOLOR_LIGHT : GCOLOR_REFLECTANCE;
    resampling(sp);
    *out = sp;
    return G_OK;
}

void gtexparam_spectral_free(GTexSpectral *sp)
{
    if (!sp)
        return;
    gimage_spectra_free(&sp->buf);
    gmem_free(sp);
}

GColorRole gtexparam_spectral_role(const GTexSpectral *sp)
{
    return sp->role;
}

/* Texel index i of a row or column of n under wrap; -1 for a black texel (GTEX_WRAP_BLACK outside). */
static int wrap_index(long i, int n, GTexWrap wrap)
{
    switch (wrap) {
    case GTEX_WRAP_CLAMP:
        return i < 0 ? 0 : i >= n ? n - 1 : (int)i;
    case GTEX_WRAP_BLACK:
        return i < 0 || i >= n ? -1 : (int)i;
    case GTEX_WRAP_MIRROR: {
        long period = 2L * n, k = i % period;
        if (k < 0)
            k += period;
        return (int)(k < n ? k : period - 1 - k);
    }
    default: { /* periodic */
        long k = i % n;
        return (int)(k < 0 ? k + n : k);
    }
    }
}

/* The two texels along one axis around coordinate c (0..1 over n texels) and the weight of the second. */
static void axis(double c, int n, GTexWrap wrap, int idx[2], double *f)
{
    double x = c * n - 0.5;
    if (!isfinite(x) || fabs(x) > 1e9) /* a coordinate far outside: the nearest texel at the wrap's rule */
        x = 0.0;
    double fl = floor(x);
    *f = x - fl;
    idx[0] = wrap_index((long)fl, n, wrap);
    idx[1] = wrap_index((long)fl + 1, n, wrap);
}

void gtexparam_spectral_lookup(const GTexSpectral *sp, GTexWrap swrap, GTexWrap twrap, double s, double t,
                               GSpectrumNM *out)
{
    const GImageSpectraBuf *b = &sp->buf;
    int xs[2], ys[2];
    double fx, fy;
    axis(s, b->width, swrap, xs, &fx);
    axis(t, b->height, twrap, ys, &fy);
    const float *texel[4];
    float weight[4];
    int m = 0;
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 2; i++) {
            double w = (i ? fx : 1.0 - fx) * (j ? fy : 1.0 - fy);
            if (xs[i] < 0 || ys[j] < 0 || w == 0.0)
                continue;
            texel[m] = b->values + ((size_t)ys[j] * (size_t)b->width + (size_t)xs[i]) * (size_t)b->count;
            weight[m++] = (float)w;
        }
    for (int k = 0; k < GNM_COUNT; k++) {
        float v = 0.0f;
        for (int q = 0; q < m; q++)
            v += weight[q] * ((1.0f - sp->t[k]) * texel[q][sp->lo[k]] + sp->t[k] * texel[q][sp->hi[k]]);
        out->v[k] = v;
    }
}

int gtexparam_spectral_max(const GTexSpectral *sp, GSpectrumNM *out)
{
    const GImageSpectraBuf *b = &sp->buf;
    const size_t npix = (size_t)b->width * (size_t)b->height, n = (size_t)b->count;
    float *top = gmem_calloc(n, sizeof *top); /* values are >= 0 (checked at open) */
    if (!top)
        return G_ERR_NOMEM;
    for (size_t p = 0; p < npix; p++)
        for (size_t k = 0; k < n; k++)
            top[k] = fmaxf(top[k], b->values[p * n + k]);
    for (int i = 0; i < GNM_COUNT; i++)
        out->v[i] = (1.0f - sp->t[i]) * top[sp->lo[i]] + sp->t[i] * top[sp->hi[i]];
    gmem_free(top);
    return G_OK;
}

void gtexparam_spectral_rgb_max(const GTexSpectral *sp, double rgb[3])
{
    const GImageSpectraBuf *b = &sp->buf;
    rgb[0] = rgb[1] = rgb[2] = 0.0;
    GSpectrumNM s;
    for (int y = 0; y < b->height; y++)
        for (int x = 0; x < b->width; x++) {
            double xyz[3], c[3];
            gtexparam_spectral_lookup(sp, GTEX_WRAP_CLAMP, GTEX_WRAP_CLAMP, (x + 0.5) / b->width,
                                      (y + 0.5) / b->height, &s);
            gcie_nm_to_xyz(&s, sp->role, xyz);
            gcie_xyz_to_rgb(xyz, c);
            for (int i = 0; i < 3; i++)
                rgb[i] = fmax(rgb[i], c[i]);
        }
}
