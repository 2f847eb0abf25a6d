/* medium_grid.c - free flight and transmittance in grid media (medium.h), whose coefficients are the medium's
 * colours times the density of its grid (grid.h).
 *
 * Free flight (medium_grid_flight) is delta tracking (Woodcock et al. 1965) against the majorant M of the bricks
 * the ray crosses, in one band j chosen uniformly: tentative collisions at the rate M sigma_t[j], each a real one
 * (a scattering event, absorption carried in the weight as in homogeneous media) with probability density / M,
 * else a null collision. Under band k's tracking, a path of m null collisions that ends in a scattering event at t
 * has the density sigma_t[k]^(m+1) exp(-sigma_t[k] tau) times factors of the densities that every band shares (tau
 * the integral of M along the ray), and the integrand of band i is sigma_t[i]^m exp(-sigma_t[i] tau) sigma_s[i]
 * times the same factors (the null-scattering path integral: Miller, Georgiev and Jarosz 2019, "A null-scattering
 * path integral formulation of light transport"). The weight is that integrand over the mean of every band's density
 * (one-sample MIS with the balance heuristic, as medium.c does for homogeneous media); passing to tmax has the
 * same form without the last collision. For a grid of constant density its majorant, no null collision happens
 * and the weights are those of the homogeneous medium.
 *
 * Transmittance (medium_transmit) is residual ratio tracking (Novak, Selle and Jarosz 2014, "Residual ratio tracking
 * for estimating attenuation in participating media") with the bricks' minorants C as the control: the exact
 * exp(-sigma_t integral of C) times ratio tracking of the rest, tentative collisions at the rate (M - C) sigma_t_max,
 * each multiplying the light by 1 - (density - C) sigma_t / ((M - C) sigma_t_max), sample by sample (sigma_t_max
 * is the largest band value: a factor is >= 0 where no sample exceeds its band's value, and the estimate stays
 * unbiased where one does). A brick of constant density costs no collision and adds no noise. */
#include "medium.h"

#include <generic/memory.h>

#include <math.h>

int medium_transmit(const Medium *m, GVec3 o, GVec3 d, double dist, Rng *rng, GColor *light, GScratch *scratch)
{
    if (!m->grid)
        return medium_attenuate(m, dist, light, scratch);
    const double top = m->sigma_t_max;
    if (!(top > 0.0))
        return G_OK;
    GridTracker k;
    grid_tracker_begin(&k, m->grid, o, d, dist, 1);
    GScratchMark mark = gscratch_mark(scratch);
    GColor f;
    int rc = gcolor_scratch_uncleared(&f, light->model, scratch), ev; /* the fill writes it */
    while (rc == G_OK) {
        double t, density, rate;
        if ((ev = grid_tracker_advance(&k, -log1p(-rng_next(rng)) / top, &t, &density, &rate)) <= 0) {
            if (ev < 0) /* beyond the work a tracking may take: the light ends here */
                rc = gcolor_fill(light, 0.0);
            else /* the minorant's part, exact */
                rc = gcolor_exp(&f, &m->sigma_t, -k.tau_min) < 0 ? G_ERR_INVALID : gcolor_mul(light, light, &f);
            break;
        }
        if ((rc = gcolor_fill(&f, 1.0)) < 0 ||
            (rc = gcolor_axpy(&f, -(density - k.minorant) / (rate * top), &m->sigma_t, &f)) < 0 ||
            (rc = gcolor_mul(light, light, &f)) < 0)
            break;
        if (gcolor_is_black(light))
            break;
    }
    gscratch_release(scratch, mark);
    return rc < 0 ? rc : G_OK;
}

/* weight = sigma_t[i]^m exp(-sigma_t[i] tau) (times sigma_s[i] when scattered), relative to band j's value of the
 * same: ((sigma_t / sj) exp(-(sigma_t - sj) tau / m))^m, which keeps every factor near 1 in floats. */
static int flight_weight(const Medium *m, double sj, long nulls, double tau, int scattered, GColor *weight,
                         GScratch *scratch)
{
    GScratchMark mark = gscratch_mark(scratch);
    GColor shifted;
    int rc = gcolor_scratch_uncleared(&shifted, weight->model, scratch); /* the fill writes it */
    if (rc == G_OK && (rc = gcolor_fill(&shifted, sj)) == G_OK &&
        (rc = gcolor_axpy(&shifted, -1.0, &shifted, &m->sigma_t)) == G_OK)
        rc = gcolor_exp(weight, &shifted, nulls > 0 ? -tau / (double)nulls : -tau);
    if (rc == G_OK && nulls > 0 && (rc = gcolor_scale(&shifted, &m->sigma_t, 1.0 / sj)) == G_OK &&
        (rc = gcolor_mul(weight, weight, &shifted)) == G_OK)
        rc = gcolor_pow(weight, weight, (double)nulls);
    if (rc == G_OK && scattered)
        rc = gcolor_mul(weight, weight, &m->sigma_s);
    gscratch_release(scratch, mark);
    return rc;
}

int medium_grid_flight(const Medium *m, GVec3 o, GVec3 d, double tmax, Rng *rng, double *t, GColor *weight,
                       GScratch *scratch)
{
    *t = tmax;
    if (!m->scatters) { /* absorption only: the transmittance, estimated */
        int rc = gcolor_fill(weight, 1.0);
        return rc < 0 ? rc : (rc = medium_transmit(m, o, d, tmax, rng, weight, scratch)) < 0 ? rc : 0;
    }
    int n = m->bands, j = (int)(rng_next(rng) * n);
    j = j < n ? j : n - 1;
    const double sj = gcolor_band_value(&m->sigma_t, j);
    GridTracker k;
    grid_tracker_begin(&k, m->grid, o, d, tmax, 0);
    long nulls = 0;
    int scattered = 0;
    for (;;) {
        double te, density, majorant;
        int ev = grid_tracker_advance(&k, sj > 0.0 ? -log1p(-rng_next(rng)) / sj : INFINITY, &te, &density, &majorant);
        if (ev < 0) /* beyond the work a tracking may take: the path ends here */
            return gcolor_fill(weight, 0.0) < 0 ? G_ERR_INVALID : 0;
        if (ev == 0)
            break;
        if (rng_next(rng) * majorant < density) {
            scattered = 1;
            *t = te;
            break;
        }
        nulls++;
    }
    /* the mean over the bands of their tracking densities, relative to band j's (see flight_weight) */
    double p = 0.0;
    for (int i = 0; i < n; i++) {
        double si = gcolor_band_value(&m->sigma_t, i);
        if (nulls > 0 && !(si > 0.0))
            continue;
        p += exp((nulls > 0 ? (double)nulls * log(si / sj) : 0.0) - (si - sj) * k.tau) * (scattered ? si : 1.0);
    }
    p /= n;
    int rc = flight_weight(m, sj, nulls, k.tau, scattered, weight, scratch);
    if (rc < 0)
        return rc;
    if (!(p > 0.0) || !isfinite(p))
        return (rc = gcolor_fill(weight, 0.0)) < 0 ? rc : 0;
    if ((rc = gcolor_scale(weight, weight, 1.0 / p)) < 0)
        return rc;
    if (!gcolor_is_finite(weight)) /* an overflow in a path far beyond any that matters: dropped */
        return (rc = gcolor_fill(weight, 0.0)) < 0 ? rc : 0;
    return scattered;
}
