/* basis.c - the basis-function approximations behind one interface: names, sizes, fitting, irradiance and
 * radiance (the bases themselves: sh.c, ambient_cube.c, sg_lobe.c, sg_fit.c). */
#include "probe_internal.h"
#include "generic/memory.h"

#include <string.h>

static const char *const basis_names[GPROBE_BASIS_COUNT] = {"sh",     "sh-hanning", "ambientcube", "sg-naive",
                                                            "sg-ls",  "sg-nnls",    "sg-ambient"};

static int is_sg(GProbeBasisKind k) { return k >= GPROBE_BASIS_SG_NAIVE && k <= GPROBE_BASIS_SG_AMBIENT; }

const char *gprobe_basis_name(GProbeBasisKind k)
{
    return (unsigned)k < GPROBE_BASIS_COUNT ? basis_names[k] : "unknown";
}

const char *gprobe_basis_unit(GProbeBasisKind k) { return is_sg(k) ? "lobes" : "coefficients"; }

int gprobe_basis_parse(const char *name, GProbeBasisKind *k, GError *err)
{
    for (int i = 0; i < GPROBE_BASIS_COUNT; i++)
        if (name && strcmp(name, basis_names[i]) == 0) {
            *k = (GProbeBasisKind)i;
            return G_OK;
        }
    return gerror_set(err, G_ERR_NOTFOUND, "unknown basis '%s' (expected sh, sh-hanning, ambientcube, sg-naive, sg-ls, "
                      "sg-nnls or sg-ambient)", name ? name : "");
}

/* The order L with (L + 1)^2 = n, or 0. */
static int sh_order(int n)
{
    for (int l = 1; l <= GPROBE_SH_MAX_ORDER; l++)
        if (GPROBE_SH_COEFFS(l) == n)
            return l;
    return 0;
}

int gprobe_basis_size_ok(GProbeBasisKind k, int n)
{
    switch (k) {
    case GPROBE_BASIS_SH:
    case GPROBE_BASIS_SH_HANNING: return sh_order(n) > 0;
    case GPROBE_BASIS_AMBIENT_CUBE: return n == 6;
    default: return is_sg(k) && n >= 1 && n <= GPROBE_SG_MAX_LOBES;
    }
}

void gprobe_basis_free(GProbeBasis *b)
{
    if (!b)
        return;
    gmem_free(b->lobes);
    gmem_free(b->table);
    b->lobes = NULL;
    b->table = NULL;
}

int gprobe_basis_fit(const GProbe *p, GProbeBasisKind k, int n, GProbeBasis *out, GError *err)
{
    if (!p || !out)
        return gerror_set(err, G_ERR_INVALID, "gprobe_basis_fit: no probe or output given");
    memset(out, 0, sizeof *out);
    if ((unsigned)k >= GPROBE_BASIS_COUNT)
        return gerror_set(err, G_ERR_INVALID, "unknown basis %d", (int)k);
    if (!gprobe_basis_size_ok(k, n))
        return gerror_set(err, G_ERR_INVALID, "%s cannot have %d %s (%s)", basis_names[k], n, gprobe_basis_unit(k),
                          is_sg(k) ? "1..128" : k == GPROBE_BASIS_AMBIENT_CUBE ? "exactly 6" : "4, 9, 16 or 25");
    out->kind = k;
    out->size = n;
    if (k == GPROBE_BASIS_SH || k == GPROBE_BASIS_SH_HANNING) {
        int rc = gprobe_sh_project(p, sh_order(n), &out->sh, err);
        if (rc == G_OK && k == GPROBE_BASIS_SH_HANNING)
            gprobe_sh_window_hanning(&out->sh);
        return rc;
    }
    if (k == GPROBE_BASIS_AMBIENT_CUBE)
        return gprobe_ambient_cube_fit(p, 0, &out->cube, err);
    out->lobes = gmem_calloc((size_t)n, sizeof *out->lobes);
    out->table = gmem_alloc((size_t)n * GPROBE_SG_TABLE * sizeof *out->table);
    if (!out->lobes || !out->table) {
        gprobe_basis_free(out);
        return gerror_set(err, G_ERR_NOMEM, "out of memory for %d lobes", n);
    }
    int rc = gprobe_sg_fit(p, n, (GProbeSGFit)(k - GPROBE_BASIS_SG_NAIVE), out->lobes, out->ambient, err);
    if (rc != G_OK) {
        gprobe_basis_free(out);
        return rc;
    }
    for (int i = 0; i < n; i++)
        for (int j = 0; j < GPROBE_SG_TABLE; j++)
            out->table[(size_t)i * GPROBE_SG_TABLE + j] =
                gprobe_sg_lobe_irradiance(out->lobes[i].sharpness, -1.0 + 2.0 * j / (GPROBE_SG_TABLE - 1));
    return G_OK;
}

/* A lobe's tabulated irradiance per unit amplitude at cosine mu (linear between entries). */
static double table_lookup(const double *t, double mu)
{
    double x = (mu + 1.0) * 0.5 * (GPROBE_SG_TABLE - 1);
    x = x < 0.0 ? 0.0 : x > GPROBE_SG_TABLE - 1 ? GPROBE_SG_TABLE - 1 : x;
    int i = (int)x;
    if (i >= GPROBE_SG_TABLE - 1)
        return t[GPROBE_SG_TABLE - 1];
    double f = x - i;
    return t[i] + f * (t[i + 1] - t[i]);
}

void gprobe_basis_irradiance(const GProbeBasis *b, const GVec3 *normals, int m, double *E)
{
    switch (b->kind) {
    case GPROBE_BASIS_SH:
    case GPROBE_BASIS_SH_HANNING: gprobe_sh_irradiance(&b->sh, normals, m, E); return;
    case GPROBE_BASIS_AMBIENT_CUBE:
        for (int i = 0; i < m; i++)
            gprobe_ambient_cube_eval(&b->cube, normals[i], E + 3 * i);
        return;
    default: break;
    }
    for (int i = 0; i < m; i++) {
        double e[3] = {M_PI * b->ambient[0], M_PI * b->ambient[1], M_PI * b->ambient[2]};
        for (int k = 0; k < b->size && b->table; k++) {
            double w = table_lookup(b->table + (size_t)k * GPROBE_SG_TABLE, gvec3_dot(normals[i], b->lobes[k].axis));
            for (int c = 0; c < 3; c++)
                e[c] += w * b->lobes[k].amp[c];
        }
        memcpy(E + 3 * i, e, sizeof e);
    }
}

void gprobe_basis_radiance(const GProbeBasis *b, GVec3 d, double rgb[3])
{
    switch (b->kind) {
    case GPROBE_BASIS_SH:
    case GPROBE_BASIS_SH_HANNING: gprobe_sh_radiance(&b->sh, d, rgb); return;
    case GPROBE_BASIS_AMBIENT_CUBE: /* the radiance of an environment uniform around d that gives E(d) */
        gprobe_ambient_cube_eval(&b->cube, d, rgb);
        for (int c = 0; c < 3; c++)
            rgb[c] /= M_PI;
        return;
    default: break;
    }
    for (int c = 0; c < 3; c++)
        rgb[c] = b->ambient[c];
    for (int k = 0; k < b->size && b->lobes; k++) {
        double g = exp(b->lobes[k].sharpness * (gvec3_dot(d, b->lobes[k].axis) - 1.0));
        for (int c = 0; c < 3; c++)
            rgb[c] += g * b->lobes[k].amp[c];
    }
}
