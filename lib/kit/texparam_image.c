/* texparam_image.c - images looked up at (u, v) (generic/kit/texparam.h): opening and checking a file through the
 * texture system, its texels memoised per surface point, and their colours in a model. The image node
 * (textures/image.c) and textured colours (`reflectance image { file "label.png" }`) both read images here. */
#include "texparam_image.h"
#include "texparam_spectral.h"
#include "generic/services/image.h"
#include "generic/services/texsys.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

struct GTexImage {
    GTextureSystem *ts;
    GTexFile *file;
    int srgb; /* the texture system decodes the file's sRGB values (gtexsys_open) */
    GTexWrap swrap, twrap;
    double blur;
    const GColorModel *model;
    GColor basis[3]; /* the colours of the linear primaries in the model (reflectance) */
    int linear;      /* the model's from_rgb is linear: a texel is the basis mixed (else from_rgb per texel) */
    double max[3];   /* the largest linear value of each channel (once have_max) */
    int have_max;
    char *path;
    GTexSpectral *spectral; /* a spectral OpenEXR's texels (then no texture system file), or NULL */
};

void gtexparam_image_free(GTexImage *im)
{
    if (!im)
        return;
    for (int i = 0; i < 3; i++)
        gcolor_free(&im->basis[i]);
    gtexsys_unref(im->ts);
    gtexparam_spectral_free(im->spectral);
    gmem_free(im->path);
    gmem_free(im);
}

/* *linear = 1 when the model's from_rgb mixes the primaries' colours (the basis uplift, rgb), so that a texel may
 * be the basis mixed by its components; 0 for a smooth uplift (the sigmoid), whose mixture of primaries would
 * leave [0, 1]: each texel is then uplifted itself. Tested on one colour, 0.25 0.5 0.75. */
static int is_linear(const GColorModel *model, const GColor basis[3], int *linear)
{
    GColor direct = {0}, mixed = {0};
    double rgb[3] = {0.25, 0.5, 0.75};
    int rc = gcolor_alloc(&direct, model);
    if (rc == G_OK)
        rc = gcolor_alloc(&mixed, model);
    if (rc == G_OK)
        rc = gcolor_from_rgb(&direct, rgb, GCOLOR_REFLECTANCE);
    for (int i = 0; i < 3 && rc == G_OK; i++)
        rc = gcolor_add_scaled(&mixed, &basis[i], rgb[i]);
    if (rc == G_OK) {
        double size = gcolor_brightness(&direct);
        rc = gcolor_axpy(&mixed, -1.0, &direct, &mixed);
        *linear = rc == G_OK && gcolor_brightness(&mixed) <= 1e-5 * size;
    }
    gcolor_free(&direct);
    gcolor_free(&mixed);
    return rc;
}

/* A value of the file as read whole (channel_max): decoded when the texture system decodes the file. */
static double linear_value(const GTexImage *im, double stored)
{
    double x = im->srgb ? gimage_srgb_decode(stored) : stored;
    return isfinite(x) && x > 0.0 ? x : 0.0;
}

/* A texture lookup's value, linear already: NaN and values below 0 as 0. */
static double lookup_value(float v)
{
    return isfinite(v) && v > 0.0f ? (double)v : 0.0;
}

/* The largest value of each channel, from the whole image read once (within the memory budget). */
static int channel_max(GTexImage *im, GError *err)
{
    if (im->have_max)
        return G_OK;
    if (im->spectral) {
        gtexparam_spectral_rgb_max(im->spectral, im->max);
        im->have_max = 1;
        return G_OK;
    }
    GImage img;
    int rc = gimage_read(im->path, GIMAGE_READ_RAW | GIMAGE_READ_RGB, &img, err);
    if (rc != G_OK)
        return rc;
    im->max[0] = im->max[1] = im->max[2] = 0.0;
    size_t n = (size_t)img.width * (size_t)img.height;
    for (size_t p = 0; p < n; p++)
        for (int c = 0; c < 3; c++) {
            double x = linear_value(im, img.pixels[p * 3 + (size_t)c]);
            if (x > im->max[c])
                im->max[c] = x;
        }
    gimage_free(&img);
    im->have_max = 1;
    return G_OK;
}

/* gtexparam_image_open for a colour in role: a spectral OpenEXR gives its reflective channels to a reflectance, its
 * emissive ones to a light (texparam_spectral.h); any other file is read as RGB through the texture system. */
