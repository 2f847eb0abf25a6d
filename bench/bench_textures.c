/* bench_textures.c - shading evaluations per second of a deep texture tree against its leaf material
 * alone, in the same run, and the cost of single nodes. One evaluation is what a Whitted tracer asks of a
 * surface point: the shading normal, reflection for two lights and the ambient term.
 *
 * The deep tree: bump (fbm height) over a spline of three children driven by marble, whose first child
 * is an interpolate of a lambert and an image node by a checker (the image node is left out when
 * examples/textures/picture.png cannot be found). Usage: bench_textures [colour model] (default rgb). */
#include <generic/materials.h>
#include <generic/textures.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "generic/builtins.h"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t); /* CPU time: other processes do not count */
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static double sink;

/* Evaluations per second of m over a grid of points for at least `seconds`. */
static double rate(const GMaterial *m, const GColorModel *model, GScratch *s, double seconds)
{
    GColor illum, c;
    gcolor_alloc(&illum, model);
    gcolor_alloc(&c, model);
    gcolor_from_rgb(&illum, (double[3]){1, 1, 1}, GCOLOR_LIGHT);
    GVec3 l1 = gvec3_normalize(gvec3(0.3, 0.2, 1)), l2 = gvec3_normalize(gvec3(-0.5, 0.1, 0.8)), out = gvec3(0, 0, 1);
    long n = 0;
    double t0 = now(), t;
    do {
        for (int i = 0; i < 4096; i++, n++) {
            GSurfPoint sp;
            gsurfpoint_init(&sp, model, s);
            sp.u = (n % 1024) / 1024.0;
            sp.v = ((n / 1024) % 1024) / 1024.0;
            sp.point = sp.object_point = gvec3(sp.u, sp.v, 0.0);
            sp.geometric_normal = gvec3(0, 0, 1);
            sp.dpdu = gvec3(1, 0, 0);
            sp.dpdv = gvec3(0, 1, 0);
            sp.uv_footprint = 1.0 / 1024;
            sp.footprint = 1.0 / 1024;
            sp.material = m;
            GScratchMark mark = gscratch_mark(s);
            GVec3 nrm = gsurfpoint_normal(&sp);
            gmaterial_reflection(m, &sp, l1, &illum, out, &c);
            sink += c.v[0];
            gmaterial_reflection(m, &sp, l2, &illum, out, &c);
            sink += c.v[0];
            gmaterial_ambient(m, &sp, &illum, &c);
            sink += c.v[0] + nrm.z;
            gscratch_release(s, mark);
        }
        t = now() - t0;
    } while (t < seconds);
    gcolor_free(&illum);
    gcolor_free(&c);
    return n / t;
}

static GMaterial *lambert(const GColorModel *m, double r, double g, double b)
{
    GColor c;
    GMaterial *out = NULL;
    GError err;
    gcolor_alloc(&c, m);
    gcolor_from_rgb(&c, (double[3]){r, g, b}, GCOLOR_REFLECTANCE);
    if (glambert_create(m, &c, &out, &err) != G_OK)
        fprintf(stderr, "%s\n", err.message);
    gcolor_free(&c);
    return out;
}

#define CHECK(x)                                                                                             \
    do {                                                                                                     \
        if ((x) != G_OK) {                                                                                   \
            fprintf(stderr, "%s\n", err.message);                                                            \
            return 1;                                                                                        \
        }                                                                                                    \
    } while (0)

