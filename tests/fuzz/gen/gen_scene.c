/* gen_scene.c - gtrace's scene files (examples/gtrace/scenefile/): many objects and lights, long transform chains,
 * groups with huge member lists and deep nesting, include chains and cycles and meshes that lie or are missing
 * (files of their own in the input, after "#@file NAME" lines: tests/fuzz/fuzz_scene_entry.h writes them into the
 * private directory), cameras asking for enormous images, samples and depths, and NaN, infinite and 1e308 numbers
 * where coordinates, radii and colours go. An input wrong by construction carries GEN_MUST_FAIL in a comment. */
#include "gen.h"

#include <stdio.h>

/* The harness's mark of a file of the input (GFUZZ_SCENE_MARK) and its most files (GFUZZ_SCENE_MAX_FILES). */
#define SCENE_FILE "#@file "
#define SCENE_MAX_FILES 100
/* The reader's nesting limit (GREADER_DEFAULT_MAX_DEPTH) and gtrace's of groups (GTRACE_MAX_NESTING). */
#define READER_MAX_DEPTH 64
#define GROUP_MAX_NESTING 64

static const char *const g_mats[] = {"lambert", "mirror", "lambert { reflectance rgb 0.2 0.5 0.7 }",
                                     "dielectric { index 1.5 }", "phong { exponent 40 }", "emitter",
                                     "plastic { roughness 0.2 }", "base", "checked", "shiny"};
static const char *const g_extremes[] = {"nan", "inf", "-inf", "1e308", "-1e308", "1.7976931348623157e308",
                                         "4.9e-324", "1e-320", "1e16", "-1e16"};

/* numbers an OBJ reader reads but no mesh may reach (the scene's coordinate limit is 1e15) */
static const char *const g_far[] = {"inf", "-inf", "1e308", "-1e308", "1e16", "1.7976931348623157e308"};

/* The largest scene written: a 1 MiB scene is some 10^4 entries, which the scene target loads (a second time when
 * libFuzzer's leak check repeats the input) in about two seconds under the sanitizers; larger files only repeat the
 * reader's own work, which the reader target fuzzes at the full budget. */
#define SCENE_MAX_BYTES ((size_t)1 << 20)

static size_t cap(size_t budget) { return budget < SCENE_MAX_BYTES ? budget : SCENE_MAX_BYTES; }

static double small(GenRng *r) { return gen_unit(r) * 4.0 - 2.0; }

static void must_fail(GenBuf *b) { gb_printf(b, "# %s\n", GEN_MUST_FAIL); }

/* One ordinary object of any shape (never a mesh: those have their own families). */
static void object(GenBuf *b, GenRng *r, unsigned long i)
{
    const char *m = GEN_PICK(r, g_mats);
    switch (gen_below(r, 8)) {
    case 0:
        gb_printf(b, "object o%lu sphere { center <%.3g, %.3g, %.3g> radius %.3g material %s }\n", i, small(r),
                  small(r), small(r), 0.01 + gen_unit(r), m);
        break;
    case 1:
        gb_printf(b, "object o%lu box { min <%.3g, %.3g, %.3g> max <3, 3, 3> material %s }\n", i, small(r), small(r),
                  small(r), m);
        break;
    case 2:
        gb_printf(b, "object o%lu disc { center <%.3g, 0, 0> normal <0, 1, %.3g> radius 0.5 material %s }\n", i,
                  small(r), small(r), m);
        break;
    case 3:
        gb_printf(b, "object o%lu cylinder { base <%.3g, 0, 0> top <0, 1, 0> radius 0.2 open %s material %s }\n", i,
                  small(r), gen_below(r, 2) ? "yes" : "no", m);
        break;
    case 4:
        gb_printf(b, "object o%lu quad { corner <%.3g, 0, 0> edge1 <1, 0, 0> edge2 <0, 1, %.3g> material %s }\n", i,
                  small(r), small(r), m);
        break;
    case 5:
        gb_printf(b, "object o%lu triangle { a <%.3g, -1, 0> b <1, 0, 0> c <0, 1, %.3g> material %s }\n", i,
                  small(r), small(r), m);
        break;
    case 6:
        gb_printf(b, "object o%lu plane { point <0, %.3g, 0> normal <0, 1, 0> material %s }\n", i, small(r), m);
        break;
    default:
        gb_printf(b, "object o%lu sphere { radius 0.3 material %s transform { translate <%.3g, %.3g, 0> } }\n", i, m,
                  small(r), small(r));
    }
}

