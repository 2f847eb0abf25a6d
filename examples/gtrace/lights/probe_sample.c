/* probe_sample.c - the reference mode of `light probe`: the direct light of the whole probe, estimated by
 * Monte Carlo with importance sampling.
 *
 * The distribution is piecewise constant over the lat-long pixels: pixel (u, v) is chosen with probability
 * proportional to w(u, v) = brightness(P(u, v)) * Omega(v), where the brightness is the colour model's own
 * (gcolor_brightness_as of the pixel converted into the scene's model, as a light) and Omega(v) is the pixel's
 * exact solid angle, 2 pi / W * (cos theta_top - cos theta_bottom) (proportional to sin theta at the
 * centre). Inside the pixel the direction is uniform in solid angle (phi uniform, cos theta uniform), so the
 * density is w(u, v) / (sum w * Omega(v)) and an estimate L / (n pdf) = P(u, v) * sum w / (n brightness)
 * has the same brightness for every sample: the estimator integrates the piecewise-constant probe exactly in
 * expectation and its noise comes from visibility and the material, not from the probe. Samples are
 * stratified per shading point (the tracer's jittered grid or N-rooks in the unit square, mapped through
 * the two inverse CDFs: rows by the first coordinate, columns within the row by the second).
 *
 * Each sample goes through the same path as every light (sample_light: material.reflection, shadow ray,
 * transmission through non-opaque surfaces); `shadows off` skips the shadow ray (the unoccluded render that
 * `gprobe compare --unshadowed` uses to find the shadows).
 *
 * One estimator for both integrators (probe_light_nee): the Whitted tracer's reference takes `samples`
 * stratified directions with weight 1 (probe_light_shade); the path tracer's next-event estimation takes one
 * per vertex, weighted against its material sampling by the power heuristic, with shadow rays blocked by any
 * surface (LightTmp.blocked), drawn from the compensated distribution (ProbeEnv.nee_dist, probe_dist.h) whose
 * directions below the probe's mean brightness material sampling alone reaches. As a light the probe is its
 * pixels, piecewise constant (probe_pixel_radiance), which is what the distribution samples and what gprobe's ground
 * truth integrates; seen directly it is the bilinear background (probe_background). */
#include "probe_dist.h"
#include "lighting.h"
#include "probe_env.h"

#include <math.h>
#include <string.h>

/* Most samples one shading point takes. */
#define PROBE_MAX_SAMPLES 65536

void probe_dist_free(ProbeDist *d)
{
    if (!d)
        return;
    gmem_free(d->row_cdf);
    gmem_free(d->col_cdf);
    memset(d, 0, sizeof *d);
}

/* Exact solid angle of a pixel of row v. */
static double row_omega(int w, int h, int v)
{
    return 2.0 * M_PI / w * (cos(M_PI * v / h) - cos(M_PI * (v + 1) / h));
}

/* The distribution of p, plain or compensated (the header's two functions). */
static int dist_build(ProbeDist *d, const GProbe *p, const GColorModel *model, int compensated, GError *err)
{
    memset(d, 0, sizeof *d);
    int w = gprobe_width(p), h = gprobe_height(p);
    GColor c = {0};
    d->row_cdf = gmem_alloc((size_t)(h + 1) * sizeof *d->row_cdf);
    d->col_cdf = gmem_alloc((size_t)h * (size_t)(w + 1) * sizeof *d->col_cdf);
    if (!d->row_cdf || !d->col_cdf || gcolor_alloc(&c, model) != G_OK) {
        probe_dist_free(d);
        return gerror_set(err, G_ERR_NOMEM, "out of memory for the sampling tables of a %dx%d probe", w, h);
    }
    d->w = w;
    d->h = h;
    int rc = G_OK;
    double mean = 0.0; /* the mean brightness over the sphere, subtracted when compensated */
    for (int pass = compensated ? 0 : 1; pass < 2 && rc == G_OK; pass++) {
        d->row_cdf[0] = 0.0;
        for (int v = 0; v < h && rc == G_OK; v++) {
            double omega = row_omega(w, h, v), *cdf = d->col_cdf + (size_t)v * (w + 1);
            cdf[0] = 0.0;
            for (int u = 0; u < w; u++) {
                if ((rc = gprobe_pixel_color(p, u, v, &c)) < 0)
                    break;
                double b = gcolor_brightness_as(&c, GCOLOR_LIGHT) - mean;
                cdf[u + 1] = cdf[u] + (b > 0.0 && isfinite(b) ? b * omega : 0.0);
            }
            d->row_cdf[v + 1] = d->row_cdf[v] + cdf[w];
        }
        if (pass == 0 && rc == G_OK)
            mean = d->row_cdf[h] / (4.0 * M_PI);
        if (pass == 1 && mean > 0.0 && !(d->row_cdf[h] > 0.0)) { /* one brightness everywhere: the plain one */
            mean = 0.0;
            pass = 0;
        }
    }
    gcolor_free(&c);
    if (rc < 0) {
        probe_dist_free(d);
        return gerror_set(err, rc, "cannot convert the probe's pixels into the colour model: %s", gstatus_string(rc));
    }
    return G_OK;
}

