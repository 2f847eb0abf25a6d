/* emitter.c - a surface that emits radiance L from its front (or both sides). */
#include "generic/kit/material_kit.h"
#include "generic/kit/texparam.h"
#include "generic/materials.h"
#include "generic/plugin.h"

#include <string.h>

typedef struct Emitter {
    GMaterialOneColor radiance; /* first: the class's destroy is gmaterial_one_color_destroy */
    int two_sided;
} Emitter;

static int emitter_emission(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *result)
{
    const Emitter *e = (const Emitter *)self;
    if (!e->two_sided) {
        /* the geometric normal faces the incident ray; the front is the object's outside */
        double c = gvec3_dot(out, sp->geometric_normal);
        if (!sp->entering)
            c = -c;
        if (c <= 0.0) {
            gcolor_black(result);
            return G_OK;
        }
    }
    return gcolor_copy(result, &e->radiance.c);
}

/* An emitter reflects nothing: no direction is drawn, no lobe has a density, and light samples would reflect
 * nothing (is_delta). */
static int emitter_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1,
                          double u2, GMaterialSample *s, GColor *weight)
{
    (void)self, (void)sp, (void)out, (void)rel_index, (void)u1, (void)u2, (void)s;
    gcolor_black(weight);
    return 0;
}

static double emitter_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    (void)self, (void)sp, (void)in, (void)out, (void)rel_index;
    return 0.0;
}

static int emitter_is_delta(const GMaterial *self, GSurfPoint *sp)
{
    (void)self, (void)sp;
    return 1;
}

static const GMaterialClass emitter_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "emitter",
    .description = "emits a radiance from its front (or both sides)",
    .destroy = gmaterial_one_color_destroy,
    .emission = emitter_emission,
    .sample = emitter_sample,
    .pdf = emitter_pdf,
    .is_delta = emitter_is_delta,
};

int gemitter_create(const GColorModel *model, const GColor *radiance, int two_sided, GMaterial **out, GError *err)
{
    int rc = gmaterial_one_color_create(&emitter_class, model, sizeof(Emitter), radiance, GCOLOR_LIGHT, 0.0, "radiance",
                                   out, err);
    if (rc == G_OK) {
        ((Emitter *)*out)->two_sided = two_sided != 0;
        /* no method reads the (u, v) parametrisation; no reflection or refraction: black, sample by sample */
        (*out)->flags |= GMAT_NO_UV | GMAT_DIAGONAL | GMAT_NO_REL_INDEX; /* nor the relative index */
    }
    return rc;
}

/* gemitter_create as a GTexParamCreate (ctx: two_sided). */
static int create_textured(const GColorModel *m, const GColor *c, void *ctx, GMaterial **out, GError *err)
{
    return gemitter_create(m, c, *(const int *)ctx, out, err);
}

/* emitter { radiance COLOR two_sided BOOL }: radiance white 1 (a light), one-sided when not given; a textured
 * radiance scales the emitter of unit radiance (gtexparam_one_color_material) */
static int parse_emitter(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GTexColor radiance = {0};
    int two_sided = 0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "radiance") == 0)
            rc = gtexparam_read_color(r, GCOLOR_LIGHT, &radiance, err);
        else if (strcmp(key, "two_sided") == 0)
            rc = greader_bool(r, &two_sided, err);
        else
            rc = greader_unknown_param(r, "radiance, two_sided", err);
        if (rc < 0)
            break;
    }
    if (rc == G_OK && radiance.kind == GTEXCOLOR_CONSTANT)
        rc = gmaterial_param_default(r, 1.0, GCOLOR_LIGHT, &radiance.a, err);
    GMaterial *m = NULL;
    if (rc == G_OK && radiance.kind != GTEXCOLOR_CONSTANT)
        rc = gtexparam_one_color_material(greader_colormodel(r), &radiance, create_textured, &two_sided, &m, err);
    else if (rc == G_OK)
        rc = gemitter_create(greader_colormodel(r), &radiance.a, two_sided, &m, err);
    if (rc == G_OK)
        *object = m;
    gtexparam_color_release(&radiance);
    return rc;
}

static const GParamInfo emitter_params[] = {
    {"radiance", GPARAM_NAMED, "texcolor", "rgb 1 1 1", ">= 0",
     "the radiance emitted, read as a light (rgb 1 1 1: D65 of luminance 1)"},
    {"two_sided", GPARAM_NAMED, "bool", "no", NULL, "emit from both sides; no: from the front (the outside) only"},
    {NULL},
};

GENERIC_TYPE_PARAMS(emitter, GKIND_MATERIAL, &emitter_class, parse_emitter, NULL, emitter_params);
