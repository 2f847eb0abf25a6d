/* wood.c - the wood generator: growth rings around the z axis, displaced by fbm. */
#include "generic/plugin.h"
#include "noise.h"
#include "textures_builtin.h"

#include <math.h>

typedef struct Wood {
    GGenerator base;
    GNoiseParams p;
    double rings, turbulence, latewood;
} Wood;

static double smoothstep(double t) { return t * t * (3.0 - 2.0 * t); }
static double dsmoothstep(double t) { return 6.0 * t * (1.0 - t); }

/* The ring profile at the point and, with grad, its gradient. */
static double profile(const GGenerator *self, GSurfPoint *sp, GVec3 *grad)
{
    const Wood *w = (const Wood *)self;
    GVec3 x = gtexnoise_coords(self, sp), d = gvec3(0, 0, 0);
    double rho = sqrt(x.x * x.x + x.y * x.y);
    double r = w->rings * rho;
    if (w->turbulence != 0.0)
        r += w->turbulence * gtexnoise_fbm(&w->p, x, grad ? &d : NULL);
    double g = r - floor(r), early = 1.0 - w->latewood;
    double v, slope;
    if (g < early) {
        v = smoothstep(g / early);
        slope = dsmoothstep(g / early) / early;
    } else {
        v = 1.0 - smoothstep((g - early) / w->latewood);
        slope = -dsmoothstep((g - early) / w->latewood) / w->latewood;
    }
    if (grad) {
        GVec3 dr = gvec3_scale(d, w->turbulence);
        if (rho > 0.0)
            dr = gvec3_madd(dr, gvec3(x.x / rho, x.y / rho, 0.0), w->rings);
        *grad = gtexnoise_space_grad(self, gvec3_scale(dr, slope));
    }
    return v;
}

static double wood_value(const GGenerator *self, GSurfPoint *sp) { return profile(self, sp, NULL); }

static int wood_gradient(const GGenerator *self, GSurfPoint *sp, GVec3 *grad)
{
    profile(self, sp, grad);
    return G_OK;
}

const GGeneratorClass ggen_wood_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "wood",
    .description = "growth rings around the z axis displaced by noise, in [0, 1]",
    .destroy = gtexgen_free,
    .value = wood_value,
    .gradient = wood_gradient,
};

int ggen_wood_create(const GNoiseParams *p, double rings, double turbulence, double latewood, GGenerator **out,
                     GError *err)
{
    *out = NULL;
    GNoiseParams q;
    int rc = gtexnoise_params("wood", p, &q, err);
    if (rc != G_OK)
        return rc;
    if (!(rings > 0.0) || !isfinite(rings))
        return gerror_set(err, G_ERR_INVALID, "wood: rings must be positive and finite, got %g", rings);
    if (!isfinite(turbulence))
        return gerror_set(err, G_ERR_INVALID, "wood: turbulence must be finite, got %g", turbulence);
    if (latewood == 0.0)
        latewood = 0.2;
    if (!(latewood > 0.0 && latewood < 1.0))
        return gerror_set(err, G_ERR_INVALID, "wood: latewood must be within (0, 1), got %g", latewood);
    GGenerator *gen;
    rc = gtexgen_new(&ggen_wood_class, q.space, sizeof(Wood), &gen, err);
    if (rc != G_OK)
        return rc;
    Wood *w = (Wood *)gen;
    w->p = q;
    w->rings = rings;
    w->turbulence = turbulence;
    w->latewood = latewood;
    *out = &w->base;
    return G_OK;
}

GENERIC_TYPE(wood, GKIND_GENERATOR, &ggen_wood_class, gtexparse_wood, ggenerator_release);
