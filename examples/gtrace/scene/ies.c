/* ies.c - a reader of IES LM-63 photometric files (LM-63-1986, -1995, -2002) and the intensity they describe.
 *
 * The file: an optional version line (IESNA:LM-63-1995, IESNA:LM-63-2002, IESNA91), keyword and free text lines
 * up to the line TILT=NONE | INCLUDE | FILENAME, then numbers separated by blanks, commas or line ends: for
 * TILT=INCLUDE the lamp-to-luminaire geometry, a count and that many angles and factors (read and checked; the lamp
 * is taken to burn as measured, so they are not applied); then the lamps, lumens per lamp (-1: absolute
 * photometry), the candela multiplier, the numbers of vertical and horizontal angles, the photometric type, the units,
 * the luminaire's width, length and height; the ballast factor, the ballast-lamp factor (1995; "future use" in 2002)
 * and the input watts; the vertical angles, the horizontal angles and the candela values, a horizontal angle's
 * vertical values together. Nothing may follow them.
 *
 * Every number is checked where it stands and refused at NAME:LINE:COL with the bound it breaks: a count that
 * disagrees with the values present (fewer: the file ends early; more: values after the table), a number that is
 * not one or not finite, an angle table out of the type's range, not increasing, or larger than IES_MAX_ANGLES, more
 * than IES_MAX_VALUES candela values, a negative candela value or factor. Photometric type A and TILT from another
 * file are G_ERR_UNSUPPORTED. The light that shines with such a table: lights/lights.c (LIGHT_IES). */
#include "ies.h"

#include <generic/memory.h>
#include <generic/services/file.h>

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define IES_MAX_HEADER_LINES 10000
#define IES_DEG (M_PI / 180.0)

/* A position in the text. */
typedef struct Cursor {
    const char *p, *end, *name;
    int line, col;
} Cursor;

static int fail_at(const Cursor *c, int line, int col, GError *err, int code, const char *fmt, ...)
    __attribute__((format(printf, 6, 7)));
