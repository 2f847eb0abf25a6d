/* fluorescent_varnish.c - the layered rough-varnish fluorescent material (Wilkie et al., section 5.2).
 *
 * Layers, from the top: a rough boundary of transparent Fresnel facets (air -> varnish of index eta), a thin
 * clear varnish, and a fluorescent Lambertian base with re-radiation matrix M. The varnish is thin, so the
 * energy leaves where it enters (no lateral transport). This is Neumann & Neumann's smooth layered model with
 * the smooth boundary replaced by a microfacet one:
 *
 *   f_r(i, o) = f_s(i, o) + f_b(i, o)
 *
 *   f_s = F(i.h) D(h) G(i, o) / (4 cos_i cos_o)                       facets reflecting at the top
 *         h = (i + o) / |i + o|, F the unpolarised Fresnel reflectance for air -> varnish,
 *         D(h) = (m + 2) / (2 pi) (h.n)^m                             normalised Blinn: int D(h) (h.n) dw = 1
 *         G = min(1, 2 (n.h)(n.o) / (o.h), 2 (n.h)(n.i) / (o.h))      V-cavity shadowing and masking
 *
 *   f_b = T(cos_i) T(cos_o) / (pi eta^2) * B,      B = (I - F_int M)^-1 M
 *         T(c) = 1 - R(c),  R(c) = int f_s cos_o dw_o                the rough boundary's directional albedo;
 *                                                                    what it does not reflect enters (energy
 *                                                                    the facets shadow is counted as entering)
 *         R_avg = 2 int_0^1 R(c) c dc                                 its albedo for diffuse light
 *         F_int = 1 - (1 - R_avg) / eta^2                              share of the diffuse light inside that
 *                                                                    the boundary sends back down (reciprocity:
 *                                                                    light leaves at o with T(cos_o) / eta^2)
 *         B sums the bounces base -> boundary -> base -> ...: W = M E + F_int M W for the radiosity W the base
 *         sends up when irradiance E reaches it, so W = (I - F_int M)^-1 M E; each bounce may fluoresce again.
 *
 * Energy: for a beam from i the reflected share is R(cos_i) + T(cos_i) (1 - F_int) (I - F_int M)^-1 M, which
 * for a scalar reflectance rho <= 1 is R + T (1 - F_int) rho / (1 - F_int rho) <= R + T = 1. f_s and f_b are
 * symmetric in i and o: the material is reciprocal (for a diagonal M). With eta = 1 the facets vanish
 * (F = 0) and the material is Lambertian with M.
 *
 * B is computed once, here, on the matrix's own grid in double precision (negative noise clamped to 0;
 * excitation samples are matched to emission wavelengths; B keeps M's excitation grid, so light below the
 * emission range still fluoresces) and handed to gcolor_from_reradiation, which makes it a matrix in the
 * bispectral model, reduces it to a 3 x 3 matrix in rgb and folds it into a reflectance elsewhere. The per-call
 * code uses only generic colour operations and works the same for a matrix or a vector value. R(c) is tabulated at
 * creation by a quadrature over h with the distribution D(h) (h.n). */
#include "generic/kit/fluorescent_kit.h"
#include "generic/plugin.h"

#include <math.h>
#include <string.h>

enum { RTABLE = 128, QUAD_U = 64, QUAD_PHI = 48 };

typedef struct Varnish {
    GMaterial base;
    GColor b;        /* B as a colour of the model */
    GColor diffuse;  /* (1 - R_avg)(1 - F_int) B: the base's albedo for diffuse light */
    double eta, m, d_norm, base_norm, r_avg, f_int;
    float r_table[RTABLE + 1]; /* R(c) at c = (k / RTABLE)^2: finer towards grazing, where R changes fast */
} Varnish;

/* ---- the Blinn distribution ---- */

double gfluor_blinn_d(double m, double cos_h)
{
    if (!(cos_h > 0.0))
        return 0.0;
    return (m + 2.0) / (2.0 * M_PI) * pow(cos_h > 1.0 ? 1.0 : cos_h, m);
}

double gfluor_blinn_mean_slope(double m)
{
    if (!(m >= 0.0) || !isfinite(m))
        return NAN;
    /* E[theta] = int theta (m + 2) cos^(m+1) theta sin theta dtheta, Simpson's rule */
    const int n = 2048;
    double h = 0.5 * M_PI / n, s = 0.0;
    for (int k = 0; k <= n; k++) {
        double t = k * h;
        double f = t * (m + 2.0) * pow(cos(t), m + 1.0) * sin(t);
        s += f * (k == 0 || k == n ? 1.0 : (k & 1) ? 4.0 : 2.0);
    }
    return s * h / 3.0 * 180.0 / M_PI;
}

