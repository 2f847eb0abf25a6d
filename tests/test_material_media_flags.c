/* test_material_media_flags.c - the instance flags of material.h about the media on both sides of a surface
 * (test_material_flags.c: the flags about emission, opacity, normals and ideal directions):
 *  - GMAT_NO_REL_INDEX: which leaves and nodes get it, and that their slots do not see the relative index;
 *  - GMAT_CONSTANT_INDEX: which leaves and nodes get it (every built-in; the kit's pass-throughs and transform over a
 *    child that has it, no blend), and that their refraction index is the same bits at generated points as for
 *    no point;
 *  - GMAT_CLEAR: which leaves and nodes get it (every built-in but a dielectric that absorbs and a thinfilm over
 *    one; the kit's pass-throughs, transform, select and interpolate-one of another method over children that have
 *    it, no blend of several, whose arithmetic the test shows is not always the light's bits), and that their
 *    class's own absorption gives the light back bit for bit at generated points, lengths and lights
 *    (test_material_clear_dispatch.c: the dispatch answers the light for the bit without calling the class). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <generic/kit/affine.h>
#include <generic/materials.h>
#include <generic/kit/node_kit.h>
#include <generic/reader.h>

#include "generic/builtins.h"
#include "texture_fixtures.h"
#include "test_util.h"

#include <math.h>

#include "material_flags_fixture.h"
#include "varying_index_material.h"

/* Every built-in leaf material by name, in bispectral (the fluorescent ones need its matrices), and dielectrics and
 * a thinfilm whose media absorb or absorb nothing: the flag tests read which of them have a bit. */
static const char *const leaves_text =
    "colormodel bispectral\n"
    "color dayglo reradiation { absorb_peak 470 absorb_width 115 absorb_shape 8 absorb_max 0.97\n"
    "    emit_width 20 stokes_shift 135 quantum_yield 0.65 reflectance 0.92 }\n"
    "material l lambert { reflectance rgb 0.5 0.5 0.5 }\n"
    "material p phong { diffuse rgb 0.3 0.3 0.3 specular rgb 0.5 0.5 0.5 exponent 50 }\n"
    "material m mirror\n"
    "material e emitter { radiance rgb 1 0.5 0.25 }\n"
    "material c conductor { metal Au roughness 0.3 }\n"
    "material pl plastic { reflectance rgb 0.3 0.5 0.2 roughness 0.2 }\n"
    "material t thindielectric { index 1.5 }\n"
    "material fv fluorescent-varnish { matrix dayglo ior 1.5 slope 17 }\n"
    "material fp fluorescent-phong { matrix dayglo ks 0.04 exponents 30 120 480 weights 0.2 0.3 0.5 }\n"
    "material d dielectric\n"
    "material tf thinfilm { thickness 400 base lambert { reflectance rgb 0.5 0.5 0.5 } }\n"
    "material ly layer { top dielectric { index 1.5 } bottom lambert { reflectance rgb 0.5 0.5 0.5 } }\n"
    "material da dielectric { index 1.5 absorption rgb 0.5 0.2 0.1 }\n"
    "material dz dielectric { index 1.5 absorption rgb 0 0 0 }\n"
    "material tfa thinfilm { thickness 400 base dielectric { index 1.5 absorption rgb 0.5 0.2 0.1 } }\n";

/* 1 when m has bit. */
static int has_bit(const GMaterial *m, unsigned bit) { return (m->flags & bit) != 0; }

/* The media bits of each leaf of leaves_text (MEDIA_ALL: all three): the dielectrics, thinfilms and the layer read
 * the relative index, the others not; all have a constant index; all but the absorbing media (da, tfa) are clear. */
#define MEDIA_ALL (GMAT_NO_REL_INDEX | GMAT_CONSTANT_INDEX | GMAT_CLEAR)
static const struct {
    const char *name;
    unsigned bits;
} leaf_bits[] = {{"l", MEDIA_ALL},  {"p", MEDIA_ALL}, {"m", MEDIA_ALL},  {"e", MEDIA_ALL},  {"c", MEDIA_ALL},
                 {"pl", MEDIA_ALL}, {"t", MEDIA_ALL}, {"fv", MEDIA_ALL}, {"fp", MEDIA_ALL},
                 {"d", GMAT_CONSTANT_INDEX | GMAT_CLEAR},  {"tf", GMAT_CONSTANT_INDEX | GMAT_CLEAR},
                 {"ly", GMAT_CONSTANT_INDEX | GMAT_CLEAR}, {"dz", GMAT_CONSTANT_INDEX | GMAT_CLEAR},
                 {"da", GMAT_CONSTANT_INDEX},              {"tfa", GMAT_CONSTANT_INDEX}};

