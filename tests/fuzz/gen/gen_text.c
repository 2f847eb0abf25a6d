/* gen_text.c - structured inputs for the text format (docs/reference/format.md): each family builds a file that
 * is valid where it matters (so the reader gets past the first token) and extreme in one direction: size,
 * depth, sharing, numbers, token length or bytes. Names never contain '/' (the harness skips such inputs). */
#include "gen.h"

#include <stdio.h>
#include <string.h>

static const char *const g_mats[] = {"lambert", "mirror", "lambert { reflectance rgb 0.2 0.5 0.7 }",
                                     "phong { exponent 40 }", "dielectric { index 1.5 }", "emitter",
                                     "conductor { metal Au roughness 0.3 }",
                                     "thinfilm { thickness 400 base lambert }", "plastic { roughness 0.2 }",
                                     "layer { top dielectric { } bottom lambert bounces 4 }"};
/* generators whose values lie strictly between 0 and 1 somewhere, so both children of a blend are evaluated */
static const char *const g_blend_gens[] = {"perlin", "fbm", "gradient { space uv slope 0.5 0.3 0 offset 0.1 }",
                                           "marble", "wood", "turbulence"};
static const char *const g_set_ops[] = {"union", "intersection", "difference"};

/* A small ordinary number. */
static void num(GenBuf *b, GenRng *r) { gb_printf(b, " %.3g", gen_unit(r) * 2.0 - 0.5); }

/* ---- long operand lists ---- */

static void csg_solid(GenBuf *b, GenRng *r)
{
    switch (gen_below(r, 4)) {
    case 0:
        gb_printf(b, " sphere %.3g", 0.1 + gen_unit(r));
        break;
    case 1:
        gb_printf(b, " box -1 -1 -1 %.2g 1 1", gen_unit(r));
        break;
    case 2:
        gb_printf(b, " cylinder %.2g -1 1", 0.1 + gen_unit(r));
        break;
    default:
        gb_printf(b, " transform { translate %.2g 0 0 } sphere 0.5", gen_unit(r));
    }
}

static void csg_list(GenBuf *b, GenRng *r, size_t budget)
{
    const char *op = GEN_PICK(r, g_set_ops);
    gb_printf(b, "generator g csg { shape %s {", op);
    while (b->n + 40 < budget)
        csg_solid(b, r);
    gb_printf(b, " } }\nnode n interpolate { a lambert b mirror t g }\n");
}

static void cpg_list(GenBuf *b, GenRng *r, size_t budget)
{
    const char *op = GEN_PICK(r, g_set_ops);
    gb_printf(b, "generator g cpg { shape %s {", op);
    while (b->n + 40 < budget) {
        if (gen_below(r, 3))
            gb_printf(b, " circle %.3g %.3g %.3g", gen_unit(r), gen_unit(r), 0.05 + 0.3 * gen_unit(r));
        else
            gb_printf(b, " square %.3g %.3g %.3g", gen_unit(r), gen_unit(r), 0.05 + 0.3 * gen_unit(r));
    }
    gb_printf(b, " } }\nnode n interpolate { a lambert b mirror t g }\n");
}

/* One path edge or polygon with as many points as the budget holds. */
static void cpg_points(GenBuf *b, GenRng *r, size_t budget)
{
    int form = (int)gen_below(r, 4);
    static const char *const heads[] = {"polygon {", "path { lines {", "path { bezier {",
                                        "path { bspline { degree 3 periodic yes points {"};
    static const char *const tails[] = {" }", " } }", " } }", " } } }"};
    gb_printf(b, "generator g cpg { shape %s", heads[form]);
    double a = 0.0;
    while (b->n + 40 < budget) {
        a += 0.001 + 0.01 * gen_unit(r);
        gb_printf(b, " %.4f %.4f", 0.5 + 0.4 * gen_unit(r) * __builtin_cos(a), 0.5 + 0.4 * __builtin_sin(a));
    }
    gb_printf(b, "%s }\nnode n interpolate { a lambert b mirror t g }\n", tails[form]);
}

/* ---- depth ---- */