static void camera(GenBuf *b, GenRng *r)
{
    static const char *const kinds[] = {"pinhole", "thinlens { aperture 0.1 focus_distance 4", "orthographic"};
    int k = (int)gen_below(r, 3);
    gb_printf(b, "camera %s%s from <0, 1, 6> at <0, 0, 0> width %d height %d depth %d%s }\n",
              k == 1 ? "" : kinds[k], k == 1 ? kinds[1] : " {", 8 + (int)gen_below(r, 64), 6 + (int)gen_below(r, 48),
              (int)gen_below(r, 6), gen_below(r, 4) == 0 ? " frame 0.1" : "");
}

static void key_light(GenBuf *b) { gb_printf(b, "light point { position <3, 4, 5> intensity rgb 30 30 30 }\n"); }

/* ---- many objects and lights ---- */

static void many_objects(GenBuf *b, GenRng *r, size_t budget)
{
    budget = cap(budget);
    gb_printf(b, "include \"common.mat\"\n");
    camera(b, r);
    key_light(b);
    for (unsigned long i = 0; b->n + 200 < budget; i++)
        object(b, r, i);
}

static void many_lights(GenBuf *b, GenRng *r, size_t budget)
{
    budget = cap(budget);
    gb_printf(b, "include \"common.mat\"\n");
    camera(b, r);
    gb_printf(b, "object floor plane { point <0, -1, 0> normal <0, 1, 0> material base }\n"
                 "object ball sphere { radius 0.5 material shiny }\n");
    for (unsigned long i = 0; b->n + 200 < budget; i++) {
        switch (gen_below(r, 7)) {
        case 0:
            gb_printf(b, "light point { position <%.3g, 3, %.3g> intensity rgb 1 2 3 }\n", small(r), small(r));
            break;
        case 1:
            gb_printf(b, "light spot { position <%.3g, 3, 0> at <0, 0, 0> intensity rgb 5 5 5 inner %d outer %d }\n",
                      small(r), (int)gen_below(r, 90), 90 + (int)gen_below(r, 90));
            break;
        case 2:
            gb_printf(b, "light sphere { center <%.3g, 3, 0> radius 0.2 radiance rgb 4 4 4 samples %d }\n", small(r),
                      1 + (int)gen_below(r, 256));
            break;
        case 3:
            gb_printf(b, "light rectangle { corner <%.3g, 3, 0> edge1 <1, 0, 0> edge2 <0, 0, 1> radiance rgb 2 2 2 "
                         "samples %d visible yes }\n", small(r), 1 + (int)gen_below(r, 256));
            break;
        case 4:
            gb_printf(b, "light directional { direction <%.3g, -1, 0.2> irradiance rgb 0.5 0.5 0.5 }\n", small(r));
            break;
        case 5:
            gb_printf(b, "light ies { file \"lamp.ies\" position <%.3g, 3, 0> color rgb 1 1 1 scale 0.01 }\n",
                      small(r));
            break;
        default:
            gb_printf(b, "light ambient { color rgb 0.01 0.01 0.01 }\n");
        }
    }
}

/* ---- transforms, groups and instances ---- */

static void transform_chain(GenBuf *b, GenRng *r, size_t budget)
{
    budget = cap(budget);
    int singular = gen_below(r, 3) == 0;
    if (singular)
        must_fail(b);
    gb_printf(b, "include \"common.mat\"\n");
    camera(b, r);
    key_light(b);
    gb_printf(b, "object chained sphere { radius 0.5 material base transform {");
    size_t singular_at = singular ? (size_t)gen_below(r, budget / 2) : (size_t)-1;
    while (b->n + 100 < budget) {
        if (b->n >= singular_at) {
            gb_printf(b, " scale 0");
            singular_at = (size_t)-1;
            continue;
        }
        switch (gen_below(r, 5)) {
        case 0: gb_printf(b, " translate <%.3g, %.3g, %.3g>", small(r) * 1e-3, small(r) * 1e-3, 0.0); break;
        case 1: gb_printf(b, " rotate <%.3g, %.3g, %.3g>", small(r) * 90, small(r) * 90, small(r) * 90); break;
        case 2: gb_printf(b, " rotate_axis <%.3g, 1, %.3g> %.3g", small(r), small(r), small(r) * 180); break;
        case 3: gb_printf(b, " scale %.6g", 1.0 + small(r) * 1e-3); break;
        default: gb_printf(b, " scale %.6g %.6g %.6g", 1.0 + small(r) * 1e-3, 1.0, 1.0 - small(r) * 1e-3);
        }
    }
    gb_printf(b, " } }\n");
}

