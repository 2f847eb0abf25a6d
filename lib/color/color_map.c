/* color_map.c - per-sample kernels over colours of any model (generic/kit/color_map.h): the loop over a model's plain
 * samples, a matrix's plain part, and the fallback through the nm exchange spectrum. */
#include "generic/kit/color_map.h"

#include <stddef.h>

/* 1 when the model's class leaves fill to the library, which then reads its vectors as nvalues plain samples (the
 * rule of lib/color/color_vector_ops.c's defaults). */
static int plain_samples(const GColorModel *m) { return m->cls->fill == NULL; }

/* The floats of operand x as a vector: its own when it is one, else its plain part (the model's pow(x, 1)) in
 * tmp's storage. */
static int vector_of(const GColor *x, GColor *tmp, GScratch *arena, const float **v)
{
    if (!x) {
        *v = NULL;
        return G_OK;
    }
    if (x->kind == GCOLOR_VECTOR) {
        *v = x->v;
        return G_OK;
    }
    int rc = gcolor_scratch_uncleared(tmp, x->model, arena);
    if (rc == G_OK)
        rc = gcolor_pow(tmp, x, 1.0);
    if (rc == G_OK && tmp->kind != GCOLOR_VECTOR)
        rc = G_ERR_UNSUPPORTED;
    *v = tmp->v;
    return rc;
}

/* map_plain with an operand that is not a vector (its plain part through the thread's arena): apart, so that the
 * common case, every operand a vector, pays for none of its frame. */
__attribute__((noinline)) static int map_plain(GColor *out, GColorSamplesFn f, const void *params, const GColor *a,
                                               const GColor *b, const GColor *c)
{
    const GColorModel *m = out->model;
    GScratch *arena = gscratch_thread();
    if (!arena)
        return G_ERR_NOMEM;
    GScratchMark mark = gscratch_mark(arena);
    GColor ta, tb, tc;
    const float *va, *vb, *vc;
    int rc = vector_of(a, &ta, arena, &va);
    if (rc == G_OK)
        rc = vector_of(b, &tb, arena, &vb);
    if (rc == G_OK)
        rc = vector_of(c, &tc, arena, &vc);
    if (rc == G_OK) {
        f(out->v, va, vb, vc, m->nvalues, params);
        out->kind = GCOLOR_VECTOR;
    }
    gscratch_release(arena, mark);
    return rc;
}

/* The fallback: every operand through the nm spectrum as a reflectance, f at each nm, and back. */
static int map_nm(GColor *out, GColorSamplesFn f, const void *params, const GColor *a, const GColor *b,
                  const GColor *c)
{
    GSpectrumNM sa, sb, sc;
    int rc = gcolor_to_nm(a, GCOLOR_REFLECTANCE, &sa);
    if (rc == G_OK && b)
        rc = gcolor_to_nm(b, GCOLOR_REFLECTANCE, &sb);
    if (rc == G_OK && c)
        rc = gcolor_to_nm(c, GCOLOR_REFLECTANCE, &sc);
    if (rc != G_OK)
        return rc;
    f(sa.v, sa.v, b ? sb.v : NULL, c ? sc.v : NULL, GNM_COUNT, params);
    return gcolor_from_nm(out, &sa, GCOLOR_REFLECTANCE);
}

int gcolor_map_samples(GColor *out, GColorSamplesFn f, const void *params, const GColor *a, const GColor *b,
                       const GColor *c)
{
    if (!out || !a || !f || !out->model)
        return G_ERR_INVALID;
    const GColorModel *m = out->model;
    if (a->model != m || (b && b->model != m) || (c && c->model != m))
        return G_ERR_MISMATCH;
    if (!plain_samples(m))
        return map_nm(out, f, params, a, b, c);
    if (a->kind == GCOLOR_VECTOR && (!b || b->kind == GCOLOR_VECTOR) && (!c || c->kind == GCOLOR_VECTOR)) {
        f(out->v, a->v, b ? b->v : NULL, c ? c->v : NULL, m->nvalues, params);
        out->kind = GCOLOR_VECTOR;
        return G_OK;
    }
    return map_plain(out, f, params, a, b, c);
}

/* gcolor_map's function and parameters, handed to the array kernel below. */
typedef struct SampleCall {
    GColorSampleFn f;
    const void *params;
} SampleCall;

static void each_sample(float *out, const float *a, const float *b, const float *c, int n, const void *params)
{
    const SampleCall *call = params;
    for (int i = 0; i < n; i++)
        out[i] = (float)call->f(a[i], b ? b[i] : 0.0, c ? c[i] : 0.0, call->params);
}

int gcolor_map(GColor *out, GColorSampleFn f, const void *params, const GColor *a, const GColor *b, const GColor *c)
{
    if (!f)
        return G_ERR_INVALID;
    SampleCall call = {f, params};
    return gcolor_map_samples(out, each_sample, &call, a, b, c);
}
