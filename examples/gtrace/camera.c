/* camera.c - the pinhole camera (look-at and vertical field of view), pixel sample positions and the
 * random number generator. */
#include "camera.h"
#include "bands.h"

#include <math.h>

void camera_defaults(Camera *c)
{
    c->from = gvec3(0, 0, 5);
    c->at = gvec3(0, 0, 0);
    c->up = gvec3(0, 1, 0);
    c->fov = 40.0;
    c->width = 320;
    c->height = 240;
    c->spp = 1;
    c->depth = 8;
    c->cutoff = 1e-3;
    c->exposure = 0.0;
    c->bands = BANDS_DEFAULT_CAP;
}

void camera_setup(Camera *c, int width, int height)
{
    c->eye = c->from;
    c->forward = gvec3_normalize(gvec3_sub(c->at, c->from));
    GVec3 r = gvec3_cross(c->forward, c->up);
    if (gvec3_length(r) < 1e-12) /* up parallel to the view direction: pick another up */
        r = gvec3_cross(c->forward, fabs(c->forward.y) < 0.9 ? gvec3(0, 1, 0) : gvec3(1, 0, 0));
    c->right = gvec3_normalize(r);
    c->upv = gvec3_cross(c->right, c->forward);
    c->half_h = tan(0.5 * c->fov * (M_PI / 180.0));
    c->half_w = c->half_h * (double)width / (double)height;
    c->spread = 2.0 * c->half_h / (double)height;
    c->width = width;
    c->height = height;
}

void camera_ray(const Camera *c, double x, double y, Ray *r)
{
    double sx = (2.0 * x / c->width - 1.0) * c->half_w;
    double sy = (1.0 - 2.0 * y / c->height) * c->half_h;
    GVec3 d = gvec3_add(c->forward, gvec3_add(gvec3_scale(c->right, sx), gvec3_scale(c->upv, sy)));
    double len = gvec3_length(d);
    r->o = c->eye;
    r->d = gvec3_scale(d, 1.0 / len);
    r->tmin = 0.0;
    r->tmax = INFINITY;
    r->cone_width = 0.0;
    /* a pixel is 2 half_h / height wide on the image plane at distance 1; off axis it is seen from len */
    r->cone_spread = c->spread / len;
}

int strata_grid(int n)
{
    int k = (int)lround(sqrt((double)n));
    return n > 1 && k * k == n ? k : 0;
}

void strata_shuffle(Rng *rng, int n, int *perm)
{
    for (int i = 0; i < n; i++)
        perm[i] = i;
    for (int i = n - 1; i > 0; i--) {
        int j = (int)(rng_next(rng) * (i + 1));
        int t = perm[i];
        perm[i] = perm[j];
        perm[j] = t;
    }
}

void pixel_sample(Rng *rng, int i, int n, int grid, const int *perm, double *sx, double *sy)
{
    if (n <= 1) {
        *sx = *sy = 0.5;
        return;
    }
    if (grid) {
        *sx = ((i % grid) + rng_next(rng)) / grid;
        *sy = ((i / grid) + rng_next(rng)) / grid;
        return;
    }
    *sx = (i + rng_next(rng)) / n;
    *sy = (perm[i] + rng_next(rng)) / n;
}

/* PCG32 (O'Neill 2014): 64-bit LCG state, xorshift-high + random rotation output. */
static uint32_t pcg32(Rng *r)
{
    uint64_t old = r->state;
    r->state = old * 6364136223846793005ULL + r->inc;
    uint32_t xs = (uint32_t)(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = (uint32_t)(old >> 59u);
    return (xs >> rot) | (xs << ((-rot) & 31u));
}

void rng_seed(Rng *r, uint64_t seed, uint64_t stream)
{
    r->state = 0;
    r->inc = (stream << 1u) | 1u;
    pcg32(r);
    r->state += seed;
    pcg32(r);
}

double rng_next(Rng *r) { return pcg32(r) * (1.0 / 4294967296.0); }