/* Loads leaves_text (file: its name in messages) and checks that each leaf has `bit` (bit_name in messages) as
 * leaf_bits says, and that query, the bit's public question, answers the same; query answers 1 for vacuum. */
static void leaves_have_bit(const char *file, unsigned bit, const char *bit_name, int (*query)(const GMaterial *))
{
    GLibrary *lib = NULL;
    GError err;
    if (greader_load_string(leaves_text, file, NULL, &lib, &err) != G_OK)
        fail_msg("%s", err.message);
    for (size_t i = 0; i < sizeof leaf_bits / sizeof leaf_bits[0]; i++) {
        GMaterial *m = glibrary_material(lib, leaf_bits[i].name);
        int want = (leaf_bits[i].bits & bit) != 0;
        assert_non_null(m);
        if (has_bit(m, bit) != want || query(m) != want)
            fail_msg("%s: %s %d, expected %d", leaf_bits[i].name, bit_name, has_bit(m, bit), want);
    }
    glibrary_destroy(lib);
    assert_int_equal(query(NULL), 1); /* vacuum: nothing read, index 1, nothing absorbed */
}

static int no_rel_index(const GMaterial *m) { return has_bit(m, GMAT_NO_REL_INDEX); }

/* The class's own slots of m at two copies of one point, one with the relative index ri[0] and one with ri[1] (set
 * on the point and handed as the argument), for light from in leaving towards out: 1 when every status, colour,
 * direction, density and flag agrees bit for bit (sample with the numbers u1, u2). */
static int same_for_both_indices(Fix *f, const GMaterial *m, GSurfPoint sp[2], const GColor ri[2], GVec3 in,
                                 GVec3 out, double u1, double u2)
{
    const GMaterialClass *c = m->cls;
    GColor r[2], w[2];
    GVec3 d[2][3];
    double pdf[2];
    int rc[2][8], flags[2];
    GMaterialSample smp[2];
    for (int k = 0; k < 2; k++) {
        assert_int_equal(gcolor_alloc(&r[k], f->rgb), G_OK);
        assert_int_equal(gcolor_alloc(&w[k], f->rgb), G_OK);
    }
    int same = 1;
    for (int slot = 0; slot < 6; slot++) {
        for (int k = 0; k < 2; k++) {
            GSurfPoint *q = &sp[k];
            d[k][0] = d[k][1] = d[k][2] = gvec3(7, 7, 7);
            pdf[k] = -1.0;
            flags[k] = -1;
            memset(&smp[k], 0, sizeof smp[k]);
            gcolor_black(&r[k]);
            gcolor_black(&w[k]);
            switch (slot) {
            case 0: rc[k][0] = c->reflection ? c->reflection(m, q, in, &f->illum, out, &r[k]) : 0; break;
            case 1: rc[k][1] = c->refraction ? c->refraction(m, q, in, &f->illum, &ri[k], out, &r[k]) : 0; break;
            case 2:
                rc[k][2] = c->reflection_dir ? c->reflection_dir(m, q, gvec3_neg(out), &d[k][0]) : 0;
                rc[k][3] = c->refraction_dir ? c->refraction_dir(m, q, gvec3_neg(out), &ri[k], &d[k][1]) : 0;
                break;
            case 3:
                rc[k][4] = c->sample ? c->sample(m, q, out, &ri[k], u1, u2, &smp[k], &w[k]) : 0;
                d[k][2] = smp[k].in;
                pdf[k] = smp[k].pdf;
                flags[k] = smp[k].flags;
                break;
            case 4: pdf[k] = c->pdf ? c->pdf(m, q, in, out, &ri[k]) : 0.0; break;
            default:
                rc[k][5] = c->diffuse ? c->diffuse(m, q, &r[k]) : 0;
                rc[k][6] = c->is_delta ? c->is_delta(m, q) : 0;
                rc[k][7] = c->opaque ? c->opaque(m, q) : 1;
                break;
            }
        }
        same = same && memcmp(r[0].v, r[1].v, 3 * sizeof(float)) == 0 && memcmp(w[0].v, w[1].v, 3 * sizeof(float)) == 0;
        same = same && memcmp(d[0], d[1], sizeof d[0]) == 0 && memcmp(&pdf[0], &pdf[1], sizeof pdf[0]) == 0;
        same = same && flags[0] == flags[1];
    }
    for (int j = 0; j < 8; j++)
        same = same && rc[0][j] == rc[1][j];
    for (int k = 0; k < 2; k++) {
        gcolor_free(&r[k]);
        gcolor_free(&w[k]);
    }
    return same;
}

