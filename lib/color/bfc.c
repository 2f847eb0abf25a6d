/* bfc.c - Labsphere BFC-450 re-radiation matrix files (see include/generic/services/bfc.h for the layout). */
#include "generic/services/bfc.h"
#include "generic/memory.h"
#include "generic/services/file.h"
#include "core/c_number.h"

#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define HEADER_LINES 10
#define MAX_SIZE (16u * 1024u * 1024u)
#define MAX_COLUMNS 4096
#define MAX_TOKEN 255 /* longest number accepted; a longer one is an error, never split */

typedef struct Cursor {
    const char *name;
    const char *p, *end;
    int line;
    const char *line_start;
    const char *tok; /* start of the last number read */
    int trusted;     /* the grid line was valid: the file is a BFC file and its tokens may be quoted */
} Cursor;

/* Moves to the start of the next line. */
static void next_line(Cursor *c)
{
    while (c->p < c->end && *c->p != '\n')
        c->p++;
    if (c->p < c->end)
        c->p++;
    c->line++;
    c->line_start = c->p;
}

static int at_line_end(Cursor *c)
{
    while (c->p < c->end && (*c->p == ' ' || *c->p == '\t' || *c->p == '\r'))
        c->p++;
    return c->p >= c->end || *c->p == '\n';
}

static int col(const Cursor *c) { return (int)(c->p - c->line_start) + 1; }

static int fail(const Cursor *c, GError *err, const char *what)
{
    return gerror_set(err, G_ERR_PARSE, "%s:%d:%d: %s", c->name, c->line, col(c), what);
}

/* Reads one number on the current line: the whole whitespace-delimited token, which must be a finite decimal
 * number (a token longer than MAX_TOKEN is refused, not cut). Before the grid line has been read the file is not
 * known to be a BFC file, and nothing of it is quoted. */
static int number(Cursor *c, double *out, const char *what, GError *err)
{
    if (at_line_end(c)) {
        char msg[160];
        snprintf(msg, sizeof msg, "expected %s, found the end of the line", what);
        return fail(c, err, msg);
    }
    char buf[MAX_TOKEN + 1];
    size_t n = 0;
    const char *start = c->p;
    c->tok = start;
    while (c->p + n < c->end && !strchr(" \t\r\n", c->p[n]))
        n++;
    if (n > MAX_TOKEN) {
        char msg[160];
        snprintf(msg, sizeof msg, "expected %s, found a token of %zu characters (at most %d)", what, n, MAX_TOKEN);
        return fail(c, err, msg);
    }
    memcpy(buf, start, n);
    buf[n] = '\0';
    char *stop;
    errno = 0;
    double v = gnum_strtod(buf, &stop);
    if (*stop || !n || !isfinite(v) || strpbrk(buf, "nNiIxX")) {
        char msg[MAX_TOKEN + 160];
        if (c->trusted)
            snprintf(msg, sizeof msg, "expected %s, found '%s'", what, buf);
        else
            snprintf(msg, sizeof msg, "expected %s: not a BFC-450 matrix file", what);
        return fail(c, err, msg);
    }
    c->p = start + n;
    *out = v;
    return G_OK;
}

static int near(double a, double b) { return fabs(a - b) < 1e-6 * (fabs(a) + fabs(b) + 1.0); }

