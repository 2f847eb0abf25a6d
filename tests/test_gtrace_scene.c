/* test_gtrace_scene.c - the tracer's geometry, scene files and output: every surface point field for each
 * shape (point, object point, facing normal, entering, tangents, (u,v), surface index, t, footprint,
 * media), object transforms, OBJ meshes, the scene text format and its error positions, the output files
 * read back through OpenImageIO, and a check that the tracer's sources name no colour model and never
 * touch colour samples. */
#include "generic/builtins.h"
#include "test_gtrace_common.h"
#include "test_alloc.h"

#include <generic/services/image.h>

#include <ctype.h>
#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

/* Intersects one ray with a scene holding the given objects and fills the surface point. */
typedef struct Probe {
    Scene *scene;
    GScratch *scratch;
    TraceCtx ctx;
    GSurfPoint sp;
    GVec3 facing;
    Hit hit;
} Probe;

static void probe_open(Probe *p)
{
    memset(p, 0, sizeof *p);
    p->scene = new_scene("rgb", gvec3(0, 0, 5), gvec3(0, 0, 0), 40.0);
    p->scratch = gscratch_create(0);
    p->ctx.scene = p->scene;
    p->ctx.scratch = p->scratch;
}

static void probe_close(Probe *p)
{
    scene_destroy(p->scene);
    gscratch_destroy(p->scratch);
}

static int probe_cast(Probe *p, GVec3 o, GVec3 d, const Media *media)
{
    GError err;
    if (!p->scene->rtc && accel_build(p->scene, &err) != G_OK)
        fail_msg("accel_build: %s", err.message);
    Ray r = {o, gvec3_normalize(d), 0.0, INFINITY, 0.0, 0.001};
    Media none = {{NULL}, 0};
    if (!accel_intersect(p->scene, &r, &p->hit))
        return 0;
    /* the parametrisation is under test: a material without GMAT_NO_UV, for which it is filled (clearing the bit
     * is always correct; test_no_uv_fields in test_gtrace_shapes.c checks what the bit leaves out) */
    ((GMaterial *)p->hit.material)->flags &= ~(unsigned)GMAT_NO_UV;
    surfpoint_fill(&p->ctx, &r, &p->hit, media ? media : &none, &p->sp, &p->facing);
    return 1;
}

static void assert_vec(GVec3 a, GVec3 b, double tol)
{
    assert_near(a.x, b.x, tol);
    assert_near(a.y, b.y, tol);
    assert_near(a.z, b.z, tol);
}

/* dpdu x dpdv points along the outward normal (the true face normal, facing the ray when entering). */
static void assert_tangents_outward(const Probe *p)
{
    const GSurfPoint *sp = &p->sp;
    GVec3 n = sp->entering ? p->facing : gvec3_neg(p->facing);
    GVec3 c = gvec3_normalize(gvec3_cross(sp->dpdu, sp->dpdv));
    assert_near(gvec3_dot(c, n), 1.0, 1e-9);
}

static void test_sphere_surface(void **state)
{
    (void)state;
    Probe p;
    probe_open(&p);
    GMaterial *g = glass(p.scene, 1.5);
    add_sphere(p.scene, gmaterial_ref(g), gvec3(1, 2, 3), 2.0);
    assert_true(probe_cast(&p, gvec3(1, 2, 10), gvec3(0, 0, -1), NULL));
    assert_vec(p.sp.point, gvec3(1, 2, 5), 1e-12);
    assert_vec(p.sp.object_point, gvec3(1, 2, 5), 1e-12);
    assert_vec(p.sp.geometric_normal, gvec3(0, 0, 1), 1e-12);
    assert_int_equal(p.sp.entering, 1);
    assert_near(p.sp.t, 5.0, 1e-12);
    assert_near(p.sp.u, 0.75, 1e-12); /* longitude of +z */
    assert_near(p.sp.v, 0.5, 1e-12);  /* the equator */
    assert_near(gvec3_length(p.sp.dpdu), 2 * M_PI * 2.0, 1e-9);
    assert_near(gvec3_length(p.sp.dpdv), M_PI * 2.0, 1e-9);
    assert_tangents_outward(&p);
    assert_int_equal(p.sp.surface, 0);
    assert_ptr_equal(p.sp.material, g);
    assert_null(p.sp.from);
    assert_ptr_equal(p.sp.to, g);
    assert_ptr_equal(p.sp.model, p.scene->model);
    assert_ptr_equal(p.sp.scratch, p.scratch);
    /* ray cone: width spread * t on a surface seen head on, in (u,v) divided by the size of the tangents */
    assert_near(p.sp.footprint, 0.001 * 5.0, 1e-12);
    assert_near(p.sp.uv_footprint, p.sp.footprint / sqrt(gvec3_length(gvec3_cross(p.sp.dpdu, p.sp.dpdv))), 1e-12);
    /* head on, the footprint ellipse is a circle of that width: along u it spans w / |dpdu|, along v w / |dpdv| */
    assert_near(fabs(p.sp.uv_axis1[0]), 0.005 / (2 * M_PI * 2.0), 1e-12);
    assert_near(p.sp.uv_axis1[1], 0.0, 1e-12);
    assert_near(p.sp.uv_axis2[0], 0.0, 1e-12);
    assert_near(fabs(p.sp.uv_axis2[1]), 0.005 / (M_PI * 2.0), 1e-12);
    /* from the inside: leaving the glass into vacuum, the normal faces the ray */
    Media in_glass = {{g}, 1};
    assert_true(probe_cast(&p, gvec3(1, 2, 3), gvec3(1, 0, 0), &in_glass));
    assert_vec(p.sp.point, gvec3(3, 2, 3), 1e-12);
    assert_vec(p.sp.geometric_normal, gvec3(-1, 0, 0), 1e-12);
    assert_int_equal(p.sp.entering, 0);
    assert_ptr_equal(p.sp.from, g);
    assert_null(p.sp.to);
    assert_tangents_outward(&p);
    gmaterial_unref(g);
    probe_close(&p);
}