/* GMAT_NO_REL_INDEX: the built-ins whose methods read no relative index have it (lambert, phong, mirror, emitter,
 * conductor, plastic, the thin pane, the fluorescent materials), those that read it not (dielectric, thinfilm,
 * layer). The kit's nodes over lamberts have it (blends, bump, scale, transform, a node of nodes), so has a blend
 * of a lambert and a mirror and a scale over the thin pane (a pass-through); a node over a dielectric has not, nor
 * a blend over the thin pane (its ideal-refraction test reads the point's index). The flagged materials' slots give
 * the same results, bit for bit, for the relative indices 1.5 and 1 / 1.5 over generated points, directions (the
 * ideal ones among them), numbers and generator values; the dielectric does not. */
static void test_no_rel_index_bit(void **state)
{
    Fix *f = *state;
    GError err;
    leaves_have_bit("relindex.mat", GMAT_NO_REL_INDEX, "GMAT_NO_REL_INDEX", gmaterial_no_rel_index);

    GMaterial *a = lambert(f, 0.2), *b = lambert(f, 0.8), *c = lambert(f, 0.5), *n[8], *yes[3], *no[5];
    GMaterial *mirror = NULL, *glass = NULL, *thin = NULL;
    GDielectricParams gp = {.index = gdispersion_constant(1.5)};
    GDispersion thin_index = gdispersion_constant(1.5);
    assert_int_equal(gdielectric_create(f->rgb, &gp, &glass, &err), G_OK);
    assert_int_equal(gmirror_create(f->rgb, &f->illum, &mirror, &err), G_OK);
    assert_int_equal(gthindielectric_create(f->rgb, &thin_index, &thin, &err), G_OK);
    CountGen *g = countgen_new(0.4);
    plain_nodes(a, b, c, g, n);
    plain_nodes_have(n, GMAT_NO_REL_INDEX, "GMAT_NO_REL_INDEX");
    GAffine2 uv = gaffine2_rotate(30.0);
    assert_int_equal(gnode_interpolate_create(a, mirror, &g->base, &yes[0], &err), G_OK);
    assert_int_equal(gnode_scale_create(thin, &g->base, &yes[1], &err), G_OK);
    assert_int_equal(gnode_transform_create(yes[0], &uv, NULL, &yes[2], &err), G_OK);
    for (int i = 0; i < 3; i++)
        if (!no_rel_index(yes[i]))
            fail_msg("node %d (%s) has no GMAT_NO_REL_INDEX", i, gmaterial_name(yes[i]));
    assert_int_equal(gnode_interpolate_create(a, glass, &g->base, &no[0], &err), G_OK);
    assert_int_equal(gnode_transform_create(glass, &uv, NULL, &no[1], &err), G_OK);
    assert_int_equal(gnode_scale_create(glass, &g->base, &no[2], &err), G_OK);
    GMaterial *mixed[2] = {n[0], no[0]};
    assert_int_equal(gnode_spline_create(mixed, 2, &g->base, GSPLINE_LINEAR, &no[3], &err), G_OK);
    assert_int_equal(gnode_interpolate_create(a, thin, &g->base, &no[4], &err), G_OK);
    for (int i = 0; i < 5; i++)
        if (no_rel_index(no[i]))
            fail_msg("node %d (%s) over a dielectric or a blended pane has GMAT_NO_REL_INDEX", i,
                     gmaterial_name(no[i]));

    /* the property: every flagged material above, and the dielectric as the control that reads the index */
    const GMaterial *all[14];
    int nall = 0;
    for (int i = 0; i < 8; i++)
        all[nall++] = n[i];
    for (int i = 0; i < 3; i++)
        all[nall++] = yes[i];
    all[nall++] = mirror;
    all[nall++] = thin;
    all[nall++] = glass;
    GColor ri[2];
    for (int k = 0; k < 2; k++) {
        assert_int_equal(gcolor_alloc(&ri[k], f->rgb), G_OK);
        assert_int_equal(gcolor_fill(&ri[k], k ? 1.0 / 1.5 : 1.5), G_OK);
    }
    int rounds = TU_SANITIZED ? 40 : 200, glass_differs = 0;
    unsigned long long s = 11;
    for (int r = 0; r < rounds; r++) {
        double x[4];
        for (int j = 0; j < 4; j++)
            x[j] = tu_uniform(&s);
        g->value = (r % 5) / 4.0; /* 0, 0.25, ..., 1: one child or a blend of two */
        int below = r & 1;
        double up = below ? -1.0 : 1.0;
        GVec3 out = gvec3_normalize(gvec3(x[0] - 0.5, x[1] - 0.5, up * (0.2 + x[2]))), in;
        switch (r % 4) {
        case 0: in = gvec3(-out.x, -out.y, out.z); break; /* the mirror direction */
        case 1: /* the ideal refraction of the view -out for one of the indices */
            if (!goptics_refract(gvec3_neg(out), gvec3(0, 0, up), r & 2 ? 1.5 : 1.0 / 1.5, &in))
                in = gvec3_neg(out);
            else
                in = gvec3_neg(in);
            break;
        case 2: in = gvec3_neg(out); break; /* straight through */
        default: in = gvec3_normalize(gvec3(x[1] - 0.5, x[3] - 0.5, x[2] - 0.5)); break;
        }
        for (int i = 0; i < nall; i++) {
            GSurfPoint sp[2];
            for (int k = 0; k < 2; k++) {
                plane_point(&sp[k], f->rgb, f->scratch, x[0] * 4.0, x[1] * 4.0);
                if (below)
                    sp[k].geometric_normal = gvec3(0, 0, -1);
                sp[k].material = all[i];
                sp[k].entering = !below;
                sp[k].from = below ? all[i] : NULL;
                sp[k].to = below ? NULL : all[i];
                gsurfpoint_set_relative_index(&sp[k], &ri[k]);
            }
            int same = same_for_both_indices(f, all[i], sp, ri, in, out, x[2], x[3]);
            if (all[i] == glass)
                glass_differs += !same;
            else if (!same)
                fail_msg("%s (%d) gives other results for another relative index (round %d)", gmaterial_name(all[i]),
                         i, r);
        }
    }
    assert_true(glass_differs > rounds / 4); /* the comparison sees an index that is read */
    for (int k = 0; k < 2; k++)
        gcolor_free(&ri[k]);
    for (int i = 4; i >= 0; i--)
        gmaterial_unref(no[i]);
    for (int i = 2; i >= 0; i--)
        gmaterial_unref(yes[i]);
    release_plain_nodes(NULL, 0, n, a, b, c, g);
    gmaterial_unref(mirror);
    gmaterial_unref(glass);
    gmaterial_unref(thin);
}

