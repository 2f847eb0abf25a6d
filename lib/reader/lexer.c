/* lexer.c - splits the text format into tokens: identifiers, numbers, strings, punctuation; `#` comments. */
#include "lexer.h"
#include "core/c_number.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

void glexer_init(GLexer *lx, const char *name, const char *text, size_t len)
{
    lx->name = name;
    lx->src = text;
    lx->len = len;
    lx->pos = 0;
    lx->line = 1;
    lx->col = 1;
    lx->quiet = 0;
    if (len >= 3 && memcmp(text, "\xef\xbb\xbf", 3) == 0) /* a UTF-8 byte-order mark: not part of the text */
        lx->pos = 3;
}

static int peekc(const GLexer *lx, size_t ahead)
{
    return lx->pos + ahead < lx->len ? (unsigned char)lx->src[lx->pos + ahead] : -1;
}

static void advance(GLexer *lx)
{
    if (lx->pos >= lx->len)
        return;
    if (lx->src[lx->pos] == '\n') {
        lx->line++;
        lx->col = 1;
    } else {
        lx->col++;
    }
    lx->pos++;
}

static int fail(const GLexer *lx, GError *err, int line, int col, const char *fmt, const char *arg)
{
    char msg[400];
    if (lx->quiet) /* a file that does not start with a statement: say so, and quote nothing of it */
        snprintf(msg, sizeof msg, "%s", GLEX_FOREIGN_MESSAGE);
    else
        snprintf(msg, sizeof msg, fmt, arg);
    gerror_set(err, G_ERR_PARSE, "%s:%d:%d: %s", lx->name, line, col, msg);
    if (err) {
        err->line = line;
        err->col = col;
    }
    return G_ERR_PARSE;
}

static void printable(int c, char *buf, size_t size)
{
    if (c >= 0x20 && c < 0x7f)
        snprintf(buf, size, "'%c'", c);
    else
        snprintf(buf, size, "byte 0x%02x", (unsigned)c & 0xffu);
}

static int is_ident_start(int c) { return isalpha(c) || c == '_'; }
static int is_ident_char(int c) { return isalnum(c) || c == '_' || c == '.' || c == '-'; }

/* Checks the strict decimal form [+-]?(D+(.D*)?|.D+)([eE][+-]?D+)? */
/* A number of valid_number's form read exactly without strtod, when that is cheap: at most 15 significant digits
 * M and a decimal exponent e (the value M x 10^e) with |e| <= 22. M and 10^|e| are then exact doubles, so the one
 * multiplication or division rounds the exact value once, to nearest: the correctly rounded result strtod gives
 * (Clinger's fast path). 1 with *v, or 0 when the number needs strtod. */
static int fast_number(const char *s, double *v)
{
    static const double pow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                   1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    int neg = *s == '-';
    if (*s == '+' || *s == '-')
        s++;
    unsigned long long m = 0;
    int sig = 0, e = 0;
    for (; isdigit((unsigned char)*s); s++)
        if (m || *s != '0') {
            if (++sig > 15)
                return 0;
            m = 10 * m + (unsigned)(*s - '0');
        }
    if (*s == '.')
        for (s++; isdigit((unsigned char)*s); s++) {
            if (m || *s != '0') {
                if (++sig > 15)
                    return 0;
                m = 10 * m + (unsigned)(*s - '0');
            }
            e--;
        }
    if (*s == 'e' || *s == 'E') {
        s++;
        int eneg = *s == '-', x = 0;
        if (*s == '+' || *s == '-')
            s++;
        for (; isdigit((unsigned char)*s); s++)
            if ((x = 10 * x + (*s - '0')) > 1000)
                return 0;
        e += eneg ? -x : x;
    }
    if (*s || e > 22 || e < -22)
        return 0;
    double d = (double)m;
    d = e >= 0 ? d * pow10[e] : d / pow10[-e];
    *v = neg ? -d : d;
    return 1;
}

static int valid_number(const char *s)
{
    const char *p = s;
    int digits = 0;
    if (*p == '+' || *p == '-')
        p++;
    while (isdigit((unsigned char)*p))
        p++, digits++;
    if (*p == '.') {
        p++;
        while (isdigit((unsigned char)*p))
            p++, digits++;
    }
    if (!digits)
        return 0;
    if (*p == 'e' || *p == 'E') {
        p++;
        if (*p == '+' || *p == '-')
            p++;
        if (!isdigit((unsigned char)*p))
            return 0;
        while (isdigit((unsigned char)*p))
            p++;
    }
    return *p == '\0';
}