static int fail_at(const Cursor *c, int line, int col, GError *err, int code, const char *fmt, ...)
{
    char msg[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return gerror_set(err, code, "%s:%d:%d: %s", c->name, line, col, msg);
}

static void advance(Cursor *c)
{
    if (*c->p == '\n')
        c->line++, c->col = 1;
    else
        c->col++;
    c->p++;
}

/* The rest of the current line (without its end) into [*b, *e), and the cursor at the next line. */
static void take_line(Cursor *c, const char **b, const char **e)
{
    *b = c->p;
    while (c->p < c->end && *c->p != '\n')
        c->p++;
    *e = c->p;
    if (*e > *b && (*e)[-1] == '\r')
        (*e)--;
    if (c->p < c->end)
        c->p++;
    c->line++;
    c->col = 1;
}

static int is_space(char ch) { return ch == ' ' || ch == '\t' || ch == '\r' || ch == '\n' || ch == ','; }

/* The next number: 1 with it and its position, 0 at the end of the text, or a status (a word that is not a
 * finite number). what names the value in messages. */
static int next_number(Cursor *c, const char *what, double *v, int *line, int *col, GError *err)
{
    while (c->p < c->end && is_space(*c->p))
        advance(c);
    if (c->p >= c->end)
        return 0;
    *line = c->line;
    *col = c->col;
    char word[64];
    size_t n = 0;
    while (c->p < c->end && !is_space(*c->p)) {
        if (n + 1 < sizeof word)
            word[n] = *c->p;
        n++;
        advance(c);
    }
    if (n >= sizeof word)
        return fail_at(c, *line, *col, err, G_ERR_INVALID, "%s: a word of %zu characters is not a number", what, n);
    word[n] = '\0';
    char *stop;
    *v = strtod(word, &stop);
    if (*stop != '\0' || stop == word)
        return fail_at(c, *line, *col, err, G_ERR_INVALID, "%s: '%s' is not a number", what, word);
    if (!isfinite(*v))
        return fail_at(c, *line, *col, err, G_ERR_INVALID, "%s: '%s' is not finite", what, word);
    return 1;
}

/* A number that must be there, within [lo, hi] (and whole when integral is set); *pos its line and column. */
static int need_number_at(Cursor *c, const char *what, double lo, double hi, int integral, double *v, int pos[2],
                          GError *err)
{
    int line, col;
    int rc = next_number(c, what, v, &line, &col, err);
    pos[0] = line;
    pos[1] = col;
    if (rc < 0)
        return rc;
    if (rc == 0)
        return fail_at(c, c->line, c->col, err, G_ERR_INVALID, "the file ends where %s is expected (truncated, or a "
                       "count above lies)", what);
    if (integral && *v != floor(*v))
        return fail_at(c, line, col, err, G_ERR_INVALID, "%s must be a whole number, not %g", what, *v);
    if (!(*v >= lo && *v <= hi))
        return fail_at(c, line, col, err, G_ERR_INVALID, "%s %g is outside [%g, %g]", what, *v, lo, hi);
    return G_OK;
}

static int need_number(Cursor *c, const char *what, double lo, double hi, int integral, double *v, GError *err)
{
    int pos[2];
    return need_number_at(c, what, lo, hi, integral, v, pos, err);
}

/* n angles within [lo, hi], strictly increasing. */
static int read_angles(Cursor *c, const char *what, int n, double lo, double hi, double *out, GError *err)
{
    for (int i = 0; i < n; i++) {
        int pos[2];
        int rc = need_number_at(c, what, lo, hi, 0, &out[i], pos, err);
        if (rc < 0)
            return rc;
        if (i > 0 && !(out[i] > out[i - 1]))
            return fail_at(c, pos[0], pos[1], err, G_ERR_INVALID, "%s %d (%g) does not increase on the one before "
                           "(%g)", what, i + 1, out[i], out[i - 1]);
    }
    return G_OK;
}

/* The header lines up to and including TILT=; the version into d. */
static int read_header(Cursor *c, IesData *d, int *tilt_include, GError *err)
{
    d->version = 1986;
    for (int k = 0; k < IES_MAX_HEADER_LINES; k++) {
        if (c->p >= c->end)
            return fail_at(c, c->line, 1, err, G_ERR_INVALID, "the file ends before its TILT= line");
        int line = c->line;
        const char *b, *e;
        take_line(c, &b, &e);
        while (b < e && (*b == ' ' || *b == '\t'))
            b++;
        size_t n = (size_t)(e - b);
        if (k == 0 && n >= 16 && strncmp(b, "IESNA:LM-63-2002", 16) == 0)
            d->version = 2002;
        else if (k == 0 && n >= 16 && strncmp(b, "IESNA:LM-63-1995", 16) == 0)
            d->version = 1995;
        else if (k == 0 && n >= 7 && strncmp(b, "IESNA91", 7) == 0)
            d->version = 1995;
        if (n >= 5 && strncmp(b, "TILT=", 5) == 0) {
            const char *v = b + 5;
            size_t vn = (size_t)(e - v);
            while (vn > 0 && (v[vn - 1] == ' ' || v[vn - 1] == '\t'))
                vn--;
            if (vn == 4 && strncmp(v, "NONE", 4) == 0) {
                *tilt_include = 0;
                return G_OK;
            }
            if (vn == 7 && strncmp(v, "INCLUDE", 7) == 0) {
                *tilt_include = 1;
                return G_OK;
            }
            return fail_at(c, line, 6, err, G_ERR_UNSUPPORTED, "TILT=%.*s: tilt data from another file is not read "
                           "(give TILT=NONE or TILT=INCLUDE)", (int)(vn < 200 ? vn : 200), v);
        }
    }
    return fail_at(c, c->line, 1, err, G_ERR_INVALID, "no TILT= line in the first %d lines", IES_MAX_HEADER_LINES);
}

/* TILT=INCLUDE's block: checked, not applied (the lamp burns as measured). */
static int read_tilt(Cursor *c, GError *err)
{
    double geometry, n, v;
    int rc;
    if ((rc = need_number(c, "the lamp-to-luminaire geometry", 1, 3, 1, &geometry, err)) < 0 ||
        (rc = need_number(c, "the number of tilt angles", 0, IES_MAX_ANGLES, 1, &n, err)) < 0)
        return rc;
    for (int i = 0; i < (int)n; i++)
        if ((rc = need_number(c, "a tilt angle", 0, 90, 0, &v, err)) < 0)
            return rc;
    for (int i = 0; i < (int)n; i++)
        if ((rc = need_number(c, "a tilt factor", 0, 1e6, 0, &v, err)) < 0)
            return rc;
    return G_OK;
}

/* The horizontal angle table's shape for its type: G_OK or the message. */
static int check_horizontal(Cursor *c, const IesData *d, GError *err)
{
    double first = d->h[0], last = d->h[d->nh - 1];
    if (d->type == IES_TYPE_C) {
        if (d->nh == 1 && first == 0.0)
            return G_OK;
        if (first == 0.0 && (last == 90.0 || last == 180.0 || last == 360.0))
            return G_OK;
        if (first == 90.0 && last == 270.0)
            return G_OK;
        return fail_at(c, c->line, c->col, err, G_ERR_INVALID, "type C horizontal angles from %g to %g: LM-63 allows "
                       "0 alone, 0 to 90, 180 or 360, or 90 to 270", first, last);
    }
    if (d->nh == 1 && first == 0.0)
        return G_OK;
    if ((first == 0.0 || first == -90.0) && last == 90.0)
        return G_OK;
    return fail_at(c, c->line, c->col, err, G_ERR_INVALID, "type B horizontal angles from %g to %g: LM-63 allows 0 "
                   "alone, 0 to 90 or -90 to 90", first, last);
}

void ies_free(IesData *d)
{
    gmem_free(d->v);
    gmem_free(d->h);
    gmem_free(d->cd);
    memset(d, 0, sizeof *d);
}

int ies_parse(const char *text, size_t len, const char *name, IesData *d, GError *err)
{
    memset(d, 0, sizeof *d);
    Cursor c = {text, text + len, name ? name : "IES file", 1, 1};
    if (memchr(text, '\0', len))
        return fail_at(&c, 1, 1, err, G_ERR_INVALID, "a NUL byte: not an IES text file");
    int tilt = 0, rc = read_header(&c, d, &tilt, err);
    if (rc == G_OK && tilt)
        rc = read_tilt(&c, err);
    double lamps, lumens, mult, nv, nh, type, units, w, l, h, ballast, blp, watts;
    if (rc < 0 || (rc = need_number(&c, "the number of lamps", 1, 1e6, 1, &lamps, err)) < 0 ||
        (rc = need_number(&c, "the lumens per lamp", -1, 1e12, 0, &lumens, err)) < 0 ||
        (rc = need_number(&c, "the candela multiplier", 0, 1e12, 0, &mult, err)) < 0 ||
        (rc = need_number(&c, "the number of vertical angles", 1, IES_MAX_ANGLES, 1, &nv, err)) < 0 ||
        (rc = need_number(&c, "the number of horizontal angles", 1, IES_MAX_ANGLES, 1, &nh, err)) < 0)
        goto fail;
    int type_line = c.line, type_col = c.col;
    if ((rc = need_number(&c, "the photometric type", 1, 3, 1, &type, err)) < 0 ||
        (rc = need_number(&c, "the units type", 1, 2, 1, &units, err)) < 0 ||
        (rc = need_number(&c, "the luminaire's width", -1e6, 1e6, 0, &w, err)) < 0 ||
        (rc = need_number(&c, "the luminaire's length", -1e6, 1e6, 0, &l, err)) < 0 ||
        (rc = need_number(&c, "the luminaire's height", -1e6, 1e6, 0, &h, err)) < 0 ||
        (rc = need_number(&c, "the ballast factor", 0, 1e6, 0, &ballast, err)) < 0 ||
        (rc = need_number(&c, "the ballast-lamp photometric factor", 0, 1e6, 0, &blp, err)) < 0 ||
        (rc = need_number(&c, "the input watts", -1e12, 1e12, 0, &watts, err)) < 0)
        goto fail;
    if (type == 3) {
        rc = fail_at(&c, type_line, type_col, err, G_ERR_UNSUPPORTED, "photometric type A (3) is not read (types C and "
                     "B are)");
        goto fail;
    }
    if (nv * nh > IES_MAX_VALUES) {
        rc = fail_at(&c, type_line, type_col, err, G_ERR_INVALID, "%g x %g candela values: more than %d", nv, nh,
                     IES_MAX_VALUES);
        goto fail;
    }
    d->type = (int)type;
    d->nv = (int)nv;
    d->nh = (int)nh;
    d->lumens = lumens > 0.0 ? lamps * lumens : -1.0;
    d->v = gmem_alloc(sizeof *d->v * (size_t)d->nv);
    d->h = gmem_alloc(sizeof *d->h * (size_t)d->nh);
    d->cd = gmem_alloc(sizeof *d->cd * (size_t)d->nv * (size_t)d->nh);
    if (!d->v || !d->h || !d->cd) {
        rc = gerror_set(err, G_ERR_NOMEM, "%s: out of memory for %d x %d candela values", c.name, d->nv, d->nh);
        goto fail;
    }
    double vlo = d->type == IES_TYPE_C ? 0.0 : -90.0, vhi = d->type == IES_TYPE_C ? 180.0 : 90.0;
    double hlo = d->type == IES_TYPE_C ? 0.0 : -90.0, hhi = d->type == IES_TYPE_C ? 360.0 : 90.0;
    if ((rc = read_angles(&c, "vertical angle", d->nv, vlo, vhi, d->v, err)) < 0 ||
        (rc = read_angles(&c, "horizontal angle", d->nh, hlo, hhi, d->h, err)) < 0 ||
        (rc = check_horizontal(&c, d, err)) < 0)
        goto fail;
    double k = mult * ballast * blp;
    for (size_t i = 0; i < (size_t)d->nv * (size_t)d->nh; i++) {
        if ((rc = need_number(&c, "a candela value", 0, 1e15, 0, &d->cd[i], err)) < 0)
            goto fail;
        d->cd[i] *= k;
    }
    double extra;
    int line, col;
    if ((rc = next_number(&c, "after the candela table", &extra, &line, &col, err)) != 0) {
        if (rc > 0)
            rc = fail_at(&c, line, col, err, G_ERR_INVALID, "a value after the %d x %d candela values the counts "
                         "announce (a count lies)", d->nh, d->nv);
        goto fail;
    }
    (void)units, (void)w, (void)l, (void)h, (void)watts;
    return G_OK;
fail:
    ies_free(d);
    return rc;
}

int ies_read(const char *path, IesData *d, GError *err)
{
    char *text = NULL;
    size_t len = 0;
    memset(d, 0, sizeof *d);
    int rc = gfile_read_all(path, IES_MAX_FILE_SIZE, &text, &len, err);
    if (rc != G_OK)
        return rc;
    rc = ies_parse(text, len, path, d, err);
    gmem_free(text);
    return rc;
}

/* The interval of sorted a[0..n) holding x: i with a[i] <= x <= a[i + 1] and the fraction, or -1 outside. */
static int bracket(const double *a, int n, double x, double *f)
{
    if (n == 1) {
        *f = 0.0;
        return x == a[0] ? 0 : -1;
    }
    if (!(x >= a[0] && x <= a[n - 1]))
        return -1;
    int lo = 0, hi = n - 1;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (a[mid] <= x)
            lo = mid;
        else
            hi = mid;
    }
    *f = (x - a[lo]) / (a[lo + 1] - a[lo]);
    return lo;
}