double gfluor_blinn_exponent(double slope_deg)
{
    if (!(slope_deg > 0.0) || !(slope_deg < 45.0))
        return NAN;
    double lo = 0.0, hi = 1.0;
    while (gfluor_blinn_mean_slope(hi) > slope_deg && hi < 1e9)
        hi *= 2.0;
    for (int k = 0; k < 100 && hi - lo > 1e-9 * hi; k++) {
        double mid = 0.5 * (lo + hi);
        if (gfluor_blinn_mean_slope(mid) > slope_deg)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

/* ---- the rough boundary ---- */

/* f_s from the cosines cos_i, cos_o (with n), cos_h = h.n and cos_d = i.h = o.h. */
static double facet_brdf(const Varnish *v, double ci, double co, double ch, double cd)
{
    if (ch <= 0.0 || cd <= 0.0)
        return 0.0;
    double g = fmin(1.0, 2.0 * ch * fmin(ci, co) / cd);
    double d = v->d_norm * pow(ch > 1.0 ? 1.0 : ch, v->m);
    return goptics_fresnel(cd, 1.0 / v->eta) * d * g / (4.0 * ci * co);
}

/* R(c): int f_s cos_o dw_o = int F G (i.h) / (c (h.n)) D(h)(h.n) dw_h, by a midpoint rule in the variables
 * that make D(h)(h.n) dw_h uniform: cos theta_h = u^(1/(m+2)), phi = pi v (the integrand is even in phi).
 * 64 x 48 points are within 1e-3 of a 1000 x 1000 rule at every angle. */
static double directional_albedo(const Varnish *v, double c, const double *ch, const double *sh, const double *cphi)
{
    double s_i = sqrt(fmax(0.0, 1.0 - c * c));
    double sum = 0.0;
    for (int a = 0; a < QUAD_U; a++)
        for (int b = 0; b < QUAD_PHI; b++) {
            double cd = s_i * sh[a] * cphi[b] + c * ch[a]; /* i.h with i = (s_i, 0, c) */
            if (cd <= 0.0)
                continue;
            double co = 2.0 * cd * ch[a] - c; /* o.n with o = 2 (i.h) h - i */
            if (co <= 0.0)
                continue;
            double g = fmin(1.0, 2.0 * ch[a] * fmin(c, co) / cd);
            sum += goptics_fresnel(cd, 1.0 / v->eta) * g * cd / (c * ch[a]);
        }
    return sum / ((double)QUAD_U * QUAD_PHI);
}

static void fill_table(Varnish *v)
{
    double ch[QUAD_U], sh[QUAD_U], cphi[QUAD_PHI];
    for (int a = 0; a < QUAD_U; a++) {
        ch[a] = pow((a + 0.5) / QUAD_U, 1.0 / (v->m + 2.0));
        sh[a] = sqrt(fmax(0.0, 1.0 - ch[a] * ch[a]));
    }
    for (int b = 0; b < QUAD_PHI; b++)
        cphi[b] = cos(M_PI * (b + 0.5) / QUAD_PHI);
    for (int k = 0; k <= RTABLE; k++) {
        double t = k == 0 ? 0.1 / RTABLE : (double)k / RTABLE;
        double r = directional_albedo(v, t * t, ch, sh, cphi);
        v->r_table[k] = (float)(r > 1.0 ? 1.0 : r);
    }
    /* R_avg = 2 int R(c) c dc = 4 int R t^3 dt with c = t^2, trapezoid rule on the table */
    double s = 0.0;
    for (int k = 0; k < RTABLE; k++) {
        double t0 = (double)k / RTABLE, t1 = (double)(k + 1) / RTABLE;
        s += 0.5 * (v->r_table[k] * t0 * t0 * t0 + v->r_table[k + 1] * t1 * t1 * t1) * (t1 - t0);
    }
    v->r_avg = 4.0 * s;
    v->f_int = 1.0 - (1.0 - v->r_avg) / (v->eta * v->eta);
}

static double transmit(const Varnish *v, double c)
{
    double f = sqrt(c) * RTABLE;
    if (!(f < RTABLE)) /* tested before the cast (also NaN) */
        return 1.0 - v->r_table[RTABLE];
    int k = (int)f;
    double t = f - k;
    return 1.0 - ((1.0 - t) * v->r_table[k] + t * v->r_table[k + 1]);
}

/* ---- B = (I - F_int M)^-1 M on M's grid ---- */

static int solve_bounces(const GReradiation *M, double f_int, GReradiation *out, GError *err)
{
    int no = M->n_out, ni = M->n_in;
    double *a = gmem_calloc((size_t)no * no, sizeof(double));
    double *x = gmem_calloc((size_t)no * ni, sizeof(double));
    float *data = gmem_calloc((size_t)no * ni, sizeof(float));
    if (!a || !x || !data) {
        gmem_free(a);
        gmem_free(x);
        gmem_free(data);
        return gerror_set(err, G_ERR_NOMEM, "fluorescent-varnish: out of memory for the %d x %d matrix", no, ni);
    }
    /* a = I - F_int Msq, Msq[o][p]: M's excitation at emission wavelength p (linear between columns) */
    for (int p = 0; p < no; p++) {
        /* clamped to just outside the columns before the cast: a grid far away is beyond any int */
        double f = fmin(fmax((M->out_min + p * M->out_step - M->in_min) / M->in_step, -2.0), ni + 1.0);
        int j = (int)floor(f + 1e-6);
        double t = f - j;
        if (fabs(t) < 1e-6)
            t = 0.0;
        for (int o = 0; o < no; o++) {
            double e = 0.0;
            if (j >= 0 && j < ni)
                e += (1.0 - t) * gfluor_entry(M, o, j);
            if (t > 0.0 && j + 1 >= 0 && j + 1 < ni)
                e += t * gfluor_entry(M, o, j + 1);
            a[(long)o * no + p] = (o == p ? 1.0 : 0.0) - f_int * e * (M->out_step / M->in_step);
        }
    }
    for (int o = 0; o < no; o++)
        for (int i = 0; i < ni; i++)
            x[(long)o * ni + i] = gfluor_entry(M, o, i);
    /* Gaussian elimination with partial pivoting on a x = M */
    int rc = G_OK;
    for (int c = 0; c < no && rc == G_OK; c++) {
        int piv = c;
        for (int r = c + 1; r < no; r++)
            if (fabs(a[(long)r * no + c]) > fabs(a[(long)piv * no + c]))
                piv = r;
        if (fabs(a[(long)piv * no + c]) < 1e-12) {
            rc = gerror_set(err, G_ERR_INVALID, "fluorescent-varnish: the matrix returns too much energy for the "
                            "internal reflections to converge");
            break;
        }
        if (piv != c) {
            for (int k = 0; k < no; k++) {
                double t = a[(long)c * no + k];
                a[(long)c * no + k] = a[(long)piv * no + k];
                a[(long)piv * no + k] = t;
            }
            for (int k = 0; k < ni; k++) {
                double t = x[(long)c * ni + k];
                x[(long)c * ni + k] = x[(long)piv * ni + k];
                x[(long)piv * ni + k] = t;
            }
        }
        for (int r = 0; r < no; r++) {
            if (r == c)
                continue;
            double q = a[(long)r * no + c] / a[(long)c * no + c];
            if (q == 0.0)
                continue;
            for (int k = c; k < no; k++)
                a[(long)r * no + k] -= q * a[(long)c * no + k];
            for (int k = 0; k < ni; k++)
                x[(long)r * ni + k] -= q * x[(long)c * ni + k];
        }
    }
    if (rc == G_OK)
        for (int o = 0; o < no; o++)
            for (int i = 0; i < ni; i++) {
                double val = x[(long)o * ni + i] / a[(long)o * no + o];
                data[(long)o * ni + i] = (float)(val > 0.0 ? val : 0.0);
            }
    gmem_free(a);
    gmem_free(x);
    if (rc != G_OK) {
        gmem_free(data);
        return rc;
    }
    *out = *M;
    out->data = data;
    return G_OK;
}

/* ---- the material ---- */

static void varnish_destroy(GMaterial *self)
{
    Varnish *v = (Varnish *)self;
    gcolor_free(&v->b);
    gcolor_free(&v->diffuse);
    gmem_free(v);
}

static int varnish_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                              GColor *result)
{
    const Varnish *v = (const Varnish *)self;
    GVec3 n;
    double ci, co;
    if (!gfluor_cosines(sp, in, out, result, &n, &ci, &co))
        return G_OK;
    GVec3 h = gvec3_normalize(gvec3_add(in, out));
    double spec = facet_brdf(v, ci, co, gvec3_dot(h, n), gvec3_dot(in, h));
    double base = transmit(v, ci) * transmit(v, co) * v->base_norm;
    return gfluor_two_parts(sp, self->model, illum, NULL, spec * ci, &v->b, base * ci, result);
}

static int varnish_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    (void)sp;
    return gcolor_copy(result, &((const Varnish *)self)->diffuse);
}

