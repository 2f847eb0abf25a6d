/* marble.c - the marble generator: sine veins across x displaced by Perlin's turbulence. */
#include "generic/plugin.h"
#include "noise.h"
#include "textures_builtin.h"

#include <math.h>

typedef struct Marble {
    GGenerator base;
    GNoiseParams p;
    double stripes, turbulence;
} Marble;

/* The phase 2 pi (stripes x + turbulence T) and, with grad, its gradient. */
static double phase(const GGenerator *self, GSurfPoint *sp, GVec3 *grad)
{
    const Marble *m = (const Marble *)self;
    GVec3 x = gtexnoise_coords(self, sp), d = gvec3(0, 0, 0);
    double s = m->stripes * x.x;
    if (m->turbulence != 0.0)
        s += m->turbulence * gtexnoise_turbulence(&m->p, x, grad ? &d : NULL);
    if (grad)
        *grad = gvec3_scale(gvec3(m->stripes + m->turbulence * d.x, m->turbulence * d.y, m->turbulence * d.z),
                            2.0 * M_PI);
    return 2.0 * M_PI * s;
}

static double marble_value(const GGenerator *self, GSurfPoint *sp) { return 0.5 + 0.5 * sin(phase(self, sp, NULL)); }

static int marble_gradient(const GGenerator *self, GSurfPoint *sp, GVec3 *grad)
{
    GVec3 d;
    double ph = phase(self, sp, &d);
    *grad = gtexnoise_space_grad(self, gvec3_scale(d, 0.5 * cos(ph)));
    return G_OK;
}

const GGeneratorClass ggen_marble_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "marble",
    .description = "sine veins across x displaced by turbulence, in [0, 1]",
    .destroy = gtexgen_free,
    .value = marble_value,
    .gradient = marble_gradient,
};

int ggen_marble_create(const GNoiseParams *p, double stripes, double turbulence, GGenerator **out, GError *err)
{
    *out = NULL;
    GNoiseParams q;
    int rc = gtexnoise_params("marble", p, &q, err);
    if (rc != G_OK)
        return rc;
    if (!isfinite(stripes) || !isfinite(turbulence))
        return gerror_set(err, G_ERR_INVALID, "marble: stripes and turbulence must be finite");
    GGenerator *gen;
    rc = gtexgen_new(&ggen_marble_class, q.space, sizeof(Marble), &gen, err);
    if (rc != G_OK)
        return rc;
    Marble *m = (Marble *)gen;
    m->p = q;
    m->stripes = stripes;
    m->turbulence = turbulence;
    *out = &m->base;
    return G_OK;
}

GENERIC_TYPE(marble, GKIND_GENERATOR, &ggen_marble_class, gtexparse_marble, ggenerator_release);
