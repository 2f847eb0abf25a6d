/* layer.c - two materials stacked: a dielectric-like interface on top (smooth or rough), any material below
 * (fluorescent ones and plug-ins included), optionally a homogeneous medium between; evaluated stochastically,
 * by random walks between the two, after Guo, Hasan, Yan and Zhao 2018 and pbrt-v4's LayeredBxDF.
 *
 * The stack is a plane-parallel slab about the shading normal: light is followed in depth only (no lateral
 * transport). Quantities follow material.h: light arriving along a ray is a beam of irradiance `illum` across
 * it, reflection() gives the radiance leaving. An estimate E(a -> b) of the light leaving towards b for a beam
 * from a:
 *   - entry: the beam crosses the top into the slab, along the top's refraction (smooth: the ideal ray, the beam
 *     keeping its flux per unit area, so its irradiance across it becomes T cos_a / cos_d times; rough: a
 *     direction the top's sample() draws for a, weighed by refraction() / pdf);
 *   - walk: at most `bounces` events: through the medium (optical depth `thickness` at normal incidence, extinction
 *     1, single-scattering albedo `albedo`, isotropic phase function; the free path drawn from e^-s), at the bottom
 *     (a direction from the bottom's own sample() for the arriving one, its reflection() of the light / pdf; what
 *     the bottom transmits leaves the stack) and at the top from inside (its ideal or sampled reflection; what it
 *     transmits leaves the stack and is counted by the connections below);
 *   - exit: at each bottom and medium event, the light sent towards the exit direction d of b (smooth top: the
 *     ideal refraction of b, radiance times T / eta^2; rough: drawn once by the top's sample() for b), times the
 *     medium's transmittance e^(-depth / cos) on the way up.
 * The bottom is always asked with the light it receives (reflection(in, light, out)), so a re-radiation matrix
 * acts on the light that reaches it, bounce after bounce. The walk's numbers come from a generator seeded by the
 * pair (a, b) (and the instance's seed): an evaluation is deterministic. reflection(in, out) is
 *   top's reflection + (E(in -> out) + E(out -> in) cos_in / cos_out) / 2,
 * an estimate symmetric in in and out, so the layer is exactly reciprocal where its parts are (each E is unbiased
 * for parts whose reflection is symmetric in its directions). At the top's ideal mirror pair only the top's ideal
 * part answers (material.h). Light the bottom transmits is not traced further: the layer is opaque.
 *
 * Sampling: the top's sample() with probability p (its Fresnel reflectance at cos_out, in [0.05, 0.95]), keeping
 * its reflected draws; else a cosine-weighted direction; pdf is p pdf_top + (1 - p) cos / pi; weights are value
 * / pdf with the value above, so they are consistent with reflection() by construction.
 *
 * Textured (kit/texparam.h): the thickness may be a generator and the albedo a colour texture, read at the point
 * when a walk starts (the albedo on the point's scratch arena); the top's own parameters (a dielectric's roughness)
 * are the top's. */
#include "generic/kit/material_kit.h"
#include "generic/kit/texparam.h"
#include "generic/kit/material_params.h"
#include "generic/kit/node_kit.h"
#include "generic/materials.h"
#include "generic/plugin.h"

#include <math.h>
#include <string.h>

#define LAYER_MAX_BOUNCES 64 /* events of one walk */
#define LAYER_MAX_SAMPLES 64 /* walks per direction and evaluation */
#define LAYER_MAX_STACK 3    /* layers stacked in one another */
#define LAYER_MAX_THICKNESS 100.0

typedef struct Layer {
    GMaterial base;
    GMaterial *top, *bottom; /* one reference each */
    double thickness;        /* optical depth of the medium at normal incidence; 0: none */
    GColor albedo;           /* the medium's single-scattering albedo */
    GTexNumber tex_thickness; /* a textured thickness (gen set), else the constant above */
    GTexColor tex_albedo;     /* a textured albedo (a mix or an image), else empty */
    int bounces, samples, stack;
    unsigned long long seed;
} Layer;

