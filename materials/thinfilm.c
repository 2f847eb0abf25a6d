/* thinfilm.c - an interference film over any material (soap films, oil on water, coated glass, temper colours).
 *
 * The film (thickness d, index n + ik) lies between the medium the light comes from (the ambient: vacuum outside,
 * the base inside a base that is not opaque) and the base, whose scalar refraction index is the substrate's. Its
 * optics are the Airy sum of kit/thinfilm.h, per nm, in the colour model's own conversion from nm (the sum at
 * each sample of a sampled-spectrum model, its integral over each band in rgb and spectrum9):
 *   - the ideal reflection about the shading normal is the film's reflectance R(theta), which replaces the base's
 *     own ideal reflection (the sum counts the reflection at the base already);
 *   - everything else the base does is seen through the film: light entering at theta_i and leaving at theta_o
 *     is scaled by F(theta_i) F(theta_o) (a reflection) or F(theta) on the ambient side (a refraction), with
 *     F = T_film / (1 - F_base) the film's transmittance over the bare base's (Fresnel at the substrate index),
 *     so a base that counts its own Fresnel loss is not charged twice. Over a lambertian base (index 1) F is the
 *     film's transmittance, and reflected light is R + T(theta_i) int f_base T(theta_o) cos <= R + T = 1.
 * The base defaults to a dielectric of index 1: a free film in air (a soap film), where R + T = 1 without
 * extinction. Sampling: the film's mirror ray with probability P (its reflectance at 450, 550 and 650 nm, kept in
 * [0.05, 0.95]), else the base's sample with the film's factors; the base's own delta reflection draws nothing
 * (the film's mirror ray is its place). */
#include "generic/kit/material_kit.h"
#include "generic/kit/texparam.h"
#include "generic/kit/node_kit.h"
#include "generic/kit/thinfilm.h"
#include "generic/materials.h"
#include "generic/plugin.h"

#include <math.h>
#include <string.h>


typedef struct ThinFilm {
    GMaterial base;
    GMaterial *under; /* the base material (one reference) */
    GTexNumber thickness, n, k; /* each a constant or textured (kit/texparam.h) */
    /* the film's colours over the angle where thickness, index and extinction are constants, for the film seen from
     * outside and from inside over the base's index at creation (kit/thinfilm.h); NULL: the Airy sum at each call */
    GThinFilmTable *table[2];
} ThinFilm;

static void thinfilm_destroy(GMaterial *self)
{
    ThinFilm *f = (ThinFilm *)self;
    gmaterial_unref(f->under);
    gtexparam_number_release(&f->thickness);
    gtexparam_number_release(&f->n);
    gtexparam_number_release(&f->k);
    gthinfilm_table_destroy(f->table[0]);
    gthinfilm_table_destroy(f->table[1]);
    gmem_free(f);
}

/* The film as seen at sp: from outside (the relative index n(from) / n(to) at most 1) vacuum over the base, from
 * inside the base over vacuum; the base's index is the scalar of its refraction index at sp, kept in [0.01, 100]. */
static GThinFilm film_at(const ThinFilm *f, GSurfPoint *sp)
{
    GColor index;
    double ns = 1.0;
    GScratchMark mark = gscratch_mark(sp->scratch);
    if (gcolor_scratch(&index, f->base.model, sp->scratch) == G_OK &&
        gmaterial_refraction_index(f->under, sp, &index) == G_OK)
        ns = gsurfpoint_scalar_index(&index);
    gscratch_release(sp->scratch, mark);
    ns = isfinite(ns) ? fmin(100.0, fmax(0.01, ns)) : 1.0;
    int inside = ns != 1.0 && gsurfpoint_relative_index(sp) > 1.0;
    GThinFilm film = {gtexparam_number_at(&f->thickness, sp), gtexparam_number_at(&f->n, sp),
                      gtexparam_number_at(&f->k, sp), inside ? ns : 1.0, inside ? 1.0 : ns};
    return film;
}

/* The film's reflectance and transmittance colours (either may be NULL) at cos_a: from the table where it was made
 * for this very film, else the Airy sum. */
