/* mesh_ply.c - the check a PLY file passes before assimp reads it, and the file assimp reads instead: a header
 * written from what was checked and the body of the vertex and face elements.
 *
 * assimp 5's PLY reader loops forever on some truncated headers, aborts on some truncated bodies, sizes its arrays
 * by the claimed counts, writes past them when a vertex or face element comes twice, follows a face's missing index
 * list when the face has a texcoord list, and reads the header its own way: the format must be the second line, an
 * obj_info or other unknown line ends the properties of the element before it (the properties after it are
 * dropped), a "comment TextureFile" line starts an element, an element of a name it does not know gets no entries
 * (its data is then read as the next element's), a binary body whose first byte is a line feed loses it; it reads
 * an ASCII body one entry a line (an entry spread over lines shifts every later one) and numbers with its own
 * parsers; it keeps the entries of the elements other than vertex and face in memory. So the whole file is checked
 * here, and assimp gets "ply", the format, the vertex and face (or tristrips) elements with their properties and
 * "end_header", then their entries, rewritten in place over the file's body: binary as they were, ASCII one entry a
 * line with its values separated by one space. */
#include "mesh_format.h"

#include <generic/memory.h>

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PLY_MAX_ELEMENTS 16
#define PLY_MAX_PROPS 32
/* Longest word of a format, element or property line, with its NUL. */
#define PLY_MAX_WORD 64
typedef enum PlyKind { PLY_OTHER, PLY_VERTEX, PLY_FACE, PLY_STRIPS } PlyKind;

typedef struct PlyProp {
    int size, count_size;        /* bytes of a value and, for a list, of its count (0: not a list) */
    char kind, count_kind;       /* 'f' floating point, 's' signed or 'u' unsigned integer (ply_type_kind) */
    int is_index, is_texcoord;   /* the face's vertex_indices (vertex_index) list, its texcoord list */
    char line[5 * PLY_MAX_WORD]; /* the property line assimp gets */
} PlyProp;

typedef struct PlyElem {
    unsigned long long n;
    PlyKind kind;
    int nprops, has_index, has_texcoord;
    char line[3 * PLY_MAX_WORD + 8]; /* the element line assimp gets */
    PlyProp prop[PLY_MAX_PROPS];
} PlyElem;

/* The words of a header line: how many, and the first six (cut is 1 when one of those was too long to keep). */
typedef struct PlyWords {
    int n, cut;
    char w[6][PLY_MAX_WORD];
} PlyWords;

static int ply_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

static void ply_split(const char *s, const char *end, PlyWords *W)
{
    W->n = W->cut = 0;
    for (;;) {
        while (s < end && ply_blank(*s))
            s++;
        if (s == end)
            return;
        const char *b = s;
        while (s < end && !ply_blank(*s))
            s++;
        if (W->n < 6) {
            size_t len = (size_t)(s - b);
            if (len >= PLY_MAX_WORD) {
                len = PLY_MAX_WORD - 1;
                W->cut = 1;
            }
            memcpy(W->w[W->n], b, len);
            W->w[W->n][len] = '\0';
        }
        W->n++;
    }
}

static int ply_type_size(const char *t)
{
    static const char *names[] = {"char", "uchar", "int8", "uint8", "short", "ushort", "int16", "uint16",
                                  "int", "uint", "int32", "uint32", "float", "float32", "double", "float64"};
    static const int sizes[] = {1, 1, 1, 1, 2, 2, 2, 2, 4, 4, 4, 4, 4, 4, 8, 8};
    for (size_t i = 0; i < sizeof sizes / sizeof *sizes; i++)
        if (strcmp(t, names[i]) == 0)
            return sizes[i];
    return 0;
}

/* 'f' for the floating-point types, 's' for the signed and 'u' for the unsigned integer types. */
static char ply_type_kind(const char *t)
{
    return t[0] == 'f' || t[0] == 'd' ? 'f' : t[0] == 'u' ? 'u' : 's';
}

typedef struct PlyBody {
    const char *p, *end;
    char *out;         /* where the body assimp reads is written, never ahead of p */
    int ascii, big_endian;
    int keep;          /* the current element goes to assimp */
    int values;        /* ASCII: values written in the current entry */
} PlyBody;

/* 1 when the word w (len bytes) is a value of kind (ply_type_kind) that assimp reads whole: a decimal number for
 * the floating-point types, digits (with a sign for the signed types) for the integers. */
static int ply_ascii_ok(const char *w, size_t len, char kind)
{
    if (kind == 'f')
        return mesh_decimal_number(w, len);
    size_t i = kind == 's' && len > 0 && (w[0] == '-' || w[0] == '+');
    if (i == len)
        return 0;
    for (; i < len; i++)
        if (w[i] < '0' || w[i] > '9')
            return 0;
    return 1;
}