static void layer_destroy(GMaterial *self)
{
    Layer *l = (Layer *)self;
    gmaterial_unref(l->top);
    gmaterial_unref(l->bottom);
    gcolor_free(&l->albedo);
    gtexparam_number_release(&l->tex_thickness);
    gtexparam_color_release(&l->tex_albedo);
    gmem_free(l);
}

/* ---- the walk ---- */

static unsigned long long mix64(unsigned long long z)
{
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

static double next_uniform(unsigned long long *s)
{
    return (double)(mix64(*s += 0x9E3779B97F4A7C15ULL) >> 11) * (1.0 / 9007199254740992.0);
}

/* The direction's hash, of its components rounded to 2^-24: a direction renormalised by the caller (a few ulps
 * apart) gets the same numbers. */
static unsigned long long hash_dir(unsigned long long h, GVec3 d)
{
    double c[3] = {d.x, d.y, d.z};
    for (int i = 0; i < 3; i++) {
        double q = isfinite(c[i]) ? nearbyint(c[i] * 16777216.0) : 0.0;
        h = mix64(h ^ (unsigned long long)(long long)q) + 0x9E3779B97F4A7C15ULL;
    }
    return h;
}

/* The three places of a walk: the top seen from outside (sp itself) and from inside, the bottom seen from the
 * medium; each with the relative index n(from) / n(to) its methods are handed. */
typedef struct Walk {
    const Layer *l;
    GSurfPoint *to;
    GSurfPoint ti, bt;
    GVec3 n; /* the stack's normal: sp's shading normal, pointing out */
    GColor rel_to, rel_ti, rel_bt;
    GColor white, a, b, c; /* work colours */
    double eta2;           /* (n_top / n_outside)^2 */
    double thickness;      /* the medium's at the point */
    const GColor *albedo;  /* the medium's at the point: the layer's, or albedo_at */
    GColor albedo_at;
    int smooth;            /* the top's lobes are ideal */
    unsigned long long rng;
} Walk;

static int scalar_index(const GMaterial *m, GSurfPoint *sp, GColor *out, double *n)
{
    int rc = gmaterial_refraction_index(m, sp, out);
    *n = rc == G_OK ? gsurfpoint_scalar_index(out) : 1.0;
    return rc;
}

/* Sets the walk up at sp; its colours come from sp's arena (the caller marks and releases it). */
static int walk_open(const Layer *l, GSurfPoint *sp, Walk *w)
{
    GColor n_out, n_top, n_bot;
    GColor *cs[] = {&w->rel_to, &w->rel_ti, &w->rel_bt, &w->white, &w->a, &w->b, &w->c, &n_out, &n_top, &n_bot};
    int rc = G_OK;
    for (size_t i = 0; i < sizeof cs / sizeof cs[0] && rc == G_OK; i++)
        rc = gcolor_scratch(cs[i], l->base.model, sp->scratch);
    if (rc != G_OK)
        return rc;
    w->l = l;
    w->to = sp;
    w->thickness = gtexparam_number_at(&l->tex_thickness, sp);
    w->albedo = &l->albedo;
    if (l->tex_albedo.kind != GTEXCOLOR_CONSTANT) { /* the texture's colour at sp, within [0, 1] as at creation */
        if ((rc = gcolor_scratch_uncleared(&w->albedo_at, l->base.model, sp->scratch)) != G_OK ||
            (rc = gtexparam_color_at(&l->tex_albedo, sp, &w->albedo_at)) != G_OK)
            return rc;
        for (int i = 0; i < l->base.model->nvalues; i++)
            w->albedo_at.v[i] = w->albedo_at.v[i] > 0.0f ? (w->albedo_at.v[i] < 1.0f ? w->albedo_at.v[i] : 1.0f) : 0.0f;
        w->albedo = &w->albedo_at;
    }
    w->n = gsurfpoint_normal(sp);
    w->smooth = gmaterial_is_delta(l->top, sp) == 1;
    w->ti = *sp;
    gsurfpoint_invalidate(&w->ti);
    w->ti.geometric_normal = gvec3_neg(w->n);
    w->ti.from = l->top, w->ti.to = sp->from, w->ti.material = l->top;
    w->bt = *sp;
    gsurfpoint_invalidate(&w->bt);
    w->bt.geometric_normal = w->n;
    w->bt.from = l->top, w->bt.to = l->bottom, w->bt.material = l->bottom;
    double no, nt, nb;
    if ((rc = scalar_index(sp->from, sp, &n_out, &no)) != G_OK || (rc = scalar_index(l->top, sp, &n_top, &nt)) ||
        (rc = scalar_index(l->bottom, &w->bt, &n_bot, &nb)))
        return rc;
    if ((rc = gcolor_div(&w->rel_to, &n_out, &n_top)) || (rc = gcolor_div(&w->rel_ti, &n_top, &n_out)) ||
        (rc = gcolor_div(&w->rel_bt, &n_top, &n_bot)) || (rc = gcolor_fill(&w->white, 1.0)))
        return rc;
    gsurfpoint_set_relative_index(&w->ti, &w->rel_ti);
    gsurfpoint_set_relative_index(&w->bt, &w->rel_bt);
    w->eta2 = (nt / no) * (nt / no);
    return G_OK;
}

/* The exit towards b: the direction d inside that the top refracts into b (pointing into the slab) and the
 * factor e (a colour: the top passes on e times the radiance arriving along -d). *ok = 0 when nothing leaves
 * towards b this time. */
static int walk_exit(Walk *w, GVec3 b, GVec3 *d, GColor *e, int *ok)
{
    const Layer *l = w->l;
    *ok = 0;
    if (w->smooth) {
        if (gmaterial_refraction_dir(l->top, w->to, gvec3_neg(b), &w->rel_to, d) != 1)
            return G_OK;
        int rc = gmaterial_refraction(l->top, w->to, *d, &w->white, &w->rel_to, b, e);
        *ok = rc == G_OK;
        return rc == G_OK ? gcolor_scale(e, e, 1.0 / w->eta2) : rc;
    }
    GMaterialSample s;
    int rc = gmaterial_sample(l->top, w->to, b, &w->rel_to, next_uniform(&w->rng), next_uniform(&w->rng), &s, e);
    if (rc <= 0 || !(s.flags & GSAMPLE_TRANSMIT) || !(s.pdf > 0.0))
        return rc < 0 ? rc : G_OK;
    *d = s.in;
    if ((rc = gmaterial_refraction(l->top, w->to, s.in, &w->white, &w->rel_to, b, e)) != G_OK)
        return rc;
    *ok = 1;
    return gcolor_scale(e, e, 1.0 / s.pdf);
}

/* The entry of the beam illum from a: its direction d in the slab and the beam there into light. *ok = 0 when
 * nothing enters this time. */
static int walk_entry(Walk *w, GVec3 a, const GColor *illum, GVec3 *d, GColor *light, int *ok)
{
    const Layer *l = w->l;
    *ok = 0;
    double scale;
    int rc;
    if (w->smooth) {
        if (gmaterial_refraction_dir(l->top, w->to, gvec3_neg(a), &w->rel_to, d) != 1)
            return G_OK;
        double cd = fabs(gvec3_dot(*d, w->n));
        if (!(cd > 1e-9))
            return G_OK;
        scale = gvec3_dot(a, w->n) / cd; /* the beam's flux per unit area kept */
    } else {
        GMaterialSample s;
        rc = gmaterial_sample(l->top, w->to, a, &w->rel_to, next_uniform(&w->rng), next_uniform(&w->rng), &s,
                              light);
        if (rc <= 0 || !(s.flags & GSAMPLE_TRANSMIT) || !(s.pdf > 0.0))
            return rc < 0 ? rc : G_OK;
        *d = s.in;
        scale = 1.0 / s.pdf;
    }
    if ((rc = gmaterial_refraction(l->top, &w->ti, a, illum, &w->rel_ti, *d, light)) != G_OK)
        return rc;
    *ok = 1;
    return gcolor_scale(light, light, scale);
}

/* Adds to acc the light sent from an event towards the exit: radiance (a colour) arriving at depth `depth` along
 * -d_exit, times the medium's transmittance up to the top and the exit's factor e. */
static int walk_connect(Walk *w, GColor *radiance, double depth, GVec3 d_exit, const GColor *e, GColor *acc)
{
    double up = fabs(gvec3_dot(d_exit, w->n));
    double tr = w->thickness > 0.0 ? (up > 1e-9 ? exp(-depth / up) : 0.0) : 1.0;
    int rc = gcolor_mul(radiance, e, radiance);
    return rc == G_OK ? gcolor_axpy(acc, tr, radiance, acc) : rc;
}

/* One event in the medium along d from depth *depth: 1 when the light scattered there (light, d and depth
 * updated, its connection added), 0 when it reached the boundary it travels to (depth set to it), <0 on error. */
static int walk_medium(Walk *w, GVec3 *d, double *depth, GColor *light, int exit_ok, GVec3 d_exit, const GColor *e,
                       GColor *acc)
{
    double dz = gvec3_dot(*d, w->n), mu = fabs(dz);
    double dist = mu > 1e-12 ? (dz < 0.0 ? w->thickness - *depth : *depth) / mu : INFINITY;
    double s = -log(1.0 - next_uniform(&w->rng));
    if (!(s < dist)) {
        *depth = dz < 0.0 ? w->thickness : 0.0;
        return 0;
    }
    *depth -= s * dz;
    int rc = gcolor_mul(light, w->albedo, light);
    double mu_e = fabs(gvec3_dot(d_exit, w->n));
    if (rc == G_OK && exit_ok && mu_e > 1e-9) { /* isotropic: intensity albedo * light * mu / (4 pi) per area */
        rc = gcolor_scale(&w->c, light, mu / (4.0 * M_PI * mu_e));
        if (rc == G_OK)
            rc = walk_connect(w, &w->c, *depth, d_exit, e, acc);
    }
    /* a new direction, uniform over the sphere: the beam's flux per area is kept */
    double u1 = next_uniform(&w->rng), u2 = next_uniform(&w->rng);
    double z = 1.0 - 2.0 * u1, r = sqrt(fmax(0.0, 1.0 - z * z)), phi = 2.0 * M_PI * u2;
    GVec3 t, bb;
    goptics_frame(w->n, &t, &bb);
    *d = gvec3_add(gvec3_scale(w->n, z), gvec3_add(gvec3_scale(t, r * cos(phi)), gvec3_scale(bb, r * sin(phi))));
    if (rc == G_OK)
        rc = fabs(z) > 1e-6 ? gcolor_scale(light, light, mu / fabs(z)) : (gcolor_black(light), G_OK);
    return rc == G_OK ? 1 : rc;
}

/* A reflection at the material m seen at sp, for light arriving from `from`: the next direction (the material's
 * own sample for `from`, a reflected one) into *d and light its reflection() of the light / pdf. 0 when the walk
 * ends there (nothing drawn, or a transmitted draw: it leaves the stack), 1 when it goes on. */
static int walk_bounce(Walk *w, const GMaterial *m, GSurfPoint *sp, const GColor *rel, GVec3 from, GVec3 *d,
                       GColor *light)
{
    GMaterialSample s;
    int rc = gmaterial_sample(m, sp, from, rel, next_uniform(&w->rng), next_uniform(&w->rng), &s, &w->a);
    if (rc <= 0 || (s.flags & GSAMPLE_TRANSMIT) || !(s.pdf > 0.0))
        return rc < 0 ? rc : 0;
    if ((rc = gmaterial_reflection(m, sp, from, light, s.in, &w->a)) != G_OK ||
        (rc = gcolor_scale(light, &w->a, 1.0 / s.pdf)) != G_OK)
        return rc;
    *d = s.in;
    return gcolor_is_black(light) ? 0 : 1;
}

/* Adds E(a -> b) for the beam illum to acc. */
static int walk_estimate(Walk *w, GVec3 a, GVec3 b, const GColor *illum, GColor *acc)
{
    const Layer *l = w->l;
    GVec3 d_exit = w->n, d;
    int exit_ok, entered;
    int rc = walk_exit(w, b, &d_exit, &w->b, &exit_ok);
    if (rc == G_OK)
        rc = walk_entry(w, a, illum, &d, &w->c, &entered);
    if (rc != G_OK || !entered || !exit_ok)
        return rc; /* nothing leaves towards b this time: only the exit connections carry light out */
    GColor light;
    if ((rc = gcolor_scratch(&light, l->base.model, w->to->scratch)) != G_OK || (rc = gcolor_copy(&light, &w->c)))
        return rc;
    double depth = 0.0;
    for (int k = 0; k < l->bounces && rc >= 0; k++) {
        if (w->thickness > 0.0) {
            rc = walk_medium(w, &d, &depth, &light, exit_ok, d_exit, &w->b, acc);
            if (rc != 0)
                continue;
        }
        GVec3 from = gvec3_neg(d);
        if (gvec3_dot(d, w->n) < 0.0) { /* the bottom, from above */
            rc = gmaterial_reflection(l->bottom, &w->bt, from, &light, gvec3_neg(d_exit), &w->c);
            if (rc == G_OK)
                rc = walk_connect(w, &w->c, w->thickness, d_exit, &w->b, acc);
            if (rc == G_OK)
                rc = walk_bounce(w, l->bottom, &w->bt, &w->rel_bt, from, &d, &light);
        } else if (w->smooth) { /* the top from inside: its ideal reflection */
            GVec3 mirror = gvec3_reflect(d, w->n);
            rc = gmaterial_reflection(l->top, &w->ti, from, &light, mirror, &w->c);
            if (rc == G_OK)
                rc = gcolor_copy(&light, &w->c);
            d = mirror;
            rc = rc == G_OK ? !gcolor_is_black(&light) : rc;
        } else
            rc = walk_bounce(w, l->top, &w->ti, &w->rel_ti, from, &d, &light);
        if (rc == 0)
            break;
    }
    return rc < 0 ? rc : G_OK;
}

/* ---- the methods ---- */

static int layer_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                            GColor *result)
{
    const Layer *l = (const Layer *)self;
    GVec3 n;
    double ci = gmaterial_cos_in(sp, in, out, &n), co = gvec3_dot(out, n);
    int rc = gmaterial_reflection(l->top, sp, in, illum, out, result);
    if (rc != G_OK || ci <= 0.0 || co <= 0.0) {
        if (rc == G_OK && (ci <= 0.0 || co <= 0.0))
            gcolor_black(result);
        return rc;
    }
    GVec3 ideal;
    if (gmaterial_reflection_dir(l->top, sp, gvec3_neg(out), &ideal) == 1 && gmaterial_is_mirror_pair(in, n, out))
        return G_OK; /* the top's ideal reflection alone (material.h) */
    Walk w;
    GColor acc, half;
    GScratchMark mark = gscratch_mark(sp->scratch);
    rc = walk_open(l, sp, &w);
    if (rc == G_OK)
        rc = gcolor_scratch(&acc, self->model, sp->scratch);
    if (rc == G_OK)
        rc = gcolor_scratch(&half, self->model, sp->scratch);
    for (int k = 0; k < l->samples && rc == G_OK; k++) {
        w.rng = hash_dir(hash_dir(l->seed + (unsigned long long)k, in), out);
        rc = walk_estimate(&w, in, out, illum, &acc);
        if (rc == G_OK) {
            gcolor_black(&half);
            w.rng = hash_dir(hash_dir(l->seed + (unsigned long long)k, out), in);
            rc = walk_estimate(&w, out, in, illum, &half);
        }
        if (rc == G_OK)
            rc = gcolor_axpy(&acc, ci / co, &half, &acc);
    }
    if (rc == G_OK)
        rc = gcolor_axpy(result, 0.5 / l->samples, &acc, result);
    gscratch_release(sp->scratch, mark);
    return rc;
}