static int film_color(const ThinFilm *f, const GThinFilm *film, double cos_a, GColor *r, GColor *t)
{
    for (int i = 0; i < 2; i++)
        if (f->table[i] && gthinfilm_table_matches(f->table[i], film))
            return gthinfilm_table_color(f->table[i], cos_a, r, t);
    return gthinfilm_color(film, cos_a, r, t);
}

/* The probability of the film's mirror ray for light leaving at cos_o. */
static double mirror_share(const ThinFilm *f, GSurfPoint *sp, double cos_o)
{
    GThinFilm film = film_at(f, sp);
    double sum = 0.0;
    static const double nm[3] = {450.0, 550.0, 650.0};
    for (int i = 0; i < 3; i++) {
        double r;
        gthinfilm_airy(&film, nm[i], cos_o, &r, NULL);
        sum += r;
    }
    double p = sum / 3.0;
    return isfinite(p) ? fmin(0.95, fmax(0.05, p)) : 0.5;
}

/* The factor F(cos) = T_film / (1 - F_bare) into factor (a scratch colour of sp). */
static int through_film(const ThinFilm *f, GSurfPoint *sp, double cos_a, GColor *factor)
{
    GThinFilm film = film_at(f, sp);
    int rc = film_color(f, &film, cos_a, NULL, factor);
    double bare = 1.0 - goptics_fresnel(fmin(1.0, fmax(0.0, cos_a)), film.ambient / film.substrate);
    if (rc == G_OK)
        rc = gcolor_scale(factor, factor, bare > 1e-9 ? 1.0 / bare : 0.0);
    return rc;
}

static int thinfilm_reflection(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum, GVec3 out,
                               GColor *result)
{
    const ThinFilm *f = (const ThinFilm *)self;
    GVec3 n;
    double ci = gmaterial_cos_in(sp, in, out, &n), co = gvec3_dot(out, n);
    if (ci <= 0.0 || co <= 0.0) {
        gcolor_black(result);
        return G_OK;
    }
    GColor a, b;
    GScratchMark mark = gscratch_mark(sp->scratch);
    int rc = gcolor_scratch(&a, self->model, sp->scratch);
    if (rc == G_OK)
        rc = gcolor_scratch(&b, self->model, sp->scratch);
    if (rc == G_OK && gmaterial_is_mirror_pair(in, n, out)) { /* the film's ideal reflection */
        GThinFilm film = film_at(f, sp);
        rc = film_color(f, &film, co, &a, NULL);
        if (rc == G_OK)
            rc = gcolor_mul(result, &a, illum);
    } else if (rc == G_OK) { /* the base through the film, in and out */
        rc = through_film(f, sp, ci, &a);
        if (rc == G_OK)
            rc = gcolor_mul(&a, &a, illum);
        if (rc == G_OK)
            rc = gmaterial_reflection(f->under, sp, in, &a, out, result);
        if (rc == G_OK)
            rc = through_film(f, sp, co, &b);
        if (rc == G_OK)
            rc = gcolor_mul(result, result, &b);
    }
    gscratch_release(sp->scratch, mark);
    return rc;
}

static int thinfilm_refraction(const GMaterial *self, GSurfPoint *sp, GVec3 in, const GColor *illum,
                               const GColor *rel_index, GVec3 out, GColor *result)
{
    const ThinFilm *f = (const ThinFilm *)self;
    double co = gvec3_dot(out, gsurfpoint_normal(sp));
    GColor a;
    GScratchMark mark = gscratch_mark(sp->scratch);
    int rc = gcolor_scratch(&a, self->model, sp->scratch);
    if (rc == G_OK)
        rc = through_film(f, sp, fabs(co), &a); /* out lies in the ambient medium, where the film's angle is */
    if (rc == G_OK)
        rc = gcolor_mul(&a, &a, illum);
    if (rc == G_OK)
        rc = gmaterial_refraction(f->under, sp, in, &a, rel_index, out, result);
    gscratch_release(sp->scratch, mark);
    return rc;
}

static int thinfilm_refraction_index(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    return gmaterial_refraction_index(((const ThinFilm *)self)->under, sp, result);
}