int gbfc_parse(const char *text, size_t len, const char *name, GBfcData *out, GError *err)
{
    memset(out, 0, sizeof *out);
    if (len >= 3 && memcmp(text, "\xef\xbb\xbf", 3) == 0) { /* a UTF-8 byte-order mark: not part of the text */
        text += 3;
        len -= 3;
    }
    Cursor c = {name ? name : "<bfc>", text, text + len, 1, text, text, 0};
    for (int i = 1; i <= HEADER_LINES; i++) {
        if (c.p >= c.end)
            return fail(&c, err, "file ends inside the 10 header lines");
        if (i == 4) {
            const char *s = c.p + (c.p < c.end && *c.p == ';');
            size_t n = 0;
            while (s + n < c.end && s[n] != '\n' && s[n] != '\r' && n + 1 < sizeof out->description)
                n++;
            memcpy(out->description, s, n);
            out->description[n] = '\0';
        }
        next_line(&c);
    }
    double g[6];
    static const char *const gnames[6] = {"the first emission wavelength", "the last emission wavelength",
                                          "the emission step", "the number of excitation columns",
                                          "the first excitation wavelength", "the excitation step"};
    for (int i = 0; i < 6; i++) {
        int rc = number(&c, &g[i], gnames[i], err);
        if (rc != G_OK)
            return rc;
    }
    double rows_f = (g[1] - g[0]) / g[2] + 1.0;
    if (!(g[2] > 0) || !(g[5] > 0) || !(g[1] >= g[0]) || fabs(rows_f - floor(rows_f + 0.5)) > 1e-6 ||
        rows_f > MAX_COLUMNS || g[3] != floor(g[3]) || g[3] < 1 || g[3] > MAX_COLUMNS) {
        c.p = c.line_start;
        return fail(&c, err, "invalid grid line (expected: out_min out_max out_step n_in in_min in_step)");
    }
    int n_out = (int)floor(rows_f + 0.5), n_in = (int)g[3];
    c.trusted = 1;
    next_line(&c);
    /* column labels */
    while (c.p < c.end && (*c.p == ' ' || *c.p == '\t'))
        c.p++;
    if (c.end - c.p < 4 || strncmp(c.p, "r:c:", 4) != 0)
        return fail(&c, err, "expected the column label row starting with 'r:c:'");
    c.p += 4;
    for (int j = 0; j < n_in; j++) {
        double v;
        int rc = number(&c, &v, "an excitation wavelength label", err);
        if (rc != G_OK)
            return rc;
        if (!near(v, g[4] + j * g[5]))
            return gerror_set(err, G_ERR_PARSE, "%s:%d:%d: column label %g does not match the grid (expected %g)",
                              c.name, c.line, (int)(c.tok - c.line_start) + 1, v, g[4] + j * g[5]);
    }
    if (!at_line_end(&c))
        return fail(&c, err, "more column labels than the grid line announces");
    next_line(&c);
    float *values = gmem_calloc((size_t)n_out * (size_t)n_in, sizeof *values);
    if (!values)
        return gerror_set(err, G_ERR_NOMEM, "out of memory reading %s", c.name);
    int rc = G_OK;
    for (int o = 0; o < n_out && rc == G_OK; o++) {
        double w;
        if ((rc = number(&c, &w, "an emission wavelength", err)) != G_OK)
            break;
        if (!near(w, g[0] + o * g[2])) {
            rc = gerror_set(err, G_ERR_PARSE, "%s:%d:1: row wavelength %g does not match the grid (expected %g)",
                            c.name, c.line, w, g[0] + o * g[2]);
            break;
        }
        for (int j = 0; j < n_in && rc == G_OK; j++) {
            double v;
            rc = number(&c, &v, "a matrix value", err);
            if (rc == G_OK && !(fabs(v) <= FLT_MAX)) /* would become infinite as a float */
                rc = gerror_set(err, G_ERR_PARSE, "%s:%d:%d: matrix value %g is out of range", c.name, c.line,
                                (int)(c.tok - c.line_start) + 1, v);
            if (rc == G_OK)
                values[(size_t)o * n_in + j] = (float)v;
        }
        if (rc == G_OK && !at_line_end(&c))
            rc = fail(&c, err, "more values on the row than the grid line announces");
        next_line(&c);
    }
    if (rc == G_OK) {
        while (c.p < c.end && (*c.p == ' ' || *c.p == '\t'))
            c.p++;
        if (c.end - c.p < 3 || strncmp(c.p, "EOD", 3) != 0)
            rc = fail(&c, err, "expected 'EOD' after the last row");
    }
    if (rc != G_OK) {
        gmem_free(values);
        memset(out, 0, sizeof *out);
        return rc;
    }
    out->values = values;
    out->rerad.in_min = g[4];
    out->rerad.in_step = g[5];
    out->rerad.n_in = n_in;
    out->rerad.out_min = g[0];
    out->rerad.out_step = g[2];
    out->rerad.n_out = n_out;
    out->rerad.data = values;
    return G_OK;
}

int gbfc_read(const char *path, GBfcData *out, GError *err)
{
    memset(out, 0, sizeof *out);
    char *text;
    size_t n;
    int rc = gfile_read_all(path, MAX_SIZE, &text, &n, err);
    if (rc == G_OK) {
        rc = gbfc_parse(text, n, path, out, err);
        gmem_free(text);
    }
    return rc;
}

void gbfc_free(GBfcData *d)
{
    if (!d)
        return;
    gmem_free(d->values);
    memset(d, 0, sizeof *d);
}