static void nest_deep(GenBuf *b, GenRng *r, size_t budget)
{
    /* around the reader's limit of 64 levels, or as deep as the budget allows */
    size_t depth = gen_below(r, 2) ? 60 + gen_below(r, 10) : budget / 24;
    if (depth > 200)
        gb_printf(b, "# " GEN_MUST_FAIL ": %zu levels\n", depth);
    switch (gen_below(r, 4)) {
    case 0: /* CSG blocks */
        gb_printf(b, "generator g csg { shape");
        for (size_t i = 0; i < depth; i++)
            gb_printf(b, " union {");
        gb_printf(b, " sphere 1");
        gb_fill(b, '}', depth);
        gb_printf(b, " }\nnode n interpolate { a lambert b mirror t g }\n");
        break;
    case 1: /* CSG transforms, each a positional block over the next */
        gb_printf(b, "generator g csg { shape");
        for (size_t i = 0; i < depth; i++)
            gb_printf(b, " transform { translate 0.01 0 0 }");
        gb_printf(b, " sphere 1 }\nnode n interpolate { a lambert b mirror t g }\n");
        break;
    case 2: /* a colour scaled again and again */
        gb_printf(b, "material m lambert { reflectance");
        for (size_t i = 0; i < depth; i++)
            gb_printf(b, " scale 1");
        gb_printf(b, " rgb 0.5 0.5 0.5 }\n");
        break;
    default: /* anonymous nodes nested in each other */
        gb_printf(b, "node n");
        for (size_t i = 0; i < depth; i++)
            gb_printf(b, " scale { factor perlin child");
        gb_printf(b, " lambert");
        for (size_t i = 0; i < depth; i++)
            gb_printf(b, " }");
        gb_byte(b, '\n');
    }
}

/* ---- references ---- */

static void ref_chain(GenBuf *b, GenRng *r, size_t budget)
{
    int form = (int)gen_below(r, 5);
    switch (form) {
    case 0:
        gb_printf(b, "node n0 lambert\n");
        break;
    case 1:
        gb_printf(b, "color c0 rgb 0.5 0.5 0.5\n");
        break;
    default:
        gb_printf(b, "material n0 %s\n", GEN_PICK(r, g_mats));
    }
    unsigned long i = 1;
    for (; b->n + 80 < budget; i++) {
        switch (form) {
        case 0:
            gb_printf(b, "node n%lu scale { child n%lu factor constant { value 0.99 } }\n", i, i - 1);
            break;
        case 1:
            gb_printf(b, "color c%lu scale 1 c%lu\n", i, i - 1);
            break;
        case 2:
            gb_printf(b, "node n%lu transform { child n%lu uv { translate 0.01 0 } }\n", i, i - 1);
            break;
        case 3:
            gb_printf(b, "node n%lu bump { child n%lu height perlin strength 0.1 }\n", i, i - 1);
            break;
        default:
            gb_printf(b, "node n%lu interpolate { a n%lu b lambert t checker }\n", i, i - 1);
        }
    }
    if (form == 1) /* the colour at the end of the chain, used */
        gb_printf(b, "material last lambert { reflectance c%lu }\n", i - 1);
}

/* Each level blends the previous level with itself: 2^levels paths to the bottom. */
static void self_blend(GenBuf *b, GenRng *r, size_t budget)
{
    size_t levels = 16 + gen_below(r, 48);
    const char *gen = GEN_PICK(r, g_blend_gens);
    gb_printf(b, "generator t %s\nnode l0 %s\n", gen, GEN_PICK(r, g_mats));
    for (size_t i = 1; i <= levels && b->n + 120 < budget; i++) {
        switch (gen_below(r, 3)) {
        case 0:
            gb_printf(b, "node l%zu interpolate { a l%zu b l%zu t t }\n", i, i - 1, i - 1);
            break;
        case 1:
            gb_printf(b, "node l%zu spline { t t children { l%zu l%zu l%zu } }\n", i, i - 1, i - 1, i - 1);
            break;
        default:
            gb_printf(b, "node l%zu scale { child interpolate { a l%zu b l%zu t t } factor t }\n", i, i - 1, i - 1);
        }
    }
}

