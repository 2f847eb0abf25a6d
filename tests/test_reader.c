/* test_reader.c - the text format: every entry type read back into objects whose values are checked, names,
 * aliases and includes, parse routines of other kinds (objects) using the public reader API, the corpus of
 * broken files in tests/bad/ with their exact `file:line:col: message`, the limits (depth, file size), and
 * an allocation-failure sweep proving that no error path leaks. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "generic/builtins.h"
#include "generic/materials.h"
#include "generic/memory.h"
#include "generic/reader.h"
#include "test_util.h"
#include "reader_fixture.h"

static GLibrary *load(const char *text)
{
    GLibrary *lib = NULL;
    GError err;
    int rc = greader_load_string(text, "t.mat", NULL, &lib, &err);
    if (rc != G_OK)
        print_error("%s\n", err.message);
    assert_int_equal(rc, G_OK);
    return lib;
}

/* A surface point facing +z with shading at normal incidence. */
static void setup_point(GSurfPoint *sp, const GColorModel *m, GScratch *s)
{
    gsurfpoint_init(sp, m, s);
    sp->geometric_normal = gvec3(0, 0, 1);
    sp->entering = 1;
}

/* ---- a test-only object kind: `object sphere { center <x,y,z> radius R material M }` ---- */

typedef struct Sphere {
    GVec3 center;
    double radius;
    GMaterial *material; /* own reference */
} Sphere;

static void sphere_destroy(void *p)
{
    Sphere *s = p;
    gmaterial_unref(s->material);
    gmem_free(s);
}

static int parse_sphere(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    Sphere *s = gmem_calloc(1, sizeof *s);
    if (!s)
        return greader_error(r, err, "out of memory");
    s->radius = 1.0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "center") == 0) {
            rc = greader_vec3(r, &s->center, err);
        } else if (strcmp(key, "radius") == 0) {
            rc = greader_number_in(r, 0.0, 1e9, &s->radius, err);
        } else if (strcmp(key, "material") == 0) {
            GMaterial *m = NULL;
            rc = greader_material(r, &m, err);
            if (rc == G_OK) {
                gmaterial_unref(s->material);
                s->material = gmaterial_ref(m);
            }
        } else {
            rc = greader_unknown_param(r, "center, radius, material", err);
        }
        if (rc < 0)
            break;
    }
    if (rc != G_OK) {
        sphere_destroy(s);
        return rc;
    }
    *object = s;
    return G_OK;
}

/* A material that nests another (for the brace depth limit): `nest { child MATERIAL }`. */
static int parse_nest(GReader *r, const void *vt, void **object, GError *err)
{
    (void)vt;
    GMaterial *child = NULL;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        rc = strcmp(key, "child") == 0 ? greader_material(r, &child, err) : greader_unknown_param(r, "child", err);
        if (rc < 0)
            return rc;
    }
    if (!child)
        return greader_error(r, err, "nest: no child");
    *object = gmaterial_ref(child);
    return G_OK;
}

static GKind object_kind; /* registered by register_test_types */
static GTypeInfo sphere_type = {GKIND_MAX, "sphere", NULL, parse_sphere, "test sphere", sphere_destroy, NULL};
static const GTypeInfo nest_type = {GKIND_MATERIAL, "nest", NULL, parse_nest, "test nesting", NULL, NULL};

static int register_test_types(void **state)
{
    (void)state;
    object_kind = sphere_type.kind = register_scene_kinds().object;
    if (!gregistry_find(object_kind, "sphere")) {
        assert_int_equal(gregistry_add(&sphere_type, NULL), G_OK);
        assert_int_equal(gregistry_add(&nest_type, NULL), G_OK);
    }
    return 0;
}

/* ---- round trips ---- */

