/* probe_color.c - a probe's radiance and its lights as colours of any colour model, read as lights, so a
 * renderer that only knows the generic colour interface can use them. */
#include "probe_internal.h"

int gprobe_radiance_color(const GProbe *p, GVec3 dir, GColor *out)
{
    float v[3];
    gprobe_radiance(p, dir, v);
    double d[3] = {v[0], v[1], v[2]};
    return gcolor_from_rgb(out, d, GCOLOR_LIGHT);
}

int gprobe_pixel_color(const GProbe *p, int u, int v, GColor *out)
{
    u = ((u % p->w) + p->w) % p->w;
    v = v < 0 ? 0 : v >= p->h ? p->h - 1 : v;
    const float *px = p->rgb + ((size_t)v * p->w + u) * 3;
    double d[3] = {px[0], px[1], px[2]};
    return gcolor_from_rgb(out, d, GCOLOR_LIGHT);
}

int gprobe_light_color(const GProbeLight *l, GColor *out)
{
    return gcolor_from_rgb(out, l->rgb, GCOLOR_LIGHT);
}

int gprobe_basis_irradiance_color(const GProbeBasis *b, GVec3 normal, GColor *out)
{
    double e[3];
    gprobe_basis_irradiance(b, &normal, 1, e);
    for (int c = 0; c < 3; c++)
        e[c] = e[c] > 0.0 ? e[c] : 0.0;
    return gcolor_from_rgb(out, e, GCOLOR_LIGHT);
}
