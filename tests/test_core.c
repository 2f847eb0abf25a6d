/* test_core.c - error records, the allocator hook, the scratch arena, the type registry (releasing objects through
 * their type record) and vec.h's inline fmax/fmin. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <generic/color.h>
#include <generic/materials.h>
#include <generic/registry.h>
#include <generic/vec.h>

#include <float.h>
#include <math.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "generic/builtins.h"
#include "test_util.h"

static void test_error_record(void **state)
{
    (void)state;
    GError e;
    assert_int_equal(gerror_set(&e, G_ERR_PARSE, "a.txt:%d:%d: expected %s", 3, 7, "number"), G_ERR_PARSE);
    assert_int_equal(e.code, G_ERR_PARSE);
    assert_string_equal(e.message, "a.txt:3:7: expected number");
    gerror_clear(&e);
    assert_int_equal(e.code, G_OK);
    assert_string_equal(e.message, "");
    assert_int_equal(gerror_set(NULL, G_ERR_IO, "ignored"), G_ERR_IO);
    assert_string_equal(gstatus_string(G_ERR_MISMATCH), "colours of different models or kinds");
}

static void test_scratch_mark_release(void **state)
{
    (void)state;
    GScratch *s = gscratch_create(1024);
    assert_non_null(s);
    char *a = gscratch_alloc(s, 100);
    assert_non_null(a);
    assert_int_equal((uintptr_t)a % 32, 0);
    GScratchMark m = gscratch_mark(s);
    char *b = gscratch_alloc(s, 10);
    char *c = gscratch_alloc(s, 5000); /* larger than a block: grows */
    assert_non_null(b);
    assert_non_null(c);
    memset(c, 1, 5000);
    gscratch_release(s, m);
    char *b2 = gscratch_alloc(s, 10);
    assert_ptr_equal(b, b2); /* released space is handed out again */
    gscratch_reset(s);
    assert_ptr_equal(gscratch_alloc(s, 1), a);
    gscratch_destroy(s);
    gscratch_destroy(NULL);
}

static void test_scratch_reuses_blocks(void **state)
{
    (void)state;
    GScratch *s = gscratch_create(256);
    static TuAlloc counter;
    tu_alloc_install(&counter);
    for (int round = 0; round < 100; round++) {
        GScratchMark m = gscratch_mark(s);
        for (int i = 0; i < 20; i++)
            assert_non_null(gscratch_alloc(s, 200));
        gscratch_release(s, m);
    }
    long grown = counter.calls;
    gmem_set_allocator(NULL);
    assert_true(grown <= 20); /* blocks grow in the first round only */
    gscratch_destroy(s);
}

/* Two threads' arenas never share a cache line: two arenas made one after the other (their headers were two
 * 24-byte mallocs side by side) hand out storage at least a 64-byte line apart, 64-byte aligned at the start; an
 * arena whose size overflows is refused, not made small. */
static void test_scratch_arenas_apart(void **state)
{
    (void)state;
    for (size_t bytes = 32; bytes <= 4096; bytes *= 2) {
        GScratch *a = gscratch_create(bytes), *b = gscratch_create(bytes);
        assert_non_null(a);
        assert_non_null(b);
        uintptr_t pa = (uintptr_t)gscratch_alloc(a, 32), pb = (uintptr_t)gscratch_alloc(b, 32);
        assert_int_equal(pa % 64, 0);
        assert_int_equal(pb % 64, 0);
        uintptr_t lo = pa < pb ? pa : pb, hi = pa < pb ? pb : pa;
        assert_true(hi - lo >= bytes + 64); /* the lower one's whole block, and a line, below the other's */
        gscratch_destroy(a);
        gscratch_destroy(b);
    }
    assert_null(gscratch_create(SIZE_MAX));
    assert_null(gscratch_create(SIZE_MAX - 100));
}

/* gfmax and gfmin are fmax and fmin inline: the same double for every pair of special and ordinary values,
 * signed zeros included (NaN results compared as NaN). */
static void test_inline_fmax_fmin(void **state)
{
    (void)state;
    volatile double vals[] = {0.0, -0.0, 1.0, -1.0, 2.5, NAN, -NAN, INFINITY, -INFINITY, 1e-310, -1e-310, DBL_MAX};
    int n = (int)(sizeof vals / sizeof vals[0]);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            double a = vals[i], b = vals[j], want[2] = {fmax(a, b), fmin(a, b)}, got[2] = {gfmax(a, b), gfmin(a, b)};
            for (int k = 0; k < 2; k++) {
                if (isnan(want[k]))
                    assert_true(isnan(got[k]));
                else
                    assert_memory_equal(&want[k], &got[k], sizeof(double));
            }
        }
    assert_true(gfmax(-0.0, 0.0) == 0.0 && !signbit(gfmax(-0.0, 0.0)));
    assert_true(gfmin(1.0, NAN) == 1.0 && gfmin(NAN, 1.0) == 1.0);
}