static void test_colormodel_entry(void **state)
{
    (void)state;
    if (!gregistry_find(GKIND_COLORMODEL, "spectrum"))
        skip();
    GLibrary *lib = load("# comment first\ncolormodel spectrum { step 10 }\ncolor c rgb 0.2 0.4 0.6\n");
    const GColorModel *m = glibrary_colormodel(lib);
    assert_string_equal(gcolormodel_name(m), "spectrum");
    assert_near(m->lambda_step, 10.0, 0);
    assert_int_equal(m->nsamples, 41);
    glibrary_destroy(lib);
    /* default model */
    lib = load("color c rgb 1 0 0");
    assert_string_equal(gcolormodel_name(glibrary_colormodel(lib)), "rgb");
    glibrary_destroy(lib);
    /* the caller's override wins over the file */
    GReaderOptions opt = {.colormodel = "rgb"};
    GError err;
    assert_int_equal(greader_load_string("colormodel spectrum { step 5 }", "t.mat", &opt, &lib, &err), G_OK);
    assert_string_equal(gcolormodel_name(glibrary_colormodel(lib)), "rgb");
    glibrary_destroy(lib);
    GColorModel *mine = NULL;
    GColorModelOptions mo = {.step_nm = 20};
    assert_int_equal(gcolormodel_create("spectrum", &mo, &mine, &err), G_OK);
    GReaderOptions opt2 = {.model = mine};
    assert_int_equal(greader_load_string("colormodel rgb\nmaterial m lambert", "t.mat", &opt2, &lib, &err), G_OK);
    assert_ptr_equal(glibrary_colormodel(lib), mine);
    assert_non_null(glibrary_material(lib, "m"));
    assert_int_equal(glibrary_count(lib, GKIND_MATERIAL), 1);
    GMaterial *mat = glibrary_entry(lib, GKIND_MATERIAL, 0, NULL, NULL);
    assert_ptr_equal(mat->model, mine);
    glibrary_destroy(lib);
    gcolormodel_destroy(mine);
}

static void test_colors_rgb_model(void **state)
{
    (void)state;
    GLibrary *lib = load("color a rgb 0.25 0.5 0.75\n"
                         "color b rgb <0.1, 0.2, 0.3>\n"
                         "color c scale 2 a\n"
                         "color d c          # an alias\n"
                         "color white illuminant D65\n");
    const GColorModel *m = glibrary_colormodel(lib);
    float v[9]; /* rgb's capacity: room for a 3 x 3 matrix */
    GColor c;
    assert_int_equal(gcolor_wrap(&c, m, v, tu_floats(v)), G_OK);
    GError err;
    assert_int_equal(glibrary_color(lib, "a", GCOLOR_REFLECTANCE, &c, &err), G_OK);
    assert_near(v[0], 0.25, 1e-7);
    assert_near(v[1], 0.5, 1e-7);
    assert_near(v[2], 0.75, 1e-7);
    assert_int_equal(glibrary_color(lib, "b", GCOLOR_LIGHT, &c, &err), G_OK);
    assert_near(v[2], 0.3, 1e-7);
    assert_int_equal(glibrary_color(lib, "d", GCOLOR_REFLECTANCE, &c, &err), G_OK);
    assert_near(v[0], 0.5, 1e-7);
    assert_near(v[2], 1.5, 1e-6);
    /* D65 at Y = 1 as a light is sRGB white */
    assert_int_equal(glibrary_color(lib, "white", GCOLOR_LIGHT, &c, &err), G_OK);
    for (int i = 0; i < 3; i++)
        assert_near(v[i], 1.0, 2e-3);
    assert_int_equal(glibrary_color(lib, "nope", GCOLOR_LIGHT, &c, &err), G_ERR_NOTFOUND);
    assert_int_equal(glibrary_count(lib, GKIND_COLOR), 5);
    const char *name = NULL;
    const GTypeInfo *type = NULL;
    assert_non_null(glibrary_entry(lib, GKIND_COLOR, 2, &name, &type));
    assert_string_equal(name, "c");
    assert_string_equal(type->name, "scale");
    assert_null(glibrary_entry(lib, GKIND_COLOR, 5, NULL, NULL));
    glibrary_destroy(lib);
}

