/* noise.c - improved gradient noise (Perlin 2002: quintic fade, twelve edge gradients) with an analytic
 * gradient, and its fractal sums. The lattice hash is an integer mix seeded per generator instead of a
 * fixed permutation table, so every seed gives a different, deterministic noise. */
#include <generic/kit/noise.h>

#include <math.h>
#include <stdint.h>

static uint32_t mix(uint32_t h)
{
    h ^= h >> 16;
    h *= 0x85ebca6bu;
    h ^= h >> 13;
    h *= 0xc2b2ae35u;
    h ^= h >> 16;
    return h;
}

/* The twelve edge directions of the cube, padded to sixteen as in Perlin's paper (as doubles: the corner
 * products need no conversion). */
static const double grads[16][3] = {
    {1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0}, {1, 0, 1},  {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
    {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}, {1, 1, 0},  {-1, 1, 0}, {0, -1, 1}, {0, -1, -1},
};

static double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
static double dfade(double t) { return 30.0 * t * t * (t * (t - 2.0) + 1.0); }
static double lerp(double t, double a, double b) { return a + t * (b - a); }

/* The lattice coordinate of a cell as the hash takes it: the integer floor(x) modulo 2^32. fmod is exact, so
 * the result equals the wrap-around of the integer for every finite x (beyond 2^53 every double is an integer
 * and the pattern is a lattice of constant cells); casting floor(x) itself would be undefined beyond the
 * range of int64_t, which a huge frequency times a huge radius reaches. */
static uint32_t lattice(double fx)
{
    if (fabs(fx) < 9.2e18) /* within int64_t: the conversion is exact, and its low 32 bits are the residue */
        return (uint32_t)(int64_t)fx;
    double m = fmod(fx, 4294967296.0); /* in (-2^32, 2^32), sign of fx */
    return (uint32_t)(int64_t)m;
}

/* The hash's multipliers of the x, y and z lattice coordinates. */
#define HASH_X 0x27d4eb2du
#define HASH_Y 0x165667b1u
#define HASH_Z 0xd3a2646cu

/* The gradient of a corner whose (x, y) stage of the hash is hxy and whose z term is kz. */
static const double *corner_grad(uint32_t hxy, uint32_t kz) { return grads[mix(hxy ^ kz) & 15]; }

/* The corner plane g . (x, y, z), in the order x, y, z of the sum. */
static double plane(const double *g, double x, double y, double z) { return g[0] * x + g[1] * y + g[2] * z; }

double gnoise_signed(unsigned seed, GVec3 p, GVec3 *grad)
{
    if (!isfinite(p.x) || !isfinite(p.y) || !isfinite(p.z)) { /* overflowed point: no lattice, no variation */
        if (grad)
            *grad = gvec3(0, 0, 0);
        return 0.0;
    }
    double fx = floor(p.x), fy = floor(p.y), fz = floor(p.z);
    uint32_t ix = lattice(fx), iy = lattice(fy), iz = lattice(fz);
    double x = p.x - fx, y = p.y - fy, z = p.z - fz, x1 = x - 1.0, y1 = y - 1.0, z1 = z - 1.0;
    uint32_t hs = mix(seed * 0x9e3779b9u + 0x7f4a7c15u);
    /* the corner hash mixes x, then y, then z: the x and (x, y) stages are shared by the corners that share
     * them (14 mixes instead of 24); corner c is (c & 1, (c >> 1) & 1, c >> 2) */
    uint32_t hx0 = mix(hs ^ ix * HASH_X), hx1 = mix(hs ^ (ix + 1u) * HASH_X);
    uint32_t ky0 = iy * HASH_Y, ky1 = (iy + 1u) * HASH_Y, kz0 = iz * HASH_Z, kz1 = (iz + 1u) * HASH_Z;
    uint32_t h00 = mix(hx0 ^ ky0), h10 = mix(hx1 ^ ky0), h01 = mix(hx0 ^ ky1), h11 = mix(hx1 ^ ky1);
    const double *g[8] = {corner_grad(h00, kz0), corner_grad(h10, kz0), corner_grad(h01, kz0), corner_grad(h11, kz0),
                          corner_grad(h00, kz1), corner_grad(h10, kz1), corner_grad(h01, kz1), corner_grad(h11, kz1)};
    double n[8] = {plane(g[0], x, y, z),  plane(g[1], x1, y, z),  plane(g[2], x, y1, z),  plane(g[3], x1, y1, z),
                   plane(g[4], x, y, z1), plane(g[5], x1, y, z1), plane(g[6], x, y1, z1), plane(g[7], x1, y1, z1)};
    double u = fade(x), v = fade(y), w = fade(z);
    double x00 = lerp(u, n[0], n[1]), x10 = lerp(u, n[2], n[3]);
    double x01 = lerp(u, n[4], n[5]), x11 = lerp(u, n[6], n[7]);
    double y0 = lerp(v, x00, x10), y1v = lerp(v, x01, x11);
    double value = lerp(w, y0, y1v);
    if (grad) {
        double du = dfade(x), dv = dfade(y), dw = dfade(z);
        /* derivative of the blend weights ... */
        double ddx = du * lerp(w, lerp(v, n[1] - n[0], n[3] - n[2]), lerp(v, n[5] - n[4], n[7] - n[6]));
        double ddy = dv * lerp(w, x10 - x00, x11 - x01);
        double ddz = dw * (y1v - y0);
        /* ... plus the blended gradients of the corner planes */
        double gs[3];
        for (int k = 0; k < 3; k++) {
            double a = lerp(u, g[0][k], g[1][k]), b = lerp(u, g[2][k], g[3][k]);
            double c = lerp(u, g[4][k], g[5][k]), d = lerp(u, g[6][k], g[7][k]);
            gs[k] = lerp(w, lerp(v, a, b), lerp(v, c, d));
        }
        *grad = gvec3(ddx + gs[0], ddy + gs[1], ddz + gs[2]);
    }
    return value;
}

double gnoise_perlin3(unsigned seed, double x, double y, double z, GVec3 *grad)
{
    double n = gnoise_signed(seed, gvec3(x, y, z), grad);
    if (grad)
        *grad = gvec3_scale(*grad, 0.5);
    return 0.5 + 0.5 * n;
}

double gnoise_fbm(const GNoiseParams *p, GVec3 x, GVec3 *grad)
{
    double sum = 0.0, norm = 0.0, amp = 1.0, f = p->frequency;
    GVec3 g = gvec3(0, 0, 0), go;
    for (int i = 0; i < p->octaves; i++) {
        sum += amp * gnoise_signed(p->seed + (unsigned)i, gvec3_scale(x, f), grad ? &go : NULL);
        if (grad)
            g = gvec3_madd(g, go, amp * f);
        norm += amp;
        amp *= p->gain;
        f *= p->lacunarity;
    }
    if (grad)
        *grad = norm > 0.0 ? gvec3_scale(g, 1.0 / norm) : g;
    return norm > 0.0 ? sum / norm : 0.0;
}

double gnoise_turbulence(const GNoiseParams *p, GVec3 x, GVec3 *grad)
{
    double sum = 0.0, norm = 0.0, amp = 1.0, f = p->frequency;
    GVec3 g = gvec3(0, 0, 0), go;
    for (int i = 0; i < p->octaves; i++) {
        double n = gnoise_signed(p->seed + (unsigned)i, gvec3_scale(x, f), grad ? &go : NULL);
        sum += amp * fabs(n);
        if (grad)
            g = gvec3_madd(g, go, (n < 0.0 ? -amp : amp) * f);
        norm += amp;
        amp *= p->gain;
        f *= p->lacunarity;
    }
    double t = norm > 0.0 ? sum / norm : 0.0;
    if (grad)
        *grad = t > 1.0 || norm <= 0.0 ? gvec3(0, 0, 0) : gvec3_scale(g, 1.0 / norm);
    return t > 1.0 ? 1.0 : t;
}

int gnoise_params(const char *name, const GNoiseParams *in, GNoiseParams *out, GError *err)
{
    GNoiseParams d = {GGENERATOR_SPACE_OBJECT, 1.0, 0u, 4, 2.0, 0.5};
    if (in) {
        if ((unsigned)in->space > GGENERATOR_SPACE_WORLD)
            return gerror_set(err, G_ERR_INVALID, "%s: unknown space %d", name, (int)in->space);
        if (in->space != GGENERATOR_SPACE_NONE)
            d.space = in->space;
        if (!isfinite(in->frequency) || in->frequency < 0.0 || !isfinite(in->lacunarity) || in->lacunarity < 0.0 ||
            !isfinite(in->gain) || in->gain < 0.0)
            return gerror_set(err, G_ERR_INVALID, "%s: frequency, lacunarity and gain must be finite and positive",
                              name);
        if (in->octaves < 0 || in->octaves > 16)
            return gerror_set(err, G_ERR_INVALID, "%s: octaves must be within 1..16, got %d", name, in->octaves);
        if (in->frequency > 0.0)
            d.frequency = in->frequency;
        if (in->lacunarity > 0.0)
            d.lacunarity = in->lacunarity;
        if (in->gain > 0.0)
            d.gain = in->gain;
        if (in->octaves > 0)
            d.octaves = in->octaves;
        d.seed = in->seed;
    }
    *out = d;
    return G_OK;
}