static int image_open(const char *path, const GImageNodeOptions *opt, const GColorModel *m, GColorRole role,
                      GTexImage **out, GError *err)
{
    *out = NULL;
    GImageNodeOptions o;
    memset(&o, 0, sizeof o);
    if (opt)
        o = *opt;
    if (!path || !path[0])
        return gerror_set(err, G_ERR_INVALID, "image: no file name given");
    if (!m)
        return gerror_set(err, G_ERR_INVALID, "image '%s': no colour model given", path);
    if ((unsigned)o.swrap > GTEX_WRAP_MIRROR || (unsigned)o.twrap > GTEX_WRAP_MIRROR ||
        (unsigned)o.colorspace > GTEX_COLORSPACE_LINEAR)
        return gerror_set(err, G_ERR_INVALID, "image '%s': unknown wrap mode or colour space", path);
    if (!(o.blur >= 0.0) || !isfinite(o.blur))
        return gerror_set(err, G_ERR_INVALID, "image '%s': blur must be >= 0, got %g", path, o.blur);
    GTexImage *im = gmem_calloc(1, sizeof *im);
    if (!im)
        return gerror_set(err, G_ERR_NOMEM, "image: out of memory");
    im->swrap = o.swrap;
    im->twrap = o.twrap;
    im->blur = o.blur;
    im->model = m;
    int rc = G_OK;
    if (!(im->path = gmem_strdup(path)))
        rc = gerror_set(err, G_ERR_NOMEM, "image: out of memory");
    if (rc == G_OK)
        rc = gtexparam_spectral_open(path, role, &im->spectral, err);
    const int rgb_file = rc == G_OK && !im->spectral;
    if (rgb_file)
        im->ts = o.texsys ? gtexsys_ref(o.texsys) : gtexsys_default(err);
    if (rgb_file && !im->ts)
        rc = err && err->code ? err->code : G_ERR_NOMEM;
    int channels = 0;
    if (rgb_file && rc == G_OK) /* the texture system decodes sRGB before it filters: its lookups are linear */
        rc = gtexsys_open(im->ts, path, o.colorspace, &im->file, &channels, &im->srgb, err);
    if (rgb_file && rc == G_OK) { /* one lookup of the finest level decodes the pixels: a truncated file fails here */
        static const double finest[4] = {0.0, 0.0, 0.0, 0.0};
        float v[3];
        if (gtexsys_lookup(im->ts, im->file, GTEX_WRAP_CLAMP, GTEX_WRAP_CLAMP, 0.5, 0.5, finest, 0.0, v) != G_OK)
            rc = gerror_set(err, G_ERR_IO, "image '%s' cannot be read: its pixels cannot be decoded (a truncated "
                                           "or damaged file)", path);
    }
    for (int i = 0; i < 3 && rc == G_OK; i++) {
        double e[3] = {i == 0, i == 1, i == 2};
        rc = gcolor_alloc(&im->basis[i], m);
        if (rc != G_OK)
            rc = gerror_set(err, G_ERR_NOMEM, "image: out of memory");
        else if ((rc = gcolor_from_rgb(&im->basis[i], e, GCOLOR_REFLECTANCE)) != G_OK)
            rc = gerror_set(err, rc, "image '%s': the colour model '%s' cannot take RGB colours", path,
                            gcolormodel_name(m));
    }
    if (rc == G_OK)
        rc = is_linear(m, im->basis, &im->linear);
    if (rc != G_OK) {
        gtexparam_image_free(im);
        return rc;
    }
    *out = im;
    return G_OK;
}

int gtexparam_image_open(const char *path, const GImageNodeOptions *opt, const GColorModel *m, GTexImage **out,
                         GError *err)
{
    return image_open(path, opt, m, GCOLOR_REFLECTANCE, out, err);
}

int gtexparam_image_channel_max(GTexImage *im, double rgb[3], GError *err)
{
    int rc = channel_max(im, err);
    for (int i = 0; i < 3; i++)
        rgb[i] = rc == G_OK ? im->max[i] : 0.0;
    return rc;
}

int gtexparam_image_rgb(const GTexImage *im, GSurfPoint *sp, double rgb[3])
{
    GVec3 c;
    if (gsurfpoint_cache_get(sp, im, NULL, &c)) {
        rgb[0] = c.x;
        rgb[1] = c.y;
        rgb[2] = c.z;
        return G_OK;
    }
    if (im->spectral) { /* the texel's spectrum in linear sRGB, as the layer's role sees it */
        GSpectrumNM s;
        double xyz[3];
        gtexparam_spectral_lookup(im->spectral, im->swrap, im->twrap, sp->u, 1.0 - sp->v, &s);
        gcie_nm_to_xyz(&s, gtexparam_spectral_role(im->spectral), xyz);
        gcie_xyz_to_rgb(xyz, rgb);
        gsurfpoint_cache_put(sp, im, 1.0, gvec3(rgb[0], rgb[1], rgb[2]));
        return G_OK;
    }
    float v[3];
    const double *a = sp->uv_axis1, *b = sp->uv_axis2;
    double deriv[4] = {sp->uv_footprint, 0.0, 0.0, sp->uv_footprint};
    if (a[0] != 0.0 || a[1] != 0.0 || b[0] != 0.0 || b[1] != 0.0) { /* the footprint's ellipse; t = 1 - v */
        deriv[0] = a[0];
        deriv[1] = -a[1];
        deriv[2] = b[0];
        deriv[3] = -b[1];
    }
    int rc = gtexsys_lookup(im->ts, im->file, im->swrap, im->twrap, sp->u, 1.0 - sp->v, deriv, im->blur, v);
    if (rc != G_OK)
        return rc;
    for (int i = 0; i < 3; i++)
        rgb[i] = lookup_value(v[i]);
    gsurfpoint_cache_put(sp, im, 1.0, gvec3(rgb[0], rgb[1], rgb[2]));
    return G_OK;
}