static void test_spectral_literals(void **state)
{
    (void)state;
    if (!gregistry_find(GKIND_COLORMODEL, "spectrum"))
        skip();
    GLibrary *lib = load("colormodel spectrum { step 1 }\n"
                         "color s spectrum { 400 0.1 500 0.5 600 0.9 }\n"
                         "color bb blackbody 2856\n"
                         "color a illuminant A\n"
                         "color e illuminant E\n"
                         "color laser line 532 2.5\n"
                         "color half line 532.5\n");
    const GColorModel *m = glibrary_colormodel(lib);
    GColor c = {0};
    assert_int_equal(gcolor_alloc(&c, m), G_OK);
    GSpectrumNM s;
    GError err;
    assert_int_equal(glibrary_color(lib, "s", GCOLOR_REFLECTANCE, &c, &err), G_OK);
    assert_int_equal(gcolor_to_nm(&c, GCOLOR_REFLECTANCE, &s), G_OK);
    assert_near(s.v[380 - GNM_MIN], 0.1, 1e-6); /* constant before the first pair */
    assert_near(s.v[450 - GNM_MIN], 0.3, 1e-6); /* linear between pairs */
    assert_near(s.v[550 - GNM_MIN], 0.7, 1e-6);
    assert_near(s.v[700 - GNM_MIN], 0.9, 1e-6); /* constant after the last */
    /* a 2856 K blackbody has the chromaticity of illuminant A (x = 0.4476, y = 0.4074) */
    double xyz[3], xyz_a[3];
    assert_int_equal(glibrary_color(lib, "bb", GCOLOR_LIGHT, &c, &err), G_OK);
    assert_int_equal(gcolor_to_xyz(&c, GCOLOR_LIGHT, xyz), G_OK);
    assert_near(xyz[1], 1.0, 1e-3);
    assert_near(xyz[0] / (xyz[0] + xyz[1] + xyz[2]), 0.4476, 2e-3);
    assert_near(xyz[1] / (xyz[0] + xyz[1] + xyz[2]), 0.4074, 2e-3);
    assert_int_equal(glibrary_color(lib, "a", GCOLOR_LIGHT, &c, &err), G_OK);
    assert_int_equal(gcolor_to_xyz(&c, GCOLOR_LIGHT, xyz_a), G_OK);
    assert_near(xyz_a[0] / (xyz_a[0] + xyz_a[1] + xyz_a[2]), 0.4476, 1e-3);
    assert_int_equal(glibrary_color(lib, "e", GCOLOR_LIGHT, &c, &err), G_OK);
    assert_int_equal(gcolor_to_xyz(&c, GCOLOR_LIGHT, xyz), G_OK);
    assert_near(xyz[0], 1.0, 1e-3);
    assert_near(xyz[1], 1.0, 1e-3);
    /* a line at an integer wavelength is one 1 nm sample holding its power */
    assert_int_equal(glibrary_color(lib, "laser", GCOLOR_LIGHT, &c, &err), G_OK);
    assert_int_equal(gcolor_to_nm(&c, GCOLOR_LIGHT, &s), G_OK);
    assert_near(s.v[532 - GNM_MIN], 2.5, 1e-5);
    assert_near(s.v[531 - GNM_MIN], 0.0, 1e-6);
    assert_near(s.v[533 - GNM_MIN], 0.0, 1e-6);
    assert_int_equal(glibrary_color(lib, "half", GCOLOR_LIGHT, &c, &err), G_OK);
    assert_int_equal(gcolor_to_nm(&c, GCOLOR_LIGHT, &s), G_OK);
    assert_near(s.v[532 - GNM_MIN], 0.5, 1e-5);
    assert_near(s.v[533 - GNM_MIN], 0.5, 1e-5);
    gcolor_free(&c);
    glibrary_destroy(lib);
}

