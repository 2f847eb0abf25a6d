/* material.c - dispatch of the generic material interface with the documented defaults. */
#include "generic/material.h"

#include <math.h>

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
    m->flags = (cls->emission ? 0u : GMAT_NO_EMISSION) | /* no slot: black, the documented default */
               (cls->opaque ? 0u : GMAT_OPAQUE) |        /* no slot: opaque, the documented default */
               (cls->normal ? 0u : GMAT_GEOMETRIC_NORMAL); /* no slot: the geometric normal, the default */
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
    if (gmaterial_emits(m) && m->cls->emission)
        return m->cls->emission(m, sp, out, result);
    gcolor_black(result);
    return G_OK;
}

int gmaterial_emits(const GMaterial *m) { return m && !(m->flags & GMAT_NO_EMISSION); }

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
    if (m && !(m->flags & GMAT_GEOMETRIC_NORMAL) && m->cls->normal)
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

int gmaterial_opaque_everywhere(const GMaterial *m) { return m && (m->flags & GMAT_OPAQUE); }

int gmaterial_lambertian(const GMaterial *m) { return m && (m->flags & GMAT_LAMBERTIAN); }

int gmaterial_diagonal(const GMaterial *m) { return m && (m->flags & GMAT_DIAGONAL); }

int gmaterial_opaque(const GMaterial *m, GSurfPoint *sp)
{
    if (m && (m->flags & GMAT_OPAQUE))
        return 1;
    if (m && m->cls->opaque)
        return m->cls->opaque(m, sp);
    return 1;
}

/* ---- sampling: the material's own, or the documented defaults built from the other methods ---- */

/* The lobes the default sampling sees at sp for light leaving towards out: the ideal reflection and refraction
 * directions (when valid), the brightness of what each passes on of white light, and the weight of the
 * non-delta lobe (cosine when the material has a diffuse colour, uniform otherwise). */
typedef struct DefaultLobes {
    GVec3 refl, refr;
    double w_refl, w_refr, w_rest;
    int cosine;
} DefaultLobes;

static int default_lobes(const GMaterial *m, GSurfPoint *sp, GVec3 out, const GColor *ri, GColor *tmp,
                         const GColor *white, DefaultLobes *l)
{
    GVec3 view = gvec3_neg(out);
    int rc, valid;
    *l = (DefaultLobes){.w_refl = 0.0};
    if ((valid = gmaterial_reflection_dir(m, sp, view, &l->refl)) < 0)
        return valid;
    if (valid) {
        if ((rc = gmaterial_reflection(m, sp, l->refl, white, out, tmp)) < 0)
            return rc;
        l->w_refl = fmax(0.0, gcolor_brightness(tmp));
    }
    if (ri && !gmaterial_opaque(m, sp)) {
        if ((valid = gmaterial_refraction_dir(m, sp, view, ri, &l->refr)) < 0)
            return valid;
        if (valid) {
            if ((rc = gmaterial_refraction(m, sp, l->refr, white, ri, out, tmp)) < 0)
                return rc;
            l->w_refr = fmax(0.0, gcolor_brightness(tmp));
        }
    }
    if ((rc = gmaterial_diffuse(m, sp, tmp)) < 0)
        return rc;
    double d = gcolor_brightness(tmp);
    l->cosine = d > 0.0;
    l->w_rest = l->cosine ? d : fmax(0.0, 1.0 - l->w_refl - l->w_refr);
    if (!(l->w_refl + l->w_refr + l->w_rest > 0.0) || !isfinite(l->w_refl + l->w_refr + l->w_rest))
        *l = (DefaultLobes){.w_rest = 1.0}; /* nothing known: uniform over the hemisphere */
    return G_OK;
}

/* The non-delta lobe's density of `in` (on the side of the normal), times its probability p. */
static double rest_pdf(const DefaultLobes *l, GVec3 n, GVec3 in, double p)
{
    double c = gvec3_dot(in, n);
    if (!(c > 0.0))
        return 0.0;
    return p * (l->cosine ? c / M_PI : 1.0 / (2.0 * M_PI));
}

/* Temporaries for the defaults: white and a scratch colour, from the point's arena or the thread's. */
static GScratch *arena_of(GSurfPoint *sp) { return sp && sp->scratch ? sp->scratch : gscratch_thread(); }