/* A point on the plane at (u, v) = 4 x[0..1] - 1 and the position 10 x[2..4] - 5, with a normal tilted by x[2..4]
 * (pointing down when below, where the incident ray comes from inside: not entering) and the surface index. */
static void generated_point(Fix *f, const double x[5], int below, int surface, GSurfPoint *sp)
{
    plane_point(sp, f->rgb, f->scratch, 4.0 * x[0] - 1.0, 4.0 * x[1] - 1.0);
    sp->point = sp->object_point = gvec3(10.0 * x[2] - 5.0, 10.0 * x[3] - 5.0, 10.0 * x[4] - 5.0);
    sp->geometric_normal = gvec3_normalize(gvec3(x[2] - 0.5, x[3] - 0.5, (below ? -1.0 : 1.0) * (0.2 + x[4])));
    sp->entering = !below;
    sp->surface = surface;
}

/* Makes m sp's material and the medium the incident ray travels in when below, else the one on the other side
 * (vacuum on the remaining side), and forgets what sp had cached. */
static void place_material(GSurfPoint *sp, const GMaterial *m, int below)
{
    sp->material = m;
    sp->from = below ? m : NULL;
    sp->to = below ? NULL : m;
    gsurfpoint_invalidate(sp);
}

/* 1 when the two colours hold the same kind and samples, bit for bit. */
static int same_bits(const GColor *x, const GColor *y)
{
    return x->kind == y->kind && memcmp(x->v, y->v, (size_t)x->model->nvalues * sizeof(float)) == 0;
}