/* Many nodes, each over a few random earlier ones (shared sub-trees, many paths). */
static void wide_dag(GenBuf *b, GenRng *r, size_t budget)
{
    gb_printf(b, "generator t perlin { frequency 3 }\n");
    unsigned long n = 0;
    for (; n < 4; n++)
        gb_printf(b, "material d%lu %s\n", n, GEN_PICK(r, g_mats));
    for (; b->n + 200 < budget; n++) {
        unsigned long k = 2 + gen_below(r, 4);
        gb_printf(b, "node d%lu spline { t t children {", n);
        for (unsigned long j = 0; j < k; j++)
            gb_printf(b, " d%lu", n - 1 - gen_below(r, n < 8 ? n : 8));
        gb_printf(b, " } }\n");
    }
}

/* ---- size ---- */

static void many_entries(GenBuf *b, GenRng *r, size_t budget)
{
    unsigned long nc = 0, nm = 0, ng = 0;
    gb_printf(b, "color c0 rgb 0.1 0.2 0.3\nmaterial m0 lambert\ngenerator g0 checker\n");
    nc = nm = ng = 1;
    while (b->n + 120 < budget) {
        switch (gen_below(r, 4)) {
        case 0:
            gb_printf(b, "color c%lu rgb %.2f %.2f %.2f\n", nc++, gen_unit(r), gen_unit(r), gen_unit(r));
            break;
        case 1:
            gb_printf(b, "material m%lu lambert { reflectance c%lu }\n", nm++, gen_below(r, nc));
            break;
        case 2:
            gb_printf(b, "generator g%lu checker { frequency %lu }\n", ng++, 1 + gen_below(r, 9));
            break;
        default:
            gb_printf(b, "node m%lu interpolate { a m%lu b m%lu t g%lu }\n", nm, gen_below(r, nm), gen_below(r, nm),
                      gen_below(r, ng));
            nm++;
        }
    }
}

/* ---- numbers ---- */

static void extreme(GenBuf *b, GenRng *r)
{
    static const char *const values[] = {
        "0", "-0", "1e308", "-1e308", "1.7976931348623157e308", "1e309", "-1e309", "4.9e-324", "1e-320",
        "2.2250738585072014e-308", "2147483647", "2147483648", "-2147483649", "4294967296",
        "9223372036854775807", "9223372036854775808", "-9223372036854775809", "1.8e18", "1e19", "1e300",
        "-1e300", "3.4028235e38", "3.5e38", "1e-45", "16777217", "0.5", "1", "-1", "1e6", "1e9",
        "0.000000000000000000000000000000000000000000000000000000000000001"};
    gb_printf(b, " %s", GEN_PICK(r, values));
}

