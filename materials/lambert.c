/* lambert.c - the ideal diffuse reflector: f_r = rho / pi. */
#include "generic/materials.h"
#include "materials_builtin.h"
#include "params.h"

#include <math.h>

typedef struct Lambert {
    GMaterial base;
    GColor rho;
} Lambert;

static void lambert_destroy(GMaterial *self)
{
    Lambert *l = (Lambert *)self;
    gcolor_free(&l->rho);
    gmem_free(l);
}

static int lambert_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                              GColor *result)
{
    const Lambert *l = (const Lambert *)self;
    GVec3 n;
    double c = gmat_cos_in(sp, in, out, &n);
    if (c <= 0.0) {
        gcolor_black(result);
        return G_OK;
    }
    int rc = gcolor_mul(result, &l->rho, illum);
    return rc ? rc : gcolor_scale(result, result, c / M_PI);
}

static int lambert_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    (void)sp;
    return gcolor_mul(result, &((const Lambert *)self)->rho, illum);
}

static int lambert_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    (void)sp;
    return gcolor_copy(result, &((const Lambert *)self)->rho);
}

const GMaterialClass gmaterial_lambert = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "lambert",
    .description = "ideal diffuse reflector (f = rho / pi)",
    .destroy = lambert_destroy,
    .reflection = lambert_reflection,
    .ambient = lambert_ambient,
    .diffuse = lambert_diffuse,
};

int glambert_create(const GColorModel *model, const GColor *reflectance, GMaterial **out, GError *err)
{
    *out = NULL;
    if (!model)
        return gerror_set(err, G_ERR_INVALID, "lambert: no colour model given");
    Lambert *l = gmem_calloc(1, sizeof *l);
    if (!l)
        return gerror_set(err, G_ERR_NOMEM, "lambert: out of memory");
    int rc = gmaterial_init(&l->base, &gmaterial_lambert, model, err);
    if (rc == G_OK)
        rc = gmatparam_color(model, reflectance, GCOLOR_REFLECTANCE, 1.0, "lambert", "reflectance", &l->rho, err);
    if (rc != G_OK) {
        lambert_destroy(&l->base);
        return rc;
    }
    *out = &l->base;
    return G_OK;
}