static int thinfilm_reflection_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, GVec3 *dir)
{
    (void)self;
    *dir = gvec3_reflect(view, gsurfpoint_normal(sp));
    return 1;
}

static int thinfilm_refraction_dir(const GMaterial *self, GSurfPoint *sp, GVec3 view, const GColor *rel_index,
                                   GVec3 *dir)
{
    return gmaterial_refraction_dir(((const ThinFilm *)self)->under, sp, view, rel_index, dir);
}

static int thinfilm_emission(const GMaterial *self, GSurfPoint *sp, GVec3 out, GColor *result)
{
    return gmaterial_emission(((const ThinFilm *)self)->under, sp, out, result);
}

static int thinfilm_absorption(const GMaterial *self, GSurfPoint *sp, const GColor *illum, double length,
                               GColor *result)
{
    return gmaterial_absorption(((const ThinFilm *)self)->under, sp, illum, length, result);
}

static int thinfilm_normal(const GMaterial *self, GSurfPoint *sp, GVec3 *n)
{
    return gmaterial_normal(((const ThinFilm *)self)->under, sp, n);
}

/* The base's diffuse colour seen through the film at normal incidence, in and out. */
static int thinfilm_diffuse(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    const ThinFilm *f = (const ThinFilm *)self;
    GColor a;
    GScratchMark mark = gscratch_mark(sp->scratch);
    int rc = gcolor_scratch(&a, self->model, sp->scratch);
    if (rc == G_OK)
        rc = gmaterial_diffuse(f->under, sp, result);
    if (rc == G_OK)
        rc = through_film(f, sp, 1.0, &a);
    if (rc == G_OK)
        rc = gcolor_mul(result, result, &a);
    if (rc == G_OK)
        rc = gcolor_mul(result, result, &a);
    gscratch_release(sp->scratch, mark);
    return rc;
}

static int thinfilm_opaque(const GMaterial *self, GSurfPoint *sp)
{
    return gmaterial_opaque(((const ThinFilm *)self)->under, sp);
}

static int thinfilm_sample(const GMaterial *self, GSurfPoint *sp, GVec3 out, const GColor *rel_index, double u1,
                           double u2, GMaterialSample *s, GColor *weight)
{
    const ThinFilm *f = (const ThinFilm *)self;
    GVec3 n = gsurfpoint_normal(sp);
    double co = gvec3_dot(out, n);
    if (co <= 0.0)
        return 0;
    double p = mirror_share(f, sp, co);
    int rc;
    if (u1 < p) {
        s->in = gvec3_reflect(gvec3_neg(out), n);
        s->pdf = p;
        s->flags = GSAMPLE_REFLECT | GSAMPLE_DELTA;
        rc = gmaterial_sample_weight(self, sp, s->in, out, rel_index, 0, p, weight);
        return rc ? rc : 1;
    }
    GScratchMark mark = gscratch_mark(sp->scratch);
    rc = gmaterial_sample(f->under, sp, out, rel_index, fmin((u1 - p) / (1.0 - p), 0x1.fffffffffffffp-1), u2, s,
                          weight);
    gscratch_release(sp->scratch, mark);
    if (rc <= 0)
        return rc;
    if ((s->flags & GSAMPLE_DELTA) && !(s->flags & GSAMPLE_TRANSMIT))
        return 0; /* the base's mirror ray: the film's own is drawn in its place */
    s->pdf *= 1.0 - p;
    rc = gmaterial_sample_weight(self, sp, s->in, out, rel_index, (s->flags & GSAMPLE_TRANSMIT) != 0, s->pdf,
                                 weight);
    return rc ? rc : 1;
}

static double thinfilm_pdf(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out, const GColor *rel_index)
{
    const ThinFilm *f = (const ThinFilm *)self;
    double co = gvec3_dot(out, gsurfpoint_normal(sp));
    if (co <= 0.0)
        return 0.0;
    return (1.0 - mirror_share(f, sp, co)) * gmaterial_pdf(f->under, sp, in, out, rel_index);
}