/* A line with numbers that are extreme in every slot (the parse routine must check every range). */
static void extreme_entry(GenBuf *b, GenRng *r, unsigned long i)
{
    switch (gen_below(r, 19)) {
    case 0:
        gb_printf(b, "generator x%lu perlin { frequency", i);
        extreme(b, r);
        gb_printf(b, " seed");
        extreme(b, r);
        gb_printf(b, " }\n");
        break;
    case 1:
        gb_printf(b, "generator x%lu fbm { octaves", i);
        extreme(b, r);
        gb_printf(b, " lacunarity");
        extreme(b, r);
        gb_printf(b, " gain");
        extreme(b, r);
        gb_printf(b, " frequency");
        extreme(b, r);
        gb_printf(b, " }\n");
        break;
    case 2:
        gb_printf(b, "generator x%lu checker { dims 3 frequency", i);
        extreme(b, r);
        gb_printf(b, " }\n");
        break;
    case 3:
        gb_printf(b, "color x%lu spectrum {", i);
        for (int k = 0; k < 4; k++) {
            extreme(b, r);
            num(b, r);
        }
        gb_printf(b, " }\n");
        break;
    case 4:
        gb_printf(b, "color x%lu blackbody", i);
        extreme(b, r);
        gb_printf(b, "\ncolor y%lu line", i);
        extreme(b, r);
        extreme(b, r);
        gb_byte(b, '\n');
        break;
    case 5:
        gb_printf(b, "material x%lu lambert { reflectance scale", i);
        extreme(b, r);
        gb_printf(b, " rgb");
        extreme(b, r);
        extreme(b, r);
        extreme(b, r);
        gb_printf(b, " }\n");
        break;
    case 6:
        gb_printf(b, "generator x%lu csg { shape transform { translate", i);
        extreme(b, r);
        extreme(b, r);
        extreme(b, r);
        gb_printf(b, " scale");
        extreme(b, r);
        gb_printf(b, " rotate x");
        extreme(b, r);
        gb_printf(b, " } sphere");
        extreme(b, r);
        gb_printf(b, " }\n");
        break;
    case 7:
        gb_printf(b, "generator x%lu cpg { shape transform { rotate", i);
        extreme(b, r);
        gb_printf(b, " scale");
        extreme(b, r);
        gb_printf(b, " } circle");
        extreme(b, r);
        extreme(b, r);
        extreme(b, r);
        gb_printf(b, " }\n");
        break;
    case 8:
        gb_printf(b, "generator x%lu cpg { shape path { bspline { degree", i);
        extreme(b, r);
        gb_printf(b, " points { 0 0 1 0 1 1 0 1 } } } }\n");
        break;
    case 9:
        gb_printf(b, "generator x%lu cpg { shape path { nurbs { degree 2 points { 0 0 1 0 1 1 } weights {", i);
        extreme(b, r);
        extreme(b, r);
        extreme(b, r);
        gb_printf(b, " } knots {");
        for (int k = 0; k < 6; k++)
            extreme(b, r);
        gb_printf(b, " } } } }\n");
        break;
    case 10:
        gb_printf(b, "material x%lu phong { exponent", i);
        extreme(b, r);
        gb_printf(b, " }\n");
        break;
    case 11:
        gb_printf(b, "material x%lu dielectric { index", i);
        if (gen_below(r, 2)) {
            gb_printf(b, " sellmeier");
            for (int k = 0; k < 6; k++)
                extreme(b, r);
        } else {
            gb_printf(b, " cauchy");
            extreme(b, r);
            extreme(b, r);
        }
        gb_printf(b, " absorption rgb");
        extreme(b, r);
        gb_printf(b, " 0 0"); /* rough, anisotropic, a named glass (known or not), a pane */
        gb_printf(b, gen_below(r, 2) ? " roughness" : " roughness_u 0.2 roughness_v");
        extreme(b, r);
        gb_printf(b, " distribution %s compensate %s }\n", gen_below(r, 2) ? "ggx" : "beckmann",
                  gen_below(r, 2) ? "on" : "off");
        gb_printf(b, "material y%lu thindielectric { glass %s }\n", i,
                  GEN_PICK(r, ((const char *const[]){"BK7", "fused_silica", "\"fused silica\"", "diamond", "flint"})));
        break;
    case 12:
        gb_printf(b, "node x%lu transform { child lambert uv { translate", i);
        extreme(b, r);
        extreme(b, r);
        gb_printf(b, " rotate");
        extreme(b, r);
        gb_printf(b, " scale");
        extreme(b, r);
        gb_printf(b, " } xyz { scale");
        extreme(b, r);
        extreme(b, r);
        extreme(b, r);
        gb_printf(b, " } }\n");
        break;
    case 13:
        gb_printf(b, "node x%lu bump { child lambert height perlin { frequency", i);
        extreme(b, r);
        gb_printf(b, " } strength");
        extreme(b, r);
        gb_printf(b, " }\n");
        break;
    case 14:
        gb_printf(b, "generator x%lu wood { rings", i);
        extreme(b, r);
        gb_printf(b, " turbulence");
        extreme(b, r);
        gb_printf(b, " frequency");
        extreme(b, r);
        gb_printf(b, " }\n");
        break;
    case 15: /* a conductor: n, k in every slot, a long spectrum of n, roughness and its anisotropy */
        gb_printf(b, "material x%lu conductor { eta spectrum {", i);
        for (int k = 0, n = 2 + (int)gen_below(r, 200); k < n; k++) {
            gb_printf(b, " %d", 300 + 3 * k);
            extreme(b, r);
        }
        gb_printf(b, " } k rgb");
        extreme(b, r);
        extreme(b, r);
        extreme(b, r);
        gb_printf(b, gen_below(r, 2) ? " roughness" : " roughness_u 0.2 roughness_v");
        extreme(b, r);
        gb_printf(b, " distribution %s", gen_below(r, 2) ? "ggx" : "beckmann");
        gb_printf(b, " fresnel %s }\n", i & 1 ? "exact" : "table"); /* by the index: no draw, the stream unchanged */
        break;
    case 16: /* a thin film: thickness, index and extinction in every slot */
        gb_printf(b, "material x%lu thinfilm { thickness", i);
        extreme(b, r);
        gb_printf(b, " index");
        extreme(b, r);
        gb_printf(b, " extinction");
        extreme(b, r);
        gb_printf(b, " base plastic { roughness");
        extreme(b, r);
        gb_printf(b, " index");
        extreme(b, r);
        gb_printf(b, " } }\n");
        break;
    case 17: /* a layer: its medium, bounces and samples in every slot, over a layer of the entry before */
        gb_printf(b, "material x%lu layer { top dielectric { index", i);
        extreme(b, r);
        gb_printf(b, " } bottom %s thickness", i > 0 && gen_below(r, 2) ? "x0" : "lambert");
        extreme(b, r);
        gb_printf(b, " bounces");
        extreme(b, r);
        gb_printf(b, " samples");
        extreme(b, r);
        gb_printf(b, " }\n");
        break;
    case 18: /* layers in layers, one deeper than the bound allows, and a costly one */
        gb_printf(b, "material y%lu_0 layer { top dielectric { } bottom lambert bounces 1 }\n", i);
        for (int k = 1; k < 5; k++)
            gb_printf(b, "material y%lu_%d layer { top dielectric { } bottom y%lu_%d bounces 1 }\n", i, k, i, k - 1);
        gb_printf(b, "material z%lu layer { top thinfilm { } bottom plastic { } bounces 64 samples 64 }\n", i);
        break;
    default:
        gb_printf(b, "generator x%lu gradient { slope", i);
        extreme(b, r);
        extreme(b, r);
        extreme(b, r);
        gb_printf(b, " offset");
        extreme(b, r);
        gb_printf(b, " }\n");
    }
}

