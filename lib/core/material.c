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
               (cls->normal ? 0u : GMAT_GEOMETRIC_NORMAL) | /* no slot: the geometric normal, the default */
               (cls->reflection_dir || cls->refraction_dir ? 0u : GMAT_NO_IDEAL) | /* no slots: no ideal ray */
               (cls->refraction_index ? 0u : GMAT_CONSTANT_INDEX) | /* no slot: 1 everywhere, the default */
               (cls->absorption ? 0u : GMAT_CLEAR); /* no slot: the light itself, the default */
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

int gmaterial_emits(const GMaterial *m) { return m && !(m->flags & GMAT_NO_EMISSION); }

int gmaterial_opaque_everywhere(const GMaterial *m) { return m && (m->flags & GMAT_OPAQUE); }

int gmaterial_lambertian(const GMaterial *m) { return m && (m->flags & GMAT_LAMBERTIAN); }

int gmaterial_diagonal(const GMaterial *m) { return m && (m->flags & GMAT_DIAGONAL); }

int gmaterial_no_rel_index(const GMaterial *m) { return !m || (m->flags & GMAT_NO_REL_INDEX); }

int gmaterial_constant_index(const GMaterial *m) { return !m || (m->flags & GMAT_CONSTANT_INDEX); }

int gmaterial_clear(const GMaterial *m) { return !m || (m->flags & GMAT_CLEAR); }

/* ---- the defaults of GMATERIAL_METHODS (material.h): what gmaterial_<name> answers for a NULL slot, a NULL
 * material, or a material with the method's `unless` bit ---- */

static inline int default_reflection(const GMaterial *m, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                                     GColor *result)
{
    (void)m, (void)sp, (void)in, (void)illum, (void)out;
    gcolor_black(result);
    return G_OK;
}

static inline int default_refraction(const GMaterial *m, GSurfPoint *sp, GVec3 in, const GColor *illum,
                                     const GColor *rel_index, GVec3 out, GColor *result)
{
    (void)m, (void)sp, (void)in, (void)illum, (void)rel_index, (void)out;
    gcolor_black(result);
    return G_OK;
}

static inline int default_refraction_index(const GMaterial *m, GSurfPoint *sp, GColor *result)
{
    (void)m, (void)sp;
    /* the constant 1: going through rgb -> spectrum would not give a flat 1 in spectral models */
    return gcolor_fill(result, 1.0);
}

static inline int default_reflection_dir(const GMaterial *m, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    (void)m, (void)sp, (void)view, (void)dir;
    return 0;
}

static inline int default_refraction_dir(const GMaterial *m, GSurfPoint *sp, GVec3 view, const GColor *rel_index,
                                         GVec3 *dir)
{
    (void)m, (void)sp, (void)view, (void)rel_index, (void)dir;
    return 0;
}

static inline int default_emission(const GMaterial *m, GSurfPoint *sp, GVec3 out, GColor *result)
{
    (void)m, (void)sp, (void)out;
    gcolor_black(result);
    return G_OK;
}

static inline int default_ambient(const GMaterial *m, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    int rc = gmaterial_diffuse(m, sp, result);
    return rc ? rc : gcolor_mul(result, result, illum);
}

static inline int default_absorption(const GMaterial *m, GSurfPoint *sp, const GColor *illum, double length,
                                     GColor *result)
{
    (void)m, (void)sp, (void)length; /* also for GMAT_CLEAR; gcolor_copy copies nothing when result is illum */
    return gcolor_copy(result, illum);
}

static inline int default_normal(const GMaterial *m, GSurfPoint *sp, GVec3 *n)
{
    (void)m;
    *n = sp->geometric_normal;
    return G_OK;
}

static inline int default_diffuse(const GMaterial *m, GSurfPoint *sp, GColor *result)
{
    (void)m, (void)sp;
    gcolor_black(result);
    return G_OK;
}

static inline int default_opaque(const GMaterial *m, GSurfPoint *sp)
{
    (void)m, (void)sp;
    return 1;
}

static inline int default_is_delta(const GMaterial *m, GSurfPoint *sp)
{
    (void)m, (void)sp; /* also for GMAT_LAMBERTIAN: a diffuse lobe is not delta (material.h) */
    return 0;
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
    if (!m) /* vacuum */
        return 0.0;
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

/* ---- the dispatch functions of GMATERIAL_METHODS whose `dispatch` is `call`: the class's slot, or the default ---- */

#define DISPATCH_call(name, type, unless, params, args)                                                            \
    type gmaterial_##name GMATERIAL_WITH(const GMaterial *m, params)                                               \
    {                                                                                                              \
        if (m && !(m->flags & (unless)) && m->cls->name)                                                           \
            return m->cls->name GMATERIAL_WITH(m, args);                                                           \
        return default_##name GMATERIAL_WITH(m, args);                                                             \
    }
#define DISPATCH_own(name, type, unless, params, args)
#define DISPATCH(name, NAME, type, attr, unless, dispatch, blend, params, args) \
    DISPATCH_##dispatch(name, type, unless, params, args)
GMATERIAL_METHODS(DISPATCH)
