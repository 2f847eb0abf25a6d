/* camera.c - the cameras (look-at; pinhole and thin lens with a vertical field of view, orthographic with a
 * window height), fitting the view to a box, pixel sample positions and the random number generator.
 *
 * Thin lens: the image position gives the pinhole direction d (unit distance along the view); the point in
 * focus is from + focus * d, and a ray from lens point from + o leaves in direction d - o / focus. A point at
 * distance z along the view is then spread over a circle of confusion of diameter aperture * |1/z - 1/focus|
 * on the image plane at unit distance (aperture * |1/z - 1/focus| * height / (2 tan(fov/2)) pixels). With
 * aperture 0 the offset is exactly 0 and the ray is the pinhole's, bit for bit. */
#include "camera.h"
#include "geometry/geometry.h"

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
    c->bands = 0;
    c->projection = CAMERA_PINHOLE;
    c->aperture = 0.0;
    c->focus_distance = 0.0;
    c->size = 2.0;
    c->frame = -1.0;
}

int camera_frame(Camera *c, GVec3 lo, GVec3 hi, int width, int height, GError *err)
{
    if (!(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z) || !scene_coord_ok(lo) || !scene_coord_ok(hi))
        return gerror_set(err, G_ERR_INVALID, "camera frame: no bounds to frame");
    Camera v = *c;
    camera_setup(&v, width, height); /* the view's direction, axes and half extents */
    double grow = 1.0 + c->frame, t = INFINITY, nearest = INFINITY, reach = 0.0;
    for (int i = 0; i < 8; i++) {
        GVec3 p = gvec3((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
        GVec3 rel = gvec3_sub(p, v.from);
        double z = gvec3_dot(rel, v.forward), x = fabs(gvec3_dot(rel, v.right)), y = fabs(gvec3_dot(rel, v.upv));
        /* the eye at from + t forward sees p when x <= (z - t) half_w / grow and y <= (z - t) half_h / grow */
        t = fmin(t, z - grow * fmax(x / v.half_w, y / v.half_h));
        nearest = fmin(nearest, z);
        reach = fmax(reach, fmax(y, x * v.half_h / v.half_w)); /* orthographic: the half height the box needs */
    }
    GVec3 centre = gvec3_scale(gvec3_add(lo, hi), 0.5), size = gvec3_sub(hi, lo);
    double pad = 1e-6 * (gvec3_length(size) + 1.0); /* no corner at the eye itself */
    if (c->projection == CAMERA_ORTHOGRAPHIC) {
        t = nearest - 0.01 * gvec3_length(size) - pad; /* the window stands before the box */
        c->size = fmax(2.0 * grow * reach, 1e-9);
    } else {
        t = fmin(t, nearest - pad);
    }
    GVec3 from = gvec3_add(v.from, gvec3_scale(v.forward, t));
    GVec3 at = gvec3_add(from, gvec3_scale(v.forward, fmax(gvec3_dot(gvec3_sub(centre, from), v.forward), pad)));
    if (!scene_coord_ok(from) || !scene_coord_ok(at) || !isfinite(from.x + from.y + from.z))
        return gerror_set(err, G_ERR_INVALID, "camera frame: the camera would stand beyond the scene's limit of %g "
                          "(a narrower field of view than the scene allows)", SCENE_MAX_COORD);
    c->from = from;
    c->at = at;
    c->frame_lo = lo;
    c->frame_hi = hi;
    return G_OK;
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
    c->half_h = c->projection == CAMERA_ORTHOGRAPHIC ? 0.5 * c->size : tan(0.5 * c->fov * (M_PI / 180.0));
    c->half_w = c->half_h * (double)width / (double)height;
    c->spread = 2.0 * c->half_h / (double)height;
    c->focus = c->focus_distance > 0.0 ? c->focus_distance : gvec3_length(gvec3_sub(c->at, c->from));
    c->width = width;
    c->height = height;
}

/* the ray through (x, y) from the lens point (lx, ly) in units of the lens radius (0, 0: the centre) */
static void lens_ray(const Camera *c, double x, double y, double lx, double ly, Ray *r)
{
    double sx = (2.0 * x / c->width - 1.0) * c->half_w;
    double sy = (1.0 - 2.0 * y / c->height) * c->half_h;
    GVec3 off = gvec3(0, 0, 0);
    if (c->projection == CAMERA_ORTHOGRAPHIC) {
        r->o = gvec3_add(c->eye, gvec3_add(gvec3_scale(c->right, sx), gvec3_scale(c->upv, sy)));
        r->d = c->forward;
        r->tmin = 0.0;
        r->tmax = INFINITY;
        r->cone_width = c->spread; /* a pixel is spread units wide at every distance */
        r->cone_spread = 0.0;
        return;
    }
    if (c->projection == CAMERA_THINLENS) {
        double rad = 0.5 * c->aperture;
        off = gvec3_add(gvec3_scale(c->right, lx * rad), gvec3_scale(c->upv, ly * rad));
    }
    GVec3 d = gvec3_add(c->forward, gvec3_add(gvec3_scale(c->right, sx), gvec3_scale(c->upv, sy)));
    double len = gvec3_length(d);
    if (c->projection == CAMERA_THINLENS) {
        d = gvec3_sub(d, gvec3_scale(off, 1.0 / c->focus));
        len = gvec3_length(d);
    }
    r->o = gvec3_add(c->eye, off);
    r->d = gvec3_scale(d, 1.0 / len);
    r->tmin = 0.0;
    r->tmax = INFINITY;
    r->cone_width = 0.0;
    /* a pixel is 2 half_h / height wide on the image plane at distance 1; off axis it is seen from len */
    r->cone_spread = c->spread / len;
}

void camera_ray(const Camera *c, double x, double y, Ray *r) { lens_ray(c, x, y, 0.0, 0.0, r); }

int camera_is_pinhole(const Camera *c) { return !(c->projection == CAMERA_THINLENS && c->aperture > 0.0); }

void camera_ray_lens(const Camera *c, double x, double y, Rng *rng, Ray *r)
{
    double lx = 0.0, ly = 0.0;
    if (!camera_is_pinhole(c)) {
        /* concentric map of the unit square onto the unit disc (Shirley and Chiu 1997): uniform by area */
        double a = 2.0 * rng_next(rng) - 1.0, b = 2.0 * rng_next(rng) - 1.0, rad, phi;
        if (a == 0.0 && b == 0.0) {
            rad = phi = 0.0;
        } else if (fabs(a) > fabs(b)) {
            rad = a;
            phi = (M_PI / 4.0) * (b / a);
        } else {
            rad = b;
            phi = M_PI / 2.0 - (M_PI / 4.0) * (a / b);
        }
        lx = rad * cos(phi);
        ly = rad * sin(phi);
    }
    lens_ray(c, x, y, lx, ly, r);
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
