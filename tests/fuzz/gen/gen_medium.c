/* gen_medium.c - gtrace's participating-media entries (examples/gtrace/media/): media and phase functions with
 * coefficients, scales and mean cosines at and beyond their bounds (negative, NaN-like words, huge, g at +-1),
 * references to phases and media defined, undefined or of the wrong kind, and long chains of named phases; an entry
 * wrong by construction carries GEN_MUST_FAIL in a comment, so the harness knows it must be refused. */
#include "gen.h"

#include <stdio.h>

static const char *const g_ok_numbers[] = {"0", "0.5", "1", "2", "9", "1e-9", "1e3", "1e6"};
static const char *const g_bad_numbers[] = {"-1", "-1e-300", "-0.001", "1e10", "1e308", "-1e308"};
static const char *const g_ok_g[] = {"0", "0.7", "-0.7", "0.999999", "-0.999999", "1e-9"};
static const char *const g_bad_g[] = {"1", "-1", "1.5", "-2", "1e308", "-1e308"};

/* A colour of three numbers, one of them bad when bad is set. */
static void sigma(GenBuf *b, GenRng *r, int bad)
{
    int which = bad ? (int)gen_below(r, 3) : -1;
    gb_printf(b, " rgb");
    for (int k = 0; k < 3; k++)
        gb_printf(b, " %s", k == which ? GEN_PICK(r, g_bad_numbers) : GEN_PICK(r, g_ok_numbers));
}

/* One medium or phase entry; *wrong is set when it is wrong by construction (a mean cosine or a scale out of range:
 * refused in every colour model; a coefficient's sign or size may change in a model's conversion, so an extreme
 * colour is written but not marked). */
static void entry(GenBuf *b, GenRng *r, unsigned long i, int may_be_wrong, int *wrong)
{
    int bad = 0;
    switch (gen_below(r, 4)) {
    case 0:
        bad = may_be_wrong;
        gb_printf(b, "phase p%lu hg { g %s }\n", i, bad ? GEN_PICK(r, g_bad_g) : GEN_PICK(r, g_ok_g));
        break;
    case 1:
        gb_printf(b, "phase p%lu isotropic { }\n", i);
        break;
    case 2:
        bad = may_be_wrong;
        gb_printf(b, "medium m%lu homogeneous { sigma_a", i);
        sigma(b, r, gen_below(r, 8) == 0);
        gb_printf(b, " sigma_s");
        sigma(b, r, 0);
        if (bad)
            gb_printf(b, " scale %s", GEN_PICK(r, g_bad_numbers));
        else if (i > 0 && gen_below(r, 2))
            gb_printf(b, " phase p%lu", (unsigned long)gen_below(r, i)); /* may name a medium or nothing */
        gb_printf(b, " }\n");
        break;
    default:
        gb_printf(b, "medium m%lu homogeneous { sigma_s", i);
        sigma(b, r, gen_below(r, 8) == 0);
        gb_printf(b, " phase hg { g %s } }\n", GEN_PICK(r, g_ok_g));
    }
    if (bad && !*wrong) {
        gb_printf(b, "# %s\n", GEN_MUST_FAIL);
        *wrong = 1;
    }
}

/* Entries up to the budget; one input in three has one entry wrong by construction, at a random place. */
static void many_media(GenBuf *b, GenRng *r, size_t budget)
{
    int wrong = 0;
    unsigned long wrong_at = gen_below(r, 3) == 0 ? (unsigned long)gen_below(r, 1 + budget / 100) : (unsigned long)-1;
    for (unsigned long i = 0; b->n + 200 < budget && !wrong; i++)
        entry(b, r, i, i >= wrong_at, &wrong);
}

/* A chain of named phases and media referring to earlier ones: the reader resolves names, never recursion. */
static void phase_chain(GenBuf *b, GenRng *r, size_t budget)
{
    gb_printf(b, "phase p0 hg { g %s }\n", GEN_PICK(r, g_ok_g));
    for (unsigned long i = 1; b->n + 200 < budget; i++)
        gb_printf(b, "medium m%lu homogeneous { sigma_s rgb 1 1 1 phase p%lu }\nphase p%lu isotropic { }\n", i,
                  (unsigned long)gen_below(r, i), i);
}

const GenFamily gen_medium_families[] = {
    {"many-media", ".scene", many_media},
    {"phase-chain", ".scene", phase_chain},
};
const int gen_medium_count = (int)(sizeof gen_medium_families / sizeof gen_medium_families[0]);