int probe_dist_build(ProbeDist *d, const GProbe *p, const GColorModel *model, GError *err)
{
    return dist_build(d, p, model, 0, err);
}

int probe_dist_build_compensated(ProbeDist *d, const GProbe *p, const GColorModel *model, GError *err)
{
    return dist_build(d, p, model, 1, err);
}

/* Index i in [0, n) with cdf[i] <= x < cdf[i + 1] for a non-decreasing cdf of n + 1 entries, skipping empty
 * intervals (x < cdf[n] is assumed; the last non-empty interval is returned otherwise). */
static int find_interval(const double *cdf, int n, double x)
{
    int lo = 0, hi = n; /* the answer is in [lo, hi) */
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (cdf[mid] <= x)
            lo = mid;
        else
            hi = mid;
    }
    while (lo > 0 && cdf[lo + 1] <= cdf[lo]) /* x at the very top: step back to a non-empty interval */
        lo--;
    return lo;
}

double probe_dist_sample(const ProbeDist *d, const GProbe *p, double u1, double u2, int *u, int *v, GVec3 *dir)
{
    double total = d->row_cdf[d->h];
    *u = *v = 0;
    *dir = gvec3(0, 0, 1);
    if (!(total > 0.0))
        return 0.0;
    double x = u1 * total;
    int row = find_interval(d->row_cdf, d->h, x);
    double rw = d->row_cdf[row + 1] - d->row_cdf[row];
    double s1 = fmin(fmax((x - d->row_cdf[row]) / rw, 0.0), 1.0);
    const double *cdf = d->col_cdf + (size_t)row * (d->w + 1);
    double y = u2 * cdf[d->w];
    int col = find_interval(cdf, d->w, y);
    double pw = cdf[col + 1] - cdf[col];
    double s2 = fmin(fmax((y - cdf[col]) / pw, 0.0), 1.0);
    /* uniform in solid angle inside the pixel: cos theta uniform across the row, phi across the column */
    double c0 = cos(M_PI * row / d->h), c1 = cos(M_PI * (row + 1) / d->h);
    double ct = fmin(fmax(c0 - s1 * (c0 - c1), -1.0), 1.0);
    *dir = gprobe_direction(p, col + s2, acos(ct) * d->h / M_PI);
    *u = col;
    *v = row;
    return pw / (total * row_omega(d->w, d->h, row));
}

/* The pixel (*u, *v) of probe p that direction dir (probe space) falls in. */
static void pixel_of(const GProbe *p, GVec3 dir, int *u, int *v)
{
    double x, y;
    gprobe_position(p, dir, &x, &y);
    int w = gprobe_width(p), h = gprobe_height(p);
    *u = (int)floor(x);
    *v = (int)floor(y);
    *u = *u < 0 ? 0 : *u >= w ? w - 1 : *u;
    *v = *v < 0 ? 0 : *v >= h ? h - 1 : *v;
}

double probe_dist_pdf(const ProbeDist *d, const GProbe *p, GVec3 dir)
{
    double total = d->row_cdf[d->h];
    if (!(total > 0.0))
        return 0.0;
    int u, v;
    pixel_of(p, dir, &u, &v);
    const double *cdf = d->col_cdf + (size_t)v * (d->w + 1);
    return (cdf[u + 1] - cdf[u]) / (total * row_omega(d->w, d->h, v));
}

/* A basis as an ambient term: the material reflects a light of the basis's irradiance E(n) arriving along the
 * normal n (for Lambert exactly the diffuse albedo times E / pi); no shadow rays; SH's negative ringing gives
 * no light. */
