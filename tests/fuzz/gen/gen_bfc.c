/* gen_bfc.c - BFC-450 matrices (include/generic/services/bfc.h) with long tokens, grids far from any colour model's,
 * grids that claim more rows or columns than the file holds, and rows one value short or long. */
#include "gen.h"

#include <stdio.h>
#include <stdlib.h>

/* The 10 header lines; the description (line 4) carries GEN_MUST_FAIL when the matrix is wrong by construction. */
static void header(GenBuf *b, int must_fail)
{
    gb_printf(b, "VEC_01\t3\nBFC-450 Matrix File\n;gen.BFC\n;%s\n;x\n;<none>\n;x\n;x\n;01/01/2000\n;00:00:00\n",
              must_fail ? GEN_MUST_FAIL : "generated");
}

/* The grid line, the labels and the rows of a matrix: emission out0..out0+(rows-1)*ostep, n_in excitations. */
static void body(GenBuf *b, GenRng *r, double out0, double ostep, int rows, double in0, double istep, int n_in,
                 int short_row)
{
    gb_printf(b, "%.17g\t%.17g\t%.17g\t%d\t%.17g\t%.17g\n", out0, out0 + (rows - 1) * ostep, ostep, n_in, in0, istep);
    gb_printf(b, "r:c:");
    for (int j = 0; j < n_in; j++)
        gb_printf(b, "\t%.17g", in0 + j * istep);
    gb_byte(b, '\n');
    for (int o = 0; o < rows; o++) {
        gb_printf(b, "%.17g", out0 + o * ostep);
        int n = o == short_row ? n_in - 1 : n_in;
        for (int j = 0; j < n; j++)
            gb_printf(b, "\t%.4f", gen_unit(r) * 0.5);
        gb_byte(b, '\n');
    }
    gb_printf(b, "EOD\n");
}

/* A number longer than any token buffer, in the grid, a label or a value. */
static void long_number(GenBuf *b, GenRng *r, size_t budget)
{
    static const size_t lengths[] = {63, 64, 65, 127, 128, 4096};
    size_t len = gen_below(r, 4) ? lengths[gen_below(r, 6)] : (budget > 2048 ? budget - 2048 : 64);
    int where = (int)gen_below(r, 3);
    header(b, where == 2);
    if (where == 0) { /* the first number of the grid line: 400 followed by zeros after the point */
        gb_printf(b, "400.");
        gb_fill(b, '0', len);
        gb_printf(b, "\t420\t10\t3\t400\t10\n");
    } else {
        gb_printf(b, "400\t420\t10\t3\t400\t10\n");
    }
    gb_printf(b, "r:c:\t400\t");
    if (where == 1) /* a label: 410 written with many leading zeros */
        gb_fill(b, '0', len);
    gb_printf(b, "410\t420\n");
    for (int o = 0; o < 3; o++) {
        gb_printf(b, "%d", 400 + 10 * o);
        for (int j = 0; j < 3; j++) {
            if (where == 2 && o == 1 && j == 1) { /* 0.1 then many digits: split in two, they would look like */
                gb_printf(b, "\t0.1");           /* two values and hide the missing third */
                gb_fill(b, '0', len);
                gb_printf(b, "5");
                break;
            }
            gb_printf(b, "\t0.%d", (int)gen_below(r, 10));
        }
        gb_byte(b, '\n');
    }
    gb_printf(b, "EOD\n");
}

/* A grid at the edge of doubles, of floats, of int, or far beyond 300..780 nm. */
static void far_grid(GenBuf *b, GenRng *r, size_t budget)
{
    (void)budget;
    static const double starts[] = {1e300, -1e300, 1e18, 1.8e19, 3e38, 1e-300, 0, -400, 2147483647.0, 1e9};
    static const double steps[] = {10, 1e-300, 1e300, 1e-9, 0.5, 1e18, 5e-324, 1};
    header(b, 0);
    body(b, r, starts[gen_below(r, 10)], steps[gen_below(r, 8)], 2 + (int)gen_below(r, 3), starts[gen_below(r, 10)],
         steps[gen_below(r, 8)], 2 + (int)gen_below(r, 3), -1);
}

/* A grid line claiming millions of rows or columns over a body of a few bytes. */
static void huge_grid(GenBuf *b, GenRng *r, size_t budget)
{
    (void)budget;
    static const char *const grids[] = {
        "300\t780\t1e-6\t49\t300\t10",     "300\t3e9\t1\t49\t300\t10",        "300\t780\t10\t2147483647\t300\t10",
        "300\t780\t10\t4096\t300\t10",     "300\t780\t10\t4097\t300\t10",     "300\t780\t10\t-5\t300\t10",
        "300\t780\t10\t1e300\t300\t10",    "780\t300\t10\t49\t300\t10",       "300\t780\t0\t49\t300\t10",
        "300\t780\t-10\t49\t300\t10",      "300\t780\t1e-300\t3\t300\t1e-300", "300\t780\t10\t3.5\t300\t10"};
    header(b, 1); /* every grid claims more (or other) than the body holds */
    gb_printf(b, "%s\nr:c:\t300\t310\t320\n300\t0.1\t0.2\t0.3\n", GEN_PICK(r, grids));
    if (gen_below(r, 2))
        gb_printf(b, "EOD\n");
}

/* An ordinary 41x49 matrix with one thing wrong: a short row, CRLF, NUL or a truncation. */
static void lying_rows(GenBuf *b, GenRng *r, size_t budget)
{
    (void)budget;
    int rows = 41, n_in = 49, form = (int)gen_below(r, 4);
    int short_row = gen_below(r, 2) ? (int)gen_below(r, rows) : -1;
    header(b, short_row >= 0 || form == 0 || form == 3);
    size_t start = b->n;
    body(b, r, 380, 10, rows, 300, 10, n_in, short_row);
    switch (form) {
    case 0: /* truncate anywhere before the EOD line */
        b->n = start + gen_below(r, b->n - 4 - start);
        break;
    case 1: /* a NUL inside */
        b->p[start + gen_below(r, b->n - start)] = 0;
        break;
    case 2: { /* CRLF line ends */
        GenBuf c = {0};
        for (size_t i = 0; i < b->n; i++) {
            if (b->p[i] == '\n')
                gb_byte(&c, '\r');
            gb_byte(&c, b->p[i]);
        }
        free(b->p);
        *b = c;
        break;
    }
    default: /* a value replaced by a word, NaN or infinity */
    {
        static const char *const words[] = {"nan", "inf", "-inf", "1e999", "abc", "--1"};
        size_t at = b->n / 2;
        while (at < b->n && b->p[at] != '\t')
            at++;
        GenBuf c = {0};
        gb_put(&c, b->p, at + (at < b->n));
        gb_printf(&c, "%s", gen_pick(r, words, 6));
        while (at + 1 < b->n && b->p[at + 1] != '\t' && b->p[at + 1] != '\n')
            at++;
        if (at + 1 < b->n)
            gb_put(&c, b->p + at + 1, b->n - at - 1);
        free(b->p);
        *b = c;
    }
    }
}

const GenFamily gen_bfc_families[] = {
    {"long-number", ".BFC", long_number},
    {"far-grid", ".BFC", far_grid},
    {"huge-grid", ".BFC", huge_grid},
    {"lying-rows", ".BFC", lying_rows},
};
const int gen_bfc_count = (int)(sizeof gen_bfc_families / sizeof gen_bfc_families[0]);
