/* image.c - the image node: the child's light-carrying colour results times the colour of an image at
 * (u, v), looked up through OpenImageIO's TextureSystem (lib/image/texture_oiio.cpp) with trilinear MIP-mapping
 * over the surface point's footprint:
 *
 *   node NAME image { child MATERIAL  file "name.png"  wrap periodic|clamp|black|mirror
 *                     swrap ...  twrap ...  colorspace auto|srgb|linear  blur 0 }
 */
#include <generic/services/image.h>
#include <generic/kit/node_kit.h>
#include <generic/plugin.h>
#include <generic/services/texsys.h>
#include <generic/kit/texture_parse.h>

#include <math.h>
#include <string.h>

typedef struct Image {
    GNodeChild node; /* base and child; first */
    GTextureSystem *ts;
    GTexFile *file;
    int srgb;
    GTexWrap swrap, twrap;
    double blur;
    GColor basis[3]; /* the colours of the linear primaries in the child's model */
    int linear;      /* the model's from_rgb is linear: a texel is the basis mixed (else from_rgb per texel) */
    char *path;
} Image;

static void image_destroy(GMaterial *self)
{
    Image *im = (Image *)self;
    gmaterial_unref(im->node.child);
    for (int i = 0; i < 3; i++)
        gcolor_free(&im->basis[i]);
    gtexsys_unref(im->ts);
    gmem_free(im->path);
    gmem_free(im);
}

/* The linear texel colour at the point, looked up once per point (cached under the node). NaN, infinite and
 * negative texels (possible in float files) become 0: they would otherwise reach the pixels. A failed lookup (a
 * file that is damaged past its header) is the lookup's status, never a black texel. */
static int texel(const Image *im, GSurfPoint *sp, double rgb[3])
{
    GVec3 c;
    if (gsurfpoint_cache_get(sp, im, NULL, &c)) {
        rgb[0] = c.x;
        rgb[1] = c.y;
        rgb[2] = c.z;
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
    for (int i = 0; i < 3; i++) {
        double x = im->srgb ? gimage_srgb_decode(v[i]) : v[i];
        rgb[i] = isfinite(x) && x > 0.0 ? x : 0.0;
    }
    gsurfpoint_cache_put(sp, im, 1.0, gvec3(rgb[0], rgb[1], rgb[2]));
    return G_OK;
}

/* result = texel * result. */
static int apply(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    const Image *im = (const Image *)self;
    double rgb[3];
    int rc = texel(im, sp, rgb);
    if (rc != G_OK)
        return rc;
    GNodeTemps t;
    gnode_temps_init(&t);
    GColor c;
    rc = gnode_temps_color(&t, sp, result->model, 0, &c);
    if (rc == G_OK) {
        if (result->model == im->node.base.model && im->linear) {
            rc = gcolor_scale(&c, &im->basis[0], rgb[0]);
            if (rc == G_OK)
                rc = gcolor_add_scaled(&c, &im->basis[1], rgb[1]);
            if (rc == G_OK)
                rc = gcolor_add_scaled(&c, &im->basis[2], rgb[2]);
        } else {
            rc = gcolor_from_rgb(&c, rgb, GCOLOR_REFLECTANCE);
        }
    }
    if (rc == G_OK)
        rc = gcolor_mul(result, &c, result);
    gnode_temps_release(&t);
    return rc;
}

static int image_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                            GColor *result)
{
    int rc = gmaterial_reflection(gnode_child_of(self), sp, in, illum, out, result);
    return rc != G_OK ? rc : apply(self, sp, result);
}

static int image_refraction(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum,
                            const GColor *rel_index, GVec3 out, GColor *result)
{
    int rc = gmaterial_refraction(gnode_child_of(self), sp, in, illum, rel_index, out, result);
    return rc != G_OK ? rc : apply(self, sp, result);
}

static int image_emission(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *result)
{
    int rc = gmaterial_emission(gnode_child_of(self), sp, out, result);
    return rc != G_OK ? rc : apply(self, sp, result);
}

static int image_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    int rc = gmaterial_ambient(gnode_child_of(self), sp, illum, result);
    return rc != G_OK ? rc : apply(self, sp, result);
}

static int image_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    int rc = gmaterial_diffuse(gnode_child_of(self), sp, result);
    return rc != G_OK ? rc : apply(self, sp, result);
}

