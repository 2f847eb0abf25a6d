/* image.c - the image node: the child's light-carrying colour results times the colour of an image at
 * (u, v), looked up through OpenImageIO's TextureSystem (lib/image/texture_oiio.cpp) with trilinear MIP-mapping
 * over the surface point's footprint, in linear light (sRGB files are decoded before filtering), or for a spectral
 * OpenEXR its reflective channels' spectra; the file, its
 * checks and its texels are the kit's (gtexparam_image_open, kit/texparam.h), shared with textured colour
 * parameters:
 *
 *   node NAME image { child MATERIAL  file "name.png"  wrap periodic|clamp|black|mirror
 *                     swrap ...  twrap ...  colorspace auto|srgb|linear  blur 0 }
 */
#include <generic/kit/node_kit.h>
#include <generic/plugin.h>
#include <generic/kit/texparam.h>
#include <generic/kit/texture_parse.h>

#include <string.h>

typedef struct Image {
    GNodeTimes node; /* base, child and the factor's function; first */
    GTexImage *image; /* the file, its lookups and the colours of its texels (kit/texparam.h) */
} Image;

static void image_destroy(GMaterial *self)
{
    Image *im = (Image *)self;
    gmaterial_unref(im->node.node.child);
    gtexparam_image_free(im->image);
    gmem_free(im);
}

/* result = texel * result: the texel at the point (an RGB texel looked up once per point, then cached; a spectral
 * one converted from its spectrum) as a reflectance. */
static int apply(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    const Image *im = (const Image *)self;
    GNodeTemps t;
    gnode_temps_init(&t);
    GColor c;
    int rc = gnode_temps_color(&t, sp, result->model, 0, &c);
    if (rc == G_OK)
        rc = gtexparam_image_color(im->image, sp, GCOLOR_REFLECTANCE, &c);
    if (rc == G_OK)
        rc = gcolor_mul(result, &c, result);
    gnode_temps_release(&t);
    return rc;
}

static const GMaterialClass image_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "image",
    .description = "the child's reflected and emitted light times an image's colour at (u, v)",
    .destroy = image_destroy,
    GNODE_TIMES_METHODS,
};

/* 1 when the image's texels are vectors in the model (then the node's results are its child's times a vector). */
static int texels_are_vectors(const GTexImage *image, const GColorModel *model)
{
    GColor c = {0};
    static const double rgb[3] = {0.25, 0.5, 0.75};
    int vector = gcolor_alloc(&c, model) == G_OK &&
                 gtexparam_image_uplift(image, rgb, GCOLOR_REFLECTANCE, &c) == G_OK && c.kind == GCOLOR_VECTOR;
    gcolor_free(&c);
    return vector;
}

int gnode_image_create(GMaterial *child, const char *path, const GImageNodeOptions *opt, GMaterial **out,
                       GError *err)
{
    *out = NULL;
    const GColorModel *model;
    int rc = gnode_check("image", &child, 1, NULL, 0, &model, err);
    if (rc != G_OK)
        return rc;
    GTexImage *image;
    if ((rc = gtexparam_image_open(path, opt, model, &image, err)) != G_OK)
        return rc;
    GMaterial *mat;
    rc = gnode_child_new(&image_class, child, NULL, 0, sizeof(Image), &mat, err);
    if (rc != G_OK) {
        gtexparam_image_free(image);
        return rc;
    }
    Image *im = (Image *)mat;
    im->image = image;
    im->node.times = apply;
    gnode_inherit_no_emission(&im->node.node.base, &child, 1); /* the child's emission times a finite texel */
    gnode_inherit_no_rel_index(&im->node.node.base, &child, 1); /* the child's results times a texel at (u, v) */
    if (texels_are_vectors(image, model)) {
        gnode_inherit_diagonal(&im->node.node.base, &child, 1); /* the child's pass-on times a texel colour */
        /* reflection and diffuse colour: the child's at the same point times the same texel colour, a vector, so
         * texel * (diffuse * light) = (texel * diffuse) * light */
        gnode_inherit_lambertian_child(&im->node.node.base, child);
    }
    *out = &im->node.node.base;
    return G_OK;
}


static int parse_image(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GMaterial *child = NULL;
    char *path = NULL;
    GImageNodeOptions o;
    memset(&o, 0, sizeof o);
    int file_line = 0, file_col = 0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "child") == 0)
            rc = greader_material(r, &child, err);
        else if (strcmp(key, "file") == 0) {
            rc = greader_path(r, &path, err);
            greader_position(r, &file_line, &file_col);
        } else if ((rc = gtexparam_image_option(r, key, &o, err)) > 0) {
            rc = greader_unknown_param(r, "child, file, wrap, swrap, twrap, colorspace, blur", err);
        }
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
     "the image, looked up at (u, v) with trilinear MIP-mapping over the footprint, filtered in linear light (sRGB "
     "values decoded first); a spectral OpenEXR "
     "(reflective channels T.<nm>nm) bilinearly, its spectra converted into the model"},
    {"wrap", GPARAM_NAMED, "choice", "periodic", IMAGE_WRAPS, "outside [0, 1] in u and v: repeat, hold the edge, "
     "black, repeat mirrored"},
    {"swrap", GPARAM_NAMED, "choice", "periodic", IMAGE_WRAPS, "the same in u only"},
    {"twrap", GPARAM_NAMED, "choice", "periodic", IMAGE_WRAPS, "the same in v only"},
    {"colorspace", GPARAM_NAMED, "choice", "auto", "auto, srgb, linear",
     "how stored values relate to linear ones; auto: sRGB for 8- and 16-bit files that say sRGB, else linear; "
     "sRGB values are decoded before MIP-mapping and filtering"},
    {"blur", GPARAM_NAMED, "number", "0", "[0, 1]", "an extra filter width, in (u, v) units"},
    {NULL},
};

GENERIC_TYPE_PARAMS(image, GKIND_NODE, &image_class, parse_image, NULL, image_params);
