/* microfacet_albedo.c - the directional albedo of the single-scattering rough mirror (generic/kit/microfacet.h),
 * read from the tables of lib/kit/microfacet_albedo_data.c. */
#include "microfacet_albedo.h"

#include <math.h>

void gmicrofacet_albedo_table(const GMicrofacet *m, float e[GMICROFACET_ALBEDO_N], double *e_avg)
{
    int d = m->distribution == GMICROFACET_BECKMANN;
    double x = gfmin(gfmax(sqrt(m->alpha_x * m->alpha_y), 0.0), 1.0) * (GMICROFACET_ALBEDO_N - 1);
    int a = (int)x;
    if (a > GMICROFACET_ALBEDO_N - 2)
        a = GMICROFACET_ALBEDO_N - 2;
    double t = x - a;
    for (int i = 0; i < GMICROFACET_ALBEDO_N; i++)
        e[i] = (float)((1.0 - t) * gmicrofacet_albedo_e[d][a][i] + t * gmicrofacet_albedo_e[d][a + 1][i]);
    if (e_avg)
        *e_avg = (1.0 - t) * gmicrofacet_albedo_avg[d][a] + t * gmicrofacet_albedo_avg[d][a + 1];
}

double gmicrofacet_albedo_at(const float e[GMICROFACET_ALBEDO_N], double mu) { return gmicrofacet_albedo_lerp(e, mu); }