/* The next value as a double: an ASCII number of kind or `size` binary bytes (integers read as unsigned when used
 * as counts or indices: the caller only needs them for those), written on to B->out when B->keep (ASCII: after a
 * space within the entry). -1 when the file ends or holds no such number there. */
static int ply_value(PlyBody *B, int size, char kind, double *out)
{
    if (B->ascii) {
        while (B->p < B->end && (*B->p == ' ' || *B->p == '\t' || *B->p == '\n' || *B->p == '\r'))
            B->p++;
        const char *w = B->p;
        while (B->p < B->end && !(*B->p == ' ' || *B->p == '\t' || *B->p == '\n' || *B->p == '\r'))
            B->p++;
        size_t len = (size_t)(B->p - w);
        char tok[64];
        if (len == 0 || len >= sizeof tok || !ply_ascii_ok(w, len, kind))
            return -1;
        memcpy(tok, w, len);
        tok[len] = '\0';
        *out = strtod(tok, NULL);
        if (B->keep) {
            if (B->values++ > 0)
                *B->out++ = ' ';
            memmove(B->out, w, len);
            B->out += len;
        }
        return 0;
    }
    if (B->end - B->p < size)
        return -1;
    unsigned long long v = 0;
    for (int i = 0; i < size; i++)
        v |= (unsigned long long)(unsigned char)B->p[B->big_endian ? i : size - 1 - i] << (8 * (size - 1 - i));
    if (B->keep) {
        memmove(B->out, B->p, (size_t)size);
        B->out += size;
    }
    B->p += size;
    *out = size <= 4 ? (double)(v & 0xffffffffull) : 0.0; /* counts and indices are at most 4 bytes */
    return 0;
}

/* The element line "element NAME COUNT" of W into el (line: its line number), or an error. */
static int ply_element(const char *path, int line, const PlyWords *W, PlyElem *el, int nel, GError *err)
{
    if (W->n != 3)
        return gerror_set(err, G_ERR_PARSE, "%s:%d: expected \"element NAME COUNT\"", path, line);
    char *e;
    errno = 0;
    unsigned long long n = strtoull(W->w[2], &e, 10);
    if (*e || errno || W->w[2][0] < '0' || W->w[2][0] > '9')
        return gerror_set(err, G_ERR_PARSE, "%s:%d: the element %s needs a count", path, line, W->w[1]);
    if (nel >= PLY_MAX_ELEMENTS)
        return gerror_set(err, G_ERR_PARSE, "%s:%d: more than %d elements", path, line, PLY_MAX_ELEMENTS);
    PlyKind kind = strcmp(W->w[1], "vertex") == 0 ? PLY_VERTEX
                   : strcmp(W->w[1], "face") == 0 ? PLY_FACE
                   : strcmp(W->w[1], "tristrips") == 0 ? PLY_STRIPS : PLY_OTHER;
    for (int i = 0; i < nel && kind != PLY_OTHER; i++)
        if (el[i].kind == kind || (el[i].kind != PLY_OTHER && el[i].kind != PLY_VERTEX && kind != PLY_VERTEX))
            return gerror_set(err, G_ERR_PARSE, "%s:%d: a second %s element (one vertex and one face or tristrips "
                              "element at most)", path, line, kind == PLY_VERTEX ? "vertex" : "face or tristrips");
    el[nel].n = n;
    el[nel].kind = kind;
    snprintf(el[nel].line, sizeof el[nel].line, "element %s %s\n", W->w[1], W->w[2]);
    return G_OK;
}

/* The property line of W, "property TYPE NAME" or "property list COUNT_TYPE TYPE NAME", into el, or an error. */
static int ply_property(const char *path, int line, const PlyWords *W, PlyElem *el, GError *err)
{
    if (!el)
        return gerror_set(err, G_ERR_PARSE, "%s:%d: a property before any element", path, line);
    if (el->nprops >= PLY_MAX_PROPS)
        return gerror_set(err, G_ERR_PARSE, "%s:%d: more than %d properties in one element", path, line,
                          PLY_MAX_PROPS);
    PlyProp *p = &el->prop[el->nprops];
    if (W->n == 3 && ply_type_size(W->w[1])) {
        *p = (PlyProp){.size = ply_type_size(W->w[1]), .kind = ply_type_kind(W->w[1])};
        snprintf(p->line, sizeof p->line, "property %s %s\n", W->w[1], W->w[2]);
    } else if (W->n == 5 && strcmp(W->w[1], "list") == 0 && ply_type_size(W->w[2]) && ply_type_size(W->w[2]) <= 4 &&
               ply_type_size(W->w[3])) {
        const char *name = W->w[4];
        *p = (PlyProp){.size = ply_type_size(W->w[3]), .count_size = ply_type_size(W->w[2]),
                       .kind = ply_type_kind(W->w[3]), .count_kind = ply_type_kind(W->w[2])};
        p->is_index = el->kind == PLY_FACE &&
                      (strcmp(name, "vertex_indices") == 0 || strcmp(name, "vertex_index") == 0);
        p->is_texcoord = el->kind == PLY_FACE && strcmp(name, "texcoord") == 0;
        el->has_index |= p->is_index;
        el->has_texcoord |= p->is_texcoord;
        snprintf(p->line, sizeof p->line, "property list %s %s %s\n", W->w[2], W->w[3], name);
    } else {
        return gerror_set(err, G_ERR_PARSE, "%s:%d: expected \"property TYPE NAME\" or \"property list COUNT_TYPE "
                          "TYPE NAME\" (types char, uchar, short, ushort, int, uint, float, double, or int8 ... "
                          "float64; a count of at most 4 bytes)", path, line);
    }
    el->nprops++;
    return G_OK;
}

