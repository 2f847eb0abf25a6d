/* fresnel.c - Fresnel reflectance of conductors and dielectrics on colours (generic/kit/fresnel.h). */
#include "generic/kit/fresnel.h"
#include "generic/kit/color_map.h"
#include "generic/kit/spectral_kernels.h"
#include "generic/material.h"

#include <math.h>

/* The reflectance of an absorbing medium (Born and Wolf; the form of Heavens 1965): with
 * a^2 + b^2 = sqrt((eta^2 - k^2 - sin^2)^2 + 4 eta^2 k^2) and a^2 = (that + eta^2 - k^2 - sin^2) / 2,
 * Rs = (a^2 + b^2 - 2 a cos + cos^2) / (a^2 + b^2 + 2 a cos + cos^2) and
 * Rp = Rs (cos^2 (a^2 + b^2) - 2 a cos sin^2 + sin^4) / (cos^2 (a^2 + b^2) + 2 a cos sin^2 + sin^4). */
double goptics_fresnel_conductor(double cos_i, double eta, double k)
{
    double c = fabs(cos_i);
    if (c > 1.0)
        c = 1.0;
    double c2 = c * c, s2 = 1.0 - c2, e2 = eta * eta, k2 = k * k;
    double t = e2 - k2 - s2;
    double ab = sqrt(t * t + 4.0 * e2 * k2); /* a^2 + b^2 */
    double a = sqrt(gfmax(0.0, 0.5 * (ab + t)));
    double rs_num = ab - 2.0 * a * c + c2, rs_den = ab + 2.0 * a * c + c2;
    double rs = rs_den > 0.0 ? rs_num / rs_den : 1.0;
    double p1 = c2 * ab + s2 * s2, p2 = 2.0 * a * c * s2;
    double rp = p1 + p2 > 0.0 ? rs * (p1 - p2) / (p1 + p2) : rs;
    return 0.5 * (rs + rp);
}

static void conductor_samples(float *out, const float *eta, const float *k, const float *unused, int n,
                              const void *params)
{
    (void)unused;
    double c = *(const double *)params;
    for (int i = 0; i < n; i++)
        out[i] = (float)goptics_fresnel_conductor(c, eta[i], k[i]);
}

/* The mix's factors. */
typedef struct MixTerms {
    float cos_i, s, t;
} MixTerms;

/* goptics_fresnel_conductor in float, without branches so that the loop vectorises (this file is compiled with
 * -fno-math-errno -fno-trapping-math: sqrtf is the instruction, a division needs no branch). With
 * a^2 + b^2 = |eta^2 - k^2 - sin^2 + 2 i eta k| (ab) and a = sqrt((ab + eta^2 - k^2 - sin^2) / 2), the mean of
 * Rs = (ab - 2 a cos + cos^2) / (ab + 2 a cos + cos^2) and Rp = Rs (p1 - p2) / (p1 + p2) is Rs p1 / (p1 + p2), so
 * one division serves both: two square roots and a division are what a sample costs. The denominator is kept above
 * 1e-30 (0 only for n = k = 0 at grazing incidence, where the reflectance is 1; its two factors are never small
 * together). */
static inline float conductor_f(float c, float c2, float s2, float eta, float k)
{
    float e2 = eta * eta, k2 = k * k, u = e2 - k2 - s2;
    float ab = sqrtf(u * u + 4.0f * e2 * k2), a2 = 0.5f * (ab + u);
    float a = sqrtf(a2 > 0.0f ? a2 : 0.0f), ac = 2.0f * a * c;
    float p1 = c2 * ab + s2 * s2, den = (ab + ac + c2) * (p1 + ac * s2);
    return (ab - ac + c2) * p1 / (den > 1e-30f ? den : 1e-30f);
}

/* s * F + t * add (add NULL: s * F) over the samples i0 to n - 1. */
#define MIX_LOOP(i0, n)                                                                                        \
    do {                                                                                                       \
        if (add) {                                                                                             \
            _Pragma("omp simd") for (int i = (i0); i < (n); i++)                                              \
                out[i] = conductor_f(c, c2, s2, eta[i], k[i]) * s + add[i] * t;                                \
        } else {                                                                                               \
            _Pragma("omp simd") for (int i = (i0); i < (n); i++) out[i] = conductor_f(c, c2, s2, eta[i], k[i]) * s; \
        }                                                                                                      \
    } while (0)

static void conductor_mix_v4(float *out, const float *eta, const float *k, const float *add, int n, const void *params)
{
    const MixTerms *m = params;
    const float c = m->cos_i, c2 = c * c, s2 = 1.0f - c2, s = m->s, t = m->t;
    MIX_LOOP(0, n);
}