static void test_materials_round_trip(void **state)
{
    (void)state;
    GLibrary *lib = load("color grey rgb 0.5 0.5 0.5\n"
                         "material wall lambert { reflectance grey }\n"
                         "material glossy phong { diffuse rgb 0.4 0.2 0.1  specular rgb 0.3 0.3 0.3\n"
                         "                         exponent 50 mirror rgb 0.1 0.1 0.1 }\n"
                         "material chrome mirror { reflectance rgb 0.9 0.8 0.7 }\n"
                         "material glass dielectric { index 1.5 tint rgb 1 1 1 }\n"
                         "material lamp emitter { radiance scale 4 rgb 1 1 1  two_sided yes }\n"
                         "material defaults lambert\n"
                         "material wall2 wall\n");
    const GColorModel *m = glibrary_colormodel(lib);
    GScratch *s = gscratch_create(0);
    GSurfPoint sp;
    setup_point(&sp, m, s);
    float iv[9], ov[9]; /* rgb's capacity: room for a 3 x 3 matrix */
    GColor illum, out;
    assert_int_equal(gcolor_wrap(&illum, m, iv, tu_floats(iv)), G_OK);
    assert_int_equal(gcolor_wrap(&out, m, ov, tu_floats(ov)), G_OK);
    double one[3] = {1, 1, 1};
    assert_int_equal(gcolor_from_rgb(&illum, one, GCOLOR_REFLECTANCE), G_OK);
    GVec3 n = gvec3(0, 0, 1), in = gvec3(0, 0, 1), outd = gvec3(0.6, 0, 0.8);

    GMaterial *wall = glibrary_material(lib, "wall");
    assert_non_null(wall);
    assert_string_equal(gmaterial_name(wall), "lambert");
    assert_ptr_equal(glibrary_material(lib, "wall2"), wall); /* alias: same object */
    sp.material = wall;
    assert_int_equal(gmaterial_reflection(wall, &sp, in, &illum, outd, &out), G_OK);
    assert_near(ov[0], 0.5 / M_PI, 1e-6);
    assert_int_equal(gmaterial_diffuse(glibrary_material(lib, "defaults"), &sp, &out), G_OK);
    assert_near(ov[1], 0.8, 1e-6);

    GMaterial *plastic = glibrary_material(lib, "glossy");
    gsurfpoint_invalidate(&sp);
    sp.material = plastic;
    assert_int_equal(gmaterial_diffuse(plastic, &sp, &out), G_OK);
    assert_near(ov[0], 0.4, 1e-6);
    assert_near(ov[2], 0.1, 1e-6);
    /* at the mirror direction of normal incidence: the mirror term 0.1 */
    assert_int_equal(gmaterial_reflection(plastic, &sp, in, &illum, n, &out), G_OK);
    assert_near(ov[1], 0.1, 1e-6);
    /* off the mirror direction: kd/pi + ks (n+2)/(2pi) cos^n(alpha), alpha = angle(out, n) */
    assert_int_equal(gmaterial_reflection(plastic, &sp, in, &illum, outd, &out), G_OK);
    assert_near(ov[1], 0.2 / M_PI + 0.3 * 52.0 / (2 * M_PI) * pow(0.8, 50), 1e-6);

    GMaterial *chrome = glibrary_material(lib, "chrome");
    sp.material = chrome;
    assert_int_equal(gmaterial_reflection(chrome, &sp, in, &illum, n, &out), G_OK);
    assert_near(ov[0], 0.9, 1e-6);
    assert_near(ov[2], 0.7, 1e-6);

    GMaterial *glass = glibrary_material(lib, "glass");
    assert_int_equal(gmaterial_opaque(glass, &sp), 0);
    assert_int_equal(gmaterial_refraction_index(glass, NULL, &out), G_OK);
    assert_near(gcolor_brightness(&out), 1.5, 1e-6);

    GMaterial *lamp = glibrary_material(lib, "lamp");
    sp.material = lamp;
    assert_int_equal(gmaterial_emission(lamp, &sp, gvec3(0, 0, -1), &out), G_OK); /* two sided: back too */
    assert_near(ov[0], 4.0, 1e-5);
    assert_near(ov[1], 4.0, 1e-5);

    /* a material referenced elsewhere outlives its library (its model must too: see reader.h) */
    gmaterial_ref(wall);
    glibrary_destroy(lib);
    assert_int_equal(wall->refcount, 1);
    gmaterial_unref(wall);
    gscratch_destroy(s);
}