/* What the tests of GMAT_CONSTANT_INDEX and GMAT_CLEAR build: a material without methods (plain, which gmaterial_init
 * gives the bit) and one whose class has the bit's slot (own, which it does not), three lamberts and plain_nodes'
 * nodes over them with their generator, a glass of index 1.5 and another dielectric (other), and the nodes each test
 * makes over them: those that must have the bit (yes) and those that must not (no). */
typedef struct MediaCase {
    unsigned bit;
    const char *bit_name;
    GMaterial *plain, *own, *a, *b, *c, *n[8], *glass, *other, *yes[8], *no[8];
    int nyes, nno;
    CountGen *g;
} MediaCase;

/* Makes mc's materials for bit (bit_name in messages) in f's model, own of own_class and other of the parameters
 * other, and checks which of plain_nodes' nodes have the bit against over_lamberts. */
static void media_case_open(Fix *f, MediaCase *mc, unsigned bit, const char *bit_name, const GMaterialClass *own_class,
                            const GDielectricParams *other, const int over_lamberts[8])
{
    GError err;
    GDielectricParams gp = {.index = gdispersion_constant(1.5)};
    *mc = (MediaCase){.bit = bit, .bit_name = bit_name};
    mc->plain = gmem_calloc(1, sizeof *mc->plain);
    mc->own = gmem_calloc(1, sizeof *mc->own);
    assert_int_equal(gmaterial_init(mc->plain, &plain_class, f->rgb, &err), G_OK);
    assert_int_equal(gmaterial_init(mc->own, own_class, f->rgb, &err), G_OK);
    assert_int_equal(has_bit(mc->plain, bit), 1); /* no slot: the default, set by gmaterial_init */
    assert_int_equal(has_bit(mc->own, bit), 0);   /* a slot of its own: not set */
    mc->a = lambert(f, 0.2);
    mc->b = lambert(f, 0.8);
    mc->c = lambert(f, 0.5);
    assert_int_equal(gdielectric_create(f->rgb, &gp, &mc->glass, &err), G_OK);
    assert_int_equal(gdielectric_create(f->rgb, other, &mc->other, &err), G_OK);
    mc->g = countgen_new(0.4);
    plain_nodes(mc->a, mc->b, mc->c, mc->g, mc->n);
    for (int i = 0; i < 8; i++)
        if (has_bit(mc->n[i], bit) != over_lamberts[i])
            fail_msg("node %d (%s) over lamberts: %s %d, expected %d", i, gmaterial_name(mc->n[i]), bit_name,
                     has_bit(mc->n[i], bit), over_lamberts[i]);
}

/* Checks that mc's yes nodes have its bit and its no nodes not (yes_over, no_over: what they are over, in messages). */
static void nodes_have_bit(const MediaCase *mc, const char *yes_over, const char *no_over)
{
    for (int i = 0; i < mc->nyes + mc->nno; i++) {
        int want = i < mc->nyes;
        const GMaterial *m = want ? mc->yes[i] : mc->no[i - mc->nyes];
        if (has_bit(m, mc->bit) != want)
            fail_msg("node %s%d (%s) over %s: %s %d", want ? "yes" : "no", want ? i : i - mc->nyes,
                     gmaterial_name(m), want ? yes_over : no_over, mc->bit_name, has_bit(m, mc->bit));
    }
}

/* The materials of mc whose property the test checks, into all (room for 20): plain_nodes' nodes with the bit, the
 * yes nodes, the glass, other when it has the bit, plain and a lambert; their number. */
static int media_case_flagged(const MediaCase *mc, const GMaterial **all)
{
    int nall = 0;
    for (int i = 0; i < 8; i++)
        if (has_bit(mc->n[i], mc->bit))
            all[nall++] = mc->n[i];
    for (int i = 0; i < mc->nyes; i++)
        all[nall++] = mc->yes[i];
    all[nall++] = mc->glass;
    if (has_bit(mc->other, mc->bit))
        all[nall++] = mc->other;
    all[nall++] = mc->plain;
    all[nall++] = mc->a;
    return nall;
}

