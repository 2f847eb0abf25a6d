/* mesh_stl.c - the check an STL file passes before assimp reads it.
 *
 * assimp 5 takes an STL file for binary when 84 bytes and 50 per triangle its header counts, in 32-bit arithmetic,
 * equal the file's size, and allocates by that count; otherwise for ASCII when it starts with "solid", and then
 * reads words its own way: a solid's name is one word (the rest of its line is read as keywords), "normal" and
 * "vertex" read numbers across a line end, a facet without its normal or with other than three vertices gives
 * arrays of different lengths, a solid without facets leaves an empty mesh. So the file is checked here against the
 * grammar both readers agree on, decided binary or ASCII as assimp decides, and refused otherwise. */
#include "mesh_format.h"

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Longest name of a solid (assimp refuses 1024 bytes and more). */
#define STL_MAX_NAME 1000

typedef struct StlText {
    const char *path, *p, *end, *line_start;
    int line;
    unsigned long long facets; /* in the whole file */
    GError *err;
} StlText;

static int stl_space(char c) { return c == ' ' || c == '\t'; }
static int stl_line_end(char c) { return c == '\n' || c == '\r' || c == '\f'; }

/* A parse error at `at` on the current line: FILE:LINE:COL and the printf-style message. */
__attribute__((format(printf, 3, 4))) static int stl_error(StlText *T, const char *at, const char *fmt, ...)
{
    char msg[200];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return gerror_set(T->err, G_ERR_PARSE, "%s:%d:%d: %s", T->path, T->line, (int)(at - T->line_start) + 1, msg);
}

/* At most 40 bytes of a word, for messages: its length for "%.*s". */
static int stl_shown(size_t len) { return (int)(len < 40 ? len : 40); }

/* Moves to the next word, across line ends when `lines`; 0 at the end of the file or (not `lines`) of the line. */
static int stl_next(StlText *T, int lines)
{
    while (T->p < T->end && (stl_space(*T->p) || (lines && stl_line_end(*T->p)))) {
        if (*T->p == '\n' || (*T->p == '\r' && (T->p + 1 == T->end || T->p[1] != '\n')) || *T->p == '\f') {
            T->line++;
            T->line_start = T->p + 1;
        }
        T->p++;
    }
    return T->p < T->end && !stl_line_end(*T->p);
}

/* The word at T->p (length *len), moving past it. */
static const char *stl_word(StlText *T, size_t *len)
{
    const char *w = T->p;
    while (T->p < T->end && !stl_space(*T->p) && !stl_line_end(*T->p))
        T->p++;
    *len = (size_t)(T->p - w);
    return w;
}

static int stl_is(const char *w, size_t len, const char *word) { return len == strlen(word) && !memcmp(w, word, len); }

/* The next word, which must be `word` (on the same line when not `lines`). */
static int stl_expect(StlText *T, int lines, const char *word)
{
    if (!stl_next(T, lines))
        return stl_error(T, T->p, "expected \"%s\" here", word);
    const char *at = T->p;
    size_t len;
    const char *w = stl_word(T, &len);
    if (stl_is(w, len, word))
        return G_OK;
    if (stl_is(w, len, "vertex") && strcmp(word, "endloop") == 0)
        return stl_error(T, at, "a facet with more than three vertices (triangles only)");
    return stl_error(T, at, "expected \"%s\", not \"%.*s\"", word, stl_shown(len), w);
}

/* 1 when the word w (len bytes) is a finite decimal number (mesh_decimal_number). */
static int stl_number(const char *w, size_t len)
{
    char tok[64];
    if (!mesh_decimal_number(w, len) || len >= sizeof tok)
        return 0;
    memcpy(tok, w, len);
    tok[len] = '\0';
    return isfinite(strtod(tok, NULL));
}

/* Three numbers (stl_number) on the keyword's line. */
static int stl_numbers(StlText *T, const char *what)
{
    for (int k = 0; k < 3; k++) {
        if (!stl_next(T, 0))
            return stl_error(T, T->p, "%s needs three numbers on its line", what);
        const char *at = T->p;
        size_t len;
        const char *w = stl_word(T, &len);
        if (!stl_number(w, len))
            return stl_error(T, at, "%s needs finite numbers (digits, a point, an exponent), not \"%.*s\"", what,
                             stl_shown(len), w);
    }
    return G_OK;
}