/* The horizontal angle folded into the table's range by its symmetry. */
static double fold_horizontal(const IesData *d, double hz)
{
    double first = d->h[0], last = d->h[d->nh - 1];
    if (d->type == IES_TYPE_B)
        return first == 0.0 ? fabs(hz) : hz;
    hz = fmod(hz, 360.0);
    if (hz < 0.0)
        hz += 360.0;
    if (d->nh == 1)
        return first;
    if (first == 90.0) { /* 90 to 270: symmetric about the 90-270 plane */
        if (hz < 90.0)
            hz = 180.0 - hz;
        else if (hz > 270.0)
            hz = 540.0 - hz;
        return hz;
    }
    if (last == 360.0)
        return hz;
    if (hz > 180.0) /* 0 to 180 and 0 to 90: symmetric about the 0-180 plane */
        hz = 360.0 - hz;
    if (last == 90.0 && hz > 90.0) /* 0 to 90: about the 90-270 plane too */
        hz = 180.0 - hz;
    return hz;
}

double ies_candela(const IesData *d, double vertical, double horizontal)
{
    double fv, fh;
    int iv = bracket(d->v, d->nv, vertical, &fv);
    if (iv < 0)
        return 0.0;
    int ih = bracket(d->h, d->nh, fold_horizontal(d, horizontal), &fh);
    if (ih < 0)
        return 0.0;
    int iv1 = d->nv > 1 ? iv + 1 : iv, ih1 = d->nh > 1 ? ih + 1 : ih;
    const double *row0 = d->cd + (size_t)ih * d->nv, *row1 = d->cd + (size_t)ih1 * d->nv;
    double a = row0[iv] + fv * (row0[iv1] - row0[iv]), b = row1[iv] + fv * (row1[iv1] - row1[iv]);
    return a + fh * (b - a);
}