/* Releases mc's materials, each node before its children. */
static void media_case_close(MediaCase *mc)
{
    for (int i = mc->nno - 1; i >= 0; i--)
        gmaterial_unref(mc->no[i]);
    for (int i = mc->nyes - 1; i >= 0; i--)
        gmaterial_unref(mc->yes[i]);
    release_plain_nodes(NULL, 0, mc->n, mc->a, mc->b, mc->c, mc->g);
    gmaterial_unref(mc->glass);
    gmaterial_unref(mc->other);
    gmaterial_unref(mc->plain);
    gmaterial_unref(mc->own);
}

/* Which leaves and nodes have GMAT_CONSTANT_INDEX, and, over generated points (both sides, positions, normals,
 * (u, v), generator values), the flagged ones' refraction index is the same bits as for sp NULL, which a blend of a
 * lambert and glass, the control, is not. */
static void test_constant_index_bit(void **state)
{
    Fix *f = *state;
    GError err;
    leaves_have_bit("constindex.mat", GMAT_CONSTANT_INDEX, "GMAT_CONSTANT_INDEX", gmaterial_constant_index);

    /* the one-child nodes (bump, scale, transform) pass their child's index; the blends do not get the bit */
    static const int over_lamberts[8] = {0, 0, 0, 0, 1, 1, 1, 0};
    GDielectricParams cp = {.index = gdispersion_cauchy(1.5, 4200.0, 0.0)};
    MediaCase mc;
    media_case_open(f, &mc, GMAT_CONSTANT_INDEX, "GMAT_CONSTANT_INDEX", &varying_index_class, &cp, over_lamberts);
    GMaterial *glass = mc.glass, *cauchy = mc.other, *varying = mc.own, **yes = mc.yes, **no = mc.no;
    CountGen *g = mc.g;
    assert_int_equal(has_bit(cauchy, GMAT_CONSTANT_INDEX), 1); /* a fit of the wavelength, read at no point */
    GAffine2 uv = gaffine2_rotate(30.0);
    GAffine3 move = gaffine3_translate(gvec3(1.0, -2.0, 0.5));
    assert_int_equal(gnode_bump_create(glass, &g->base, 1.0, &yes[0], &err), G_OK);
    assert_int_equal(gnode_scale_create(cauchy, &g->base, &yes[1], &err), G_OK);
    assert_int_equal(gnode_transform_create(glass, &uv, &move, &yes[2], &err), G_OK);
    assert_int_equal(gnode_transform_create(yes[1], NULL, &move, &yes[3], &err), G_OK);
    assert_int_equal(gnode_bump_create(mc.plain, &g->base, 0.5, &yes[4], &err), G_OK);
    mc.nyes = 5;
    assert_int_equal(gnode_interpolate_create(mc.a, glass, &g->base, &no[0], &err), G_OK);
    assert_int_equal(gnode_transform_create(varying, &uv, NULL, &no[1], &err), G_OK);
    assert_int_equal(gnode_scale_create(varying, &g->base, &no[2], &err), G_OK);
    assert_int_equal(gnode_transform_create(no[0], &uv, NULL, &no[3], &err), G_OK);
    mc.nno = 4;
    nodes_have_bit(&mc, "one constant index", "a blend or a varying index");

    /* the property: every flagged material's index at generated points is its index for no point, bit for bit */
    const GMaterial *all[20];
    int nall = media_case_flagged(&mc, all);
    const GMaterial *control = no[0];
    GColor ref, at, first;
    assert_int_equal(gcolor_alloc(&ref, f->rgb), G_OK);
    assert_int_equal(gcolor_alloc(&at, f->rgb), G_OK);
    assert_int_equal(gcolor_alloc(&first, f->rgb), G_OK);
    int rounds = TU_SANITIZED ? 40 : 300, control_differs = 0;
    unsigned long long s = 17;
    for (int r = 0; r < rounds; r++) {
        double x[6];
        for (int j = 0; j < 6; j++)
            x[j] = tu_uniform(&s);
        g->value = x[5]; /* the generators' value: a blend of the lambert and the glass follows it */
        int below = r & 1;
        GSurfPoint sp;
        generated_point(f, x, below, r % 6, &sp);
        for (int i = 0; i <= nall; i++) {
            const GMaterial *m = i < nall ? all[i] : control;
            place_material(&sp, m, below);
            assert_int_equal(gmaterial_refraction_index(m, &sp, &at), G_OK);
            if (m == control) {
                if (r == 0)
                    assert_int_equal(gcolor_copy(&first, &at), G_OK);
                control_differs += !same_bits(&at, &first);
                continue;
            }
            assert_int_equal(gmaterial_refraction_index(m, NULL, &ref), G_OK);
            if (!same_bits(&at, &ref))
                fail_msg("%s (%d): another refraction index at a generated point (round %d)", gmaterial_name(m), i, r);
        }
    }
    assert_true(control_differs > rounds / 2); /* the comparison sees an index that varies */
    gcolor_free(&ref);
    gcolor_free(&at);
    gcolor_free(&first);
    media_case_close(&mc);
}

