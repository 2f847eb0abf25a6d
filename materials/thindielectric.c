/* thindielectric.c - a thin dielectric pane: both interfaces and the light reflected between them summed, the
 * transmitted light going straight through (no offset, no refraction). */
#include "generic/kit/dispersion.h"
#include "generic/kit/material_kit.h"
#include "generic/materials.h"
#include "generic/plugin.h"

#include <math.h>
#include <string.h>

typedef struct ThinDielectric {
    GMaterial base;
    double n; /* the pane's index: the brightness of n(lambda) in the material's model */
} ThinDielectric;

/* The pane's reflectance for a cosine cos_o: one interface reflects F; the light passes the first (1 - F), then
 * bounces inside, so R = F + (1 - F)^2 F (1 + F^2 + F^4 + ...) = F + (1 - F)^2 F / (1 - F^2) = 2 F / (1 + F). */
static double pane_reflectance(const ThinDielectric *t, double cos_o)
{
    double f = goptics_fresnel(cos_o, 1.0 / t->n);
    return 2.0 * f / (1.0 + f);
}

static int thin_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                           GColor *result)
{
    GVec3 n = gsurfpoint_normal(sp);
    double cos_o = gvec3_dot(out, n);
    if (cos_o <= 0.0 || !gmaterial_sides_agree(sp, in, out, 0) || !gmaterial_is_mirror_pair(in, n, out)) {
        gcolor_black(result);
        return G_OK;
    }
    return gcolor_scale(result, illum, pane_reflectance((const ThinDielectric *)self, cos_o));
}

/* The transmitted light goes on along its line: in is -out. rel_index plays no part (the pane has the same medium on
 * both sides). */
static int thin_refraction(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum,
                           const GColor *rel_index, GVec3 out, GColor *result)
{
    (void)rel_index;
    GVec3 n = gsurfpoint_normal(sp);
    double cos_o = gvec3_dot(out, n);
    if (cos_o <= 0.0 || !gmaterial_sides_agree(sp, in, out, 1) ||
        !goptics_is_refraction_pair(gvec3_neg(out), n, 1.0, in)) {
        gcolor_black(result);
        return G_OK;
    }
    return gcolor_scale(result, illum, 1.0 - pane_reflectance((const ThinDielectric *)self, cos_o));
}

static int thin_reflection_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    (void)self;
    *dir = gvec3_reflect(view, gsurfpoint_normal(sp));
    return 1;
}

static int thin_refraction_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, const GColor *rel_index,
                               GVec3 *dir)
{
    (void)self, (void)sp, (void)rel_index;
    *dir = view;
    return 1;
}

static int thin_opaque(const GMaterial *self, GSurfPoint *sp)
{
    (void)self, (void)sp;
    return 0;
}

/* Two delta lobes: reflection with probability R (the pane's reflectance), straight transmission with 1 - R. */
static int thin_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1,
                       double u2, GMaterialSample *s, GColor *weight)
{
    (void)u2;
    GVec3 n = gsurfpoint_normal(sp);
    double cos_o = gvec3_dot(out, n);
    if (cos_o <= 0.0)
        return 0;
    double r = pane_reflectance((const ThinDielectric *)self, cos_o);
    int transmit = !(u1 < r), rc;
    s->in = transmit ? gvec3_neg(out) : gvec3_reflect(gvec3_neg(out), n);
    s->pdf = transmit ? 1.0 - r : r;
    s->flags = (transmit ? GSAMPLE_TRANSMIT : GSAMPLE_REFLECT) | GSAMPLE_DELTA;
    rc = gmaterial_sample_weight(self, sp, s->in, out, rel_index, transmit, s->pdf, weight);
    return rc ? rc : 1;
}

static double thin_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    (void)self, (void)sp, (void)in, (void)out, (void)rel_index;
    return 0.0;
}

static int thin_is_delta(const GMaterial *self, GSurfPoint *sp)
{
    (void)self, (void)sp;
    return 1;
}

static void thin_destroy(GMaterial *self) { gmem_free(self); }

static const GMaterialClass thindielectric_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "thindielectric",
    .description = "thin dielectric pane: both interfaces and their inner reflections, straight transmission",
    .destroy = thin_destroy,
    .reflection = thin_reflection,
    .refraction = thin_refraction,
    .reflection_dir = thin_reflection_dir,
    .refraction_dir = thin_refraction_dir,
    .opaque = thin_opaque,
    .sample = thin_sample,
    .pdf = thin_pdf,
    .is_delta = thin_is_delta,
};

int gthindielectric_create(const GColorModel *model, const GDispersion *index, GMaterial **out, GError *err)
{
    *out = NULL;
    if (!model || !index)
        return gerror_set(err, G_ERR_INVALID, "thindielectric: no colour model or index given");
    GError check;
    int rc = gdispersion_check(index, &check);
    if (rc != G_OK) /* the kit's message names the dielectric */
        return gerror_set_param(err, rc, "index", "thin%s", check.message);
    GColor n;
    if (gcolor_alloc(&n, model) != G_OK)
        return gerror_set(err, G_ERR_NOMEM, "thindielectric: out of memory");
    rc = gdispersion_color(index, &n);
    double nb = gcolor_brightness(&n);
    gcolor_free(&n);
    if (rc != G_OK || !(nb > 0.0) || !isfinite(nb))
        return gerror_set_param(err, rc ? rc : G_ERR_INVALID, "index",
                                "thindielectric: cannot express the index in model '%s'", gcolormodel_name(model));
    GMaterial *m;
    if ((rc = gmaterial_new(&thindielectric_class, model, sizeof(ThinDielectric), &m, err)) != G_OK)
        return rc;
    ((ThinDielectric *)m)->n = nb;
    m->flags |= GMAT_NO_UV | GMAT_DIAGONAL; /* no (u, v); R * illum and (1 - R) * illum, sample by sample */
    m->flags |= GMAT_NO_REL_INDEX; /* the pane's own index: the same medium on both sides, rel_index unread */
    *out = m;
    return G_OK;
}

/* thindielectric { index N | cauchy A B [C] | sellmeier B1 B2 B3 C1 C2 C3 | glass NAME  glass NAME }: index 1.5 */
static int parse_thindielectric(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GDispersion index = gdispersion_constant(1.5);
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "index") == 0)
            rc = gdispersion_read(r, &index, err);
        else if (strcmp(key, "glass") == 0)
            rc = gdispersion_read_glass(r, &index, err);
        else
            rc = greader_unknown_param(r, "index, glass", err);
        if (rc < 0)
            break;
    }
    GMaterial *m = NULL;
    if (rc == G_OK && (rc = gthindielectric_create(greader_colormodel(r), &index, &m, err)) == G_OK)
        *object = m;
    return rc;
}

static const GParamInfo thindielectric_params[] = {
    {"index", GPARAM_NAMED, "formula", "1.5",
     "N in [0.01, 100]; cauchy A B [C]; sellmeier B1 B2 B3 C1 C2 C3; glass NAME",
     "the pane's refraction index (its brightness in the model sets the Fresnel reflectance of both faces)"},
    {"glass", GPARAM_NAMED, "choice", "none", "a name `gmat glasses` lists", "the same as `index glass NAME`"},
    {NULL},
};

GENERIC_TYPE_PARAMS(thindielectric, GKIND_MATERIAL, &thindielectric_class, parse_thindielectric, NULL,
                    thindielectric_params);
