/* node_fixture.h - the fixture of the texture node tests (test_texture_nodes.c, test_texture_transform.c) and of
 * the material flag tests (through material_flags_fixture.h): an rgb model, a scratch arena, a surface point on a
 * plane, a colour and a white light; call_all calls every material method once. Include after cmocka.h and
 * texture_fixtures.h. */
#ifndef NODE_FIXTURE_H
#define NODE_FIXTURE_H

typedef struct Fix {
    GColorModel *rgb;
    GScratch *scratch;
    GSurfPoint sp;
    GColor c, illum;
} Fix;

static int setup(void **state)
{
    Fix *f = calloc(1, sizeof *f);
    GError err;
    if (!f || gcolormodel_create("rgb", NULL, &f->rgb, &err) != G_OK)
        return -1;
    f->scratch = gscratch_create(0);
    assert_int_equal(gcolor_alloc(&f->c, f->rgb), G_OK);
    assert_int_equal(gcolor_alloc(&f->illum, f->rgb), G_OK);
    double one[3] = {1, 1, 1};
    assert_int_equal(gcolor_from_rgb(&f->illum, one, GCOLOR_LIGHT), G_OK);
    plane_point(&f->sp, f->rgb, f->scratch, 0.3, 0.4);
    *state = f;
    return 0;
}

static int teardown(void **state)
{
    Fix *f = *state;
    gcolor_free(&f->c);
    gcolor_free(&f->illum);
    gscratch_destroy(f->scratch);
    gcolormodel_destroy(f->rgb);
    free(f);
    return 0;
}

/* Calls every method of m once on the point. */
static inline void call_all(Fix *f, const GMaterial *m)
{
    GVec3 d, z = gvec3(0, 0, 1);
    assert_int_equal(gmaterial_reflection(m, &f->sp, z, &f->illum, z, &f->c), G_OK);
    assert_int_equal(gmaterial_refraction(m, &f->sp, z, &f->illum, NULL, gvec3(0, 0, -1), &f->c), G_OK);
    assert_int_equal(gmaterial_refraction_index(m, &f->sp, &f->c), G_OK);
    assert_true(gmaterial_reflection_dir(m, &f->sp, gvec3(0, 0, -1), &d) >= 0);
    assert_true(gmaterial_refraction_dir(m, &f->sp, gvec3(0, 0, -1), NULL, &d) >= 0);
    assert_int_equal(gmaterial_emission(m, &f->sp, z, &f->c), G_OK);
    assert_int_equal(gmaterial_ambient(m, &f->sp, &f->illum, &f->c), G_OK);
    assert_int_equal(gmaterial_absorption(m, &f->sp, &f->illum, 1.0, &f->c), G_OK);
    assert_int_equal(gmaterial_normal(m, &f->sp, &d), G_OK);
    assert_int_equal(gmaterial_diffuse(m, &f->sp, &f->c), G_OK);
    assert_true(gmaterial_opaque(m, &f->sp) >= 0);
}

#endif