/* The child's direction and density; the weight times the texel, as reflection and refraction are. */
static int image_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1,
                        double u2, GMaterialSample *s, GColor *weight)
{
    int rc = gmaterial_sample(gnode_child_of(self), sp, out, rel_index, u1, u2, s, weight);
    if (rc <= 0)
        return rc;
    rc = apply(self, sp, weight);
    return rc ? rc : 1;
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

static const GMaterialClass image_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "image",
    .description = "the child's reflected and emitted light times an image's colour at (u, v)",
    .destroy = image_destroy,
    .reflection = image_reflection,
    .refraction = image_refraction,
    .refraction_index = gnode_child_refraction_index,
    .reflection_dir = gnode_child_reflection_dir,
    .refraction_dir = gnode_child_refraction_dir,
    .emission = image_emission,
    .ambient = image_ambient,
    .absorption = gnode_child_absorption,
    .normal = gnode_child_normal,
    .diffuse = image_diffuse,
    .opaque = gnode_child_opaque,
    .sample = image_sample,
    .pdf = gnode_child_pdf,
    .is_delta = gnode_child_is_delta,
};

int gnode_image_create(GMaterial *child, const char *path, const GImageNodeOptions *opt, GMaterial **out,
                       GError *err)
{
    *out = NULL;
    GImageNodeOptions o;
    memset(&o, 0, sizeof o);
    if (opt)
        o = *opt;
    const GColorModel *model;
    int rc = gnode_check("image", &child, 1, NULL, 0, &model, err);
    if (rc != G_OK)
        return rc;
    if (!path || !path[0])
        return gerror_set(err, G_ERR_INVALID, "image: no file name given");
    if ((unsigned)o.swrap > GTEX_WRAP_MIRROR || (unsigned)o.twrap > GTEX_WRAP_MIRROR ||
        (unsigned)o.colorspace > GTEX_COLORSPACE_LINEAR)
        return gerror_set(err, G_ERR_INVALID, "image '%s': unknown wrap mode or colour space", path);
    if (!(o.blur >= 0.0) || !isfinite(o.blur))
        return gerror_set(err, G_ERR_INVALID, "image '%s': blur must be >= 0, got %g", path, o.blur);
    GMaterial *mat;
    rc = gnode_child_new(&image_class, child, NULL, 0, sizeof(Image), &mat, err);
    if (rc != G_OK)
        return rc;
    Image *im = (Image *)mat;
    im->swrap = o.swrap;
    im->twrap = o.twrap;
    im->blur = o.blur;
    im->path = gmem_strdup(path);
    im->ts = o.texsys ? gtexsys_ref(o.texsys) : gtexsys_default(err);
    if (!im->path)
        rc = gerror_set(err, G_ERR_NOMEM, "image: out of memory");
    else if (!im->ts)
        rc = err && err->code ? err->code : G_ERR_NOMEM;
    int channels = 0, srgb = 0;
    if (rc == G_OK)
        rc = gtexsys_open(im->ts, path, &im->file, &channels, &srgb, err);
    im->srgb = o.colorspace == GTEX_COLORSPACE_SRGB || (o.colorspace == GTEX_COLORSPACE_AUTO && srgb);
    if (rc == G_OK) { /* one lookup of the finest level decodes the pixels: a truncated file fails here */
        static const double finest[4] = {0.0, 0.0, 0.0, 0.0};
        float v[3];
        if (gtexsys_lookup(im->ts, im->file, GTEX_WRAP_CLAMP, GTEX_WRAP_CLAMP, 0.5, 0.5, finest, 0.0, v) != G_OK)
            rc = gerror_set(err, G_ERR_IO, "image '%s' cannot be read: its pixels cannot be decoded (a truncated "
                                           "or damaged file)", path);
    }
    for (int i = 0; i < 3 && rc == G_OK; i++) {
        double e[3] = {i == 0, i == 1, i == 2};
        rc = gcolor_alloc(&im->basis[i], model);
        if (rc != G_OK)
            rc = gerror_set(err, G_ERR_NOMEM, "image: out of memory");
        else if ((rc = gcolor_from_rgb(&im->basis[i], e, GCOLOR_REFLECTANCE)) != G_OK)
            rc = gerror_set(err, rc, "image '%s': the colour model '%s' cannot take RGB colours", path,
                            gcolormodel_name(model));
    }
    if (rc == G_OK)
        rc = is_linear(model, im->basis, &im->linear);
    if (rc != G_OK) {
        image_destroy(&im->node.base);
        return rc;
    }
    gnode_inherit_no_emission(&im->node.base, &child, 1); /* the child's emission times a finite texel */
    int vectors = im->basis[0].kind == GCOLOR_VECTOR && im->basis[1].kind == GCOLOR_VECTOR &&
                  im->basis[2].kind == GCOLOR_VECTOR;
    if (vectors) {
        gnode_inherit_diagonal(&im->node.base, &child, 1); /* the child's pass-on times a texel colour */
        /* reflection and diffuse colour: the child's at the same point times the same texel colour, a vector, so
         * texel * (diffuse * light) = (texel * diffuse) * light */
        gnode_inherit_lambertian_child(&im->node.base, child);
    }
    *out = &im->node.base;
    return G_OK;
}

