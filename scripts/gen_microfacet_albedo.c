/* gen_microfacet_albedo.c - writes lib/kit/microfacet_albedo_data.c: the directional albedo E(mu, alpha) of the
 * single-scattering rough mirror with Fresnel 1 (the integral over the incident hemisphere of
 * gmicrofacet_reflect_cos) for GGX and Beckmann, on GMICROFACET_ALBEDO_N nodes of mu = cos theta_out and of alpha in
 * [0, 1], and its cosine-weighted mean E_avg(alpha) = 2 * integral of E mu dmu of the table's linear interpolation.
 * Built and run by hand against the kit's own D and G2:
 *
 *   cc -O2 -Iinclude scripts/gen_microfacet_albedo.c lib/kit/microfacet.c -lm -o gen && ./gen > FILE
 *
 * The integral is taken over the half vector h, f cos dw_i = D(h) G2 (wo.h) / mu dw_h, by the midpoint rule in
 * (r, phi) with tan theta_h = alpha r / (1 - r): 1200 x 600 points per node (phi over half the circle, the
 * integrand being symmetric about the plane of wo), exact to about 1e-5. */
#include "generic/kit/microfacet.h"

#include <math.h>
#include <stdio.h>

enum { NR = 1200, NPHI = 600, N = GMICROFACET_ALBEDO_N };

static double albedo(const GMicrofacet *m, double mu, double alpha)
{
    if (mu <= 0.0)
        return 0.0;
    GVec3 wo = gvec3(sqrt(1.0 - mu * mu), 0.0, mu);
    double sum = 0.0;
    for (int i = 0; i < NR; i++) {
        double r = (i + 0.5) / NR, t = alpha * r / (1.0 - r), dt = alpha / ((1.0 - r) * (1.0 - r)) / NR;
        double th = atan(t), dth = dt / (1.0 + t * t), st = sin(th), ct = cos(th);
        for (int j = 0; j < NPHI; j++) {
            double phi = M_PI * (j + 0.5) / NPHI;
            GVec3 h = gvec3(st * cos(phi), st * sin(phi), ct);
            double c = gvec3_dot(wo, h);
            if (c <= 0.0)
                continue;
            GVec3 wi = gvec3_sub(gvec3_scale(h, 2.0 * c), wo);
            if (wi.z <= 0.0)
                continue;
            sum += gmicrofacet_d(m, h) * gmicrofacet_g2(m, wi, wo, h) * c / mu * st * dth * (M_PI / NPHI);
        }
    }
    return 2.0 * sum;
}

int main(void)
{
    static double e[2][N][N], avg[2][N];
    for (int d = 0; d < 2; d++)
        for (int a = 0; a < N; a++) {
            double alpha = (double)a / (N - 1);
            GMicrofacet m = gmicrofacet_make(d, alpha, alpha);
            for (int i = 0; i < N; i++)
                e[d][a][i] = a == 0 ? 1.0 : albedo(&m, (double)i / (N - 1), alpha);
            double s = 0.0; /* 2 * integral of the linear interpolant times mu, exactly: per interval */
            for (int i = 0; i + 1 < N; i++) {
                double m0 = (double)i / (N - 1), m1 = (double)(i + 1) / (N - 1), h = m1 - m0;
                s += h * (e[d][a][i] * (2.0 * m0 + m1) + e[d][a][i + 1] * (m0 + 2.0 * m1)) / 6.0;
            }
            avg[d][a] = 2.0 * s;
        }
    printf(
        "/* microfacet_albedo_data.c - the directional albedo of the single-scattering rough mirror with Fresnel 1,\n"
        " * E(mu, alpha), and its cosine-weighted mean, for GGX [0] and Beckmann [1] (lib/kit/microfacet_albedo.h),\n"
        " * written by scripts/gen_microfacet_albedo.c; regenerate, do not edit. Rows: alpha = a / %d; columns:\n"
        " * mu = i / %d. */\n#include \"microfacet_albedo.h\"\n\n",
        N - 1, N - 1);
    printf("const float gmicrofacet_albedo_e[2][GMICROFACET_ALBEDO_N][GMICROFACET_ALBEDO_N] = {\n");
    for (int d = 0; d < 2; d++) {
        printf("    {\n");
        for (int a = 0; a < N; a++) {
            printf("        {");
            for (int i = 0; i < N; i++)
                printf("%s%.6ff", i == 0 ? "" : i % 8 == 0 ? ",\n         " : ", ", e[d][a][i]);
            printf("},\n");
        }
        printf("    },\n");
    }
    printf("};\n\nconst float gmicrofacet_albedo_avg[2][GMICROFACET_ALBEDO_N] = {\n");
    for (int d = 0; d < 2; d++) {
        printf("    {");
        for (int a = 0; a < N; a++)
            printf("%s%.6ff", a == 0 ? "" : a % 8 == 0 ? ",\n     " : ", ", avg[d][a]);
        printf("},\n");
    }
    printf("};\n");
    return 0;
}