static int scan_number(GLexer *lx, GLexToken *out, GError *err)
{
    int line = lx->line, col = lx->col;
    size_t n = 0;
    int c;
    /* a number holds no line break: the column moves by its length */
    const unsigned char *src = (const unsigned char *)lx->src;
    for (; lx->pos < lx->len; lx->pos++, lx->col++) {
        c = src[lx->pos];
        int prev = n ? out->text[n - 1] : 0;
        int sign = (c == '+' || c == '-') && (n == 0 || prev == 'e' || prev == 'E');
        if (!(is_ident_char(c) && c != '-') && !sign)
            break;
        if (n + 1 >= GLEX_TEXT_MAX)
            return fail(lx, err, line, col, "%s", "number too long");
        out->text[n++] = (char)c;
    }
    out->text[n] = '\0';
    const char *body = out->text + (out->text[0] == '+' || out->text[0] == '-');
    int c0 = tolower((unsigned char)*body);
    if ((c0 == 'n' || c0 == 'i') &&
        (strcasecmp(body, "nan") == 0 || strcasecmp(body, "inf") == 0 || strcasecmp(body, "infinity") == 0))
        return fail(lx, err, line, col, "'%s' is not allowed: numbers must be finite", out->text);
    if (!valid_number(out->text))
        return fail(lx, err, line, col, "bad number '%s'", out->text);
    errno = 0;
    double v;
    if (!fast_number(out->text, &v))
        v = gnum_strtod(out->text, NULL);
    if (!isfinite(v))
        return fail(lx, err, line, col, "number '%s' is out of range", out->text);
    out->tok.type = GTOK_NUMBER;
    out->tok.number = v;
    out->tok.text = out->text;
    out->tok.line = line;
    out->tok.col = col;
    return G_OK;
}

static int scan_string(GLexer *lx, GLexToken *out, GError *err)
{
    int line = lx->line, col = lx->col;
    size_t n = 0;
    advance(lx); /* the opening quote */
    for (;;) {
        int c = peekc(lx, 0);
        if (c < 0 || c == '\n' || c == '\r')
            return fail(lx, err, line, col, "%s", "unterminated string (a string ends on the line it starts)");
        advance(lx);
        if (c == '"')
            break;
        if (c == '\\') {
            int e = peekc(lx, 0), ecol = lx->col - 1;
            switch (e) {
            case '"': c = '"'; break;
            case '\\': c = '\\'; break;
            case 'n': c = '\n'; break;
            case 't': c = '\t'; break;
            default: {
                char what[24];
                printable(e, what, sizeof what);
                return fail(lx, err, lx->line, ecol, "unknown escape '\\' followed by %s in string", what);
            }
            }
            advance(lx);
        } else if (c == 0) {
            return fail(lx, err, lx->line, lx->col - 1, "%s", "NUL byte in string");
        }
        if (n + 1 >= GLEX_TEXT_MAX)
            return fail(lx, err, line, col, "%s", "string longer than 4095 bytes");
        out->text[n++] = (char)c;
    }
    out->text[n] = '\0';
    out->tok.type = GTOK_STRING;
    out->tok.text = out->text;
    out->tok.number = 0.0;
    out->tok.line = line;
    out->tok.col = col;
    return G_OK;
}

static int scan(GLexer *lx, GLexToken *out, GError *err);

int glexer_next(GLexer *lx, GLexToken *out, GError *err)
{
    int rc = scan(lx, out, err);
    out->end = lx->pos;
    return rc;
}

static int scan(GLexer *lx, GLexToken *out, GError *err)
{
    int c;
    for (;;) { /* whitespace and comments */
        c = peekc(lx, 0);
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v') {
            advance(lx);
        } else if (c == '#') {
            while ((c = peekc(lx, 0)) >= 0 && c != '\n')
                advance(lx);
        } else {
            break;
        }
    }
    out->tok.line = lx->line;
    out->tok.col = lx->col;
    out->tok.number = 0.0;
    out->tok.text = out->text;
    out->start = lx->pos;
    if (c < 0) {
        out->tok.type = GTOK_EOF;
        snprintf(out->text, sizeof out->text, "end of file");
        return G_OK;
    }
    int c1 = peekc(lx, 1), c2 = peekc(lx, 2);
    if (isdigit(c) || (c == '.' && isdigit(c1)) ||
        ((c == '+' || c == '-') && (isdigit(c1) || (c1 == '.' && isdigit(c2)) || isalpha(c1))))
        return scan_number(lx, out, err);
    if (c == '"')
        return scan_string(lx, out, err);
    if (is_ident_start(c)) {
        size_t n = 0; /* a name holds no line break: the column moves by its length */
        const unsigned char *src = (const unsigned char *)lx->src;
        for (; lx->pos < lx->len && is_ident_char(src[lx->pos]); lx->pos++, lx->col++) {
            if (n + 1 >= GLEX_TEXT_MAX)
                return fail(lx, err, out->tok.line, out->tok.col, "%s", "name longer than 4095 bytes");
            out->text[n++] = (char)src[lx->pos];
        }
        out->text[n] = '\0';
        out->tok.type = GTOK_IDENT;
        return G_OK;
    }
    static const char punct[] = "{}<>,";
    static const int types[] = {GTOK_LBRACE, GTOK_RBRACE, GTOK_LANGLE, GTOK_RANGLE, GTOK_COMMA};
    const char *p = c ? strchr(punct, c) : NULL;
    if (p) {
        out->tok.type = types[p - punct];
        out->text[0] = (char)c;
        out->text[1] = '\0';
        advance(lx);
        return G_OK;
    }
    char what[24];
    printable(c, what, sizeof what);
    return fail(lx, err, lx->line, lx->col, "unexpected character %s", what);
}

void glexer_describe(const GToken *tok, char *buf, size_t size)
{
    switch (tok->type) {
    case GTOK_EOF: snprintf(buf, size, "end of file"); break;
    case GTOK_NUMBER: snprintf(buf, size, "number %.60s", tok->text); break;
    case GTOK_STRING: snprintf(buf, size, "string \"%.60s\"", tok->text); break;
    default: snprintf(buf, size, "'%.60s'", tok->text); break;
    }
}