static int probe_basis_shade(TraceCtx *c, const ProbeEnv *env, GSurfPoint *sp, GVec3 facing, GVec3 out_dir,
                             LightTmp *t, GColor *result)
{
    int rc = gprobe_basis_irradiance_color(&env->basis, probe_from_world(env, facing), &t->illum);
    if (rc == G_OK && env->scale != 1.0)
        rc = gcolor_scale(&t->illum, &t->illum, env->scale);
    if (rc == G_OK)
        rc = gmaterial_reflection(sp->material, sp, facing, &t->illum, out_dir, &t->refl);
    if (rc == G_OK)
        rc = light_add(t, result, &t->refl);
    (void)c;
    return rc;
}

int probe_pixel_radiance(const ProbeEnv *env, GVec3 d, GColor *out)
{
    int u, v;
    pixel_of(env->probe, probe_from_world(env, d), &u, &v);
    int rc = gprobe_pixel_color(env->probe, u, v, out);
    if (rc == G_OK && env->scale != 1.0)
        rc = gcolor_scale(out, out, env->scale);
    return rc;
}

int probe_light_shade(TraceCtx *c, const Light *l, GSurfPoint *sp, GVec3 facing, const Media *media,
                      GVec3 out_dir, int opaque, LightTmp *t, GColor *result)
{
    const ProbeEnv *env = l->env;
    if (env && PROBE_IS_BASIS(env->technique))
        return probe_basis_shade(c, env, sp, facing, out_dir, t, result);
    return probe_light_nee(c, l, sp, facing, media, out_dir, opaque, l->samples, NULL, NULL, 1.0, t, result);
}

int probe_light_nee(TraceCtx *c, const Light *l, GSurfPoint *sp, GVec3 facing, const Media *media, GVec3 out_dir,
                    int opaque, int n, const double *u, const GColor *mis_ri, double pick, LightTmp *t,
                    GColor *result)
{
    const ProbeEnv *env = l->env;
    if (!env || !env->probe || !env->dist.row_cdf)
        return G_OK;
    const GProbe *p = env->probe;
    const ProbeDist *d = mis_ri && env->nee_dist.row_cdf ? &env->nee_dist : &env->dist;
    n = n < 1 ? 1 : n > PROBE_MAX_SAMPLES ? PROBE_MAX_SAMPLES : n;
    int grid = strata_grid(n), *perm = NULL;
    double scale = env->scale;
    int shadows = env->shadows || mis_ri;
    GScratchMark mark = gscratch_mark(c->scratch);
    GColor radiance;
    int rc = gcolor_scratch(&radiance, c->scene->model, c->scratch);
    if (rc == G_OK && !grid && n > 1) { /* N-rooks: the pairing lives on the thread's arena */
        if (!(perm = gscratch_alloc(c->scratch, (size_t)n * sizeof *perm)))
            rc = G_ERR_NOMEM;
        else
            strata_shuffle(&c->rng, n, perm);
    }
    for (int i = 0; i < n && rc == G_OK; i++) {
        double u1, u2;
        pixel_sample(&c->rng, i, n, grid, perm, &u1, &u2);
        if (n == 1 && u)
            u1 = u[0], u2 = u[1];
        else if (n == 1)
            u1 = rng_next(&c->rng), u2 = rng_next(&c->rng);
        int pu, pv;
        GVec3 local;
        double pdf = probe_dist_sample(d, p, u1, u2, &pu, &pv, &local);
        if (!(pdf > 0.0))
            break; /* a black probe */
        GVec3 in = probe_to_world(env, local);
        if (opaque && gvec3_dot(in, facing) <= 0.0)
            continue;
        double w = mis_ri ? mis_power(pdf * pick, gmaterial_pdf(sp->material, sp, in, out_dir, mis_ri)) : 1.0;
        if (!(w > 0.0))
            continue;
        if ((rc = gprobe_pixel_color(p, pu, pv, &radiance)) < 0)
            break;
        double s = w * scale / (n * pdf);
        if (shadows) {
            rc = sample_light(c, sp, facing, media, in, INFINITY, &radiance, s, out_dir, t, result);
        } else if ((rc = gcolor_scale(&t->illum, &radiance, s)) == G_OK &&
                   (rc = gmaterial_reflection(sp->material, sp, in, &t->illum, out_dir, &t->refl)) == G_OK) {
            rc = light_add(t, result, &t->refl);
        }
    }
    gscratch_release(c->scratch, mark);
    return rc;
}