static void test_transformed_sphere(void **state)
{
    (void)state;
    Probe p;
    probe_open(&p);
    Object *o = add_sphere(p.scene, lambert(p.scene, 0.5), gvec3(0, 0, 0), 1.0);
    o->has_xf = 1;
    assert_int_equal(xform_scale(&o->xf, gvec3(1, 1, 3)), G_OK);
    assert_int_equal(xform_rotate(&o->xf, gvec3(0, 1, 0), 90.0), G_OK); /* the long axis is now x */
    assert_int_equal(xform_translate(&o->xf, gvec3(0, 0, -5)), G_OK);
    /* the ellipsoid (x/3)^2 + y^2 + (z+5)^2 = 1: hit it from +x along the axis */
    assert_true(probe_cast(&p, gvec3(10, 0, -5), gvec3(-1, 0, 0), NULL));
    assert_vec(p.sp.point, gvec3(3, 0, -5), 1e-9);
    assert_vec(p.sp.geometric_normal, gvec3(1, 0, 0), 1e-9);
    assert_near(p.sp.t, 7.0, 1e-9);
    /* object space: rotated back, the point is on the unit sphere's z axis before the scale */
    assert_vec(p.sp.object_point, gvec3(0, 0, 1), 1e-9);
    /* a point off the axes: the normal is the inverse transpose of the object normal */
    GVec3 target = gvec3(3 * 0.8, 0.6, -5);
    assert_true(probe_cast(&p, gvec3(target.x, target.y, 5), gvec3(0, 0, -1), NULL));
    assert_vec(p.sp.point, target, 1e-9);
    GVec3 n = gvec3_normalize(gvec3(0.8 / 3.0, 0.6, 0));
    assert_vec(p.sp.geometric_normal, n, 1e-9);
    assert_tangents_outward(&p);
    probe_close(&p);
}

