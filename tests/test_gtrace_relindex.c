/* test_gtrace_relindex.c - the relative indices a tracing context keeps (trace.h's trace_cached_index, through
 * trace_relative_index): over generated pairs of media (vacuum, glasses of constant and Cauchy index, a transform of
 * one) and generated points, the kept colour has the bits of the index computed at the point without a cache (a
 * context without temporaries), the same entry serves a pair every time, and an entry, once filled, never changes
 * while later pairs beyond its slots are computed at the point; a medium whose index follows the point bypasses the
 * cache, and a material that reads no index gets the unit colour. In rgb and spectrum. */
#include "test_gtrace_common.h"

#include "generic/builtins.h"

#include <generic/kit/affine.h>
#include <generic/kit/node_kit.h>

#include "varying_index_material.h"

#ifdef __SANITIZE_ADDRESS__
#define RELINDEX_SANITIZED 1 /* fewer rounds in the sanitizers' build, several times slower */
#else
#define RELINDEX_SANITIZED 0
#endif

static GMaterial *dispersive(const Scene *s, GDispersion index)
{
    GDielectricParams p = {.index = index};
    GMaterial *m = NULL;
    GError err;
    assert_int_equal(gdielectric_create(s->model, &p, &m, &err), G_OK);
    return m;
}

/* A context for s: with its temporaries and kept indices (kept = 1), or without (every index computed at the point). */
static void context(TraceCtx *c, Scene *s, int kept)
{
    *c = (TraceCtx){.scene = s, .max_depth = 2, .band = -1};
    c->scratch = gscratch_create(0);
    assert_non_null(c->scratch);
    assert_int_equal(gcolor_scratch(&c->unit, s->model, c->scratch), G_OK);
    assert_int_equal(gmaterial_refraction_index(NULL, NULL, &c->unit), G_OK);
    if (kept)
        assert_int_equal(trace_ctx_temps(c), G_OK);
}

static int same_bits(const GColor *a, const GColor *b)
{
    return a->kind == b->kind && memcmp(a->v, b->v, (size_t)a->model->nvalues * sizeof(float)) == 0;
}

/* The index of the pair (from, to) at a point drawn from x[0..3], through the surface of `surface`, in both contexts:
 * *kept and *fresh are the two colours (kept's copied into keep_copy), *sk and *sf the points' scalar indices. */
static void both(TraceCtx *kc, TraceCtx *fc, const GMaterial *surface, const GMaterial *from, const GMaterial *to,
                 const double x[4], const GColor **kept, GColor *room_k, GColor *room_f, double *sk, double *sf)
{
    GSurfPoint sp[2];
    TraceCtx *cs[2] = {kc, fc};
    GColor *rooms[2] = {room_k, room_f};
    const GColor *ri[2];
    for (int k = 0; k < 2; k++) {
        gsurfpoint_init(&sp[k], cs[k]->scene->model, cs[k]->scratch);
        sp[k].point = sp[k].object_point = gvec3(4.0 * x[0] - 2.0, 4.0 * x[1] - 2.0, x[2]);
        sp[k].u = x[0];
        sp[k].v = x[3];
        int below = x[2] < 0.5;
        sp[k].geometric_normal = gvec3_normalize(gvec3(x[1] - 0.5, x[3] - 0.5, below ? -1.0 : 1.0));
        sp[k].entering = !below;
        sp[k].material = surface;
        sp[k].from = from;
        sp[k].to = to;
        assert_int_equal(trace_relative_index(cs[k], &sp[k], rooms[k], &ri[k]), G_OK);
    }
    if (!same_bits(ri[0], ri[1]))
        fail_msg("%s -> %s: the kept index differs from the one computed at the point", gmaterial_name(from),
                 gmaterial_name(to));
    *kept = ri[0];
    *sk = gsurfpoint_relative_index(&sp[0]);
    *sf = gsurfpoint_relative_index(&sp[1]);
}

static int in_cache(const TraceCtx *c, const GColor *ri)
{
    for (int i = 0; i < TRACE_RI_SLOTS; i++)
        if (ri == &c->ri_cache[i].ri)
            return 1;
    return 0;
}

