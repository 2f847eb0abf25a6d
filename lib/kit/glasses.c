/* glasses.c - the named glasses: published Sellmeier coefficients (data, as the sources give them) and the lookup
 * by name. The SCHOTT glasses are the catalogue's formula n^2 = 1 + sum B_i l^2 / (l^2 - C_i), l in micrometres,
 * C in square micrometres; Malitson's and Peter's papers give sqrt(C_i), written squared here. */
#include "generic/kit/dispersion.h"

#include <ctype.h>
#include <stdio.h>
#include <string.h>

#define SCHOTT "SCHOTT optical glass catalogue (Zemax catalogue 2017-01-20), as listed by refractiveindex.info"
#define SELLMEIER(b1, b2, b3, c1, c2, c3) {GDISPERSION_SELLMEIER, {b1, b2, b3, c1, c2, c3}}

static const GGlass glasses[] = {
    {"BK7", "SCHOTT N-BK7 (borosilicate crown)", SCHOTT, 300, 2500,
     SELLMEIER(1.03961212, 0.231792344, 1.01046945, 0.00600069867, 0.0200179144, 103.560653)},
    {"BAF10", "SCHOTT N-BAF10 (barium flint)", SCHOTT, 350, 2500,
     SELLMEIER(1.5851495, 0.143559385, 1.08521269, 0.00926681282, 0.0424489805, 105.613573)},
    {"F5", "SCHOTT F5 (flint)", SCHOTT, 320, 2500,
     SELLMEIER(1.3104463, 0.19603426, 0.96612977, 0.00958633048, 0.0457627627, 115.011883)},
    /* pbrt-v4's names glass-F10 and glass-F11 stand for the dense flints SF10 and SF11 */
    {"F10", "SCHOTT N-SF10 (pbrt-v4's glass-F10)", SCHOTT, 380, 2500,
     SELLMEIER(1.62153902, 0.256287842, 1.64447552, 0.0122241457, 0.0595736775, 147.468793)},
    {"F11", "SCHOTT N-SF11 (pbrt-v4's glass-F11)", SCHOTT, 370, 2500,
     SELLMEIER(1.73759695, 0.313747346, 1.89878101, 0.013188707, 0.0623068142, 155.23629)},
    {"FK51A", "SCHOTT N-FK51A (fluorite crown)", SCHOTT, 290, 2500,
     SELLMEIER(0.971247817, 0.216901417, 0.904651666, 0.00472301995, 0.0153575612, 168.68133)},
    {"LASF9", "SCHOTT N-LASF9 (lanthanum dense flint)", SCHOTT, 365, 2500,
     SELLMEIER(2.00029547, 0.298926886, 1.80691843, 0.0121426017, 0.0538736236, 156.530829)},
    {"SF5", "SCHOTT SF5 (dense flint)", SCHOTT, 350, 2500,
     SELLMEIER(1.46141885, 0.247713019, 0.949995832, 0.0111826126, 0.0508594669, 112.041888)},
    {"SF10", "SCHOTT N-SF10 (dense flint)", SCHOTT, 380, 2500,
     SELLMEIER(1.62153902, 0.256287842, 1.64447552, 0.0122241457, 0.0595736775, 147.468793)},
    {"SF11", "SCHOTT N-SF11 (dense flint)", SCHOTT, 370, 2500,
     SELLMEIER(1.73759695, 0.313747346, 1.89878101, 0.013188707, 0.0623068142, 155.23629)},
    {"fused silica", "fused silica (SiO2 glass) at 20 C",
     "I. H. Malitson, Interspecimen comparison of the refractive index of fused silica, J. Opt. Soc. Am. 55, "
     "1205-1208 (1965)", 210, 3710,
     SELLMEIER(0.6961663, 0.4079426, 0.8974794, 0.0684043 * 0.0684043, 0.1162414 * 0.1162414, 9.896161 * 9.896161)},
    /* Daimon and Masumura give four terms; their second and third (poles at 0.0182 and 0.0262 um^2) are merged
     * into one by a minimax fit over 360..830 nm, which stays within 4e-6 of their formula there */
    {"water", "distilled water at 20 C",
     "M. Daimon, A. Masumura, Measurement of the refractive index of distilled water from the near-infrared region "
     "to the ultraviolet region, Appl. Opt. 46, 3811-3820 (2007); terms 2 and 3 merged (within 4e-6, 360-830 nm)",
     182, 1129, SELLMEIER(0.5684027565, 0.1934522428, 0.1130748688, 0.005101829712, 0.01914323392, 10.69792721)},
    {"diamond", "diamond (cubic carbon) at room temperature",
     "F. Peter, Ueber Brechungsindizes und Absorptionskonstanten des Diamanten zwischen 644 und 226 mu, "
     "Z. Phys. 15, 358-368 (1923)", 226, 760, SELLMEIER(0.3306, 4.3356, 0.0, 0.1750 * 0.1750, 0.1060 * 0.1060, 0.0)},
};

enum { GLASS_COUNT = (int)(sizeof glasses / sizeof glasses[0]) };

int gdispersion_glass_count(void) { return GLASS_COUNT; }

const GGlass *gdispersion_glass_at(int i) { return i >= 0 && i < GLASS_COUNT ? &glasses[i] : NULL; }

/* The character as names compare: lower case, '_' as ' '. */
static int name_char(char c) { return c == '_' ? ' ' : tolower((unsigned char)c); }

const GGlass *gdispersion_glass_find(const char *name)
{
    if (!name)
        return NULL;
    for (int i = 0; i < GLASS_COUNT; i++) {
        const char *a = glasses[i].name, *b = name;
        while (*a && *b && name_char(*a) == name_char(*b))
            a++, b++;
        if (!*a && !*b)
            return &glasses[i];
    }
    return NULL;
}

const char *gdispersion_glass_names(char *buf, size_t size)
{
    size_t used = 0;
    if (!buf || size == 0)
        return buf;
    buf[0] = '\0';
    for (int i = 0; i < GLASS_COUNT && used < size; i++) {
        size_t start = used + (i ? 2 : 0);
        int n = snprintf(buf + used, size - used, "%s%s", i ? ", " : "", glasses[i].name);
        if (n < 0)
            break;
        used += (size_t)n;
        for (size_t k = start; k < used && k < size; k++) /* the form a file writes: fused_silica */
            buf[k] = buf[k] == ' ' ? '_' : buf[k];
    }
    return buf;
}