static int layer_refraction_index(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    return gmaterial_refraction_index(((const Layer *)self)->top, sp, result);
}

static int layer_reflection_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    return gmaterial_reflection_dir(((const Layer *)self)->top, sp, view, dir);
}

/* For previews and the ambient term: the bottom's diffuse colour through the top at normal incidence, in and
 * out. */
static int layer_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    const Layer *l = (const Layer *)self;
    double t = 1.0 - goptics_fresnel(1.0, gsurfpoint_relative_index(sp));
    int rc = gmaterial_diffuse(l->bottom, sp, result);
    return rc == G_OK ? gcolor_scale(result, result, t * t) : rc;
}

/* The probability of drawing from the top for light leaving at cos_o. */
static double top_share(GSurfPoint *sp, double cos_o)
{
    return fmin(0.95, fmax(0.05, goptics_fresnel(cos_o, gsurfpoint_relative_index(sp))));
}

static double layer_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    const Layer *l = (const Layer *)self;
    GVec3 n = gsurfpoint_normal(sp);
    double co = gvec3_dot(out, n), ci = gvec3_dot(in, n);
    if (co <= 0.0 || ci <= 0.0 || gvec3_dot(out, sp->geometric_normal) <= 0.0)
        return 0.0;
    double p = top_share(sp, co);
    return p * gmaterial_pdf(l->top, sp, in, out, rel_index) + (1.0 - p) * ci / M_PI;
}