static void test_box_faces(void **state)
{
    (void)state;
    Probe p;
    probe_open(&p);
    add_box(p.scene, lambert(p.scene, 0.5), gvec3(-1, -2, -3), gvec3(1, 2, 3));
    const GVec3 n[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
    const double half[3] = {1, 2, 3};
    for (int f = 0; f < 6; f++) {
        GVec3 o = gvec3_scale(n[f], 10.0);
        o = gvec3_add(o, gvec3(0.1 * (f != 0 && f != 1), 0.1 * (f < 2), 0.0)); /* off the face centre */
        assert_true(probe_cast(&p, o, gvec3_neg(n[f]), NULL));
        assert_int_equal(p.sp.surface, f);
        assert_vec(p.sp.geometric_normal, n[f], 1e-12);
        assert_near(p.sp.t, 10.0 - half[f / 2], 1e-9);
        assert_true(p.sp.u > 0.0 && p.sp.u < 1.0 && p.sp.v > 0.0 && p.sp.v < 1.0);
        assert_tangents_outward(&p);
        /* the tangents span the face: (u,v) in [0,1] across it */
        double area = gvec3_length(gvec3_cross(p.sp.dpdu, p.sp.dpdv));
        double face = 1.0;
        for (int a = 0; a < 3; a++)
            if (a != f / 2)
                face *= 2 * half[a];
        assert_near(area, face, 1e-9);
    }
    /* a face centre maps to (0.5, 0.5) */
    assert_true(probe_cast(&p, gvec3(0, 0, 10), gvec3(0, 0, -1), NULL));
    assert_near(p.sp.u, 0.5, 1e-12);
    assert_near(p.sp.v, 0.5, 1e-12);
    probe_close(&p);
}

static void test_cylinder_disc_plane(void **state)
{
    (void)state;
    Probe p;
    probe_open(&p);
    GError err;
    Object *c = object_new(SHAPE_CYLINDER, NULL);
    assert_int_equal(object_cylinder(c, gvec3(0, 0, 0), gvec3(0, 2, 0), 0.5, 0, &err), G_OK);
    c->material = lambert(p.scene, 0.5);
    assert_int_equal(scene_add_object(p.scene, c, &err), G_OK);
    Object *d = object_new(SHAPE_DISC, NULL);
    assert_int_equal(object_disc(d, gvec3(5, 1, 0), gvec3(0, 1, 0), 1.0, &err), G_OK);
    d->material = lambert(p.scene, 0.5);
    assert_int_equal(scene_add_object(p.scene, d, &err), G_OK);
    add_plane(p.scene, lambert(p.scene, 0.5), gvec3(0, -1, 0), gvec3(0, 1, 0));
    /* side */
    assert_true(probe_cast(&p, gvec3(5, 1, 0), gvec3(-1, 0, 0), NULL) && p.hit.obj == c);
    assert_int_equal(p.sp.surface, 0);
    assert_vec(p.sp.point, gvec3(0.5, 1, 0), 1e-12);
    assert_vec(p.sp.geometric_normal, gvec3(1, 0, 0), 1e-12);
    assert_near(p.sp.v, 0.5, 1e-12);
    assert_tangents_outward(&p);
    /* top and bottom caps */
    assert_true(probe_cast(&p, gvec3(0.1, 5, 0), gvec3(0, -1, 0), NULL) && p.hit.obj == c);
    assert_int_equal(p.sp.surface, 2);
    assert_vec(p.sp.geometric_normal, gvec3(0, 1, 0), 1e-12);
    assert_tangents_outward(&p);
    assert_true(probe_cast(&p, gvec3(0.1, -0.5, 0), gvec3(0, 1, 0), NULL) && p.hit.obj == c);
    assert_int_equal(p.sp.surface, 1);
    assert_vec(p.sp.geometric_normal, gvec3(0, -1, 0), 1e-12);
    assert_tangents_outward(&p);
    /* the disc: inside the radius a hit, outside it the plane below */
    assert_true(probe_cast(&p, gvec3(5.5, 5, 0.5), gvec3(0, -1, 0), NULL) && p.hit.obj == d);
    assert_near(p.sp.t, 4.0, 1e-12);
    assert_tangents_outward(&p);
    assert_true(probe_cast(&p, gvec3(5.9, 5, 0.9), gvec3(0, -1, 0), NULL) && p.hit.obj != d);
    /* the plane: (u,v) are distances along its frame, u along +x and v along -z for a floor */
    assert_true(probe_cast(&p, gvec3(-3, 5, 2), gvec3(0, -1, 0), NULL));
    assert_near(p.sp.u, -3.0, 1e-12);
    assert_near(p.sp.v, -2.0, 1e-12);
    assert_tangents_outward(&p);
    /* 60 degrees from the normal along +x: the footprint is twice as long along u (the ray's projection) as
     * across it, along v */
    assert_true(probe_cast(&p, gvec3(-3, 5, 2), gvec3(sin(M_PI / 3), -cos(M_PI / 3), 0), NULL));
    assert_near(fabs(p.sp.uv_axis1[0]), p.sp.footprint, 1e-12);
    assert_near(p.sp.uv_axis1[1], 0.0, 1e-12);
    assert_near(p.sp.uv_axis2[0], 0.0, 1e-12);
    assert_near(fabs(p.sp.uv_axis2[1]), 0.5 * p.sp.footprint, 1e-12);
    double wu, wv;
    gsurfpoint_uv_widths(&p.sp, &wu, &wv);
    assert_near(wu, p.sp.footprint, 1e-12);
    assert_near(wv, 0.5 * p.sp.footprint, 1e-12);
    /* an open cylinder seen from above: the ray enters and meets the inside of the wall */
    probe_close(&p);
    probe_open(&p);
    c = object_new(SHAPE_CYLINDER, NULL);
    assert_int_equal(object_cylinder(c, gvec3(0, 0, 0), gvec3(0, 2, 0), 0.5, 1, &err), G_OK);
    c->material = lambert(p.scene, 0.5);
    assert_int_equal(scene_add_object(p.scene, c, &err), G_OK);
    assert_true(probe_cast(&p, gvec3(0, 3, 0), gvec3(1, -2, 0), NULL));
    assert_int_equal(p.sp.entering, 0);
    assert_vec(p.sp.geometric_normal, gvec3(-1, 0, 0), 1e-12);
    probe_close(&p);
}

static char *write_temp(const char *name, const char *text)
{
    static char path[4][256];
    static int k;
    char *p = path[k++ % 4];
    snprintf(p, sizeof path[0], "/tmp/gtrace_test_%d_%s", (int)getpid(), name);
    FILE *f = fopen(p, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
    return p;
}

static void test_obj_mesh(void **state)
{
    (void)state;
    /* a unit quad in z = 0 split in two triangles (one quad face), normals tilted towards +x at x = 1 */
    const char *obj = "# quad\n"
                      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                      "vt 0 0\nvt 2 0\nvt 2 2\nvt 0 2\n"
                      "vn 0 0 1\nvn 0.6 0 0.8\n"
                      "usemtl a\n"
                      "f 1/1/1 2/2/2 3/3/2 4/4/1\n"
                      "usemtl b\n"
                      "f -4 -2 -1\n";
    char *path = write_temp("quad.obj", obj);
    Probe p;
    probe_open(&p);
    GError err;
    Object *o = object_new(SHAPE_MESH, NULL);
    o->material = lambert(p.scene, 0.5);
    if (object_mesh_load(o, path, &err) != G_OK)
        fail_msg("%s", err.message);
    assert_int_equal(o->mesh->ntris, 3);
    o->has_xf = 1;
    assert_int_equal(xform_translate(&o->xf, gvec3(0, 0, -1)), G_OK);
    assert_int_equal(scene_add_object(p.scene, o, &err), G_OK);
    assert_true(probe_cast(&p, gvec3(0.75, 0.25, 5), gvec3(0, 0, -1), NULL));
    assert_vec(p.sp.point, gvec3(0.75, 0.25, -1), 1e-6);
    assert_vec(p.sp.object_point, gvec3(0.75, 0.25, 0), 1e-6);
    assert_near(p.sp.u, 1.5, 1e-6);
    assert_near(p.sp.v, 0.5, 1e-6);
    assert_near(gvec3_length(p.sp.dpdu), 0.5, 1e-9); /* u runs twice as fast as x */
    assert_tangents_outward(&p);
    assert_vec(p.facing, gvec3(0, 0, 1), 1e-12);
    /* the interpolated normal leans towards +x */
    assert_true(p.sp.geometric_normal.x > 0.2 && p.sp.geometric_normal.z > 0.8);
    assert_int_equal(p.sp.surface, 0);
    probe_close(&p);
    unlink(path);

    /* errors name the file, line and column */
    path = write_temp("bad.obj", "v 0 0 0\nv 1 0 0\nf 1 2 7\n");
    o = object_new(SHAPE_MESH, NULL);
    assert_int_not_equal(object_mesh_load(o, path, &err), G_OK);
    print_message("%s\n", err.message);
    assert_non_null(strstr(err.message, "bad.obj:3:7: index out of range"));
    object_free(o);
    unlink(path);
}

/* ---- the scene text format ---- */

static Scene *load_text(const char *text, const char *model, GError *err)
{
    assert_int_equal(gtrace_register_types(err), G_OK);
    char *path = write_temp("scene.scene", text);
    Scene *s = NULL;
    int rc = scene_load(path, model, &s, err);
    unlink(path);
    return rc == G_OK ? s : NULL;
}

static void test_scene_file(void **state)
{
    (void)state;
    char *objpath = write_temp("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    char text[4096];
    snprintf(text, sizeof text,
             "colormodel spectrum9\n"
             "material grey lambert { reflectance rgb 0.5 0.5 0.5 }\n"
             "camera pinhole { from <0, 1, 5> at <0, 1, 0> fov 35 width 64 height 48 spp 4 depth 3 exposure 1 }\n"
             "object ball sphere { center <0, 1, 0> radius 0.5 material grey\n"
             "                     transform { scale 2 translate <1, 0, 0> } }\n"
             "object plane { point <0, 0, 0> normal <0, 1, 0> material lambert { reflectance rgb 0.2 0.2 0.2 } }\n"
             "object box { min <-1,-1,-1> max <1,1,1> material grey transform { rotate <0, 45, 0> } }\n"
             "object disc { center <3,0,0> normal <0,1,0> radius 0.5 material grey }\n"
             "object cylinder { base <0,0,0> top <0,1,0> radius 0.1 open true material grey }\n"
             "object mesh { file \"%s\" material grey }\n"
             "light point { position <0, 5, 0> intensity rgb 10 10 10 }\n"
             "light directional { direction <0, -1, 0> irradiance rgb 1 1 1 }\n"
             "light spot { position <0, 5, 0> at <0, 0, 0> intensity rgb 5 5 5 inner 20 outer 30 }\n"
             "light sphere { center <2, 4, 0> radius 0.3 radiance rgb 3 3 3 samples 9 }\n"
             "light rectangle { corner <0, 4, 0> edge1 <1, 0, 0> edge2 <0, 0, 1> radiance rgb 2 2 2 }\n"
             "light ambient { color rgb 0.1 0.1 0.1 }\n"
             "light background { color rgb 0.2 0.3 0.4 }\n",
             objpath);
    GError err;
    Scene *s = load_text(text, NULL, &err);
    if (!s)
        fail_msg("%s", err.message);
    unlink(objpath);
    assert_string_equal(gcolormodel_name(s->model), "spectrum9");
    assert_int_equal(s->nobjects, 6);
    assert_int_equal(s->nlights, 5);
    assert_int_equal(s->objects[0]->kind, SHAPE_SPHERE);
    assert_int_equal(s->objects[5]->kind, SHAPE_MESH);
    assert_int_equal(s->objects[4]->open, 1);
    assert_int_equal(s->camera.width, 64);
    assert_int_equal(s->camera.spp, 4);
    assert_int_equal(s->camera.depth, 3);
    assert_near(s->camera.exposure, 1.0, 0);
    assert_true(s->have_ambient);
    assert_near(gcolor_brightness(&s->ambient), 0.1, 0.002);
    double bg[3];
    assert_int_equal(gcolor_to_rgb(&s->background, GCOLOR_LIGHT, bg), G_OK);
    assert_near(bg[2], 0.4, 0.01);
    assert_near(s->lights[2]->cos_outer, cos(15 * M_PI / 180), 1e-12);
    assert_int_equal(s->lights[3]->samples, 9);
    /* the transform scaled the sphere by 2 about the origin and moved it: centre (1, 2, 0), radius 1 */
    const Object *o = s->objects[0];
    assert_vec(xform_point(&o->xf, o->center), gvec3(1, 2, 0), 1e-12);
    assert_near(gvec3_length(xform_vector(&o->xf, gvec3(o->radius, 0, 0))), 1.0, 1e-12);
    scene_destroy(s);

    /* --colormodel overrides the file's model */
    s = load_text("colormodel spectrum9\nmaterial g lambert { reflectance rgb 0.5 0.5 0.5 }\n"
                  "object sphere { material g }\n",
                  "spectrum", &err);
    if (!s)
        fail_msg("%s", err.message);
    assert_string_equal(gcolormodel_name(s->model), "spectrum");
    assert_int_equal(s->objects[0]->kind, SHAPE_SPHERE);
    assert_near(s->objects[0]->radius, 1.0, 0);
    scene_destroy(s);
}

static void expect_error(const char *text, const char *what)
{
    GError err;
    gerror_clear(&err);
    Scene *s = load_text(text, NULL, &err);
    assert_null(s);
    print_message("%s\n", err.message);
    if (!strstr(err.message, what))
        fail_msg("expected '%s' in '%s'", what, err.message);
}

static void test_scene_errors(void **state)
{
    (void)state;
    expect_error("material g lambert { reflectance rgb 0.5 0.5 0.5 }\nobject sphere { material g radus 2 }\n",
                 "scene.scene:2:28:");
    expect_error("object sphere { radius 2 }\n", "needs a material");
    expect_error("material g lambert { }\nobject teapot { material g }\n", "scene.scene:2:8:");
    expect_error("material g lambert { }\nobject sphere { material g radius -1 }\n", "scene.scene:2:35:");
    expect_error("material g lambert { }\nobject box { min <1,1,1> max <0,0,0> material g }\n", "box:");
    expect_error("light point { position <0,0,0> }\n", "needs its intensity");
    expect_error("light spot { position <0,0,0> intensity rgb 1 1 1 }\n", "needs `at`");
    expect_error("camera pinhole { }\ncamera pinhole { }\n", "2 cameras");
    expect_error("material g lambert { }\nobject sphere { material g transform { scale 0 } }\n", "singular");
    expect_error("material g lambert { }\nobject mesh { material g file \"/nonexistent.obj\" }\n",
                 "cannot open \"/nonexistent.obj\": No such file");
}

/* ---- output files read back equal what was written ---- */

static void test_output_roundtrip(void **state)
{
    (void)state;
    Framebuffer fb = {.width = 5, .height = 4};
    fb.pixels = gmem_calloc(5 * 4 * 3, sizeof(float));
    for (int i = 0; i < 5 * 4 * 3; i++)
        fb.pixels[i] = (float)(0.013 * i * i) - 0.1f; /* negative, in range and above 1 */
    char exr[256], png[256], bad[256], missing[256];
    snprintf(exr, sizeof exr, "/tmp/gtrace_test_%d.exr", (int)getpid());
    snprintf(png, sizeof png, "/tmp/gtrace_test_%d.png", (int)getpid());
    snprintf(bad, sizeof bad, "/tmp/gtrace_test_%d.unknownformat", (int)getpid());
    snprintf(missing, sizeof missing, "/tmp/gtrace_no_such_dir_%d/out.png", (int)getpid());
    GError err;
    assert_int_equal(output_write(exr, &fb, 2.0, NULL, &err), G_OK); /* exposure is for display formats only */
    GImage img;
    assert_int_equal(gimage_read(exr, GIMAGE_READ_RGB, &img, &err), G_OK);
    assert_int_equal(img.width, 5);
    assert_int_equal(img.height, 4);
    for (int i = 0; i < 5 * 4 * 3; i++)
        assert_true(img.pixels[i] == fb.pixels[i]);
    gimage_free(&img);
    assert_int_equal(output_write(png, &fb, 1.0, NULL, &err), G_OK);
    assert_int_equal(gimage_read(png, GIMAGE_READ_RAW | GIMAGE_READ_RGB, &img, &err), G_OK);
    for (int i = 0; i < 5 * 4 * 3; i++) {
        double v = fmin(1.0, fmax(0.0, 2.0 * fb.pixels[i]));
        assert_near(img.pixels[i], gimage_srgb_encode(v), 0.5 / 255 + 1e-6);
    }
    gimage_free(&img);
    /* failures leave no file */
    assert_int_not_equal(output_write(bad, &fb, 0.0, NULL, &err), G_OK);
    assert_int_not_equal(access(bad, F_OK), 0);
    assert_int_not_equal(output_write(missing, &fb, 0.0, NULL, &err), G_OK);
    assert_int_not_equal(access(missing, F_OK), 0);
    unlink(exr);
    unlink(png);
    framebuffer_free(&fb);
}

/* ---- the tracer names no colour model and never reads colour samples ---- */

/* Adds the .c and .h files of dirpath/sub (sub "" for dirpath itself) to files as paths below dirpath; with
 * folders, also those of each folder in it (one level: the MPI module, dist/mpi/, is no part of the tracer). */
static void list_sources(const char *dirpath, const char *sub, int folders, char files[][256], int *nfiles, int cap)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dirpath, sub);
    DIR *dir = opendir(path);
    if (!dir)
        fail_msg("cannot open %s", path);
    struct dirent *de;
    while ((de = readdir(dir)) && *nfiles < cap) {
        size_t l = strlen(de->d_name);
        char entry[256];
        snprintf(entry, sizeof entry, "%s%s%.200s", sub, *sub ? "/" : "", de->d_name);
        if (l > 2 && l < 200 && de->d_name[l - 2] == '.' && (de->d_name[l - 1] == 'c' || de->d_name[l - 1] == 'h'))
            snprintf(files[(*nfiles)++], 256, "%s", entry);
        else if (folders && de->d_name[0] != '.') {
            char sub_path[1280];
            struct stat st;
            snprintf(sub_path, sizeof sub_path, "%s/%s", dirpath, entry);
            if (stat(sub_path, &st) == 0 && S_ISDIR(st.st_mode))
                list_sources(dirpath, entry, 0, files, nfiles, cap);
        }
    }
    closedir(dir);
}

/* 1 when the include line names one of the tracer's own headers: "folder/name.h" below the tracer's directory, or
 * "name.h" beside the file that includes it. */
static int own_header(const char *line, const char *file, char files[][256], int nfiles)
{
    const char *slash = strrchr(file, '/');
    size_t dir = slash ? (size_t)(slash - file) + 1 : 0;
    for (int g = 0; g < nfiles; g++) {
        if (files[g][strlen(files[g]) - 1] != 'h')
            continue;
        char own[264];
        snprintf(own, sizeof own, "\"%.255s\"", files[g]);
        if (strstr(line, own))
            return 1;
        if (strncmp(files[g], file, dir) == 0 && !strchr(files[g] + dir, '/')) {
            snprintf(own, sizeof own, "\"%.255s\"", files[g] + dir);
            if (strstr(line, own))
                return 1;
        }
    }
    return 0;
}

static void test_sources_are_model_free(void **state)
{
    (void)state;
    const char *root = getenv("GENERIC_SOURCE_DIR");
    if (!root)
        root = ".";
    /* every .c and .h of the tracer */
    char dirpath[1024];
    snprintf(dirpath, sizeof dirpath, "%s/examples/gtrace", root);
    static char files[128][256];
    int nfiles = 0;
    list_sources(dirpath, "", 1, files, &nfiles, 128);
    assert_true(nfiles >= 40);
    /* allowed spellings: the XYZ -> display conversion, the name of the display encoding and the option that
     * asks for the values at the model's wavelengths (it names no model: they come through gcolor_at_wavelengths) */
    const char *allowed[] = {"gcie_xyz_to_rgb", "sRGB", "--spectral", "\"spectral\""};
    /* colour model names, the rgb conversions, sample access, the nm exchange and the models' sizes */
    const char *forbidden[] = {"rgb", "spectrum", "spectral", ".v[", "->v[", "_nm", "nsamples",
                               "nvalues", "capacity", "lambda", "gcolor_wrap", "cls->"};
    int checked = 0;
    for (int f = 0; f < nfiles; f++) {
        char path[2048];
        snprintf(path, sizeof path, "%.1023s/%.255s", dirpath, files[f]);
        FILE *fp = fopen(path, "r");
        if (!fp)
            fail_msg("cannot read %s", path);
        char line[1024];
        int ln = 0;
        while (fgets(line, sizeof line, fp)) {
            ln++;
            for (size_t a = 0; a < sizeof allowed / sizeof *allowed; a++)
                for (char *p = strstr(line, allowed[a]); p; p = strstr(p, allowed[a]))
                    memset(p, ' ', strlen(allowed[a]));
            char low[1024];
            for (size_t i = 0; i < sizeof low && (low[i] = (char)tolower((unsigned char)line[i])); i++)
                ;
            for (size_t k = 0; k < sizeof forbidden / sizeof *forbidden; k++)
                if (strstr(low, forbidden[k]))
                    fail_msg("%s:%d: the tracer must not use '%s': %s", files[f], ln, forbidden[k], line);
            /* includes: only the generic interfaces, Embree, OpenMP, the C library, SSE2 (x86-64's baseline: the
             * direct list's box tests), its own headers, the command-line conventions all tools share
             * (examples/common/cli.h, libc only; examples/common/startup.h, on the public headers: the memory limit
             * option) and the reference page of the registered types
             * (examples/common/type_doc.h, on the public registry); libdl for the MPI module's loader; posix_spawn
             * and its companions for the OpenVDB reader's process (media/grid_load.c) */
            if (strncmp(line, "#include", 8) == 0) {
                const char *ok[] = {"<generic/", "<embree3/", "<assimp/", "<omp.h>", "<math.h>", "<stdio.h>",
                                    "<stdlib.h>", "<string.h>", "<strings.h>", "<errno.h>", "<stdint.h>", "<time.h>",
                                    "<unistd.h>", "<stdarg.h>", "<stddef.h>", "<limits.h>", "<signal.h>", "<dlfcn.h>",
                                    "<emmintrin.h>", "<spawn.h>", "<sys/wait.h>", "<sys/stat.h>", "<fcntl.h>",
                                    "<poll.h>", "<pthread.h>", "<sys/socket.h>",
                                    "\"../common/cli.h\"", "\"../../common/cli.h\"",
                                    "\"../../common/type_doc.h\"", "\"../common/startup.h\""};
                int good = own_header(line, files[f], files, nfiles);
                for (size_t i = 0; i < sizeof ok / sizeof *ok; i++)
                    good |= strstr(line, ok[i]) != NULL;
                if (!good)
                    fail_msg("%s:%d: include outside the generic interfaces: %s", files[f], ln, line);
                /* only mpi_load.c opens a module (gtrace_mpi.so), and MPI itself stays in that module;
                 * mesh_assimp_lib.c loads assimp on the first mesh it reads (a reader program is found by the
                 * library's gspawn_find) */
                if (strstr(line, "<dlfcn.h>") && strcmp(files[f], "distributed/mpi_load.c") != 0 &&
                    strcmp(files[f], "geometry/mesh_assimp_lib.c") != 0)
                    fail_msg("%s:%d: only mpi_load.c and mesh_assimp_lib.c open libraries: %s", files[f], ln, line);
                /* only the clients of the two readers in processes of their own start a process: grid_load.c (the
                 * OpenVDB reader gtrace-vdb) and mesh_isolated.c (the mesh reader gtrace-mesh) */
                if ((strstr(line, "<spawn.h>") || strstr(line, "<sys/wait.h>") || strstr(line, "<fcntl.h>") ||
                     strstr(line, "<poll.h>") || strstr(line, "<sys/socket.h>")) &&
                    strcmp(files[f], "media/grid_load.c") != 0 && strcmp(files[f], "geometry/mesh_isolated.c") != 0)
                    fail_msg("%s:%d: only grid_load.c and mesh_isolated.c start processes: %s", files[f], ln, line);
                /* Embree stays behind the acceleration structure */
                if (strstr(line, "<embree3/") && strcmp(files[f], "scene/accel.c") != 0)
                    fail_msg("%s:%d: only accel.c includes Embree: %s", files[f], ln, line);
                /* and assimp behind the PLY/glTF reader and its file system */
                if (strstr(line, "<assimp/") && strncmp(files[f], "geometry/mesh_assimp", 20) != 0)
                    fail_msg("%s:%d: only mesh_assimp.c and mesh_assimp_io.c include assimp: %s", files[f], ln, line);
            }
            checked++;
        }
        fclose(fp);
    }
    print_message("%d lines in %d files of the tracer checked\n", checked, nfiles);
    assert_true(checked > 1000);
}

/* ---- allocation failures: loading and rendering fail cleanly at every allocation ---- */

static void test_allocation_failures(void **state)
{
    (void)state;
    GError err;
    assert_int_equal(gtrace_register_types(&err), G_OK);
    char *path = write_temp("alloc.scene",
                            "material g lambert { reflectance rgb 0.5 0.5 0.5 }\n"
                            "material glass dielectric { index 1.5 }\n"
                            "camera pinhole { from <0, 1, 4> at <0, 0.5, 0> width 8 height 6 spp 2 depth 3 }\n"
                            "object plane { material g }\n"
                            "object sphere { center <0, 0.5, 0> radius 0.5 material glass }\n"
                            "light sphere { center <1, 3, 1> radius 0.2 radiance rgb 5 5 5 samples 4 }\n"
                            "light ambient { color rgb 0.1 0.1 0.1 }\n");
    static TuAlloc alloc;
    int failures = 0, k;
    for (k = 0; k < 5000; k++) {
        alloc = (TuAlloc){.fail_call = k + 1, .fail_after = 1}; /* k calls succeed */
        tu_alloc_install(&alloc);
        Scene *s = NULL;
        Framebuffer fb = {0};
        RenderStats st;
        int rc = scene_load(path, NULL, &s, &err);
        if (rc == G_OK)
            rc = accel_build(s, &err);
        if (rc == G_OK) {
            RenderSettings rs = {.width = 8, .height = 6, .spp = 2, .depth = 3, .threads = 2, .quiet = 1};
            rc = render_image(s, &rs, &fb, &st, &err);
            if (rc != G_OK)
                assert_null(fb.pixels); /* a failed render keeps no image */
        }
        framebuffer_free(&fb);
        scene_destroy(s);
        gmem_set_allocator(NULL);
        if (rc == G_OK)
            break;
        assert_true(rc < 0);
        failures++;
    }
    print_message("loading and rendering failed cleanly at each of the first %d allocations, then succeeded\n",
                  failures);
    assert_true(k < 5000 && failures > 10);
    unlink(path);
}

int main(void)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sphere_surface),       cmocka_unit_test(test_transformed_sphere),
        cmocka_unit_test(test_box_faces),            cmocka_unit_test(test_cylinder_disc_plane),
        cmocka_unit_test(test_obj_mesh),             cmocka_unit_test(test_scene_file),
        cmocka_unit_test(test_scene_errors),         cmocka_unit_test(test_output_roundtrip),
        cmocka_unit_test(test_sources_are_model_free), cmocka_unit_test(test_allocation_failures),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