static int default_sample(const GMaterial *m, GSurfPoint *sp, GVec3 out, const GColor *ri, double u1, double u2,
                          GMaterialSample *s, GColor *weight)
{
    GScratch *arena = arena_of(sp);
    if (!arena)
        return G_ERR_NOMEM;
    GScratchMark mark = gscratch_mark(arena);
    GColor white, tmp;
    DefaultLobes l;
    int rc = gcolor_scratch(&white, m->model, arena);
    if (rc == G_OK)
        rc = gcolor_scratch(&tmp, m->model, arena);
    if (rc == G_OK)
        rc = gcolor_fill(&white, 1.0);
    if (rc == G_OK)
        rc = default_lobes(m, sp, out, ri, &tmp, &white, &l);
    if (rc < 0)
        goto done;
    double total = l.w_refl + l.w_refr + l.w_rest, x = u1 * total;
    GVec3 n = gsurfpoint_normal(sp);
    if (x < l.w_refl + l.w_refr) { /* a delta lobe */
        int refl = x < l.w_refl;
        double p = (refl ? l.w_refl : l.w_refr) / total;
        s->in = refl ? l.refl : l.refr;
        s->pdf = p;
        s->flags = GSAMPLE_DELTA | (refl ? GSAMPLE_REFLECT : GSAMPLE_TRANSMIT);
        rc = refl ? gmaterial_reflection(m, sp, s->in, &white, out, weight)
                  : gmaterial_refraction(m, sp, s->in, &white, ri, out, weight);
        if (rc == G_OK)
            rc = gcolor_scale(weight, weight, 1.0 / p);
        if (rc == G_OK)
            rc = 1;
        goto done;
    }
    double p = l.w_rest / total, v = (x - l.w_refl - l.w_refr) / l.w_rest; /* u1 reused within the lobe */
    v = fmin(fmax(v, 0.0), 0x1.fffffffffffffp-1);
    s->in = l.cosine ? goptics_sample_cosine(n, v, u2) : goptics_sample_hemisphere(n, v, u2);
    s->pdf = rest_pdf(&l, n, s->in, p);
    s->flags = GSAMPLE_REFLECT;
    if (!(s->pdf > 0.0)) {
        rc = 0;
        goto done;
    }
    rc = gmaterial_reflection(m, sp, s->in, &white, out, weight);
    if (rc == G_OK)
        rc = gcolor_scale(weight, weight, 1.0 / s->pdf);
    if (rc == G_OK)
        rc = 1;
done:
    gscratch_release(arena, mark);
    return rc;
}

static double default_pdf(const GMaterial *m, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *ri)
{
    GScratch *arena = arena_of(sp);
    if (!arena)
        return 0.0;
    GScratchMark mark = gscratch_mark(arena);
    GColor white, tmp;
    DefaultLobes l;
    double pdf = 0.0;
    if (gcolor_scratch(&white, m->model, arena) == G_OK && gcolor_scratch(&tmp, m->model, arena) == G_OK &&
        gcolor_fill(&white, 1.0) == G_OK && default_lobes(m, sp, out, ri, &tmp, &white, &l) == G_OK)
        pdf = rest_pdf(&l, gsurfpoint_normal(sp), in, l.w_rest / (l.w_refl + l.w_refr + l.w_rest));
    gscratch_release(arena, mark);
    return pdf;
}

int gmaterial_sample(const GMaterial *m, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1, double u2,
                     GMaterialSample *s, GColor *weight)
{
    *s = (GMaterialSample){.pdf = 0.0};
    if (!m) {
        gcolor_black(weight);
        return 0;
    }
    if (!(u1 >= 0.0 && u1 < 1.0 && u2 >= 0.0 && u2 < 1.0))
        return G_ERR_INVALID;
    int rc = m->cls->sample ? m->cls->sample(m, sp, out, rel_index, u1, u2, s, weight)
                            : default_sample(m, sp, out, rel_index, u1, u2, s, weight);
    if (rc <= 0)
        gcolor_black(weight);
    return rc;
}

double gmaterial_pdf(const GMaterial *m, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    if (!m)
        return 0.0;
    return m->cls->pdf ? m->cls->pdf(m, sp, in, out, rel_index) : default_pdf(m, sp, in, out, rel_index);
}

int gmaterial_is_delta(const GMaterial *m, GSurfPoint *sp)
{
    if (m && (m->flags & GMAT_LAMBERTIAN)) /* a diffuse lobe: not delta (material.h) */
        return 0;
    if (m && m->cls->is_delta)
        return m->cls->is_delta(m, sp);
    return 0;
}