static void extreme_numbers(GenBuf *b, GenRng *r, size_t budget)
{
    if (gen_below(r, 3) == 0) {
        gb_printf(b, "colormodel spectrum { step");
        extreme(b, r);
        gb_printf(b, " min");
        extreme(b, r);
        gb_printf(b, " max");
        extreme(b, r);
        gb_printf(b, " }\n");
    }
    for (unsigned long i = 0; b->n + 400 < budget && i < 4096; i++)
        extreme_entry(b, r, i);
}

/* ---- tokens ---- */

static void long_tokens(GenBuf *b, GenRng *r, size_t budget)
{
    static const size_t lengths[] = {4094, 4095, 4096, 4097, 8191, 65536};
    size_t len = gen_below(r, 4) ? lengths[gen_below(r, 6)] : (budget > 64 ? budget - 64 : 1);
    int form = (int)gen_below(r, 5);
    /* a name of len + 1 bytes or a number of len + 2 is over the limit of 4095; the others are always wrong */
    if ((form == 0 && len + 1 > 4095) || (form == 2 && len + 2 > 4095) || form == 1 || form >= 3)
        gb_printf(b, "# " GEN_MUST_FAIL "\n");
    switch (form) {
    case 0: /* a name */
        gb_printf(b, "material a");
        gb_fill(b, 'x', len);
        gb_printf(b, " lambert\n");
        break;
    case 1: /* a string (an include of a name too long for any file system) */
        gb_printf(b, "include \"");
        gb_fill(b, 'i', len);
        gb_printf(b, ".mat\"\n");
        break;
    case 2: /* a number with many digits */
        gb_printf(b, "color c rgb 0.");
        gb_fill(b, '3', len);
        gb_printf(b, " 1");
        gb_fill(b, '0', len % 400);
        gb_printf(b, " 0.5\n");
        break;
    case 3: /* a comment, then a line without end */
        gb_printf(b, "# ");
        gb_fill(b, 'c', len);
        gb_printf(b, "\nmaterial m lambert { reflectance rgb 0.5 0.5 0.5 } ");
        gb_fill(b, ' ', len);
        gb_printf(b, "material");
        break;
    default: /* an unknown type keyword */
        gb_printf(b, "material m ");
        gb_fill(b, 'k', len);
        gb_byte(b, '\n');
    }
}

