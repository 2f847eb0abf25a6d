/* material.c - dispatch of the generic material interface with the documented defaults. */
#include "generic/material.h"

int gmaterial_init(GMaterial *m, const GMaterialClass *cls, const GColorModel *model, GError *err)
{
    if (!cls || cls->abi_version != GMATERIAL_ABI_VERSION)
        return gerror_set(err, G_ERR_VERSION, "material '%s' has interface version %d, the library has %d",
                          cls && cls->name ? cls->name : "?", cls ? cls->abi_version : -1, GMATERIAL_ABI_VERSION);
    if (!cls->destroy)
        return gerror_set(err, G_ERR_INVALID, "material '%s' has no destroy method", cls->name);
    m->cls = cls;
    m->model = model;
    m->refcount = 1;
    m->depth = 1;
    m->cost = 1;
    return G_OK;
}

GMaterial *gmaterial_ref(GMaterial *m)
{
    if (m)
        m->refcount++;
    return m;
}

void gmaterial_unref(GMaterial *m)
{
    if (m && --m->refcount == 0)
        m->cls->destroy(m);
}

const char *gmaterial_name(const GMaterial *m) { return m ? m->cls->name : "vacuum"; }

int gmaterial_reflection(const GMaterial *m, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                         GColor *result)
{
    if (m && m->cls->reflection)
        return m->cls->reflection(m, sp, in, illum, out, result);
    gcolor_black(result);
    return G_OK;
}

int gmaterial_refraction(const GMaterial *m, GSurfPoint *sp, GVec3 in, const GColor *illum,
                         const GColor *rel_index, GVec3 out, GColor *result)
{
    if (m && m->cls->refraction)
        return m->cls->refraction(m, sp, in, illum, rel_index, out, result);
    gcolor_black(result);
    return G_OK;
}

int gmaterial_refraction_index(const GMaterial *m, GSurfPoint *sp, GColor *result)
{
    if (m && m->cls->refraction_index)
        return m->cls->refraction_index(m, sp, result);
    /* the constant 1: going through rgb -> spectrum would not give a flat 1 in spectral models */
    return gcolor_fill(result, 1.0);
}

int gmaterial_reflection_dir(const GMaterial *m, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    if (m && m->cls->reflection_dir)
        return m->cls->reflection_dir(m, sp, view, dir);
    return 0;
}

int gmaterial_refraction_dir(const GMaterial *m, GSurfPoint *sp, GVec3 view, const GColor *rel_index, GVec3 *dir)
{
    if (m && m->cls->refraction_dir)
        return m->cls->refraction_dir(m, sp, view, rel_index, dir);
    return 0;
}

int gmaterial_emission(const GMaterial *m, GSurfPoint *sp, GVec3 out, GColor *result)
{
    if (m && m->cls->emission)
        return m->cls->emission(m, sp, out, result);
    gcolor_black(result);
    return G_OK;
}

int gmaterial_ambient(const GMaterial *m, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    if (m && m->cls->ambient)
        return m->cls->ambient(m, sp, illum, result);
    int rc = gmaterial_diffuse(m, sp, result);
    return rc ? rc : gcolor_mul(result, result, illum);
}

int gmaterial_absorption(const GMaterial *m, GSurfPoint *sp, const GColor *illum, double length, GColor *result)
{
    if (m && m->cls->absorption)
        return m->cls->absorption(m, sp, illum, length, result);
    return gcolor_copy(result, illum);
}

int gmaterial_normal(const GMaterial *m, GSurfPoint *sp, GVec3 *n)
{
    if (m && m->cls->normal)
        return m->cls->normal(m, sp, n);
    *n = sp->geometric_normal;
    return G_OK;
}

int gmaterial_diffuse(const GMaterial *m, GSurfPoint *sp, GColor *result)
{
    if (m && m->cls->diffuse)
        return m->cls->diffuse(m, sp, result);
    gcolor_black(result);
    return G_OK;
}

int gmaterial_opaque(const GMaterial *m, GSurfPoint *sp)
{
    if (m && m->cls->opaque)
        return m->cls->opaque(m, sp);
    return 1;
}