static const char *const wrap_names[] = {"periodic", "clamp", "black", "mirror", NULL};
static const char *const space_names[] = {"auto", "srgb", "linear", NULL};

static int parse_image(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GMaterial *child = NULL;
    char *path = NULL;
    GImageNodeOptions o;
    memset(&o, 0, sizeof o);
    int w, file_line = 0, file_col = 0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "child") == 0)
            rc = greader_material(r, &child, err);
        else if (strcmp(key, "file") == 0) {
            rc = greader_path(r, &path, err);
            greader_position(r, &file_line, &file_col);
        } else if (strcmp(key, "wrap") == 0) {
            rc = greader_choice(r, wrap_names, &w, err);
            o.swrap = o.twrap = (GTexWrap)w;
        } else if (strcmp(key, "swrap") == 0) {
            rc = greader_choice(r, wrap_names, &w, err);
            o.swrap = (GTexWrap)w;
        } else if (strcmp(key, "twrap") == 0) {
            rc = greader_choice(r, wrap_names, &w, err);
            o.twrap = (GTexWrap)w;
        } else if (strcmp(key, "colorspace") == 0) {
            rc = greader_choice(r, space_names, &w, err);
            o.colorspace = (GTexColorSpace)w;
        } else if (strcmp(key, "blur") == 0)
            rc = greader_number_in(r, 0.0, 1.0, &o.blur, err);
        else
            rc = greader_unknown_param(r, "child, file, wrap, swrap, twrap, colorspace, blur", err);
        if (rc < 0)
            break;
    }
    if (rc == 0 && (!child || !path))
        rc = greader_error(r, err, "image: needs child and file");
    if (rc == 0) {
        GMaterial *m = NULL;
        rc = gnode_image_create(child, path, &o, &m, err);
        if (rc != G_OK) { /* a file that cannot be read is reported at its name */
            char msg[sizeof err->message];
            strcpy(msg, err->message);
            rc = greader_error_at(r, err, rc, file_line, file_col, "%s", msg);
        } else {
            *object = m;
        }
    }
    gmem_free(path);
    return rc;
}

#define IMAGE_WRAPS "periodic, clamp, black, mirror"

static const GParamInfo image_params[] = {
    {"child", GPARAM_NAMED, "material", NULL, NULL, "the material whose reflected and emitted light is multiplied"},
    {"file", GPARAM_NAMED, "path", NULL,
     "an image file: OpenEXR, HDR, PFM, PNM, PNG, JPEG or TIFF, at most 8192 x 8192 pixels",
     "the image, looked up at (u, v) with trilinear MIP-mapping over the footprint"},
    {"wrap", GPARAM_NAMED, "choice", "periodic", IMAGE_WRAPS, "outside [0, 1] in u and v: repeat, hold the edge, "
     "black, repeat mirrored"},
    {"swrap", GPARAM_NAMED, "choice", "periodic", IMAGE_WRAPS, "the same in u only"},
    {"twrap", GPARAM_NAMED, "choice", "periodic", IMAGE_WRAPS, "the same in v only"},
    {"colorspace", GPARAM_NAMED, "choice", "auto", "auto, srgb, linear",
     "how stored values relate to linear ones; auto: sRGB for 8- and 16-bit files that say sRGB, else linear"},
    {"blur", GPARAM_NAMED, "number", "0", "[0, 1]", "an extra filter width, in (u, v) units"},
    {NULL},
};

GENERIC_TYPE_PARAMS(image, GKIND_NODE, &image_class, parse_image, NULL, image_params);