static int varnish_ambient(const GMaterial *self, GSurfPoint *sp, const GColor *illum, GColor *result)
{
    const Varnish *v = (const Varnish *)self;
    return gfluor_two_parts(sp, self->model, illum, NULL, v->r_avg, &v->diffuse, 1.0, result);
}

/* ---- sampling: the facets' lobe (a half vector from D(h)(h.n), reflected) with the probability of the
 * boundary's directional albedo R(cos_o), and a cosine lobe for the base with T(cos_o) times its albedo ---- */

static void varnish_lobes(const Varnish *v, double co, double w[2])
{
    double t = transmit(v, co), b = gcolor_brightness(&v->diffuse);
    w[0] = v->eta > 1.0 ? fmax(1.0 - t, 1e-3) : 0.0;
    w[1] = t * fmin(fmax(b, 0.05), 1.0);
}

/* The density of in: the facets' D(h)(h.n) / (4 o.h) with h = (in + out) / |in + out| and the cosine lobe. */
static double varnish_lobes_pdf(const Varnish *v, GVec3 n, GVec3 out, const double w[2], GVec3 in)
{
    double total = w[0] + w[1], pdf = 0.0, c = gvec3_dot(in, n);
    if (w[1] > 0.0 && c > 0.0)
        pdf += w[1] / total * c / M_PI;
    GVec3 sum = gvec3_add(in, out);
    double len = gvec3_length(sum);
    if (w[0] > 0.0 && len > 1e-9) {
        GVec3 h = gvec3_scale(sum, 1.0 / len);
        double ch = gvec3_dot(h, n), od = gvec3_dot(out, h);
        if (ch > 0.0 && od > 0.0)
            pdf += w[0] / total * gfluor_blinn_d(v->m, ch) * ch / (4.0 * od);
    }
    return pdf;
}