/* ---- bytes ---- */

static void control_bytes(GenBuf *b, GenRng *r, size_t budget)
{
    static const char *const boms[] = {"\xef\xbb\xbf", "\xff\xfe", "\xfe\xff", "\xef\xbb\xbf\xef\xbb\xbf", ""};
    gb_printf(b, "%s", GEN_PICK(r, boms));
    static const char *const lines[] = {
        "color warm blackbody 3200\n", "material base lambert { reflectance warm }\n",
        "node n interpolate { a base b mirror t checker }\n", "generator p perlin { frequency 4 }\n",
        "material \"quoted\" lambert\n", "include \"common.mat\"\n", "color s spectrum { 400 0.1 700 0.9 }\n"};
    static const unsigned char bad[] = {0x00, 0x01, 0x07, 0x08, 0x0b, 0x0c, 0x0d, 0x1b, 0x7f,
                                        0x80, 0xc0, 0xe2, 0xfe, 0xff, '\r', '\t', '"', '\\'};
    size_t limit = budget < 65536 ? budget : 65536;
    while (b->n + 80 < limit) {
        const char *line = GEN_PICK(r, lines);
        size_t len = strlen(line);
        size_t at = gen_below(r, len + 1);
        gb_put(b, line, at);
        int n = (int)gen_below(r, 3);
        for (int k = 0; k < n; k++)
            gb_byte(b, bad[gen_below(r, sizeof bad)]);
        gb_put(b, line + at, len - at);
        if (gen_below(r, 8) == 0) /* an escape sequence in a name, echoed by the error message */
            gb_printf(b, "material \x1b[31mred\x1b[0m lambert\n");
    }
    if (gen_below(r, 2)) /* old Mac line ends */
        for (size_t i = 0; i < b->n; i++)
            if (b->p[i] == '\n')
                b->p[i] = '\r';
}

/* ---- random trees over the grammar ---- */

static void any_generator(GenBuf *b, GenRng *r, int depth);
static void any_material(GenBuf *b, GenRng *r, int depth, unsigned long defined)
{
    if (depth <= 0 || gen_below(r, 3) == 0) {
        if (defined && gen_below(r, 2))
            gb_printf(b, " e%lu", gen_below(r, defined));
        else
            gb_printf(b, " %s", GEN_PICK(r, g_mats));
        return;
    }
    switch (gen_below(r, 6)) {
    case 0:
        gb_printf(b, " interpolate { a");
        any_material(b, r, depth - 1, defined);
        gb_printf(b, " b");
        any_material(b, r, depth - 1, defined);
        gb_printf(b, " t");
        any_generator(b, r, depth - 1);
        gb_printf(b, " }");
        break;
    case 1:
    case 2: {
        gb_printf(b, " %s { %s", gen_below(r, 2) ? "spline" : "select", "children {");
        int n = 1 + (int)gen_below(r, 5);
        for (int k = 0; k < n; k++)
            any_material(b, r, depth - 1, defined);
        gb_printf(b, " } %s", gen_below(r, 2) ? "t" : "index");
        any_generator(b, r, depth - 1);
        gb_printf(b, " }");
        break;
    }
    case 3:
        gb_printf(b, " bump { child");
        any_material(b, r, depth - 1, defined);
        gb_printf(b, " height");
        any_generator(b, r, depth - 1);
        gb_printf(b, " strength");
        num(b, r);
        gb_printf(b, " }");
        break;
    case 4:
        gb_printf(b, " scale { child");
        any_material(b, r, depth - 1, defined);
        gb_printf(b, " factor");
        any_generator(b, r, depth - 1);
        gb_printf(b, " }");
        break;
    default:
        gb_printf(b, " transform { child");
        any_material(b, r, depth - 1, defined);
        gb_printf(b, " uv { rotate");
        num(b, r);
        gb_printf(b, " scale");
        num(b, r);
        gb_printf(b, " } }");
    }
}

