/* gen_ies.c - IES LM-63 files (gtrace's examples/gtrace/scene/ies.c) whose counts lie, that end early, carry NaN,
 * infinity or words among the numbers, claim huge angle tables, have angles out of order or range, long headers and
 * tokens; and valid tables as large as the budget allows. A file wrong by construction carries GEN_MUST_FAIL in a
 * keyword line of its header. */
#include "gen.h"

#include <stdio.h>
#include <stdlib.h>

/* The header up to TILT=NONE (the mark in a keyword line when must_fail). */
static void header(GenBuf *b, GenRng *r, int must_fail)
{
    static const char *const versions[] = {"IESNA:LM-63-2002", "IESNA:LM-63-1995", "IESNA91", "[TEST] 1986"};
    gb_printf(b, "%s\n[TEST] %s\n[MANUFAC] gen\n", GEN_PICK(r, versions), must_fail ? GEN_MUST_FAIL : "generated");
    if (gen_below(r, 4) == 0)
        gb_printf(b, "TILT=INCLUDE\n1\n2\n0 90\n1 1\n");
    else
        gb_printf(b, "TILT=NONE\n");
}

/* A table of type C (0..90 or full) or B, with nv x nh values: the counts line as claimed, then the data of the
 * real sizes rv x rh (fewer or more values than claimed when they differ). */
static void table(GenBuf *b, GenRng *r, int type, int nv, int nh, int rv, int rh)
{
    gb_printf(b, "1 %d 1 %d %d %d 2 0.1 0.2 0.3\n1 1 50\n", 1000 + (int)gen_below(r, 9000), nv, nh, type);
    double v0 = type == 1 ? 0.0 : -90.0, v1 = type == 1 ? 180.0 : 90.0;
    double h0 = type == 1 ? 0.0 : -90.0, h1 = type == 1 ? 360.0 : 90.0;
    for (int i = 0; i < rv; i++)
        gb_printf(b, "%.6f%c", rv > 1 ? v0 + (v1 - v0) * i / (rv - 1) : v0, i % 10 == 9 ? '\n' : ' ');
    gb_byte(b, '\n');
    for (int j = 0; j < rh; j++)
        gb_printf(b, "%.6f%c", rh > 1 ? h0 + (h1 - h0) * j / (rh - 1) : 0.0, j % 10 == 9 ? '\n' : ' ');
    gb_byte(b, '\n');
    for (long k = 0; k < (long)rv * rh; k++)
        gb_printf(b, "%.2f%c", 1000.0 * gen_unit(r), k % 10 == 9 ? '\n' : ' ');
    gb_byte(b, '\n');
}

/* The largest square-ish table the budget holds (about 9 bytes a value), valid. */
static void valid_large(GenBuf *b, GenRng *r, size_t budget)
{
    long values = (long)(budget / 10);
    if (values > 1000000)
        values = 1000000;
    int nh = 2 + (int)gen_below(r, 360), nv = (int)(values / nh);
    if (nv > 1441)
        nv = 1441;
    if (nv < 2)
        nv = 2;
    header(b, r, 0);
    table(b, r, gen_below(r, 2) ? 1 : 2, nv, nh, nv, nh);
}

/* Counts that differ from the data by one or many, either way. */
static void lying_counts(GenBuf *b, GenRng *r, size_t budget)
{
    int nv = 2 + (int)gen_log(r, 1, budget / 200 > 1400 ? 1400 : budget / 200 + 1), nh = 1 + (int)gen_below(r, 4);
    if (nh > 1)
        nh = 37;
    int rv = nv, rh = nh, lie = (int)gen_below(r, 4);
    if (lie == 0)
        nv += 1 + (int)gen_below(r, 3); /* claims more than given */
    else if (lie == 1)
        rv += 1 + (int)gen_below(r, 3); /* gives more than claimed */
    else if (lie == 2)
        nh = nh > 1 ? nh + 1 : 2;
    else
        nv = (int)gen_log(r, 2000, 100000000); /* beyond the limit */
    header(b, r, 1);
    table(b, r, 1, nv, nh, rv, rh);
}