static int layer_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1,
                        double u2, GMaterialSample *s, GColor *weight)
{
    const Layer *l = (const Layer *)self;
    GVec3 n = gsurfpoint_normal(sp);
    double co = gvec3_dot(out, n);
    if (co <= 0.0 || gvec3_dot(out, sp->geometric_normal) <= 0.0)
        return 0;
    double p = top_share(sp, co);
    int rc;
    if (u1 < p) {
        GScratchMark mark = gscratch_mark(sp->scratch);
        rc = gmaterial_sample(l->top, sp, out, rel_index, fmin(u1 / p, 0x1.fffffffffffffp-1), u2, s, weight);
        gscratch_release(sp->scratch, mark);
        if (rc <= 0 || (s->flags & GSAMPLE_TRANSMIT))
            return rc < 0 ? rc : 0;
        if (s->flags & GSAMPLE_DELTA)
            s->pdf *= p;
        else
            s->pdf = layer_pdf(self, sp, s->in, out, rel_index);
    } else {
        s->in = goptics_sample_cosine(n, (u1 - p) / (1.0 - p), u2);
        s->flags = GSAMPLE_REFLECT;
        s->pdf = layer_pdf(self, sp, s->in, out, rel_index);
    }
    if (!(s->pdf > 0.0))
        return 0;
    rc = gmaterial_sample_weight(self, sp, s->in, out, rel_index, 0, s->pdf, weight);
    return rc ? rc : 1;
}