static void test_dispersion_forms(void **state)
{
    (void)state;
    GLibrary *lib = load("material bk7 dielectric { index sellmeier 1.03961212 0.231792344 1.01046945\n"
                         "                                        0.00600069867 0.0200179144 103.560653 }\n"
                         "material c dielectric { index cauchy 1.5046 0.0042 }\n");
    const GColorModel *m = glibrary_colormodel(lib);
    float v[9]; /* rgb's capacity: room for a 3 x 3 matrix */
    GColor c;
    assert_int_equal(gcolor_wrap(&c, m, v, tu_floats(v)), G_OK);
    assert_int_equal(gmaterial_refraction_index(glibrary_material(lib, "bk7"), NULL, &c), G_OK);
    assert_near(v[1], 1.5185, 1e-3); /* BK7 at 550 nm */
    assert_true(v[2] > v[1] && v[1] > v[0]); /* normal dispersion: blue bends more */
    assert_int_equal(gmaterial_refraction_index(glibrary_material(lib, "c"), NULL, &c), G_OK);
    assert_near(v[1], 1.5046 + 0.0042 / (0.55 * 0.55), 1e-5);
    glibrary_destroy(lib);
}

static void test_objects_and_nesting(void **state)
{
    (void)state;
    GLibrary *lib = load("material red lambert { reflectance rgb 0.8 0.1 0.1 }\n"
                         "object sphere { center <1, 2, 3> radius 2 material red }\n"
                         "object sphere { center 0 0 -1 material lambert { reflectance rgb 0.1 0.1 0.8 } }\n"
                         "object ball sphere { material nest { child nest { child red } } }\n");
    assert_int_equal(glibrary_count(lib, object_kind), 3);
    Sphere *a = glibrary_entry(lib, object_kind, 0, NULL, NULL);
    Sphere *b = glibrary_entry(lib, object_kind, 1, NULL, NULL);
    Sphere *ball = glibrary_find(lib, object_kind, "ball");
    assert_near(a->center.y, 2.0, 0);
    assert_near(a->radius, 2.0, 0);
    assert_ptr_equal(a->material, glibrary_material(lib, "red"));
    assert_near(b->center.z, -1.0, 0);
    assert_string_equal(gmaterial_name(b->material), "lambert");
    assert_ptr_not_equal(b->material, a->material);
    assert_ptr_equal(ball->material, glibrary_material(lib, "red"));
    /* nested anonymous entries are owned but not listed */
    assert_int_equal(glibrary_count(lib, GKIND_MATERIAL), 1);
    glibrary_destroy(lib);
}

static void test_add_and_lookup(void **state)
{
    (void)state;
    GLibrary *lib = NULL;
    GError err;
    assert_int_equal(glibrary_create(NULL, &lib, &err), G_OK);
    const GColorModel *m = glibrary_colormodel(lib);
    GColor refl = {0};
    assert_int_equal(gcolor_alloc(&refl, m), G_OK);
    GMaterial *mat = NULL;
    assert_int_equal(glambert_create(m, &refl, &mat, &err), G_OK);
    const GTypeInfo *lt = gregistry_find(GKIND_MATERIAL, "lambert");
    assert_int_equal(glibrary_add(lib, lt, "black", mat, &err), G_OK);
    assert_ptr_equal(glibrary_material(lib, "black"), mat);
    assert_int_equal(glambert_create(m, &refl, &mat, &err), G_OK);
    assert_int_equal(glibrary_add(lib, lt, "black", mat, &err), G_ERR_EXISTS); /* released at once */
    /* materials and nodes share one namespace */
    assert_ptr_equal(glibrary_find(lib, GKIND_NODE, "black"), glibrary_material(lib, "black"));
    assert_null(glibrary_find(lib, GKIND_COLOR, "black"));
    /* many names (the table grows) */
    for (int i = 0; i < 300; i++) {
        char name[32];
        snprintf(name, sizeof name, "m%d", i);
        assert_int_equal(glambert_create(m, &refl, &mat, &err), G_OK);
        assert_int_equal(glibrary_add(lib, lt, name, mat, &err), G_OK);
    }
    assert_non_null(glibrary_material(lib, "m0"));
    assert_non_null(glibrary_material(lib, "m299"));
    assert_null(glibrary_material(lib, "m300"));
    assert_int_equal(glibrary_count(lib, GKIND_MATERIAL), 301);
    gcolor_free(&refl);
    glibrary_destroy(lib);
    glibrary_destroy(NULL);
}