static void any_solid(GenBuf *b, GenRng *r, int depth)
{
    if (depth <= 0 || gen_below(r, 2)) {
        csg_solid(b, r);
        return;
    }
    gb_printf(b, " %s {", GEN_PICK(r, g_set_ops));
    int n = 1 + (int)gen_below(r, 4);
    for (int k = 0; k < n; k++)
        any_solid(b, r, depth - 1);
    gb_printf(b, " }");
}

static void any_generator(GenBuf *b, GenRng *r, int depth)
{
    static const char *const simple[] = {"checker", "perlin", "fbm { octaves 4 }", "turbulence", "wood",
                                         "marble", "surface", "constant { value 0.5 }", "gradient"};
    if (depth <= 0 || gen_below(r, 2)) {
        gb_printf(b, " %s", GEN_PICK(r, simple));
        return;
    }
    if (gen_below(r, 2)) {
        gb_printf(b, " csg { shape");
        any_solid(b, r, depth);
        gb_printf(b, " }");
    } else {
        gb_printf(b, " cpg { shape %s { circle 0.5 0.5 0.3 square 0.2 0.2 0.3 } }", GEN_PICK(r, g_set_ops));
    }
}

static void random_tree(GenBuf *b, GenRng *r, size_t budget)
{
    static const char *const models[] = {"", "colormodel spectrum { step 10 }\n", "colormodel bispectral\n",
                                         "colormodel spectrum9\n"};
    gb_printf(b, "%s", GEN_PICK(r, models));
    size_t limit = budget < 262144 ? budget : 262144;
    for (unsigned long i = 0; b->n + 2000 < limit; i++) {
        gb_printf(b, "node e%lu", i);
        any_material(b, r, 1 + (int)gen_below(r, 6), i);
        gb_byte(b, '\n');
        if (gen_below(r, 32) == 0 && b->n > 0) /* a mistake somewhere: a dropped or doubled byte */
            b->p[gen_below(r, b->n)] = (unsigned char)GEN_PICK(r, ((const char *const[]){"{", "}", " ", "x"}))[0];
    }
}

/* ---- textured parameters (kit/texparam.h) ---- */

/* A generator with a `range` of extreme or reversed bounds, or none. */
static void ranged_generator(GenBuf *b, GenRng *r)
{
    static const char *const gens[] = {"checker { dims 2", "perlin { frequency 3", "fbm { octaves 3", "marble {",
                                       "gradient { space uv slope 1 0 0", "surface {", "turbulence {"};
    gb_printf(b, " %s", GEN_PICK(r, gens));
    switch (gen_below(r, 4)) {
    case 0:
        break;
    case 1:
        gb_printf(b, " range");
        extreme(b, r);
        extreme(b, r);
        break;
    case 2:
        gb_printf(b, " range %.3g %.3g", gen_unit(r) * 4.0, gen_unit(r) * 4.0); /* LO > HI half the time */
        break;
    default:
        gb_printf(b, " range 0 1 range 0 1"); /* given twice */
    }
    gb_printf(b, " }");
}

/* A textured colour: a mix of extreme or plain colours by a ranged generator, an image that may not exist, or a
 * block with a missing, repeated or unknown key. */
static void textured_colour(GenBuf *b, GenRng *r)
{
    switch (gen_below(r, 5)) {
    case 0:
        gb_printf(b, " mix { by");
        ranged_generator(b, r);
        gb_printf(b, " a rgb %.2g %.2g %.2g b rgb", gen_unit(r), gen_unit(r), gen_unit(r));
        extreme(b, r);
        extreme(b, r);
        extreme(b, r);
        gb_printf(b, " }");
        break;
    case 1:
        gb_printf(b, " mix { by");
        ranged_generator(b, r);
        gb_printf(b, " a rgb 0.1 0.2 0.3 b rgb 0.4 0.4 0.4 }");
        break;
    case 2:
        gb_printf(b, " image { file \"%s\" wrap %s blur", gen_below(r, 2) ? "label.png" : "missing.png",
                  gen_below(r, 2) ? "clamp" : "mirror");
        extreme(b, r);
        gb_printf(b, " }");
        break;
    case 3:
        gb_printf(b, " mix { by checker a rgb 1 1 1 a rgb 0 0 0 b rgb 0 0 0 }");
        break;
    default:
        gb_printf(b, " %s { %s }", gen_below(r, 2) ? "mix" : "image", gen_below(r, 2) ? "" : "nosuchkey 1");
    }
}