static int varnish_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1,
                          double u2, GMaterialSample *s, GColor *weight)
{
    const Varnish *v = (const Varnish *)self;
    GVec3 n = gsurfpoint_normal(sp);
    double co = gvec3_dot(out, n);
    if (gvec3_dot(out, sp->geometric_normal) <= 0.0 || co <= 0.0)
        return 0;
    double w[2], prob;
    varnish_lobes(v, co, w);
    int lobe = gmaterial_pick_lobe(w, 2, &u1, &prob);
    if (lobe == 1)
        s->in = goptics_sample_cosine(n, u1, u2);
    else { /* cos theta_h = u^(1 / (m + 2)) makes D(h)(h.n) dw_h uniform */
        double ch = pow(1.0 - u1, 1.0 / (v->m + 2.0)), sh = sqrt(fmax(0.0, 1.0 - ch * ch)), phi = 2.0 * M_PI * u2;
        GVec3 t, b;
        goptics_frame(n, &t, &b);
        GVec3 h =
            gvec3_add(gvec3_add(gvec3_scale(t, sh * cos(phi)), gvec3_scale(b, sh * sin(phi))), gvec3_scale(n, ch));
        double od = gvec3_dot(out, h);
        if (!(od > 0.0))
            return 0; /* a facet turned away from out reflects nothing towards it */
        s->in = gvec3_normalize(gvec3_sub(gvec3_scale(h, 2.0 * od), out));
    }
    s->pdf = varnish_lobes_pdf(v, n, out, w, s->in);
    s->flags = GSAMPLE_REFLECT;
    if (!(s->pdf > 0.0))
        return 0;
    int rc = gmaterial_sample_weight(self, sp, s->in, out, rel_index, 0, s->pdf, weight);
    return rc ? rc : 1;
}

static double varnish_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    (void)rel_index;
    const Varnish *v = (const Varnish *)self;
    GVec3 n = gsurfpoint_normal(sp);
    double co = gvec3_dot(out, n);
    if (gvec3_dot(out, sp->geometric_normal) <= 0.0 || co <= 0.0)
        return 0.0;
    double w[2];
    varnish_lobes(v, co, w);
    return varnish_lobes_pdf(v, n, out, w, in);
}

static const GMaterialClass fluorescent_varnish_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "fluorescent-varnish",
    .description = "rough Fresnel varnish over a fluorescent Lambertian base (Wilkie et al. 5.2)",
    .destroy = varnish_destroy,
    .reflection = varnish_reflection,
    .ambient = varnish_ambient,
    .diffuse = varnish_diffuse,
    .sample = varnish_sample,
    .pdf = varnish_pdf,
};

void gfluor_varnish_default(GFluorVarnishParams *p)
{
    p->ior = 1.5;
    p->exponent = 0.0;
    p->slope_deg = 17.0;
}