/* The body from B on, against the elements: every value present, counts the file can hold, face lists of at least
 * 3 indices within the vertex count and no more texture coordinates than assimp can pair with them; the entries of
 * the vertex and face (tristrips) elements written on to B->out. */
static int ply_body(const char *path, PlyBody *B, const PlyElem *el, int nel, GError *err)
{
    unsigned long long nverts = 0;
    for (int e = 0; e < nel; e++)
        if (el[e].kind == PLY_VERTEX)
            nverts = el[e].n;
    for (int e = 0; e < nel; e++) {
        B->keep = el[e].kind != PLY_OTHER;
        if (B->keep && el[e].nprops == 0 && el[e].n > 0) /* assimp would skip a line for each entry */
            return gerror_set(err, G_ERR_PARSE, "%s: element %d has entries but no properties", path, e);
        for (unsigned long long i = 0; i < el[e].n; i++) {
            double nidx = 0, ntex = 0;
            for (int k = 0; k < el[e].nprops; k++) {
                const PlyProp *pp = &el[e].prop[k];
                double x, cnt = 1;
                if (pp->count_size && ply_value(B, pp->count_size, pp->count_kind, &cnt) < 0)
                    return gerror_set(err, G_ERR_PARSE, "%s: the data ends early or holds a non-number "
                                      "(entry %llu of element %d)", path, i, e);
                if (cnt < 0 || cnt != (long long)cnt || cnt > (double)(B->end - B->p) || (pp->is_index && cnt < 3))
                    return gerror_set(err, G_ERR_PARSE, "%s: entry %llu of element %d: a list of %g values", path,
                                      i, e, cnt);
                nidx = pp->is_index ? cnt : nidx;
                ntex = pp->is_texcoord ? cnt : ntex;
                for (long long j = 0; j < (long long)cnt; j++) {
                    if (ply_value(B, pp->size, pp->kind, &x) < 0)
                        return gerror_set(err, G_ERR_PARSE, "%s: the data ends early or holds a non-number "
                                          "(entry %llu of element %d)", path, i, e);
                    if (pp->is_index && !(x >= 0 && x < (double)nverts))
                        return gerror_set(err, G_ERR_PARSE, "%s: face %llu: vertex index %g out of range", path, i,
                                          x);
                }
            }
            /* assimp pairs 6 to 8 texture coordinates with the face's corners two by two */
            if (el[e].has_texcoord && (long long)ntex / 3 == 2 && ntex > 2 * nidx)
                return gerror_set(err, G_ERR_PARSE, "%s: face %llu: %g texture coordinates for %g corners", path, i,
                                  ntex, nidx);
            if (B->ascii && B->keep) { /* the entry's line ends */
                *B->out++ = '\n';
                B->values = 0;
            }
        }
    }
    return G_OK;
}

/* The header assimp reads: "ply", the format, the vertex and face (tristrips) elements and their properties, and
 * "end_header" ended by CR LF (assimp drops a line feed at the start of a binary body: the one after the CR). */
static char *ply_header(const char *format, const PlyElem *el, int nel, size_t *len)
{
    static const char end_line[] = "end_header\r\n";
    char head[PLY_MAX_WORD + 32];
    snprintf(head, sizeof head, "ply\nformat %s 1.0\n", format);
    size_t n = strlen(head) + strlen(end_line);
    for (int e = 0; e < nel; e++) {
        if (el[e].kind == PLY_OTHER)
            continue;
        n += strlen(el[e].line);
        for (int k = 0; k < el[e].nprops; k++)
            n += strlen(el[e].prop[k].line);
    }
    char *h = gmem_alloc(n + 1), *w = h;
    if (!h)
        return NULL;
    w = stpcpy(w, head);
    for (int e = 0; e < nel; e++) {
        if (el[e].kind == PLY_OTHER)
            continue;
        w = stpcpy(w, el[e].line);
        for (int k = 0; k < el[e].nprops; k++)
            w = stpcpy(w, el[e].prop[k].line);
    }
    stpcpy(w, end_line);
    *len = n;
    return h;
}