static const GMaterialClass layer_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "layer",
    .description = "two materials stacked, evaluated by random walks between them (Guo et al. 2018)",
    .destroy = layer_destroy,
    .reflection = layer_reflection,
    .refraction_index = layer_refraction_index,
    .reflection_dir = layer_reflection_dir,
    .diffuse = layer_diffuse,
    .sample = layer_sample,
    .pdf = layer_pdf,
};

/* ---- construction ---- */

/* Layers stacked in m: those of a layer, else 0. */
static int stack_of(const GMaterial *m)
{
    return m && m->cls == &layer_class ? ((const Layer *)m)->stack : 0;
}

static int cost_of(const GMaterial *m) { return m && m->cost > 0 ? m->cost : 1; }
static int depth_of(const GMaterial *m) { return m && m->depth > 0 ? m->depth : 1; }

/* The extremes of a textured albedo within [0, 1] (the walk's energy holds for every albedo in [0, 1]). */
static int check_textured_albedo(const GColorModel *model, const GTexColor *albedo, GError *err)
{
    GColor ext[2];
    int n = 0;
    int rc = gtexparam_color_extremes(albedo, ext, &n, err);
    for (int i = 0; i < n; i++) {
        GColor checked = {0};
        if (rc == G_OK)
            rc = gmaterial_param_color(model, &ext[i], GCOLOR_REFLECTANCE, 1.0, "layer", "albedo", &checked, err);
        gcolor_free(&checked);
        gcolor_free(&ext[i]);
    }
    return rc;
}

