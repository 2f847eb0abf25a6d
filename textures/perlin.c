/* perlin.c - the perlin generator: improved Perlin noise mapped to [0, 1], with its analytic gradient. */
#include "noise.h"
#include "textures_builtin.h"

typedef struct Perlin {
    GGenerator base;
    GNoiseParams p;
} Perlin;

static void perlin_destroy(GGenerator *self) { gmem_free(self); }

static double perlin_value(const GGenerator *self, GSurfPoint *sp)
{
    const Perlin *n = (const Perlin *)self;
    GVec3 x = gvec3_scale(gtexnoise_coords(self, sp), n->p.frequency);
    return gnoise_perlin3(n->p.seed, x.x, x.y, x.z, NULL);
}

static int perlin_gradient(const GGenerator *self, GSurfPoint *sp, GVec3 *grad)
{
    const Perlin *n = (const Perlin *)self;
    GVec3 x = gvec3_scale(gtexnoise_coords(self, sp), n->p.frequency);
    gnoise_perlin3(n->p.seed, x.x, x.y, x.z, grad);
    *grad = gvec3_scale(*grad, n->p.frequency);
    if (self->space == GGENERATOR_SPACE_UV)
        grad->z = 0.0;
    return G_OK;
}

const GGeneratorClass ggen_perlin_class = {
    .abi_version = GGENERATOR_ABI_VERSION,
    .name = "perlin",
    .description = "improved Perlin noise (2002) in [0, 1]",
    .destroy = perlin_destroy,
    .value = perlin_value,
    .gradient = perlin_gradient,
};

int ggen_perlin_create(const GNoiseParams *p, GGenerator **out, GError *err)
{
    *out = NULL;
    GNoiseParams q;
    int rc = gtexnoise_params("perlin", p, &q, err);
    if (rc != G_OK)
        return rc;
    Perlin *n = gmem_calloc(1, sizeof *n);
    if (!n)
        return gerror_set(err, G_ERR_NOMEM, "perlin: out of memory");
    rc = ggenerator_init(&n->base, &ggen_perlin_class, q.space, err);
    if (rc != G_OK) {
        gmem_free(n);
        return rc;
    }
    n->p = q;
    *out = &n->base;
    return G_OK;
}
