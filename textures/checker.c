/* checker.c - the checker generator in (u, v) or in object space, box-filtered over the footprint:
 *
 *   generator NAME checker { dims 2|3  frequency F }
 */
#include <generic/generators.h>
#include <generic/plugin.h>
#include <generic/kit/texture_parse.h>

#include <math.h>
#include <stdint.h>
#include <string.h>

typedef struct Checker {
    GGenerator base;
    int dims;
    double frequency;
} Checker;

/* Integral of the square wave that is 0 on [0, 1) and 1 on [1, 2), repeating. */
static double wave_integral(double x)
{
    double h = floor(0.5 * x);
    return h + gfmax(0.0, x - 2.0 * h - 1.0);
}

/* The square wave averaged over [x - w/2, x + w/2] (w in cells); the wave itself when w is negligible or the
 * window lies in one cell. That value is exactly 0 or 1, where the difference of the integrals would give 1 only
 * to rounding (1 - 2e-16: a blend over the checker would then evaluate both of its children). */
static double filtered(double x, double w)
{
    if (w > 1e3)
        return 0.5;
    double lo = x - 0.5 * w, hi = x + 0.5 * w;
    if (fabs(x) < 0x1p52) {
        /* the same answer from one floor, as an integer: the cell i = floor(x) (exact below 2^52, as are i and
         * i + 1 as doubles); lo <= x <= hi, so floor(lo) == floor(hi) exactly when lo >= i and hi < i + 1; the
         * parity is the integer's low bit (two's complement: also for negative cells) */
        int64_t i = (int64_t)x;
        i -= (double)i > x;
        if (w > 1e-9 && !(lo >= (double)i && hi < (double)(i + 1)))
            return (wave_integral(hi) - wave_integral(lo)) / w;
        return (double)(i & 1);
    }
    if (w > 1e-9 && floor(lo) != floor(hi))
        return (wave_integral(hi) - wave_integral(lo)) / w;
    /* the parity of the cell, 0 or 1: fmod(|floor(x)|, 2) without the call, exact for every double (h and
     * 2 floor(h / 2) are integers that differ by 0 or 1; a NaN or an infinity gives a NaN, as fmod does) */
    double h = floor(x);
    return h - 2.0 * floor(0.5 * h);
}

/* Probability that the xor of two independent bits is 1. */
static double xor2(double a, double b) { return a + b - 2.0 * a * b; }

static double checker_value(const GGenerator *self, GSurfPoint *sp)
{
    const Checker *c = (const Checker *)self;
    double f = c->frequency;
    if (c->dims == 2) {
        double wu, wv;
        gsurfpoint_uv_widths(sp, &wu, &wv);
        return xor2(filtered(sp->u * f, wu * f), filtered(sp->v * f, wv * f));
    }
    double w = sp->footprint * f;
    GVec3 p = sp->object_point;
    return xor2(xor2(filtered(p.x * f, w), filtered(p.y * f, w)), filtered(p.z * f, w));
}

static const GGeneratorClass checker_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "checker",
    .description = "checkerboard 0/1 in (u, v) (dims 2) or object space (dims 3), box-filtered",
    .destroy = ggenerator_free,
    .value = checker_value,
};

int ggenerator_checker_create(int dims, double frequency, GGenerator **out, GError *err)
{
    *out = NULL;
    if (dims != 2 && dims != 3)
        return gerror_set(err, G_ERR_INVALID, "checker: dims must be 2 or 3, got %d", dims);
    if (!(frequency > 0.0) || !isfinite(frequency))
        return gerror_set(err, G_ERR_INVALID, "checker: frequency must be positive and finite, got %g", frequency);
    GGenerator *gen;
    GGeneratorSpace space = dims == 2 ? GGENERATOR_SPACE_UV : GGENERATOR_SPACE_OBJECT;
    int rc = ggenerator_new(&checker_class, space, sizeof(Checker), &gen, err);
    if (rc != G_OK)
        return rc;
    Checker *c = (Checker *)gen;
    c->dims = dims;
    c->frequency = frequency;
    *out = &c->base;
    return G_OK;
}

static int parse_checker(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    long dims = 2;
    double f = 1.0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "dims") == 0)
            rc = greader_int(r, 2, 3, &dims, err);
        else if (strcmp(key, "frequency") == 0)
            rc = greader_number_in(r, 1e-9, 1e9, &f, err);
        else
            rc = greader_unknown_param(r, "dims, frequency", err);
        if (rc < 0)
            return rc;
    }
    if (rc < 0)
        return rc;
    GGenerator *g = NULL;
    rc = ggenerator_checker_create((int)dims, f, &g, err);
    return gtexparse_finish(r, rc, g, object, err);
}

static const GParamInfo checker_params[] = {
    {"dims", GPARAM_NAMED, "integer", "2", "2, 3", "2: squares in (u, v); 3: cubes in object space"},
    {"frequency", GPARAM_NAMED, "number", "1", "[1e-9, 1e9]", "squares (cubes) per unit"},
    {NULL},
};

GENERIC_TYPE_PARAMS(checker, GKIND_GENERATOR, &checker_class, parse_checker, ggenerator_release, checker_params);