/* Every textured parameter of the built-in materials, and parameters that must stay constant, given generators and
 * textures with extreme ranges and colours: each is read, checked at its extremes or refused at its position. */
static void textured_params(GenBuf *b, GenRng *r, size_t budget)
{
    unsigned long entries = 1 + gen_below(r, 6); /* few: a load stops at its first refusal */
    for (unsigned long i = 0; b->n < budget / 2 && i < entries; i++) {
        switch (gen_below(r, 8)) {
        case 0:
            gb_printf(b, "material t%lu lambert { reflectance", i);
            textured_colour(b, r);
            gb_printf(b, " }\n");
            break;
        case 1:
            gb_printf(b, "material t%lu phong { diffuse", i);
            textured_colour(b, r);
            gb_printf(b, " specular");
            textured_colour(b, r);
            gb_printf(b, " exponent");
            ranged_generator(b, r);
            gb_printf(b, " mirror rgb 0 0 0 }\n");
            break;
        case 2:
            gb_printf(b, "material t%lu emitter { radiance", i);
            textured_colour(b, r);
            gb_printf(b, " two_sided %s }\n", gen_below(r, 2) ? "on" : "off");
            break;
        case 3:
            gb_printf(b, "material t%lu mirror { reflectance", i);
            textured_colour(b, r);
            gb_printf(b, " }\n");
            break;
        case 4:
            gb_printf(b, "material t%lu thinfilm { thickness", i);
            ranged_generator(b, r);
            gb_printf(b, " index");
            ranged_generator(b, r);
            gb_printf(b, " extinction");
            ranged_generator(b, r);
            gb_printf(b, " }\n");
            break;
        case 5: /* must stay constant */
            gb_printf(b, "material t%lu %s", i,
                      GEN_PICK(r, ((const char *const[]){"conductor { metal Au roughness",
                                                         "dielectric { roughness", "plastic { index",
                                                         "layer { top dielectric { } bottom lambert thickness"})));
            ranged_generator(b, r);
            gb_printf(b, " }\n");
            break;
        case 6: /* a colour no type reads as a texture */
            gb_printf(b, "material t%lu plastic { reflectance", i);
            textured_colour(b, r);
            gb_printf(b, " }\nmaterial u%lu dielectric { tint", i);
            textured_colour(b, r);
            gb_printf(b, " }\n");
            break;
        default: /* a named ranged generator used by name, and in a texture node */
            gb_printf(b, "generator g%lu", i);
            ranged_generator(b, r);
            gb_printf(b, "\nmaterial t%lu phong { exponent g%lu }\nnode n%lu interpolate { a lambert b mirror t "
                         "g%lu }\n", i, i, i, i);
        }
    }
}

const GenFamily gen_text_families[] = {
    {"csg-list", ".mat", csg_list},         {"cpg-list", ".mat", cpg_list},
    {"cpg-points", ".mat", cpg_points},     {"nest-deep", ".mat", nest_deep},
    {"ref-chain", ".mat", ref_chain},       {"self-blend", ".mat", self_blend},
    {"wide-dag", ".mat", wide_dag},         {"many-entries", ".mat", many_entries},
    {"extreme-numbers", ".mat", extreme_numbers}, {"long-tokens", ".mat", long_tokens},
    {"control-bytes", ".mat", control_bytes}, {"random-tree", ".mat", random_tree},
    {"textured-params", ".mat", textured_params},
};
const int gen_text_count = (int)(sizeof gen_text_families / sizeof gen_text_families[0]);