/* One facet after its "facet" word. */
static int stl_facet(StlText *T)
{
    int rc = stl_expect(T, 0, "normal");
    if (rc == G_OK)
        rc = stl_numbers(T, "a facet normal");
    if (rc == G_OK)
        rc = stl_expect(T, 1, "outer");
    if (rc == G_OK)
        rc = stl_expect(T, 1, "loop");
    for (int v = 0; v < 3 && rc == G_OK; v++)
        if ((rc = stl_expect(T, 1, "vertex")) == G_OK)
            rc = stl_numbers(T, "a vertex");
    if (rc == G_OK)
        rc = stl_expect(T, 1, "endloop");
    if (rc == G_OK)
        rc = stl_expect(T, 1, "endfacet");
    if (rc == G_OK && ++T->facets > MESH_MAX_COUNT / 3)
        rc = gerror_set(T->err, G_ERR_PARSE, "%s: more than %d facets", T->path, MESH_MAX_COUNT / 3);
    return rc;
}

/* One solid from its "solid" word: the name, facets, and "endsolid" with the rest of its line. */
static int stl_solid(StlText *T)
{
    size_t len;
    const char *at = T->p;
    stl_word(T, &len);
    if (!stl_is(at, len, "solid"))
        return stl_error(T, at, "expected \"solid\"");
    for (int k = 0; stl_next(T, 0); k++) { /* the name, and words after it that assimp reads as keywords */
        at = T->p;
        const char *w = stl_word(T, &len);
        if (k == 0 && len > STL_MAX_NAME)
            return stl_error(T, at, "a solid's name longer than %d bytes", STL_MAX_NAME);
        if (k > 0 && (stl_is(w, len, "facet") || stl_is(w, len, "vertex") || (len >= 8 && !memcmp(w, "endsolid", 8))))
            return stl_error(T, at, "\"%.*s\" on the line of \"solid\" after its name", stl_shown(len), w);
    }
    unsigned long long before = T->facets;
    for (;;) {
        if (!stl_next(T, 1))
            return stl_error(T, T->p, "the file ends before \"endsolid\"");
        at = T->p;
        const char *w = stl_word(T, &len);
        if (len >= 8 && !memcmp(w, "endsolid", 8))
            break;
        if (!stl_is(w, len, "facet"))
            return stl_error(T, at, "expected \"facet\" or \"endsolid\", not \"%.*s\"", stl_shown(len), w);
        int rc = stl_facet(T);
        if (rc < 0)
            return rc;
    }
    if (T->facets == before)
        return stl_error(T, at, "a solid without facets");
    while (T->p < T->end && !stl_line_end(*T->p)) /* the rest of the endsolid line, as assimp skips it */
        T->p++;
    return G_OK;
}

int mesh_stl_check(const char *path, const char *data, size_t size, GError *err)
{
    const unsigned char *u = (const unsigned char *)data;
    uint32_t count = size >= 84 ? (uint32_t)u[80] | (uint32_t)u[81] << 8 | (uint32_t)u[82] << 16 | (uint32_t)u[83] << 24
                                : 0;
    unsigned long long need = 84 + 50ull * count;
    if (size >= 84 && size <= 0xffffffffu && (uint32_t)(count * 50u + 84u) == (uint32_t)size) { /* assimp: binary */
        if (need != size)
            return gerror_set(err, G_ERR_PARSE, "%s: a binary STL whose header counts %u triangles (%llu bytes), "
                              "in a %zu-byte file", path, count, need, size);
        if (count == 0 || count > MESH_MAX_COUNT / 3)
            return gerror_set(err, G_ERR_PARSE, "%s: a binary STL of %u triangles (1 to %d)", path, count,
                              MESH_MAX_COUNT / 3);
        return G_OK;
    }
    size_t i = 0;
    while (i < size && stl_space(data[i]))
        i++;
    const char *nul = memchr(data, '\0', size);
    if (size - i < 5 || memcmp(data + i, "solid", 5) != 0 || nul) {
        if (size < 84)
            return gerror_set(err, G_ERR_PARSE, "%s: not an STL file: %zu bytes, too short for a binary STL (84 at "
                              "least), and no ASCII \"solid\"", path, size);
        return gerror_set(err, G_ERR_PARSE, "%s: not an STL file: %s, and as a binary STL its header counts %u "
                          "triangles (%llu bytes), in a %zu-byte file", path,
                          nul ? "binary data (a NUL byte)" : "no \"solid\" at the start", count, need, size);
    }
    StlText T = {path, data + i, data + size, data, 1, 0, err};
    for (const char *c = data; c < data + size; c++)
        if ((unsigned char)*c < 0x20 && !stl_space(*c) && !stl_line_end(*c))
            return gerror_set(err, G_ERR_PARSE, "%s: a control byte (0x%02x) in an ASCII STL", path,
                              (unsigned char)*c);
    do {
        int rc = stl_solid(&T);
        if (rc < 0)
            return rc;
    } while (stl_next(&T, 1));
    return G_OK;
}