/* ---- files: includes, the broken corpus, limits ---- */

static char *source_path(const char *rel)
{
    const char *src = getenv("GENERIC_SOURCE_DIR");
    static char buf[4096];
    snprintf(buf, sizeof buf, "%s/%s", src ? src : ".", rel);
    return buf;
}

static void test_include_file(void **state)
{
    (void)state;
    GLibrary *lib = NULL;
    GError err;
    int rc = greader_load_file(source_path("tests/good/scene.mat"), NULL, &lib, &err);
    if (rc != G_OK)
        print_error("%s\n", err.message);
    assert_int_equal(rc, G_OK);
    assert_non_null(glibrary_material(lib, "base_white")); /* from the included file */
    assert_non_null(glibrary_material(lib, "tile"));
    glibrary_destroy(lib);
}

/* Every .mat file in tests/bad whose first line is `# expect: MESSAGE` must fail with exactly MESSAGE when loaded
 * from inside tests/bad ("..." in MESSAGE matches any text). */
static void test_bad_corpus(void **state)
{
    (void)state;
    char here[4096];
    assert_non_null(getcwd(here, sizeof here));
    assert_int_equal(chdir(source_path("tests/bad")), 0);
    DIR *d = opendir(".");
    assert_non_null(d);
    int checked = 0, wrong = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        size_t n = strlen(e->d_name);
        if (n < 5 || strcmp(e->d_name + n - 4, ".mat") != 0)
            continue;
        FILE *f = fopen(e->d_name, "r");
        char line[1024] = "";
        assert_non_null(f);
        if (!fgets(line, sizeof line, f))
            line[0] = '\0';
        fclose(f);
        if (strncmp(line, "# expect: ", 10) != 0)
            continue;
        char *want = line + 10;
        want[strcspn(want, "\n")] = '\0';
        /* "..." stands for any text (lists of registered types grow as modules and models are added) */
        const char *dots = strstr(want, "...");
        size_t pl = dots ? (size_t)(dots - want) : strlen(want);
        const char *suffix = dots ? dots + 3 : "";
        GLibrary *lib = NULL;
        GError err;
        int rc = greader_load_file(e->d_name, NULL, &lib, &err);
        size_t ml = rc ? strlen(err.message) : 0, sl = strlen(suffix);
        int match = rc != G_OK && (dots ? strncmp(err.message, want, pl) == 0 && ml >= pl + sl &&
                                              strcmp(err.message + ml - sl, suffix) == 0
                                        : strcmp(err.message, want) == 0);
        if (!match) {
            print_error("%s:\n  expected: %s\n  got:      %s\n", e->d_name, want, rc ? err.message : "(loaded)");
            glibrary_destroy(lib);
            wrong++;
        }
        checked++;
    }
    closedir(d);
    assert_int_equal(chdir(here), 0);
    assert_int_equal(wrong, 0);
    assert_true(checked >= 30);
}

static void test_unknown_material_lists_types(void **state)
{
    (void)state;
    GLibrary *lib = NULL;
    GError err;
    assert_int_equal(greader_load_string("material m lamber { }", "t.mat", NULL, &lib, &err), G_ERR_NOTFOUND);
    assert_non_null(strstr(err.message, "t.mat:1:12: unknown material 'lamber': neither a material type ("));
    for (const char *n = "lambert\0phong\0mirror\0dielectric\0emitter\0"; *n; n += strlen(n) + 1)
        assert_non_null(strstr(err.message, n));
}