/* The layer of top over bottom (albedo: the medium's, NULL for white) into *out; messages name the parameter.
 * tex_thickness (a generator, else NULL) and tex_albedo (a mix or an image, else NULL) make those vary over the
 * surface; their contents are taken when the layer is made. */
static int layer_create(const GColorModel *model, GMaterial *top, GMaterial *bottom, double thickness,
                        const GColor *albedo, int bounces, int samples, GTexNumber *tex_thickness,
                        GTexColor *tex_albedo, GMaterial **out, GError *err)
{
    *out = NULL;
    if (!top || !bottom)
        return gerror_set_param(err, G_ERR_INVALID, top ? "bottom" : "top", "layer: %s is missing",
                                top ? "the bottom material" : "the top material");
    if (top->model != model || bottom->model != model)
        return gerror_set_param(err, G_ERR_MISMATCH, top->model != model ? "top" : "bottom",
                                "layer: the material is in another colour model");
    int stack = 1 + (stack_of(top) > stack_of(bottom) ? stack_of(top) : stack_of(bottom));
    if (stack > LAYER_MAX_STACK)
        return gerror_set_param(err, G_ERR_INVALID, stack_of(top) >= stack_of(bottom) ? "top" : "bottom",
                                "layer: a stack of %d layers, the limit is %d (LAYER_MAX_STACK)", stack,
                                LAYER_MAX_STACK);
    /* one evaluation: two walks per sample, each of setup calls and up to 5 calls per event, on either child */
    long long per = 2LL * samples * (5LL * bounces + 12);
    long long cost = 1 + per * ((long long)cost_of(top) + cost_of(bottom));
    int depth = 1 + (depth_of(top) > depth_of(bottom) ? depth_of(top) : depth_of(bottom));
    if (cost > GNODE_MAX_COST || depth > GNODE_MAX_DEPTH)
        return gerror_set_param(err, G_ERR_INVALID, cost_of(top) >= cost_of(bottom) ? "top" : "bottom",
                                "layer: one call would make %lld material calls at depth %d, the limits are %d "
                                "(GNODE_MAX_COST) and %d (GNODE_MAX_DEPTH); use fewer bounces or samples",
                                cost, depth, GNODE_MAX_COST, GNODE_MAX_DEPTH);
    GMaterial *m = NULL;
    int rc = gmaterial_new(&layer_class, model, sizeof(Layer), &m, err);
    if (rc != G_OK)
        return rc;
    Layer *l = (Layer *)m;
    l->top = gmaterial_ref(top), l->bottom = gmaterial_ref(bottom);
    l->thickness = thickness, l->bounces = bounces, l->samples = samples, l->stack = stack;
    l->seed = 0x6c61796572ULL; /* "layer" */
    m->cost = (int)cost, m->depth = depth;
    l->tex_thickness = gtexparam_number_const(thickness);
    if (albedo)
        rc = gmaterial_param_color(model, albedo, GCOLOR_REFLECTANCE, 1.0, "layer", "albedo", &l->albedo, err);
    else if ((rc = gcolor_alloc(&l->albedo, model)) == G_OK)
        rc = gcolor_fill(&l->albedo, 1.0);
    if (rc == G_OK && l->albedo.kind != GCOLOR_VECTOR)
        rc = gerror_set_param(err, G_ERR_INVALID, "albedo", "layer: albedo must be a plain colour, not a matrix");
    if (rc == G_OK && tex_albedo && tex_albedo->kind != GTEXCOLOR_CONSTANT &&
        (rc = check_textured_albedo(model, tex_albedo, err)) == G_OK) {
        l->tex_albedo = *tex_albedo;
        memset(tex_albedo, 0, sizeof *tex_albedo);
    }
    if (rc == G_OK && tex_thickness && tex_thickness->gen) {
        l->tex_thickness = *tex_thickness;
        *tex_thickness = gtexparam_number_const(0.0);
    }
    if (rc != G_OK) {
        layer_destroy(m);
        return rc;
    }
    /* no method reads (u, v) itself; light is filtered sample by sample when both parts do so */
    m->flags |= top->flags & bottom->flags & (GMAT_NO_UV | GMAT_DIAGONAL);
    if (gtexparam_number_reads_uv(&l->tex_thickness) || gtexparam_color_reads_uv(&l->tex_albedo))
        m->flags &= ~(unsigned)GMAT_NO_UV;
    m->flags |= top->flags & GMAT_CONSTANT_INDEX; /* its index is the top's */
    *out = m;
    return G_OK;
}