static void test_registry(void **state)
{
    (void)state;
    assert_non_null(gregistry_find(GKIND_COLORMODEL, "rgb"));
    assert_null(gregistry_find(GKIND_COLORMODEL, "no-such-model"));
    assert_null(gregistry_find((GKind)gkind_count(), "rgb"));
    static const int dummy = 1;
    GTypeInfo t = {GKIND_GENERATOR, "test-core-dummy", &dummy, NULL, "a test entry", NULL, NULL};
    GError e;
    assert_int_equal(gregistry_add(&t, &e), G_OK);
    assert_int_equal(gregistry_add(&t, &e), G_ERR_EXISTS);
    assert_non_null(strstr(e.message, "test-core-dummy"));
    const GTypeInfo *f = gregistry_find(GKIND_GENERATOR, "test-core-dummy");
    assert_non_null(f);
    assert_ptr_equal(f->vtable, &dummy);
    char names[512];
    gregistry_names(GKIND_COLORMODEL, names, sizeof names);
    assert_non_null(strstr(names, "rgb"));
    assert_string_equal(gkind_name(GKIND_MATERIAL), "material");
    GTypeInfo bad = {(GKind)gkind_count(), "x", NULL, NULL, NULL, NULL, NULL};
    assert_int_equal(gregistry_add(&bad, &e), G_ERR_INVALID);
}

static int released;
static void count_release(void *object)
{
    released++;
    gmem_free(object);
}

/* An object goes back through its type record: the record's destroy, else its kind's default (a material's
 * reference is dropped). */
static void test_release_through_type_record(void **state)
{
    (void)state;
    GTypeInfo own = {GKIND_GENERATOR, "test-core-released", NULL, NULL, "counts releases", count_release, NULL};
    released = 0;
    gtypeinfo_release(&own, gmem_alloc(16));
    gtypeinfo_release(&own, NULL);
    assert_int_equal(released, 1);
    GColorModel *m = NULL;
    assert_int_equal(gcolormodel_create("rgb", NULL, &m, NULL), G_OK);
    GColor refl = {0};
    assert_int_equal(gcolor_alloc(&refl, m), G_OK);
    GMaterial *mat = NULL;
    assert_int_equal(glambert_create(m, &refl, &mat, NULL), G_OK);
    gmaterial_ref(mat);
    assert_int_equal(mat->refcount, 2);
    const GTypeInfo *lambert = gregistry_find(GKIND_MATERIAL, "lambert");
    assert_non_null(lambert);
    assert_null(lambert->destroy); /* the kind's default */
    gtypeinfo_release(lambert, mat);
    assert_int_equal(mat->refcount, 1);
    gmaterial_unref(mat);
    gcolor_free(&refl);
    gcolormodel_destroy(m);
}

static void test_unknown_model_lists_known(void **state)
{
    (void)state;
    GColorModel *m = (GColorModel *)1;
    GError e;
    assert_int_equal(gcolormodel_create("cmyk", NULL, &m, &e), G_ERR_NOTFOUND);
    assert_null(m);
    assert_non_null(strstr(e.message, "cmyk"));
    assert_non_null(strstr(e.message, "rgb"));
}

static int never_init(GColorModel *self, const GColorModelOptions *opt, GError *err)
{
    (void)self;
    (void)opt;
    return gerror_set(err, G_ERR_INVALID, "must not be called");
}

static void test_model_version_refused(void **state)
{
    (void)state;
    GColorModelClass cls = {.abi_version = GCOLOR_ABI_VERSION + 1, .name = "future", .init = never_init};
    GColorModel *m = NULL;
    GError e;
    assert_int_equal(gcolormodel_create_class(&cls, NULL, &m, &e), G_ERR_VERSION);
    assert_null(m);
    char want[128];
    snprintf(want, sizeof want, "version %d, the library has %d", GCOLOR_ABI_VERSION + 1, GCOLOR_ABI_VERSION);
    assert_non_null(strstr(e.message, want));
    cls.abi_version = GCOLOR_ABI_VERSION; /* right version but no operations */
    assert_int_equal(gcolormodel_create_class(&cls, NULL, &m, &e), G_ERR_INVALID);
}

/* Every allocation failure while creating a model and colours must give G_ERR_NOMEM, never a crash. */
static void test_out_of_memory(void **state)
{
    (void)state;
    gregistry_find(GKIND_COLORMODEL, "rgb"); /* registry built before counting */
    for (long k = 0; k < 8; k++) {
        static TuAlloc alloc;
        alloc = (TuAlloc){.fail_call = k + 1};
        tu_alloc_install(&alloc);
        GError e;
        GColorModel *m = NULL;
        int rc = gcolormodel_create("rgb", NULL, &m, &e);
        GColor c = {0};
        int rc2 = rc == G_OK ? gcolor_alloc(&c, m) : G_ERR_NOMEM;
        GScratch *s = gscratch_create(0);
        gmem_set_allocator(NULL);
        assert_true(rc == G_OK || rc == G_ERR_NOMEM);
        assert_true(rc2 == G_OK || rc2 == G_ERR_NOMEM);
        if (rc2 == G_ERR_NOMEM)
            assert_null(c.v);
        gcolor_free(&c);
        gcolormodel_destroy(m);
        gscratch_destroy(s);
    }
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_error_record),
        cmocka_unit_test(test_scratch_mark_release),
        cmocka_unit_test(test_scratch_reuses_blocks),
        cmocka_unit_test(test_scratch_arenas_apart),
        cmocka_unit_test(test_inline_fmax_fmin),
        cmocka_unit_test(test_registry),
        cmocka_unit_test(test_release_through_type_record),
        cmocka_unit_test(test_unknown_model_lists_known),
        cmocka_unit_test(test_model_version_refused),
        cmocka_unit_test(test_out_of_memory),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