static void test_limits(void **state)
{
    (void)state;
    /* depth: a chain of 64 nested entries is fine, 65 is not */
    char text[4096];
    size_t used = 0;
    used += (size_t)snprintf(text + used, sizeof text - used, "color c");
    for (int i = 0; i < 63; i++)
        used += (size_t)snprintf(text + used, sizeof text - used, " scale 1");
    snprintf(text + used, sizeof text - used, " rgb 1 1 1");
    GLibrary *lib = load(text);
    glibrary_destroy(lib);
    snprintf(text + used, sizeof text - used, " scale 1 rgb 1 1 1");
    load_fails(text, "t.mat:1:521: nesting deeper than 64 levels (entries, blocks and includes)");
    GReaderOptions opt = {.max_depth = 3};
    GError err;
    assert_int_equal(greader_load_string("color c scale 1 scale 1 scale 1 rgb 1 1 1", "t.mat", &opt, &lib, &err),
                     G_ERR_PARSE);
    assert_string_equal(err.message, "t.mat:1:33: nesting deeper than 3 levels (entries, blocks and includes)");

    /* size: a sparse file one byte over a 16 MiB memory budget is refused before it is read, the budget named */
    const char *build = getenv("GENERIC_BUILD_DIR");
    char dir[4096], big[4200], main_file[4200];
    snprintf(dir, sizeof dir, "%s/tmp_reader_limits", build ? build : "/tmp");
    mkdir(dir, 0755);
    snprintf(big, sizeof big, "%s/big.mat", dir);
    snprintf(main_file, sizeof main_file, "%s/main.mat", dir);
    int fd = open(big, O_CREAT | O_TRUNC | O_WRONLY, 0644);
    assert_true(fd >= 0);
    assert_int_equal(ftruncate(fd, (16 << 20) + 1), 0);
    close(fd);
    FILE *f = fopen(main_file, "w");
    fputs("# includes a file that is too big\ninclude \"big.mat\"\n", f);
    fclose(f);
    size_t in_use = gmem_budget_used();
    gmem_budget_set_limit((16u << 20) + in_use);
    assert_int_equal(greader_load_file(main_file, NULL, &lib, &err), G_ERR_NOMEM);
    char want[16384];
    snprintf(want, sizeof want, "%s:2:9: cannot include: the file \"%s\" (16777217 bytes) needs 16.0 MiB, over the "
             "memory budget", main_file, big);
    assert_non_null(strstr(err.message, want));
    assert_int_equal(gmem_budget_used(), in_use);
    gmem_budget_set_limit(0);
    /* a limit of the caller's own */
    GReaderOptions small = {.max_file_size = 16};
    assert_int_equal(greader_load_file(main_file, &small, &lib, &err), G_ERR_IO);
    snprintf(want, sizeof want, "\"%s\" is 52 bytes, more than the limit of 16 bytes", main_file);
    assert_string_equal(err.message, want);
    unlink(big);
    unlink(main_file);
    rmdir(dir);
}

/* The texts of a load are charged to the memory budget while they are read, and after it only those that `like`
 * may re-read (the texts of named entries) stay charged, until the library is destroyed. */
