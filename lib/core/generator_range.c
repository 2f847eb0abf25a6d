/* generator_range.c - a generator's value mapped linearly onto [lo, hi] (`range LO HI`, texture.h). */
#include "generic/texture.h"

#include <math.h>

typedef struct RangeGenerator {
    GGenerator base;
    GGenerator *inner; /* owned reference */
    double lo, hi;
} RangeGenerator;

static void range_destroy(GGenerator *self)
{
    ggenerator_unref(((RangeGenerator *)self)->inner);
    gmem_free(self);
}

/* lo (1 - v) + hi v: exactly lo at 0 and exactly hi at 1. */
static double range_value(const GGenerator *self, GSurfPoint *sp)
{
    const RangeGenerator *g = (const RangeGenerator *)self;
    double v = ggenerator_value(g->inner, sp);
    return g->lo * (1.0 - v) + g->hi * v;
}

static int range_gradient(const GGenerator *self, GSurfPoint *sp, GVec3 *grad)
{
    const RangeGenerator *g = (const RangeGenerator *)self;
    int rc = ggenerator_gradient(g->inner, sp, grad);
    if (rc == G_OK)
        *grad = gvec3_scale(*grad, g->hi - g->lo);
    return rc;
}

static const GGeneratorClass range_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "range",
    .description = "a generator's value mapped linearly from [0, 1] onto [lo, hi]",
    .destroy = range_destroy,
    .value = range_value,
    .gradient = range_gradient,
};

int ggenerator_range_create(GGenerator *inner, double lo, double hi, GGenerator **out, GError *err)
{
    *out = NULL;
    if (!inner)
        return gerror_set(err, G_ERR_INVALID, "range: no generator given");
    if (!isfinite(lo) || !isfinite(hi) || lo > hi)
        return gerror_set_param(err, G_ERR_INVALID, "range",
                                "%s: range %g %g is refused (both finite, LO <= HI)", ggenerator_name(inner), lo, hi);
    GGenerator *g;
    int rc = ggenerator_new(&range_class, (GGeneratorSpace)inner->space, sizeof(RangeGenerator), &g, err);
    if (rc != G_OK)
        return rc;
    RangeGenerator *rg = (RangeGenerator *)g;
    rg->inner = ggenerator_ref(inner);
    rg->lo = lo;
    rg->hi = hi;
    *out = g;
    return G_OK;
}

void ggenerator_declared_range(const GGenerator *g, double *lo, double *hi)
{
    if (g && g->cls == &range_class) {
        *lo = ((const RangeGenerator *)g)->lo;
        *hi = ((const RangeGenerator *)g)->hi;
    } else {
        *lo = 0.0;
        *hi = 1.0;
    }
}