int main(int argc, char **argv)
{
    if (generic_register_builtins(NULL) != G_OK)
        return 1;
    const char *model_name = argc > 1 ? argv[1] : "rgb";
    GError err;
    GColorModel *model;
    CHECK(gcolormodel_create(model_name, NULL, &model, &err));
    GScratch *s = gscratch_create(0);
    const double secs = 0.4;

    GMaterial *leaf = lambert(model, 0.6, 0.5, 0.4), *b = lambert(model, 0.8, 0.8, 0.75),
              *c = lambert(model, 0.3, 0.3, 0.35), *white = lambert(model, 0.9, 0.9, 0.9);
    GGenerator *chk, *marble, *fbm, *half, *zero;
    CHECK(ggenerator_checker_create(2, 8, &chk, &err));
    GNoiseParams np = {.frequency = 2, .octaves = 4};
    CHECK(ggenerator_marble_create(&np, 2, 2, &marble, &err));
    GNoiseParams bp = {.space = GGENERATOR_SPACE_UV, .frequency = 16, .octaves = 3};
    CHECK(ggenerator_fbm_create(&bp, &fbm, &err));
    CHECK(ggenerator_constant_create(0.5, &half, &err));
    CHECK(ggenerator_constant_create(0.0, &zero, &err));

    /* the image node, when the example picture is there */
    char path[1024];
    const char *src = getenv("GENERIC_SOURCE_DIR");
    snprintf(path, sizeof path, "%s/examples/textures/picture.png", src ? src : ".");
    GMaterial *img = NULL;
    GTextureSystem *ts;
    CHECK(gtexsys_create(&ts, &err));
    GImageNodeOptions io = {.texsys = ts};
    if (gnode_image_create(white, path, &io, &img, &err) != G_OK) {
        fprintf(stderr, "(no image node: %s)\n", err.message);
        img = gmaterial_ref(white);
    }

    GMaterial *inter, *spline, *tree;
    CHECK(gnode_interpolate_create(leaf, img, chk, &inter, &err));
    GMaterial *kids[3] = {inter, b, c};
    CHECK(gnode_spline_create(kids, 3, marble, GSPLINE_CATMULL_ROM, &spline, &err));
    CHECK(gnode_bump_create(spline, fbm, 0.01, &tree, &err));

    /* single nodes over the leaf */
    GMaterial *i_fast, *i_blend, *sc, *tr, *bump_lin, *imgnode = img;
    GGenerator *lin;
    CHECK(gnode_interpolate_create(leaf, b, zero, &i_fast, &err));
    CHECK(gnode_interpolate_create(leaf, b, half, &i_blend, &err));
    CHECK(gnode_scale_create(leaf, half, &sc, &err));
    GAffine2 rot = gaffine2_rotate(30);
    CHECK(gnode_transform_create(leaf, &rot, NULL, &tr, &err));
    /* a transform over a generator-driven subtree: its cost should stay the copy of the point, the subtree's
     * generator being evaluated once per point (cached in the transform's scope) */
    GMaterial *bands, *tr_bands, *kids3[3] = {leaf, b, c};
    CHECK(gnode_spline_create(kids3, 3, marble, GSPLINE_CATMULL_ROM, &bands, &err));
    CHECK(gnode_transform_create(bands, &rot, NULL, &tr_bands, &err));
    CHECK(ggenerator_gradient_create(GGENERATOR_SPACE_UV, gvec3(1, 0, 0), 0, &lin, &err));
    CHECK(gnode_bump_create(leaf, lin, 0.5, &bump_lin, &err));

    printf("texture trees, colour model %s, one evaluation = normal + 2 reflections + ambient\n", model_name);
    double r_leaf = rate(leaf, model, s, secs);
    double r_tree = rate(tree, model, s, secs);
    double r_leaf2 = rate(leaf, model, s, secs); /* again, to see the noise of the measurement */
    r_leaf = 0.5 * (r_leaf + r_leaf2);
    printf("  %-44s %12.0f /s  %8.1f ns\n", "leaf lambert alone", r_leaf, 1e9 / r_leaf);
    printf("  %-44s %12.0f /s  %8.1f ns\n", "deep tree (bump/spline/interpolate/image)", r_tree, 1e9 / r_tree);
    printf("  deep tree: %.1fx the leaf's time, %.1f ns over it: %.1f ns per node (4 nodes, 4 generators)\n",
           r_leaf / r_tree, 1e9 / r_tree - 1e9 / r_leaf, (1e9 / r_tree - 1e9 / r_leaf) / 4.0);

    struct {
        const char *name;
        const GMaterial *m;
    } single[] = {
        {"interpolate, t = 0 (one child)", i_fast},
        {"interpolate, t = 0.5 (two children)", i_blend},
        {"scale by a constant", sc},
        {"transform (2D rotation)", tr},
        {"bump (linear height field)", bump_lin},
        {"image over the leaf (MIP-mapped lookup)", imgnode},
    };
    printf("  single nodes over the leaf (overhead per evaluation):\n");
    for (size_t i = 0; i < sizeof single / sizeof single[0]; i++) {
        double r = rate(single[i].m, model, s, secs);
        printf("    %-42s %12.0f /s  %+8.1f ns\n", single[i].name, r, 1e9 / r - 1e9 / r_leaf);
    }
    double r_bands = rate(bands, model, s, secs), r_tr_bands = rate(tr_bands, model, s, secs);
    printf("  spline over marble alone %.1f ns; under a transform %.1f ns (%+.1f ns for the transform)\n",
           1e9 / r_bands, 1e9 / r_tr_bands, 1e9 / r_tr_bands - 1e9 / r_bands);

    gmaterial_unref(tree);
    gmaterial_unref(spline);
    gmaterial_unref(inter);
    gmaterial_unref(i_fast);
    gmaterial_unref(i_blend);
    gmaterial_unref(sc);
    gmaterial_unref(tr);
    gmaterial_unref(tr_bands);
    gmaterial_unref(bands);
    gmaterial_unref(bump_lin);
    gmaterial_unref(img);
    gmaterial_unref(leaf);
    gmaterial_unref(b);
    gmaterial_unref(c);
    gmaterial_unref(white);
    ggenerator_unref(chk);
    ggenerator_unref(marble);
    ggenerator_unref(fbm);
    ggenerator_unref(half);
    ggenerator_unref(zero);
    ggenerator_unref(lin);
    gtexsys_unref(ts);
    gscratch_destroy(s);
    gcolormodel_destroy(model);
    return sink == 12345.678 ? 2 : 0;
}