#ifdef GSPECTRAL_AVX2
/* conductor_f on 8 lanes, operation for operation (no FMA: each lane rounds as conductor_f does). */
static inline GSPECTRAL_TARGET_AVX2 __m256 conductor_f8(__m256 c, __m256 c2, __m256 s2, __m256 eta, __m256 k)
{
    const __m256 zero = _mm256_setzero_ps(), half = _mm256_set1_ps(0.5f), two = _mm256_set1_ps(2.0f);
    const __m256 four = _mm256_set1_ps(4.0f), tiny = _mm256_set1_ps(1e-30f);
    __m256 e2 = _mm256_mul_ps(eta, eta), k2 = _mm256_mul_ps(k, k), u = _mm256_sub_ps(_mm256_sub_ps(e2, k2), s2);
    __m256 ab = _mm256_sqrt_ps(_mm256_add_ps(_mm256_mul_ps(u, u), _mm256_mul_ps(_mm256_mul_ps(four, e2), k2)));
    __m256 a2 = _mm256_mul_ps(half, _mm256_add_ps(ab, u));
    __m256 a = _mm256_sqrt_ps(_mm256_max_ps(a2, zero)), ac = _mm256_mul_ps(_mm256_mul_ps(two, a), c);
    __m256 p1 = _mm256_add_ps(_mm256_mul_ps(c2, ab), _mm256_mul_ps(s2, s2));
    __m256 den = _mm256_mul_ps(_mm256_add_ps(_mm256_add_ps(ab, ac), c2), _mm256_add_ps(p1, _mm256_mul_ps(ac, s2)));
    __m256 num = _mm256_mul_ps(_mm256_add_ps(_mm256_sub_ps(ab, ac), c2), p1);
    return _mm256_div_ps(num, _mm256_max_ps(den, tiny));
}

/* The same on 8-float vectors: the whole blocks, then the last n % 8 samples as one block whose other lanes hold a
 * harmless index (1 + 0i), so that no sample runs alone through the chain of two square roots and a division
 * (rgb's three samples are one block). Each lane gives the 4-float body's float. */
static GSPECTRAL_TARGET_AVX2 void conductor_mix_v8(float *out, const float *eta, const float *k, const float *add,
                                                  int n, const void *params)
{
    const MixTerms *m = params;
    const __m256 c = _mm256_set1_ps(m->cos_i), c2 = _mm256_set1_ps(m->cos_i * m->cos_i);
    const __m256 s2 = _mm256_set1_ps(1.0f - m->cos_i * m->cos_i), s = _mm256_set1_ps(m->s), t = _mm256_set1_ps(m->t);
    int whole = n & ~7, rest = n - whole;
    for (int i = 0; i < whole; i += 8) {
        __m256 f = _mm256_mul_ps(conductor_f8(c, c2, s2, _mm256_loadu_ps(eta + i), _mm256_loadu_ps(k + i)), s);
        if (add)
            f = _mm256_add_ps(f, _mm256_mul_ps(_mm256_loadu_ps(add + i), t));
        _mm256_storeu_ps(out + i, f);
    }
    if (!rest)
        return;
    static const int lanes[16] = {-1, -1, -1, -1, -1, -1, -1, -1, 0, 0, 0, 0, 0, 0, 0, 0};
    __m256i mask = _mm256_loadu_si256((const __m256i *)(lanes + 8 - rest));
    __m256 e = _mm256_blendv_ps(_mm256_set1_ps(1.0f), _mm256_maskload_ps(eta + whole, mask),
                                _mm256_castsi256_ps(mask));
    __m256 f = _mm256_mul_ps(conductor_f8(c, c2, s2, e, _mm256_maskload_ps(k + whole, mask)), s);
    if (add)
        f = _mm256_add_ps(f, _mm256_mul_ps(_mm256_maskload_ps(add + whole, mask), t));
    float lane[8];
    _mm256_storeu_ps(lane, f);
    for (int j = 0; j < rest; j++)
        out[whole + j] = lane[j];
}
#endif

/* The kernel: the 8-float body where the processor has AVX2, chosen once when the library is loaded. */
static void conductor_mix(float *out, const float *eta, const float *k, const float *add, int n, const void *params);
#ifdef GSPECTRAL_AVX2
GSPECTRAL_PICK(conductor_mix);
#else
static void conductor_mix(float *out, const float *eta, const float *k, const float *add, int n, const void *params)
{
    conductor_mix_v4(out, eta, k, add, n, params);
}
#endif