int mesh_ply_check(const char *path, char *data, size_t size, char **header, size_t *header_len, size_t *body,
                   size_t *body_len, GError *err)
{
    *header = NULL;
    *header_len = *body = *body_len = 0;
    PlyElem *el = gmem_calloc(PLY_MAX_ELEMENTS, sizeof *el);
    if (!el)
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory", path);
    char *s = data, *end = data + size;
    int rc = G_OK, line = 1, nel = 0, header_done = 0;
    char format[PLY_MAX_WORD] = "";
    PlyWords W;
    while (rc == G_OK && !header_done) {
        char *nl = memchr(s, '\n', (size_t)(end - s));
        if (!nl) {
            rc = gerror_set(err, G_ERR_PARSE, "%s:%d: the header ends before end_header", path, line);
            break;
        }
        ply_split(s, nl, &W);
        const char *w0 = W.n > 0 ? W.w[0] : "";
        int keyword = strcmp(w0, "format") == 0 || strcmp(w0, "element") == 0 || strcmp(w0, "property") == 0 ||
                      strcmp(w0, "end_header") == 0;
        if (memchr(s, '\0', (size_t)(nl - s))) {
            rc = gerror_set(err, G_ERR_PARSE, "%s:%d: a NUL byte in the header", path, line);
        } else if (line == 1) {
            if (W.n != 1 || strcmp(w0, "ply") != 0)
                rc = gerror_set(err, G_ERR_PARSE, "%s:1: not a PLY file (no \"ply\" line)", path);
        } else if (!keyword) {
            /* comment, obj_info, an exporter's own line (Blender 2.4x: "Created by Blender3D 247 ..."): skipped */
        } else if (W.cut) {
            rc = gerror_set(err, G_ERR_PARSE, "%s:%d: a word longer than %d bytes", path, line, PLY_MAX_WORD - 1);
        } else if (strcmp(w0, "format") == 0) {
            if (W.n != 3 || strcmp(W.w[2], "1.0") != 0 || format[0] ||
                (strcmp(W.w[1], "ascii") != 0 && strcmp(W.w[1], "binary_little_endian") != 0 &&
                 strcmp(W.w[1], "binary_big_endian") != 0))
                rc = gerror_set(err, G_ERR_PARSE, "%s:%d: expected one line \"format ascii 1.0\", \"format "
                                "binary_little_endian 1.0\" or \"format binary_big_endian 1.0\"", path, line);
            else
                strcpy(format, W.w[1]);
        } else if (strcmp(w0, "element") == 0) {
            rc = ply_element(path, line, &W, el, nel, err);
            if (rc == G_OK && (el[nel].n > MESH_MAX_COUNT || el[nel].n > (unsigned long long)size))
                rc = gerror_set(err, G_ERR_PARSE,
                                "%s:%d: element %s claims %llu entries, more than the %llu-byte file can hold "
                                "(limit %d)", path, line, W.w[1], el[nel].n, (unsigned long long)size, MESH_MAX_COUNT);
            nel += rc == G_OK;
        } else if (strcmp(w0, "property") == 0) {
            rc = ply_property(path, line, &W, nel > 0 ? &el[nel - 1] : NULL, err);
        } else if (W.n != 1 || !format[0]) {
            rc = gerror_set(err, G_ERR_PARSE, "%s:%d: end_header %s", path, line,
                            format[0] ? "has more words" : "before the format line");
        } else {
            header_done = 1;
        }
        s = nl + 1;
        line++;
    }
    for (int e = 0; e < nel && rc == G_OK; e++)
        if (el[e].has_texcoord && !el[e].has_index)
            rc = gerror_set(err, G_ERR_PARSE, "%s: the face element has a texcoord list but no vertex_indices list",
                            path);
    PlyBody B = {.p = s, .end = end, .out = s, .ascii = strcmp(format, "ascii") == 0,
                 .big_endian = strcmp(format, "binary_big_endian") == 0};
    if (rc == G_OK)
        rc = ply_body(path, &B, el, nel, err);
    if (rc == G_OK) {
        *header = ply_header(format, el, nel, header_len);
        *body = (size_t)(s - data);
        *body_len = (size_t)(B.out - s);
        if (!*header)
            rc = gerror_set(err, G_ERR_NOMEM, "%s: out of memory", path);
    }
    gmem_free(el);
    return rc;
}