/* A valid table cut short anywhere in its numbers. */
static void truncated(GenBuf *b, GenRng *r, size_t budget)
{
    int nv = 2 + (int)gen_log(r, 1, budget / 100 > 1400 ? 1400 : budget / 100 + 1);
    header(b, r, 1);
    size_t start = b->n;
    table(b, r, 1, nv, 1, nv, 1);
    size_t keep = start + (size_t)((b->n - start) * gen_unit(r) * 0.95);
    while (keep > start && b->p[keep - 1] != ' ' && b->p[keep - 1] != '\n')
        keep--; /* at a token's end, so no shorter number is left that might still count */
    b->n = keep;
}

/* A value replaced by NaN, infinity or a word. */
static void bad_number(GenBuf *b, GenRng *r, size_t budget)
{
    static const char *const words[] = {"nan", "inf", "-inf", "1e999", "abc", "--1", "0x", "1.2.3", "-nan"};
    int nv = 2 + (int)gen_log(r, 1, budget / 100 > 1400 ? 1400 : budget / 100 + 1);
    header(b, r, 1);
    size_t start = b->n;
    table(b, r, 1, nv, 1, nv, 1);
    size_t at = start + (size_t)((b->n - start) * gen_unit(r));
    while (at > start && b->p[at - 1] != ' ' && b->p[at - 1] != '\n')
        at--;
    size_t end = at;
    while (end < b->n && b->p[end] != ' ' && b->p[end] != '\n')
        end++;
    GenBuf c = {0};
    gb_put(&c, b->p, at);
    gb_printf(&c, "%s", GEN_PICK(r, words));
    gb_put(&c, b->p + end, b->n - end);
    free(b->p);
    *b = c;
}

/* Angles out of order or out of range, and horizontal tables LM-63 does not allow. */
static void bad_angles(GenBuf *b, GenRng *r, size_t budget)
{
    (void)budget;
    int what = (int)gen_below(r, 4);
    header(b, r, 1);
    if (what == 0)
        gb_printf(b, "1 1000 1 3 1 1 2 0 0 0\n1 1 50\n0 90 45\n0\n1 2 3\n");
    else if (what == 1)
        gb_printf(b, "1 1000 1 3 1 1 2 0 0 0\n1 1 50\n0 90 181\n0\n1 2 3\n");
    else if (what == 2)
        gb_printf(b, "1 1000 1 2 2 1 2 0 0 0\n1 1 50\n0 90\n0 45\n1 2 3 4\n");
    else
        gb_printf(b, "1 1000 1 2 1 3 2 0 0 0\n1 1 50\n0 90\n0\n1 2\n");
}

/* A header of many lines, or one long token among the numbers. */
static void long_text(GenBuf *b, GenRng *r, size_t budget)
{
    size_t len = budget > 4096 ? budget - 4096 : 1024;
    if (gen_below(r, 2)) { /* many keyword lines before TILT: refused beyond the 10000 the reader looks through */
        size_t lines = len / 20;
        gb_printf(b, "IESNA:LM-63-2002\n[TEST] %s\n", lines > 10000 ? GEN_MUST_FAIL : "long");
        for (size_t n = 0; n < lines; n++)
            gb_printf(b, "[MORE] line %09zu\n", n);
        gb_printf(b, "TILT=NONE\n1 1000 1 2 1 1 2 0 0 0\n1 1 50\n0 90\n0\n1 2\n");
        return;
    }
    header(b, r, 1);
    gb_printf(b, "1 1000 1 2 1 1 2 0 0 0\n1 1 50\n0 90\n0\n1 0.");
    gb_fill(b, '0', len);
    gb_printf(b, "5\n");
}

const GenFamily gen_ies_families[] = {
    {"valid-large", ".ies", valid_large}, {"lying-counts", ".ies", lying_counts}, {"truncated", ".ies", truncated},
    {"bad-number", ".ies", bad_number},   {"bad-angles", ".ies", bad_angles},     {"long-text", ".ies", long_text},
};
const int gen_ies_count = (int)(sizeof gen_ies_families / sizeof gen_ies_families[0]);