static void kept_indices(const char *model)
{
    Scene *s = new_scene(model, gvec3(0, 0, 5), gvec3(0, 0, 0), 40.0);
    GError err;
    double b[3] = {1.03961212, 0.231792344, 1.01046945}, cc[3] = {0.00600069867, 0.0200179144, 103.560653};
    GMaterial *g15 = glass(s, 1.5), *g133 = glass(s, 1.33);
    GMaterial *cauchy = dispersive(s, gdispersion_cauchy(1.5, 4200.0, 0.0));
    GMaterial *bk7 = dispersive(s, gdispersion_sellmeier(b, cc));
    GMaterial *moved = NULL, *varying = gmem_calloc(1, sizeof(GMaterial)), *lam = lambert(s, 0.5);
    GAffine2 uv = gaffine2_rotate(20.0);
    assert_int_equal(gnode_transform_create(cauchy, &uv, NULL, &moved, &err), G_OK);
    assert_int_equal(gmaterial_init(varying, &varying_index_class, s->model, &err), G_OK);
    assert_true(gmaterial_constant_index(moved));
    assert_false(gmaterial_constant_index(varying));
    /* six media: 36 pairs, more than the slots */
    const GMaterial *media[6] = {NULL, g15, g133, cauchy, bk7, moved};
    TraceCtx kc, fc;
    context(&kc, s, 1);
    context(&fc, s, 0);
    GScratchMark mk = gscratch_mark(kc.scratch), mf = gscratch_mark(fc.scratch);
    const GColor *first = NULL;
    GColor first_copy;
    assert_int_equal(gcolor_alloc(&first_copy, s->model), G_OK);
    const GColor *entry[6][6] = {{NULL}};
    int rounds = RELINDEX_SANITIZED ? 150 : 600, seen_bypass = 0;
    uint64_t seed = 5;
    for (int r = 0; r < rounds; r++) {
        double x[6];
        for (int j = 0; j < 6; j++) {
            seed = seed * 6364136223846793005ull + 1442695040888963407ull;
            x[j] = (double)(seed >> 11) / 9007199254740992.0;
        }
        int i = (int)(6.0 * x[4]), j = (int)(6.0 * x[5]);
        const GMaterial *surface = media[i] ? media[i] : media[j] ? media[j] : g15;
        GColor room_k, room_f;
        const GColor *ri;
        double sk, sf;
        both(&kc, &fc, surface, media[i], media[j], x, &ri, &room_k, &room_f, &sk, &sf);
        assert_true(sk == sf); /* the point's scalar, taken from either colour */
        if (in_cache(&kc, ri)) { /* one entry per pair, every time */
            if (entry[i][j] && entry[i][j] != ri)
                fail_msg("pair %d -> %d: kept in two entries", i, j);
            entry[i][j] = ri;
        } else { /* computed at the point: the slots were full when the pair first came */
            assert_ptr_equal(ri, &room_k);
            assert_int_equal(kc.ri_filled, TRACE_RI_SLOTS);
            assert_null(entry[i][j]);
            seen_bypass++;
        }
        if (!first) {
            first = ri;
            assert_int_equal(gcolor_copy(&first_copy, ri), G_OK);
        }
        gscratch_release(kc.scratch, mk);
        gscratch_release(fc.scratch, mf);
    }
    assert_true(seen_bypass > 0);
    assert_true(in_cache(&kc, first));
    assert_true(same_bits(first, &first_copy)); /* a filled entry never changes */

    /* a medium whose index follows the point: computed at each point, two points two indices */
    double x1[4] = {0.1, 0.3, 0.7, 0.2}, x2[4] = {0.9, 0.3, 0.7, 0.2};
    GColor room_k, room_f, copy;
    assert_int_equal(gcolor_alloc(&copy, s->model), G_OK);
    const GColor *ri;
    double sk, sf;
    both(&kc, &fc, g15, varying, NULL, x1, &ri, &room_k, &room_f, &sk, &sf);
    assert_ptr_equal(ri, &room_k);
    assert_int_equal(gcolor_copy(&copy, ri), G_OK);
    both(&kc, &fc, g15, NULL, varying, x2, &ri, &room_k, &room_f, &sk, &sf);
    assert_ptr_equal(ri, &room_k);
    both(&kc, &fc, g15, varying, NULL, x2, &ri, &room_k, &room_f, &sk, &sf);
    assert_false(same_bits(ri, &copy));
    /* a material that reads no index: the unit colour, no index computed */
    both(&kc, &fc, lam, g15, NULL, x1, &ri, &room_k, &room_f, &sk, &sf);
    assert_ptr_equal(ri, &kc.unit);
    gscratch_release(kc.scratch, mk);
    gscratch_release(fc.scratch, mf);

    gcolor_free(&copy);
    gcolor_free(&first_copy);
    trace_ctx_free_temps(&kc);
    assert_int_equal(kc.ri_filled, 0);
    gscratch_destroy(kc.scratch);
    gscratch_destroy(fc.scratch);
    gmaterial_unref(moved);
    gmaterial_unref(varying);
    gmaterial_unref(lam);
    gmaterial_unref(g15);
    gmaterial_unref(g133);
    gmaterial_unref(cauchy);
    gmaterial_unref(bk7);
    scene_destroy(s);
}

static void test_kept_indices_rgb(void **state)
{
    (void)state;
    kept_indices("rgb");
}

static void test_kept_indices_spectrum(void **state)
{
    (void)state;
    kept_indices("spectrum");
}

int main(void)
{
    GError err;
    if (generic_register_builtins(&err) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_kept_indices_rgb),
        cmocka_unit_test(test_kept_indices_spectrum),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