int gfluor_varnish_create(const GColorModel *model, const GReradiation *matrix, const GFluorVarnishParams *params,
                          GMaterial **out, GError *err)
{
    *out = NULL;
    GFluorVarnishParams p;
    gfluor_varnish_default(&p);
    if (params)
        p = *params;
    if (!model)
        return gerror_set(err, G_ERR_INVALID, "fluorescent-varnish: no colour model given");
    int rc = gfluor_matrix_check(matrix, "fluorescent-varnish", err);
    if (rc != G_OK)
        return rc;
    if (!isfinite(p.ior) || p.ior < 1.0 || p.ior > 4.0)
        return gerror_set(err, G_ERR_INVALID, "fluorescent-varnish: ior is %g (must be in [1, 4])", p.ior);
    double m = p.exponent;
    if (!isfinite(m) || m < 0.0 || m > 1e6)
        return gerror_set(err, G_ERR_INVALID, "fluorescent-varnish: exponent is %g (must be in [0, 1e6]; 0 takes "
                          "it from slope)", m);
    if (m == 0.0) {
        m = gfluor_blinn_exponent(p.slope_deg);
        if (!isfinite(m))
            return gerror_set(err, G_ERR_INVALID, "fluorescent-varnish: slope is %g degrees (must be in (0, 45))",
                              p.slope_deg);
    }
    GMaterial *base;
    rc = gmaterial_new(&fluorescent_varnish_class, model, sizeof(Varnish), &base, err);
    if (rc != G_OK)
        return rc;
    Varnish *v = (Varnish *)base;
    v->eta = p.ior;
    v->m = m;
    v->d_norm = (m + 2.0) / (2.0 * M_PI);
    v->base_norm = 1.0 / (M_PI * p.ior * p.ior);
    fill_table(v);
    GReradiation bounced;
    rc = solve_bounces(matrix, v->f_int, &bounced, err);
    if (rc == G_OK) {
        if (gcolor_alloc(&v->b, model) != G_OK || gcolor_alloc(&v->diffuse, model) != G_OK)
            rc = gerror_set(err, G_ERR_NOMEM, "fluorescent-varnish: out of memory");
        if (rc == G_OK)
            rc = gcolor_from_reradiation(&v->b, &bounced, err);
        if (rc == G_OK)
            rc = gcolor_scale(&v->diffuse, &v->b, (1.0 - v->r_avg) * (1.0 - v->f_int));
        gfluor_matrix_free(&bounced);
    }
    if (rc != G_OK) {
        varnish_destroy(&v->base);
        return rc;
    }
    v->base.flags |= GMAT_NO_UV | GMAT_NO_REL_INDEX; /* they read no (u, v) parametrisation, no index (material.h) */
    *out = &v->base;
    return G_OK;
}

/* ---- the text format ---- */

static const GFluorParam varnish_params[] = {
    {"ior", 1.0, 4.0, offsetof(GFluorVarnishParams, ior), 1},
    {"slope", 0.01, 44.99, offsetof(GFluorVarnishParams, slope_deg), 1},
    {"exponent", 0.0, 1e6, offsetof(GFluorVarnishParams, exponent), 1},
    {NULL, 0.0, 0.0, 0, 0},
};

static int parse_fluorescent_varnish(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    GFluorVarnishParams p;
    gfluor_varnish_default(&p);
    GReradiation mat = {0};
    GMaterial *m = NULL;
    int rc = gfluor_read_params(r, varnish_params, "matrix, ior, slope, exponent", &p, &mat, err);
    if (rc == G_OK)
        rc = gfluor_varnish_create(greader_colormodel(r), &mat, &p, &m, err);
    return gfluor_finish(rc, &mat, m, object);
}

static const GParamInfo fluorescent_varnish_doc[] = {
    {"matrix", GPARAM_NAMED, "color", "reradiation (a day-glo orange)",
     "a re-radiation matrix (bfc, reradiation) or a reflectance; not a line",
     "the pigment of the Lambertian base under the varnish; a plain reflectance makes a non-fluorescent matrix"},
    {"ior", GPARAM_NAMED, "number", "1.5", "[1, 4]", "the refraction index of the clear varnish"},
    {"slope", GPARAM_NAMED, "number", "17", "[0.01, 44.99]",
     "the facets' mean slope in degrees under the Blinn distribution (used when exponent is 0)"},
    {"exponent", GPARAM_NAMED, "number", "0 (from slope)", "[0, 1e6]", "the Blinn exponent m of the facets"},
    {NULL},
};

GENERIC_TYPE_PARAMS(fluorescent_varnish, GKIND_MATERIAL, &fluorescent_varnish_class, parse_fluorescent_varnish, NULL,
                    fluorescent_varnish_doc);