/* A group with as many members as the budget holds (an operand list), placed by instances. */
static void wide_group(GenBuf *b, GenRng *r, size_t budget)
{
    budget = cap(budget);
    gb_printf(b, "include \"common.mat\"\n");
    camera(b, r);
    key_light(b);
    gb_printf(b, "object g group {");
    while (b->n + 200 < budget)
        gb_printf(b, " sphere { center <%.3g, %.3g, %.3g> radius 0.05 material %s }", small(r), small(r), small(r),
                  GEN_PICK(r, g_mats));
    gb_printf(b, " transform { scale 0.5 } }\nobject instance { of g transform { translate <1, 0, 0> } }\n");
}

/* Groups nested in groups: within gtrace's limit, or past it (refused); instances of instances whose placements
 * multiply past GTRACE_MAX_INSTANCES (refused). */
static void deep_groups(GenBuf *b, GenRng *r, size_t budget)
{
    (void)budget;
    gb_printf(b, "include \"common.mat\"\n");
    camera(b, r);
    key_light(b);
    int depth = 1 + (int)gen_below(r, 2 * GROUP_MAX_NESTING), fan = gen_below(r, 2) ? 1 : 2 + (int)gen_below(r, 3);
    double placements = 1.0;
    for (int k = 0; k < depth; k++)
        placements *= fan;
    if (depth > GROUP_MAX_NESTING || placements > 100000.0)
        must_fail(b);
    gb_printf(b, "object g0 sphere { radius 0.1 material base }\n");
    for (int k = 1; k <= depth; k++) {
        gb_printf(b, "object g%d group {", k);
        for (int j = 0; j < fan; j++)
            gb_printf(b, " instance { of g%d transform { translate <%.3g, 0, 0> } }", k - 1, 0.1 * j);
        gb_printf(b, " }\n");
    }
    gb_printf(b, "object instance { of g%d }\n", depth);
}

/* ---- files of the input: includes and meshes ---- */

/* A chain of includes of files of the input; past the reader's nesting limit, or closed into a cycle, refused. */
static void include_chain(GenBuf *b, GenRng *r, size_t budget)
{
    budget = cap(budget);
    int n = 1 + (int)gen_below(r, SCENE_MAX_FILES - 1), cycle = gen_below(r, 4) == 0;
    if (n > READER_MAX_DEPTH + 1 || cycle) /* (the limit counts the outer file's levels too: a margin of one) */
        must_fail(b);
    gb_printf(b, "include \"common.mat\"\n");
    camera(b, r);
    gb_printf(b, "include \"inc0.scene\"\n");
    size_t per = budget / (size_t)(n + 1);
    for (int k = 0; k < n; k++) {
        gb_printf(b, "\n" SCENE_FILE "inc%d.scene\n", k);
        size_t start = b->n;
        for (unsigned long i = 0; b->n - start + 200 < per; i++)
            object(b, r, (unsigned long)k * 1000000ul + i);
        if (k + 1 < n)
            gb_printf(b, "include \"inc%d.scene\"\n", k + 1);
        else if (cycle)
            gb_printf(b, "include \"inc%d.scene\"\n", (int)gen_below(r, (uint64_t)n));
        else
            key_light(b);
    }
}

/* A mesh named by the scene: missing, an OBJ of the input that lies (indices out of range, NaN, huge numbers, a
 * face of one vertex: refused), or a large honest one; some vertices carry the optional weight (v x y z w). */
