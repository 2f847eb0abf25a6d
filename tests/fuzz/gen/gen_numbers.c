/* gen_numbers.c - the reader's "extreme-numbers" family (gen_text.c lists it): entries of every kind whose number
 * slots hold the extremes of double, float and the integer types, so every range check of every parse routine is
 * reached. */
#include "gen.h"

#include <stdio.h>

/* A small ordinary number. */
static void num(GenBuf *b, GenRng *r) { gb_printf(b, " %.3g", gen_unit(r) * 2.0 - 0.5); }

void gen_text_extreme(GenBuf *b, GenRng *r)
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
        gen_text_extreme(b, r);
        gb_printf(b, " seed");
        gen_text_extreme(b, r);
        gb_printf(b, " }\n");
        break;
    case 1:
        gb_printf(b, "generator x%lu fbm { octaves", i);
        gen_text_extreme(b, r);
        gb_printf(b, " lacunarity");
        gen_text_extreme(b, r);
        gb_printf(b, " gain");
        gen_text_extreme(b, r);
        gb_printf(b, " frequency");
        gen_text_extreme(b, r);
        gb_printf(b, " }\n");
        break;
    case 2:
        gb_printf(b, "generator x%lu checker { dims 3 frequency", i);
        gen_text_extreme(b, r);
        gb_printf(b, " }\n");
        break;
    case 3:
        gb_printf(b, "color x%lu spectrum {", i);
        for (int k = 0; k < 4; k++) {
            gen_text_extreme(b, r);
            num(b, r);
        }
        gb_printf(b, " }\n");
        break;
    case 4:
        gb_printf(b, "color x%lu blackbody", i);
        gen_text_extreme(b, r);
        gb_printf(b, "\ncolor y%lu line", i);
        gen_text_extreme(b, r);
        gen_text_extreme(b, r);
        gb_byte(b, '\n');
        break;
    case 5:
        gb_printf(b, "material x%lu lambert { reflectance scale", i);
        gen_text_extreme(b, r);
        gb_printf(b, " rgb");
        gen_text_extreme(b, r);
        gen_text_extreme(b, r);
        gen_text_extreme(b, r);
        gb_printf(b, " }\n");
        break;
    case 6:
        gb_printf(b, "generator x%lu csg { shape transform { translate", i);
        gen_text_extreme(b, r);
        gen_text_extreme(b, r);
        gen_text_extreme(b, r);
        gb_printf(b, " scale");
        gen_text_extreme(b, r);
        gb_printf(b, " rotate x");
        gen_text_extreme(b, r);
        gb_printf(b, " } sphere");
        gen_text_extreme(b, r);
        gb_printf(b, " }\n");
        break;
    case 7:
        gb_printf(b, "generator x%lu cpg { shape transform { rotate", i);
        gen_text_extreme(b, r);
        gb_printf(b, " scale");
        gen_text_extreme(b, r);
        gb_printf(b, " } circle");
        gen_text_extreme(b, r);
        gen_text_extreme(b, r);
        gen_text_extreme(b, r);
        gb_printf(b, " }\n");
        break;
    case 8:
        gb_printf(b, "generator x%lu cpg { shape path { bspline { degree", i);
        gen_text_extreme(b, r);
        gb_printf(b, " points { 0 0 1 0 1 1 0 1 } } } }\n");
        break;
    case 9:
        gb_printf(b, "generator x%lu cpg { shape path { nurbs { degree 2 points { 0 0 1 0 1 1 } weights {", i);
        gen_text_extreme(b, r);
        gen_text_extreme(b, r);
        gen_text_extreme(b, r);
        gb_printf(b, " } knots {");
        for (int k = 0; k < 6; k++)
            gen_text_extreme(b, r);
        gb_printf(b, " } } } }\n");
        break;
    case 10:
        gb_printf(b, "material x%lu phong { exponent", i);
        gen_text_extreme(b, r);
        gb_printf(b, " }\n");
        break;
    case 11:
        gb_printf(b, "material x%lu dielectric { index", i);
        if (gen_below(r, 2)) {
            gb_printf(b, " sellmeier");
            for (int k = 0; k < 6; k++)
                gen_text_extreme(b, r);
        } else {
            gb_printf(b, " cauchy");
            gen_text_extreme(b, r);
            gen_text_extreme(b, r);
        }
        gb_printf(b, " absorption rgb");
        gen_text_extreme(b, r);
        gb_printf(b, " 0 0"); /* rough, anisotropic, a named glass (known or not), a pane */
        gb_printf(b, gen_below(r, 2) ? " roughness" : " roughness_u 0.2 roughness_v");
        gen_text_extreme(b, r);
        gb_printf(b, " distribution %s compensate %s }\n", gen_below(r, 2) ? "ggx" : "beckmann",
                  gen_below(r, 2) ? "on" : "off");
        gb_printf(b, "material y%lu thindielectric { glass %s }\n", i,
                  GEN_PICK(r, ((const char *const[]){"BK7", "fused_silica", "\"fused silica\"", "diamond", "flint"})));
        break;
    case 12:
        gb_printf(b, "node x%lu transform { child lambert uv { translate", i);
        gen_text_extreme(b, r);
        gen_text_extreme(b, r);
        gb_printf(b, " rotate");
        gen_text_extreme(b, r);
        gb_printf(b, " scale");
        gen_text_extreme(b, r);
        gb_printf(b, " } xyz { scale");
        gen_text_extreme(b, r);
        gen_text_extreme(b, r);
        gen_text_extreme(b, r);
        gb_printf(b, " } }\n");
        break;
    case 13:
        gb_printf(b, "node x%lu bump { child lambert height perlin { frequency", i);
        gen_text_extreme(b, r);
        gb_printf(b, " } strength");
        gen_text_extreme(b, r);
        gb_printf(b, " }\n");
        break;
    case 14:
        gb_printf(b, "generator x%lu wood { rings", i);
        gen_text_extreme(b, r);
        gb_printf(b, " turbulence");
        gen_text_extreme(b, r);
        gb_printf(b, " frequency");
        gen_text_extreme(b, r);
        gb_printf(b, " }\n");
        break;
    case 15: /* a conductor: n, k in every slot, a long spectrum of n, roughness and its anisotropy */
        gb_printf(b, "material x%lu conductor { eta spectrum {", i);
        for (int k = 0, n = 2 + (int)gen_below(r, 200); k < n; k++) {
            gb_printf(b, " %d", 300 + 3 * k);
            gen_text_extreme(b, r);
        }
        gb_printf(b, " } k rgb");
        gen_text_extreme(b, r);
        gen_text_extreme(b, r);
        gen_text_extreme(b, r);
        gb_printf(b, gen_below(r, 2) ? " roughness" : " roughness_u 0.2 roughness_v");
        gen_text_extreme(b, r);
        gb_printf(b, " distribution %s", gen_below(r, 2) ? "ggx" : "beckmann");
        gb_printf(b, " fresnel %s }\n", i & 1 ? "exact" : "table"); /* by the index: no draw, the stream unchanged */
        break;
    case 16: /* a thin film: thickness, index and extinction in every slot */
        gb_printf(b, "material x%lu thinfilm { thickness", i);
        gen_text_extreme(b, r);
        gb_printf(b, " index");
        gen_text_extreme(b, r);
        gb_printf(b, " extinction");
        gen_text_extreme(b, r);
        gb_printf(b, " base plastic { roughness");
        gen_text_extreme(b, r);
        gb_printf(b, " index");
        gen_text_extreme(b, r);
        gb_printf(b, " } }\n");
        break;
    case 17: /* a layer: its medium, bounces and samples in every slot, over a layer of the entry before */
        gb_printf(b, "material x%lu layer { top dielectric { index", i);
        gen_text_extreme(b, r);
        gb_printf(b, " } bottom %s thickness", i > 0 && gen_below(r, 2) ? "x0" : "lambert");
        gen_text_extreme(b, r);
        gb_printf(b, " bounces");
        gen_text_extreme(b, r);
        gb_printf(b, " samples");
        gen_text_extreme(b, r);
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
        gen_text_extreme(b, r);
        gen_text_extreme(b, r);
        gen_text_extreme(b, r);
        gb_printf(b, " offset");
        gen_text_extreme(b, r);
        gb_printf(b, " }\n");
    }
}

void gen_text_extreme_numbers(GenBuf *b, GenRng *r, size_t budget)
{
    if (gen_below(r, 3) == 0) {
        gb_printf(b, "colormodel spectrum { step");
        gen_text_extreme(b, r);
        gb_printf(b, " min");
        gen_text_extreme(b, r);
        gb_printf(b, " max");
        gen_text_extreme(b, r);
        gb_printf(b, " }\n");
    }
    for (unsigned long i = 0; b->n + 400 < budget && i < 4096; i++)
        extreme_entry(b, r, i);
}