static void test_text_budget(void **state)
{
    (void)state;
    const char *build = getenv("GENERIC_BUILD_DIR");
    char path[4200];
    snprintf(path, sizeof path, "%s/tmp_reader_text_budget.mat", build ? build : "/tmp");
    size_t base = gmem_budget_used();
    GLibrary *lib = NULL;
    GError err;
    const char *plain = "material lambert { reflectance rgb 0.5 0.5 0.5 }\n", *named = "material m lambert { }\n";
    for (int k = 0; k < 2; k++) {
        FILE *f = fopen(path, "w");
        assert_non_null(f);
        fputs(k ? named : plain, f);
        fclose(f);
        assert_int_equal(greader_load_file(path, NULL, &lib, &err), G_OK);
        /* the plain entry's text is freed at the end of the load, the named one's kept (its size and NUL) */
        assert_int_equal(gmem_budget_used() - base, k ? strlen(named) + 1 : 0);
        if (k) { /* a later load derives from m: its kept text is re-read */
            char second[4300];
            snprintf(second, sizeof second, "%s.like", path);
            f = fopen(second, "w");
            assert_non_null(f);
            fputs("material n like m { }\n", f);
            fclose(f);
            assert_int_equal(glibrary_load_file(lib, second, NULL, &err), G_OK);
            assert_non_null(glibrary_material(lib, "n"));
            unlink(second);
        }
        glibrary_destroy(lib);
        assert_int_equal(gmem_budget_used(), base);
    }
    /* a named entry followed by 100,000 bytes of plain entries: only the text up to the end of the named one stays */
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(named, f);
    for (int i = 0; i < 2000; i++)
        fputs("material lambert { reflectance rgb 0.5 0.5 0.5 }\n", f); /* 50 bytes */
    fclose(f);
    assert_int_equal(greader_load_file(path, NULL, &lib, &err), G_OK);
    assert_int_equal(gmem_budget_used() - base, strlen(named)); /* its text to the closing brace, and a NUL */
    glibrary_destroy(lib);
    assert_int_equal(gmem_budget_used(), base);
    unlink(path);
}

/* ---- no leak on any error path: fail the n-th allocation for every n ---- */

static void test_allocation_failures(void **state)
{
    (void)state;
    const char *text = "colormodel rgb\n"
                       "color warm blackbody 3200\n"
                       "color s spectrum { 400 0.2 700 0.6 }\n"
                       "material a lambert { reflectance scale 0.5 warm }\n"
                       "material b phong { diffuse s specular rgb 0.1 0.1 0.1 exponent 30 }\n"
                       "material c dielectric { index cauchy 1.5 0.004 absorption rgb 0.1 0.2 0.3 }\n"
                       "object sphere { center <0, 0, 0> material nest { child a } }\n"
                       "object sphere { material lambert { reflectance rgb 0.1 0.2 0.3 } }\n";
    GLibrary *lib = load(text); /* registers everything the run needs before counting */
    glibrary_destroy(lib);
    /* tagged blocks: a block the library frees with free() instead of gmem_free, or the reverse, crashes */
    static TuAlloc alloc;
    int failures = 0;
    for (long n = 1; n < 100000; n++) {
        alloc = (TuAlloc){.fail_call = n, .tagged = 1};
        tu_alloc_install(&alloc);
        GError err;
        int rc = greader_load_string(text, "t.mat", NULL, &lib, &err);
        if (rc == G_OK)
            glibrary_destroy(lib);
        gmem_set_allocator(NULL);
        if (alloc.live != 0)
            print_error("allocation %ld failing leaves %ld blocks (rc %d: %s)\n", n, alloc.live, rc, err.message);
        assert_int_equal(alloc.live, 0);
        if (rc == G_OK && !alloc.failed)
            break; /* every allocation succeeded: all failure points were covered */
        assert_true(rc < 0);
        failures++;
    }
    assert_true(failures > 20);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_colormodel_entry),
        cmocka_unit_test(test_colors_rgb_model),
        cmocka_unit_test(test_spectral_literals),
        cmocka_unit_test(test_materials_round_trip),
        cmocka_unit_test(test_dispersion_forms),
        cmocka_unit_test(test_objects_and_nesting),
        cmocka_unit_test(test_add_and_lookup),
        cmocka_unit_test(test_include_file),
        cmocka_unit_test(test_bad_corpus),
        cmocka_unit_test(test_unknown_material_lists_types),
        cmocka_unit_test(test_limits),
        cmocka_unit_test(test_text_budget),
        cmocka_unit_test(test_allocation_failures),
    };
    return cmocka_run_group_tests(tests, register_test_types, NULL);
}