static int thinfilm_is_delta(const GMaterial *self, GSurfPoint *sp)
{
    return gmaterial_is_delta(((const ThinFilm *)self)->under, sp);
}

static const GMaterialClass thinfilm_class = {
    .abi_version = GMATERIAL_ABI_VERSION,
    .name = "thinfilm",
    .description = "interference film over a material: the Airy sum per wavelength (iridescence)",
    .destroy = thinfilm_destroy,
    .reflection = thinfilm_reflection,
    .refraction = thinfilm_refraction,
    .refraction_index = thinfilm_refraction_index,
    .reflection_dir = thinfilm_reflection_dir,
    .refraction_dir = thinfilm_refraction_dir,
    .emission = thinfilm_emission,
    .absorption = thinfilm_absorption,
    .normal = thinfilm_normal,
    .diffuse = thinfilm_diffuse,
    .opaque = thinfilm_opaque,
    .sample = thinfilm_sample,
    .pdf = thinfilm_pdf,
    .is_delta = thinfilm_is_delta,
};

/* One call of the film makes at most this many calls of its base (sample: the base's sample, its index, and for
 * the weight the film's reflection or refraction, which asks the index again). */
#define THINFILM_CALLS 4

/* The tables of the film seen from outside and from inside over the base's index at a point of its surface (the
 * index at every point unless the base's is textured), when thickness, index and extinction are constants and the
 * film and the memory budget allow one (gthinfilm_table_create); otherwise none. */
static void film_table(ThinFilm *f)
{
    if (f->thickness.gen || f->n.gen || f->k.gen)
        return;
    const GColorModel *m = f->base.model;
    GScratch *scratch = gscratch_create(0);
    GSurfPoint *sp = scratch ? gsurfpoint_new(m, scratch, gvec3(0, 0, 0), gvec3(0, 0, 1), gvec3(1, 0, 0),
                                               gvec3(0, 1, 0), 0.0, 0.0, 0, NULL)
                             : NULL;
    if (sp) {
        GThinFilm film = film_at(f, sp);
        double ns = film.ambient != 1.0 ? film.ambient : film.substrate; /* the base's index */
        for (int i = 0; i < 2; i++) { /* a film without a table (or no memory for one) is summed exactly */
            film.ambient = i ? ns : 1.0, film.substrate = i ? 1.0 : ns;
            if (gthinfilm_table_create(&film, m, &f->table[i]) != G_OK)
                f->table[i] = NULL;
        }
    }
    gsurfpoint_free(sp);
    gscratch_destroy(scratch);
}

/* The film over base (NULL: a dielectric of index 1) into *out. */
/* Takes references of its own to the numbers' generators. */
static int thinfilm_create(const GColorModel *model, const GTexNumber *thickness, const GTexNumber *n,
                           const GTexNumber *k, GMaterial *base, int table, GMaterial **out, GError *err)
{
    GMaterial *under = base ? gmaterial_ref(base) : NULL;
    int rc = G_OK;
    if (!under) {
        GDielectricParams air = {gdispersion_constant(1.0), NULL, NULL};
        rc = gdielectric_create(model, &air, &under, err);
    }
    if (rc != G_OK)
        return rc;
    if (under->model != model) {
        gmaterial_unref(under);
        return gerror_set_param(err, G_ERR_MISMATCH, "base", "thinfilm: the base is in another colour model");
    }
    long long cost = 1 + (long long)THINFILM_CALLS * (under->cost > 0 ? under->cost : 1);
    int depth = 1 + (under->depth > 0 ? under->depth : 1);
    if (depth > GNODE_MAX_DEPTH || cost > GNODE_MAX_COST) {
        gmaterial_unref(under);
        return gerror_set_param(err, G_ERR_INVALID, "base",
                                "thinfilm: the film over its base would be %d deep and make %lld material calls a "
                                "call, the limits are %d (GNODE_MAX_DEPTH) and %d (GNODE_MAX_COST)",
                                depth, cost, GNODE_MAX_DEPTH, GNODE_MAX_COST);
    }
    GMaterial *m = NULL;
    if ((rc = gmaterial_new(&thinfilm_class, model, sizeof(ThinFilm), &m, err)) == G_OK) {
        ThinFilm *f = (ThinFilm *)m;
        f->under = under, under = NULL;
        gtexparam_number_copy(&f->thickness, thickness);
        gtexparam_number_copy(&f->n, n);
        gtexparam_number_copy(&f->k, k);
        m->depth = depth, m->cost = (int)cost;
        /* what the base promises holds through the film: its factors are plain colours of the ambient angle */
        m->flags |= f->under->flags &
                    (GMAT_NO_EMISSION | GMAT_OPAQUE | GMAT_GEOMETRIC_NORMAL | GMAT_NO_UV | GMAT_DIAGONAL);
        if (gtexparam_number_reads_uv(thickness) || gtexparam_number_reads_uv(n) || gtexparam_number_reads_uv(k))
            m->flags &= ~(unsigned)GMAT_NO_UV;
        m->flags |= f->under->flags & GMAT_CONSTANT_INDEX; /* its index is the base's */
        m->flags |= f->under->flags & GMAT_CLEAR; /* its absorption is the base's */
        if (table)
            film_table(f);
        *out = m;
    }
    gmaterial_unref(under);
    return rc;
}