static void lying_mesh(GenBuf *b, GenRng *r, size_t budget)
{
    budget = cap(budget);
    int form = (int)gen_below(r, 6);
    if (form != 5)
        must_fail(b);
    gb_printf(b, "include \"common.mat\"\n");
    camera(b, r);
    key_light(b);
    gb_printf(b, "object m mesh { file \"%s\" material base transform { scale 0.5 } }\n",
              form == 0 ? "missing.obj" : "lies.obj");
    if (form == 0)
        return;
    gb_printf(b, SCENE_FILE "lies.obj\n");
    unsigned long nv = 0;
    while (b->n + 200 < budget) {
        if (nv < 3 || gen_below(r, 3) == 0) {
            gb_printf(b, "v %.4g %.4g %.4g", small(r), small(r), small(r));
            if (gen_below(r, 4) == 0) /* the optional weight */
                gb_printf(b, " %.3g", gen_unit(r));
            gb_printf(b, "\n");
            nv++;
        } else {
            gb_printf(b, "f %lu %lu %lu\n", 1 + gen_below(r, nv), 1 + gen_below(r, nv), 1 + gen_below(r, nv));
        }
    }
    switch (form) {
    case 1: gb_printf(b, "f 1 2 %lu\n", nv + 1 + gen_below(r, 1000000000)); break;
    case 2: gb_printf(b, "v nan 0 0\n"); break;
    case 3: gb_printf(b, "v %s 1 1\nf 1 2 %lu\n", GEN_PICK(r, g_far), nv + 1); break;
    case 4: gb_printf(b, "f 1\n"); break;
    default: gb_printf(b, "f 1 2 3\n");
    }
}

/* ---- numbers ---- */

/* A camera asking for enormous images, samples or depths: past the bounds (refused at the number), or within them
 * (loaded; the full framebuffer must then be refused by the memory budget, not allocated). */
static void huge_camera(GenBuf *b, GenRng *r, size_t budget)
{
    budget = cap(budget);
    static const char *const keys[] = {"width", "height", "spp", "depth", "bands"};
    static const char *const over[] = {"1000000000", "65537", "2147483648", "1e308", "-1", "nan"};
    int past = (int)gen_below(r, 2);
    if (past)
        must_fail(b);
    gb_printf(b, "include \"common.mat\"\nobject ball sphere { radius 1 material base }\n");
    key_light(b);
    gb_printf(b, "camera pinhole { from <0, 0, 5> at <0, 0, 0>");
    if (past)
        gb_printf(b, " %s %s", GEN_PICK(r, keys), GEN_PICK(r, over));
    else
        gb_printf(b, " width %d height %d spp %d depth %d", 65536 >> gen_below(r, 4), 65536 >> gen_below(r, 4),
                  65536 >> gen_below(r, 16), 1000 >> gen_below(r, 10));
    gb_printf(b, " }\n");
    /* a quarter of the budget in objects, so that the big numbers come with a scene to render */
    for (unsigned long i = 0; b->n + 200 < budget / 4; i++)
        object(b, r, i);
}

/* One entry whose coordinate, radius, colour or translation is NaN, infinite or extreme, after ordinary entries:
 * refused every time (the scene's coordinate limit, the parameters' ranges, finite colours). */
static void extreme_numbers(GenBuf *b, GenRng *r, size_t budget)
{
    (void)budget;
    must_fail(b);
    gb_printf(b, "include \"common.mat\"\n");
    camera(b, r);
    key_light(b);
    unsigned long n = 1 + gen_below(r, 200);
    for (unsigned long i = 0; i < n; i++)
        object(b, r, i);
    int k = (int)gen_below(r, sizeof g_extremes / sizeof g_extremes[0]);
    const char *x = g_extremes[k];
    int tiny = k == 6 || k == 7, nonfinite = k < 3;
    switch (tiny ? 0 : gen_below(r, nonfinite ? 6 : 5)) {
    case 0: gb_printf(b, "object bad sphere { radius %s material base }\n", x); break;
    case 1: gb_printf(b, "object bad sphere { center <%s, 0, 0> material base }\n", x); break;
    case 2: gb_printf(b, "object bad box { min <0, 0, 0> max <1, %s, 1> material base }\n", x); break;
    case 3: gb_printf(b, "light point { position <0, %s, 0> intensity rgb 1 1 1 }\n", x); break;
    case 4: gb_printf(b, "object bad sphere { material base transform { translate <%s, 0, 0> } }\n", x); break;
    default: gb_printf(b, "light point { position <0, 1, 0> intensity rgb 1 %s 1 }\n", x);
    }
}

const GenFamily gen_scene_families[] = {
    {"many-objects", ".scene", many_objects},     {"many-lights", ".scene", many_lights},
    {"transform-chain", ".scene", transform_chain}, {"wide-group", ".scene", wide_group},
    {"deep-groups", ".scene", deep_groups},       {"include-chain", ".scene", include_chain},
    {"lying-mesh", ".scene", lying_mesh},         {"huge-camera", ".scene", huge_camera},
    {"extreme-numbers", ".scene", extreme_numbers},
};
const int gen_scene_count = (int)(sizeof gen_scene_families / sizeof gen_scene_families[0]);