int gtexparam_image_uplift(const GTexImage *im, const double rgb[3], GColorRole role, GColor *out)
{
    if (out->model == im->model && im->linear && role == GCOLOR_REFLECTANCE) {
        int rc = gcolor_scale(out, &im->basis[0], rgb[0]);
        if (rc == G_OK)
            rc = gcolor_add_scaled(out, &im->basis[1], rgb[1]);
        return rc != G_OK ? rc : gcolor_add_scaled(out, &im->basis[2], rgb[2]);
    }
    return gcolor_from_rgb(out, rgb, role);
}

int gtexparam_image_color(const GTexImage *im, GSurfPoint *sp, GColorRole role, GColor *out)
{
    if (im->spectral) { /* the texels' spectrum at the point, into out's model */
        GSpectrumNM s;
        gtexparam_spectral_lookup(im->spectral, im->swrap, im->twrap, sp->u, 1.0 - sp->v, &s);
        return gcolor_from_nm(out, &s, role);
    }
    double rgb[3];
    int rc = gtexparam_image_rgb(im, sp, rgb);
    return rc != G_OK ? rc : gtexparam_image_uplift(im, rgb, role, out);
}

int gtexparam_image_max(GTexImage *im, GColorRole role, GColor *out, GError *err)
{
    if (im->spectral) { /* the largest value of every wavelength */
        GSpectrumNM top;
        int rc = gtexparam_spectral_max(im->spectral, &top);
        if (rc != G_OK)
            return gerror_set(err, rc, "image '%s': out of memory", im->path);
        if ((rc = gcolor_alloc(out, im->model)) == G_OK && (rc = gcolor_from_nm(out, &top, role)) != G_OK)
            gcolor_free(out);
        return rc;
    }
    double mx[3];
    int rc = gtexparam_image_channel_max(im, mx, err);
    if (rc != G_OK)
        return rc;
    rc = gcolor_alloc(out, im->model);
    if (rc == G_OK && (rc = gcolor_from_rgb(out, mx, role)) != G_OK)
        gcolor_free(out);
    return rc;
}

static const char *const wrap_names[] = {"periodic", "clamp", "black", "mirror", NULL};
static const char *const space_names[] = {"auto", "srgb", "linear", NULL};

int gtexparam_image_option(GReader *r, const char *key, GImageNodeOptions *o, GError *err)
{
    int w, rc;
    if (strcmp(key, "wrap") == 0) {
        if ((rc = greader_choice(r, wrap_names, &w, err)) == G_OK)
            o->swrap = o->twrap = (GTexWrap)w;
    } else if (strcmp(key, "swrap") == 0) {
        if ((rc = greader_choice(r, wrap_names, &w, err)) == G_OK)
            o->swrap = (GTexWrap)w;
    } else if (strcmp(key, "twrap") == 0) {
        if ((rc = greader_choice(r, wrap_names, &w, err)) == G_OK)
            o->twrap = (GTexWrap)w;
    } else if (strcmp(key, "colorspace") == 0) {
        if ((rc = greader_choice(r, space_names, &w, err)) == G_OK)
            o->colorspace = (GTexColorSpace)w;
    } else if (strcmp(key, "blur") == 0) {
        rc = greader_number_in(r, 0.0, 1.0, &o->blur, err);
    } else {
        return 1;
    }
    return rc;
}

int gtexparam_image_read(GReader *r, const GColorModel *m, GColorRole role, GTexImage **out, GError *err)
{
    *out = NULL;
    GImageNodeOptions o;
    memset(&o, 0, sizeof o);
    char *path = NULL;
    int file_line = 0, file_col = 0;
    char key[16];
    int rc = greader_block_begin(r, err);
    while (rc == G_OK && (rc = greader_block_end(r, err)) == 0) {
        int line, col;
        if ((rc = greader_ident(r, key, sizeof key, err)) != G_OK)
            break;
        greader_position(r, &line, &col);
        if (strcmp(key, "file") == 0) {
            if (path)
                rc = greader_error_at(r, err, G_ERR_PARSE, line, col, "image: 'file' is given twice");
            else if ((rc = greader_path(r, &path, err)) == G_OK)
                greader_position(r, &file_line, &file_col);
        } else if ((rc = gtexparam_image_option(r, key, &o, err)) > 0) {
            rc = greader_error_at(r, err, G_ERR_PARSE, line, col,
                                  "image: unknown parameter '%s' (expected one of: file, wrap, swrap, twrap, "
                                  "colorspace, blur)", key);
        }
    }
    if (rc > 0)
        rc = G_OK;
    if (rc == G_OK && !path)
        rc = greader_error(r, err, "image: needs file");
    if (rc == G_OK && (rc = image_open(path, &o, m, role, out, err)) != G_OK) {
        char msg[sizeof err->message]; /* a file that cannot be read is reported at its name */
        snprintf(msg, sizeof msg, "%s", err ? err->message : "image cannot be read");
        rc = greader_error_at(r, err, rc, file_line, file_col, "%s", msg);
    }
    gmem_free(path);
    return rc;
}