/* A class with an absorption slot of its own: half the light passes at any length (no bit: gmaterial_init cannot
 * tell). */
static int half_absorption(const GMaterial *self, GSurfPoint *sp, const GColor *illum, double length, GColor *result)
{
    (void)self, (void)sp, (void)length;
    return gcolor_scale(result, illum, 0.5);
}

static const GMaterialClass absorbing_class = {
    .abi_version = GMATERIAL_ABI_VERSION, .name = "absorbing", .description = "half the light passes (tests)",
    .destroy = bare_destroy, .absorption = half_absorption,
};

/* A light of rgb values drawn in [0, 10) from *s, black one time in four. */
static void draw_light(GColor *light, unsigned long long *s)
{
    double rgb[3];
    for (int j = 0; j < 3; j++)
        rgb[j] = 10.0 * tu_uniform(s);
    if (tu_uniform(s) < 0.25)
        gcolor_black(light);
    else
        assert_int_equal(gcolor_from_rgb(light, rgb, GCOLOR_LIGHT), G_OK);
}

/* The absorption of m's class (the default for a class without the slot: gmaterial_absorption, which answers the
 * light for a clear material without asking the class) of light over length at sp (NULL: none) into at, filled
 * with NaN bits first: 1 when it is the light, bit for bit. */
static int gives_light_back(const GMaterial *m, GSurfPoint *sp, const GColor *light, double length, GColor *at)
{
    memset(at->v, 0xff, (size_t)at->model->nvalues * sizeof(float));
    int rc = m->cls->absorption ? m->cls->absorption(m, sp, light, length, at)
                                : gmaterial_absorption(m, sp, light, length, at);
    return rc == G_OK && same_bits(at, light);
}

/* Which leaves and nodes have GMAT_CLEAR; over generated points (both sides, positions, normals, (u, v), surface
 * indices, generator values), lengths and lights (black among them) the flagged ones give the light back bit for
 * bit, and so for sp NULL. A blend of two clear children, which does not get the bit, is shown to give other bits
 * for some lights and weights: w x + (1 - w) x rounds. */