/* thinfilm { thickness NM index N extinction K base MATERIAL airy exact|table }: each number may be textured */
static int parse_thinfilm(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GTexNumber thickness = gtexparam_number_const(500.0), n = gtexparam_number_const(1.33),
               k = gtexparam_number_const(0.0);
    GMaterial *base = NULL;
    static const char *const airy_modes[] = {"exact", "table", NULL}; /* the choice's index: tabulated */
    int table = 1;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "thickness") == 0)
            rc = gtexparam_read_number(r, 0.0, GTHINFILM_MAX_THICKNESS, 0, "thinfilm", "thickness", NULL, &thickness,
                                       err);
        else if (strcmp(key, "index") == 0)
            rc = gtexparam_read_number(r, 0.01, GTHINFILM_MAX_INDEX, 0, "thinfilm", "index", NULL, &n, err);
        else if (strcmp(key, "extinction") == 0)
            rc = gtexparam_read_number(r, 0.0, GTHINFILM_MAX_INDEX, 0, "thinfilm", "extinction", NULL, &k, err);
        else if (strcmp(key, "base") == 0)
            rc = greader_material(r, &base, err);
        else if (strcmp(key, "airy") == 0)
            rc = greader_choice(r, airy_modes, &table, err);
        else
            rc = greader_unknown_param(r, "thickness, index, extinction, base, airy", err);
        if (rc < 0)
            break;
    }
    GMaterial *m = NULL;
    if (rc == G_OK && (rc = thinfilm_create(greader_colormodel(r), &thickness, &n, &k, base, table, &m, err)) == G_OK)
        *object = m;
    gtexparam_number_release(&thickness);
    gtexparam_number_release(&n);
    gtexparam_number_release(&k);
    return rc;
}

static const GParamInfo thinfilm_params[] = {
    {"thickness", GPARAM_NAMED, "texnumber", "500", "[0, 5000]", "the film's thickness in nm"},
    {"index", GPARAM_NAMED, "texnumber", "1.33", "[0.01, 10]", "the film's refraction index n"},
    {"extinction", GPARAM_NAMED, "texnumber", "0", "[0, 10]", "the film's extinction coefficient k (absorption)"},
    {"base", GPARAM_NAMED, "material", "dielectric { index 1 } (a free film)", "any material",
     "what lies under the film; the scalar of its refraction index is the substrate's"},
    {"airy", GPARAM_NAMED, "choice", "table", "table, exact",
     "the film's colours: table, tabulated over the angle at creation for constant thickness, index and extinction "
     "(kit/thinfilm.h: 256 nodes per period of the phase, dense towards grazing, within 2e-6 of exact; exact within "
     "0.6 degrees of grazing and where the film differs); or exact, the Airy sum at every nm and the model's "
     "conversion at each evaluation"},
    {NULL},
};

GENERIC_TYPE_PARAMS(thinfilm, GKIND_MATERIAL, &thinfilm_class, parse_thinfilm, NULL, thinfilm_params);
