/* generator.c - dispatch of the generator interface: creation, references, cached values and gradients. */
#include "generic/texture.h"

#include <math.h>
#include <string.h>

int ggenerator_init(GGenerator *g, const GGeneratorClass *cls, GGeneratorSpace space, GError *err)
{
    if (!cls || cls->abi_version != GGENERATOR_ABI_VERSION)
        return gerror_set(err, G_ERR_VERSION, "generator '%s' has interface version %d, the library has %d",
                          cls && cls->name ? cls->name : "?", cls ? cls->abi_version : -1, GGENERATOR_ABI_VERSION);
    if (!cls->destroy || !cls->value)
        return gerror_set(err, G_ERR_INVALID, "generator '%s' lacks destroy or value", cls->name);
    if ((unsigned)space > GGENERATOR_SPACE_WORLD)
        return gerror_set(err, G_ERR_INVALID, "generator '%s': unknown space %d", cls->name, (int)space);
    g->cls = cls;
    g->refcount = 1;
    g->space = (int)space;
    return G_OK;
}

int ggenerator_new(const GGeneratorClass *cls, GGeneratorSpace space, size_t size, GGenerator **out, GError *err)
{
    *out = NULL;
    GGenerator *g = gmem_calloc(1, size);
    if (!g)
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory", cls->name);
    int rc = ggenerator_init(g, cls, space, err);
    if (rc != G_OK) {
        gmem_free(g);
        return rc;
    }
    *out = g;
    return G_OK;
}

void ggenerator_free(GGenerator *self) { gmem_free(self); }

GGenerator *ggenerator_ref(GGenerator *g)
{
    if (g)
        g->refcount++;
    return g;
}

void ggenerator_unref(GGenerator *g)
{
    if (g && --g->refcount == 0)
        g->cls->destroy(g);
}

void ggenerator_release(void *g) { ggenerator_unref(g); }

const char *ggenerator_name(const GGenerator *g) { return g ? g->cls->name : "(none)"; }

double ggenerator_value(const GGenerator *g, GSurfPoint *sp) { return g->cls->value(g, sp); }

static double step_for(double x) { return 1e-4 * fmax(1.0, fabs(x)); }

/* Central differences on a private copy of the point (empty caches, so nothing cached at the moved
 * coordinates leaks back to the caller). */
static void central_differences(const GGenerator *g, const GSurfPoint *sp, GVec3 *grad)
{
    GSurfPoint q = *sp;
    q.priv.ncache = 0;
    if (g->space == GGENERATOR_SPACE_UV) {
        double hu = step_for(sp->u), hv = step_for(sp->v);
        q.u = sp->u + hu;
        double a = g->cls->value(g, &q);
        q.u = sp->u - hu;
        double b = g->cls->value(g, &q);
        q.u = sp->u;
        q.v = sp->v + hv;
        double c = g->cls->value(g, &q);
        q.v = sp->v - hv;
        double d = g->cls->value(g, &q);
        *grad = gvec3((a - b) / (2 * hu), (c - d) / (2 * hv), 0.0);
        return;
    }
    GVec3 *p = g->space == GGENERATOR_SPACE_OBJECT ? &q.object_point : &q.point;
    GVec3 p0 = *p;
    double *cp = &p->x, *c0 = &p0.x;
    double out[3];
    for (int i = 0; i < 3; i++) {
        double h = step_for(c0[i]);
        cp[i] = c0[i] + h;
        double a = g->cls->value(g, &q);
        cp[i] = c0[i] - h;
        double b = g->cls->value(g, &q);
        cp[i] = c0[i];
        out[i] = (a - b) / (2 * h);
    }
    *grad = gvec3(out[0], out[1], out[2]);
}

int ggenerator_gradient(const GGenerator *g, GSurfPoint *sp, GVec3 *grad)
{
    if (g->cls->gradient)
        return g->cls->gradient(g, sp, grad);
    if (g->space == GGENERATOR_SPACE_NONE) {
        *grad = gvec3(0, 0, 0);
        return G_OK;
    }
    central_differences(g, sp, grad);
    return G_OK;
}

/* Values are cached under the generator's address; value and gradient together under the address of its
 * second byte, which no other object can start at. */
static const void *gradient_key(const GGenerator *g) { return (const char *)g + 1; }

double ggenerator_cached_value(const GGenerator *g, GSurfPoint *sp)
{
    double v;
    if (gsurfpoint_cache_get(sp, g, &v, NULL) || gsurfpoint_cache_get(sp, gradient_key(g), &v, NULL))
        return v;
    v = g->cls->value(g, sp);
    gsurfpoint_cache_put(sp, g, v, gvec3(0, 0, 0));
    return v;
}

int ggenerator_cached_gradient(const GGenerator *g, GSurfPoint *sp, double *value, GVec3 *grad)
{
    double v;
    GVec3 d;
    if (!gsurfpoint_cache_get(sp, gradient_key(g), &v, &d)) {
        int rc = ggenerator_gradient(g, sp, &d);
        if (rc != G_OK)
            return rc;
        if (!gsurfpoint_cache_get(sp, g, &v, NULL))
            v = g->cls->value(g, sp);
        gsurfpoint_cache_put(sp, gradient_key(g), v, d);
    }
    if (value)
        *value = v;
    if (grad)
        *grad = d;
    return G_OK;
}

static int is_zero(GVec3 a) { return a.x == 0.0 && a.y == 0.0 && a.z == 0.0; }

int ggenerator_surface_derivatives(const GGenerator *g, GSurfPoint *sp, double *dh_du, double *dh_dv)
{
    GVec3 d;
    int rc = ggenerator_cached_gradient(g, sp, NULL, &d);
    if (rc != G_OK)
        return rc;
    switch (g->space) {
    case GGENERATOR_SPACE_UV:
        *dh_du = d.x;
        *dh_dv = d.y;
        break;
    case GGENERATOR_SPACE_OBJECT: {
        int have = !is_zero(sp->object_dpdu) || !is_zero(sp->object_dpdv);
        *dh_du = gvec3_dot(d, have ? sp->object_dpdu : sp->dpdu);
        *dh_dv = gvec3_dot(d, have ? sp->object_dpdv : sp->dpdv);
        break;
    }
    case GGENERATOR_SPACE_WORLD:
        *dh_du = gvec3_dot(d, sp->dpdu);
        *dh_dv = gvec3_dot(d, sp->dpdv);
        break;
    default:
        *dh_du = *dh_dv = 0.0;
        break;
    }
    return G_OK;
}