static void test_clear_bit(void **state)
{
    Fix *f = *state;
    GError err;
    leaves_have_bit("clear.mat", GMAT_CLEAR, "GMAT_CLEAR", gmaterial_clear);

    /* interpolate-one of the diffuse colour, select, bump, scale and transform give one child's absorption */
    static const int over_lamberts[8] = {0, 1, 0, 1, 1, 1, 1, 0};
    GColor coeff;
    double k[3] = {0.5, 0.2, 0.1};
    assert_int_equal(gcolor_alloc(&coeff, f->rgb), G_OK);
    assert_int_equal(gcolor_from_rgb(&coeff, k, GCOLOR_REFLECTANCE), G_OK);
    GDielectricParams tp = {.index = gdispersion_constant(1.5), .absorption = &coeff};
    MediaCase mc;
    media_case_open(f, &mc, GMAT_CLEAR, "GMAT_CLEAR", &absorbing_class, &tp, over_lamberts);
    gcolor_free(&coeff);
    GMaterial *glass = mc.glass, *tinted = mc.other, *a = mc.a, **yes = mc.yes, **no = mc.no;
    CountGen *g = mc.g;
    assert_int_equal(has_bit(glass, GMAT_CLEAR), 1);
    assert_int_equal(has_bit(tinted, GMAT_CLEAR), 0);
    GAffine2 uv = gaffine2_rotate(30.0);
    GAffine3 move = gaffine3_translate(gvec3(1.0, -2.0, 0.5));
    GMaterial *clear_kids[3] = {glass, a, mc.plain}, *mixed_kids[3] = {glass, tinted, a};
    assert_int_equal(gnode_bump_create(glass, &g->base, 1.0, &yes[0], &err), G_OK);
    assert_int_equal(gnode_scale_create(glass, &g->base, &yes[1], &err), G_OK);
    assert_int_equal(gnode_transform_create(glass, &uv, &move, &yes[2], &err), G_OK);
    assert_int_equal(gnode_transform_create(yes[1], NULL, &move, &yes[3], &err), G_OK);
    assert_int_equal(gnode_select_create(clear_kids, 3, &g->base, &yes[4], &err), G_OK);
    assert_int_equal(gnode_interpolate_one_create(glass, tinted, &g->base, GNODE_REFLECTION, &yes[5], &err), G_OK);
    assert_int_equal(gnode_bump_create(mc.plain, &g->base, 0.5, &yes[6], &err), G_OK);
    mc.nyes = 7;
    assert_int_equal(gnode_interpolate_create(a, glass, &g->base, &no[0], &err), G_OK);
    assert_int_equal(gnode_bump_create(tinted, &g->base, 1.0, &no[1], &err), G_OK);
    assert_int_equal(gnode_transform_create(mc.own, &uv, NULL, &no[2], &err), G_OK);
    assert_int_equal(gnode_select_create(mixed_kids, 3, &g->base, &no[3], &err), G_OK);
    assert_int_equal(gnode_interpolate_one_create(glass, a, &g->base, GNODE_ABSORPTION, &no[4], &err), G_OK);
    assert_int_equal(gnode_interpolate_one_create(tinted, glass, &g->base, GNODE_DIFFUSE, &no[5], &err), G_OK);
    assert_int_equal(gnode_scale_create(no[0], &g->base, &no[6], &err), G_OK);
    mc.nno = 7;
    nodes_have_bit(&mc, "clear children", "a blend or an absorbing child");

    /* the property: every flagged material gives the light back, bit for bit, at generated points and for none */
    const GMaterial *all[20];
    int nall = media_case_flagged(&mc, all);
    const GMaterial *blends[2] = {no[0], no[4]}; /* two clear children blended: not flagged */
    static const double lengths[] = {0.0, 1e-3, 1.0, 1e3};
    GColor light, at;
    assert_int_equal(gcolor_alloc(&light, f->rgb), G_OK);
    assert_int_equal(gcolor_alloc(&at, f->rgb), G_OK);
    int rounds = TU_SANITIZED ? 40 : 300, blend_calls = 0, blend_differs = 0;
    unsigned long long s = 23;
    for (int r = 0; r < rounds; r++) {
        double x[6];
        for (int j = 0; j < 6; j++)
            x[j] = tu_uniform(&s);
        /* the generators' value: the blends' weights (in (0, 1) every other round) and select's child follow it */
        g->value = r % 2 ? x[5] : 3.0 * x[5];
        int below = r & 1;
        GSurfPoint sp;
        generated_point(f, x, below, r % 6, &sp);
        sp.t = 5.0 * x[4];
        double length = r % 5 < 4 ? lengths[r % 5] : 100.0 * tu_uniform(&s);
        draw_light(&light, &s);
        for (int i = 0; i < nall + 2; i++) {
            const GMaterial *m = i < nall ? all[i] : blends[i - nall];
            place_material(&sp, m, below);
            if (i >= nall) {
                blend_calls++;
                blend_differs += !gives_light_back(m, &sp, &light, length, &at);
                continue;
            }
            if (!gives_light_back(m, &sp, &light, length, &at))
                fail_msg("%s (%d): absorption over %g is not the light (round %d)", gmaterial_name(m), i, length, r);
            if (!gives_light_back(m, NULL, &light, length, &at))
                fail_msg("%s (%d): absorption for no point over %g is not the light (round %d)", gmaterial_name(m), i,
                         length, r);
        }
    }
    /* the blend's arithmetic changes some lights' bits: the kit must not give a blend the bit */
    assert_true(blend_differs > 0);
    assert_true(blend_differs < blend_calls); /* black light, weights 0 and 1 give the light itself */
    gcolor_free(&light);
    gcolor_free(&at);
    media_case_close(&mc);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_no_rel_index_bit, setup, teardown),
        cmocka_unit_test_setup_teardown(test_constant_index_bit, setup, teardown),
        cmocka_unit_test_setup_teardown(test_clear_bit, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