/* layer { top MATERIAL bottom MATERIAL thickness T albedo COLOR bounces N samples N } */
static int parse_layer(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GMaterial *top = NULL, *bottom = NULL;
    GTexColor albedo = {0};
    GTexNumber thickness = gtexparam_number_const(0.0);
    long bounces = 16, samples = 1;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "top") == 0)
            rc = greader_material(r, &top, err);
        else if (strcmp(key, "bottom") == 0)
            rc = greader_material(r, &bottom, err);
        else if (strcmp(key, "thickness") == 0)
            rc = gtexparam_read_number(r, 0.0, LAYER_MAX_THICKNESS, 0, "layer", "thickness", NULL, &thickness, err);
        else if (strcmp(key, "albedo") == 0)
            rc = gtexparam_read_color(r, GCOLOR_REFLECTANCE, &albedo, err);
        else if (strcmp(key, "bounces") == 0)
            rc = greader_int(r, 1, LAYER_MAX_BOUNCES, &bounces, err);
        else if (strcmp(key, "samples") == 0)
            rc = greader_int(r, 1, LAYER_MAX_SAMPLES, &samples, err);
        else
            rc = greader_unknown_param(r, "top, bottom, thickness, albedo, bounces, samples", err);
        if (rc < 0)
            break;
    }
    GMaterial *m = NULL;
    const GColor *constant = gtexparam_color_constant(&albedo);
    if (rc == G_OK && (rc = layer_create(greader_colormodel(r), top, bottom, thickness.value,
                                         constant && constant->v ? constant : NULL, (int)bounces, (int)samples,
                                         &thickness, &albedo, &m, err)) == G_OK)
        *object = m;
    gtexparam_color_release(&albedo);
    gtexparam_number_release(&thickness);
    return rc;
}

static const GParamInfo layer_params[] = {
    {"top", GPARAM_NAMED, "material", "(required)", "a dielectric-like interface",
     "the interface on top: its reflection, refraction and sampling (smooth when is_delta says so, else rough)"},
    {"bottom", GPARAM_NAMED, "material", "(required)", "any material", "what lies under the top"},
    {"thickness", GPARAM_NAMED, "texnumber", "0 (no medium)", "[0, 100]",
     "the optical depth of a medium between them at normal incidence (extinction 1 per unit)"},
    {"albedo", GPARAM_NAMED, "texcolor", "rgb 1 1 1", "[0, 1], not a matrix",
     "the medium's single-scattering albedo (isotropic scattering)"},
    {"bounces", GPARAM_NAMED, "integer", "16", "[1, 64]", "the most events of one random walk"},
    {"samples", GPARAM_NAMED, "integer", "1", "[1, 64]", "random walks per direction and evaluation"},
    {NULL},
};

GENERIC_TYPE_PARAMS(layer, GKIND_MATERIAL, &layer_class, parse_layer, NULL, layer_params);
