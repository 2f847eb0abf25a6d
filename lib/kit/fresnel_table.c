/* fresnel_table.c - a conductor's Fresnel reflectance tabulated per sample, read by a lerp of two nodes
 * (kit/fresnel.h). */
#include "generic/kit/fresnel.h"
#include "generic/kit/spectral_kernels.h"
#include "generic/memory.h"

#include <math.h>
#include <string.h>

struct GFresnelTable {
    const GColorModel *model;
    int n;         /* floats a node: the model's nvalues */
    float *nodes;  /* GFRESNEL_TABLE_K + 1 nodes, node-major */
};

int gmaterial_fresnel_table_create(const GColor *eta, const GColor *k, GFresnelTable **out)
{
    *out = NULL;
    const GColorModel *m = eta->model;
    if (k->model != m)
        return G_ERR_MISMATCH;
    if (m->cls->fill || eta->kind != GCOLOR_VECTOR || k->kind != GCOLOR_VECTOR)
        return G_ERR_UNSUPPORTED;
    GFresnelTable *t = gmem_calloc(1, sizeof *t);
    GColor f = {0};
    int rc = t ? gcolor_alloc(&f, m) : G_ERR_NOMEM;
    if (rc == G_OK) {
        t->model = m, t->n = m->nvalues;
        t->nodes = gmem_calloc((size_t)(GFRESNEL_TABLE_K + 1) * (size_t)t->n, sizeof *t->nodes);
        rc = t->nodes ? G_OK : G_ERR_NOMEM;
    }
    /* each node the exact kernel's value, the last at cos_h = 1 */
    for (int j = 0; j <= GFRESNEL_TABLE_K && rc == G_OK; j++) {
        double u = (double)j / GFRESNEL_TABLE_K;
        rc = gmaterial_fresnel_conductor_mix(&f, j == GFRESNEL_TABLE_K ? 1.0 : u * u, eta, k, 1.0, NULL, 0.0);
        if (rc == G_OK && f.kind != GCOLOR_VECTOR)
            rc = G_ERR_UNSUPPORTED;
        if (rc == G_OK)
            memcpy(t->nodes + (size_t)j * t->n, f.v, (size_t)t->n * sizeof *f.v);
    }
    gcolor_free(&f);
    if (rc != G_OK) {
        gmaterial_fresnel_table_destroy(t);
        return rc;
    }
    *out = t;
    return G_OK;
}

void gmaterial_fresnel_table_destroy(GFresnelTable *t)
{
    if (!t)
        return;
    gmem_free(t->nodes);
    gmem_free(t);
}

/* The lerp of a table's two nodes: out = ((w0 lo + w1 hi) s + t add) light over n samples (add NULL: nothing added,
 * light NULL: white); out may be light. */
typedef struct TableMix {
    const float *lo, *hi, *add, *light;
    float w0, w1, s, t;
} TableMix;

/* The loop of table_mix, for each operand given or not, so that each compiles without a test per sample. Each step
 * rounds to float as gcolor_mul after the mix would. */
#define TABLE_MIX_LOOP(out, m, n)                                                                                      \
    do {                                                                                                               \
        const float *lo = (m)->lo, *hi = (m)->hi, *a = (m)->add, *l = (m)->light;                                      \
        const float w0 = (m)->w0, w1 = (m)->w1, fs = (m)->s, ft = (m)->t;                                              \
        if (a && l) {                                                                                                  \
            GSPECTRAL_SIMD for (int i = 0; i < (n); i++) {                                                             \
                float v = (w0 * lo[i] + w1 * hi[i]) * fs + a[i] * ft;                                                  \
                (out)[i] = v * l[i];                                                                                   \
            }                                                                                                          \
        } else if (a) {                                                                                                \
            GSPECTRAL_SIMD for (int i = 0; i < (n); i++)(out)[i] = (w0 * lo[i] + w1 * hi[i]) * fs + a[i] * ft;         \
        } else if (l) {                                                                                                \
            GSPECTRAL_SIMD for (int i = 0; i < (n); i++) {                                                             \
                float v = (w0 * lo[i] + w1 * hi[i]) * fs;                                                              \
                (out)[i] = v * l[i];                                                                                   \
            }                                                                                                          \
        } else {                                                                                                       \
            GSPECTRAL_SIMD for (int i = 0; i < (n); i++)(out)[i] = (w0 * lo[i] + w1 * hi[i]) * fs;                     \
        }                                                                                                              \
    } while (0)

/* The operands of a mix checked and the two nodes about cos_h found, into *m. */
static inline int mix_operands(const GFresnelTable *t, double cos_h, double s, const GColor *add, double t_add,
                               const GColor *light, const GColor *out, TableMix *m)
{
    if (out->model != t->model || (add && (add->model != t->model || add->kind != GCOLOR_VECTOR)) ||
        (light && (light->model != t->model || light->kind != GCOLOR_VECTOR)))
        return G_ERR_MISMATCH;
    double x = sqrt(cos_h > 0.0 ? (cos_h < 1.0 ? cos_h : 1.0) : 0.0) * GFRESNEL_TABLE_K;
    int j = (int)x;
    j = j < GFRESNEL_TABLE_K ? j : GFRESNEL_TABLE_K - 1;
    const float *lo = t->nodes + (size_t)j * t->n;
    const float w1 = (float)(x - j);
    *m = (TableMix){lo, lo + t->n, add ? add->v : NULL, light ? light->v : NULL, 1.0f - w1, w1, (float)s,
                    (float)t_add};
    return G_OK;
}

/* The mix on 4-float vectors. */
static int gmaterial_fresnel_table_mix_v4(const GFresnelTable *t, double cos_h, double s, const GColor *add,
                                          double t_add, const GColor *light, GColor *out)
{
    TableMix m;
    int rc = mix_operands(t, cos_h, s, add, t_add, light, out, &m);
    if (rc != G_OK)
        return rc;
    TABLE_MIX_LOOP(out->v, &m, t->n);
    out->kind = GCOLOR_VECTOR;
    return G_OK;
}
#ifdef GSPECTRAL_AVX2
/* The same on 8-float vectors (no FMA: each sample rounds as the 4-float body's), chosen once when loaded. */
static GSPECTRAL_TARGET_AVX2 int gmaterial_fresnel_table_mix_v8(const GFresnelTable *t, double cos_h, double s,
                                                                const GColor *add, double t_add, const GColor *light,
                                                                GColor *out)
{
    TableMix m;
    int rc = mix_operands(t, cos_h, s, add, t_add, light, out, &m);
    if (rc != G_OK)
        return rc;
    TABLE_MIX_LOOP(out->v, &m, t->n);
    out->kind = GCOLOR_VECTOR;
    return G_OK;
}
GSPECTRAL_PICK(gmaterial_fresnel_table_mix);
#else
int gmaterial_fresnel_table_mix(const GFresnelTable *t, double cos_h, double s, const GColor *add, double t_add,
                                const GColor *light, GColor *out)
{
    return gmaterial_fresnel_table_mix_v4(t, cos_h, s, add, t_add, light, out);
}
#endif