int gmaterial_fresnel_conductor_mix(GColor *out, double cos_i, const GColor *eta, const GColor *k, double s,
                                    const GColor *add, double t)
{
    if (!k)
        return G_ERR_INVALID;
    double c = fabs(cos_i);
    MixTerms m = {(float)(c > 1.0 ? 1.0 : c), (float)s, (float)t};
    return gcolor_map_samples(out, conductor_mix, &m, eta, k, add);
}

int gmaterial_fresnel_conductor(GColor *out, double cos_i, const GColor *eta, const GColor *k)
{
    if (!k)
        return G_ERR_INVALID;
    return gcolor_map_samples(out, conductor_samples, &cos_i, eta, k, NULL);
}

static void dielectric_samples(float *out, const float *eta, const float *b, const float *c, int n,
                               const void *params)
{
    (void)b, (void)c;
    double cos_i = *(const double *)params;
    for (int i = 0; i < n; i++)
        out[i] = (float)goptics_fresnel(cos_i, eta[i]);
}

int gmaterial_fresnel_dielectric(GColor *out, double cos_i, const GColor *eta)
{
    return gcolor_map_samples(out, dielectric_samples, &cos_i, eta, NULL, NULL);
}

/* k for a normal-incidence reflectance r and index n: ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2) = r solved for k. */
static double k_for_reflectance(double n, double r, double unused, const void *params)
{
    (void)unused, (void)params;
    r = gfmin(gfmax(r, 0.0), 0.9999);
    double k2 = (r * (n + 1.0) * (n + 1.0) - (n - 1.0) * (n - 1.0)) / (1.0 - r);
    return k2 > 0.0 ? sqrt(k2) : 0.0;
}

/* A model whose samples are values of the curve at wavelengths at most GCOMPLEX_INDEX_FINE_NM apart: its n and k are
 * the measured ones there. A coarser model (spectrum9's knots 50 nm apart) or one without samples matches R(0). */
#define GCOMPLEX_INDEX_FINE_NM 10.0
static int finely_sampled(const GColorModel *m) { return m->nsamples > 0 && m->lambda_step <= GCOMPLEX_INDEX_FINE_NM; }

int gmaterial_complex_index_from_nm(GColor *eta, GColor *k, const GSpectrumNM *eta_nm, const GSpectrumNM *k_nm)
{
    if (!eta || !k || !eta_nm || !k_nm)
        return G_ERR_INVALID;
    if (eta->model != k->model)
        return G_ERR_MISMATCH;
    int rc = gcolor_from_nm(eta, eta_nm, GCOLOR_UNITLESS);
    if (rc != G_OK || finely_sampled(eta->model))
        return rc ? rc : gcolor_from_nm(k, k_nm, GCOLOR_UNITLESS);
    GSpectrumNM r0;
    for (int i = 0; i < GNM_COUNT; i++)
        r0.v[i] = (float)goptics_fresnel_conductor(1.0, eta_nm->v[i], k_nm->v[i]);
    rc = gcolor_from_nm(k, &r0, GCOLOR_REFLECTANCE);
    return rc ? rc : gcolor_map(k, k_for_reflectance, NULL, eta, k, NULL);
}

/* A spectrum literal's nm values, scaled. */
static void spec_nm(const GColorSpec *s, GSpectrumNM *out)
{
    for (int i = 0; i < GNM_COUNT; i++)
        out->v[i] = (float)(s->nm.v[i] * s->scale);
}

int gmaterial_complex_index_from_specs(const GColorSpec *eta_spec, const GColorSpec *k_spec, GColor *eta, GColor *k,
                                       GError *err)
{
    int rc;
    if (eta_spec->form == GCOLORSPEC_NM && k_spec->form == GCOLORSPEC_NM) {
        GSpectrumNM n_nm, k_nm;
        spec_nm(eta_spec, &n_nm);
        spec_nm(k_spec, &k_nm);
        rc = gmaterial_complex_index_from_nm(eta, k, &n_nm, &k_nm);
        return rc == G_OK ? G_OK : gerror_set(err, rc, "cannot express n and k in model '%s' (%s)",
                                              gcolormodel_name(eta->model), gstatus_string(rc));
    }
    GError why;
    rc = gcolorspec_to_color(eta_spec, GCOLOR_UNITLESS, eta, &why);
    if (rc != G_OK)
        return gerror_set_param(err, rc, "eta", "eta: %s", why.message);
    rc = gcolorspec_to_color(k_spec, GCOLOR_UNITLESS, k, &why);
    return rc == G_OK ? G_OK : gerror_set_param(err, rc, "k", "k: %s", why.message);
}