double ies_candela_dir(const IesData *d, GVec3 dir, GVec3 aim, GVec3 along, GVec3 third)
{
    double a = gvec3_dot(dir, aim), x = gvec3_dot(dir, along), y = gvec3_dot(dir, third);
    if (d->type == IES_TYPE_C)
        return ies_candela(d, acos(fmax(-1.0, fmin(1.0, a))) / IES_DEG, atan2(y, x) / IES_DEG);
    /* type B: the plane's rotation about the polar axis `along`, and the lateral angle towards it */
    return ies_candela(d, atan2(y, a) / IES_DEG, asin(fmax(-1.0, fmin(1.0, x))) / IES_DEG);
}

double ies_flux(const IesData *d)
{
    /* midpoint sums of I dOmega in 0.25 degree steps: type C over (vertical 0..180, horizontal 0..360) with
     * dOmega = sin V dV dH (one step around the axis of a symmetric table); type B over (vertical -180..180,
     * lateral -90..90) with dOmega = cos H dV dH */
    int nv = 720, nh = d->nh == 1 && d->type == IES_TYPE_C ? 1 : 1440;
    double sum = 0.0;
    if (d->type == IES_TYPE_C) {
        double dv = 180.0 / nv, dh = 360.0 / nh;
        for (int i = 0; i < nv; i++) {
            double v = (i + 0.5) * dv, s = 0.0;
            for (int j = 0; j < nh; j++)
                s += ies_candela(d, v, (j + 0.5) * dh);
            sum += s * sin(v * IES_DEG) * dv * IES_DEG * dh * IES_DEG;
        }
        return sum;
    }
    nv = 1440;
    nh = 720;
    double dv = 360.0 / nv, dh = 180.0 / nh;
    for (int j = 0; j < nh; j++) {
        double hz = -90.0 + (j + 0.5) * dh, s = 0.0;
        for (int i = 0; i < nv; i++)
            s += ies_candela(d, -180.0 + (i + 0.5) * dv, hz);
        sum += s * cos(hz * IES_DEG) * dv * IES_DEG * dh * IES_DEG;
    }
    return sum;
}
