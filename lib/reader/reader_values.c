/* reader_values.c - typed values: numbers (and constants), vectors, booleans, strings, names, choices, paths. */
#include "reader_state.h"
#include "reader_confine.h"
#include "generic/memory.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

int greader_at_number(GReader *r, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    return t.type == GTOK_NUMBER || (t.type == GTOK_IDENT && glibrary_constant(r->lib, t.text, NULL, NULL, NULL, NULL));
}

int greader_number(GReader *r, double *out, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    if (t.type == GTOK_IDENT && (strcasecmp(t.text, "nan") == 0 || strcasecmp(t.text, "inf") == 0 ||
                                 strcasecmp(t.text, "infinity") == 0))
        return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col, "'%s' is not allowed: numbers must be finite",
                                t.text);
    double value = t.number;
    if (t.type == GTOK_IDENT && glibrary_constant(r->lib, t.text, &value, NULL, NULL, NULL)) {
        greader_take(r, NULL); /* a constant (`define`), peeked above */
        *out = value;
        return G_OK;
    }
    if (t.type == GTOK_IDENT)
        return greader_expected(r, "a number or a constant defined before", err);
    if (t.type != GTOK_NUMBER)
        return greader_expected(r, "a number", err);
    greader_take(r, NULL); /* the token peeked above */
    *out = t.number;
    return G_OK;
}

int greader_number_in(GReader *r, double lo, double hi, double *out, GError *err)
{
    double v;
    int rc = greader_number(r, &v, err);
    if (rc != G_OK)
        return rc;
    if (!(v >= lo && v <= hi))
        return greader_error(r, err, "value %g is out of range [%g, %g]", v, lo, hi);
    *out = v;
    return G_OK;
}

int greader_int(GReader *r, long lo, long hi, long *out, GError *err)
{
    double v;
    int rc = greader_number(r, &v, err);
    if (rc != G_OK)
        return rc;
    if (v != floor(v))
        return greader_error(r, err, "expected a whole number, found %g", v);
    if (!(v >= (double)lo && v <= (double)hi))
        return greader_error(r, err, "value %g is out of range [%ld, %ld]", v, lo, hi);
    *out = (long)v;
    return G_OK;
}

int greader_vec3(GReader *r, GVec3 *out, GError *err)
{
    int angle = greader_accept(r, GTOK_LANGLE, err);
    if (angle < 0)
        return angle;
    double v[3];
    for (int i = 0; i < 3; i++) {
        if (angle && i > 0) {
            int rc = greader_expect(r, GTOK_COMMA, "',' between vector components", err);
            if (rc != G_OK)
                return rc;
        }
        int rc = greader_number(r, &v[i], err);
        if (rc != G_OK)
            return rc;
    }
    if (angle) {
        int rc = greader_expect(r, GTOK_RANGLE, "'>' to close the vector", err);
        if (rc != G_OK)
            return rc;
    }
    *out = gvec3(v[0], v[1], v[2]);
    return G_OK;
}

int greader_bool(GReader *r, int *out, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    if (t.type == GTOK_NUMBER && (t.number == 0.0 || t.number == 1.0)) {
        *out = t.number != 0.0;
        return greader_next(r, NULL, err);
    }
    static const char *const names[] = {"false", "true", "no", "yes", "off", "on", NULL};
    for (int i = 0; t.type == GTOK_IDENT && names[i]; i++)
        if (strcmp(t.text, names[i]) == 0) {
            *out = i & 1;
            return greader_next(r, NULL, err);
        }
    return greader_expected(r, "true or false", err);
}

int greader_string(GReader *r, char **out, GError *err)
{
    *out = NULL;
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    if (t.type != GTOK_STRING)
        return greader_expected(r, "a quoted string", err);
    greader_take(r, &t); /* the token peeked above */
    *out = gmem_strdup(t.text);
    return *out ? G_OK : greader_error_at(r, err, G_ERR_NOMEM, t.line, t.col, "out of memory");
}

int greader_ident(GReader *r, char *buf, size_t size, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    if (t.type != GTOK_IDENT)
        return greader_expected(r, "a name", err);
    greader_take(r, &t); /* the token peeked above */
    if (strlen(t.text) >= size)
        return greader_error(r, err, "name '%.40s...' is too long (at most %zu characters)", t.text, size - 1);
    memcpy(buf, t.text, strlen(t.text) + 1);
    return G_OK;
}

int greader_choice(GReader *r, const char *const *choices, int *index, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    for (int i = 0; t.type == GTOK_IDENT && choices[i]; i++)
        if (strcmp(t.text, choices[i]) == 0) {
            *index = i;
            return greader_next(r, NULL, err);
        }
    char list[400];
    size_t used = 0;
    list[0] = '\0';
    for (int i = 0; choices[i] && used < sizeof list; i++)
        used += (size_t)snprintf(list + used, sizeof list - used, "%s%s", i ? ", " : "", choices[i]);
    char what[420];
    snprintf(what, sizeof what, "one of %s", list);
    return greader_expected(r, what, err);
}

int greader_path(GReader *r, char **out, GError *err)
{
    char *rel = NULL;
    int rc = greader_string(r, &rel, err);
    if (rc != G_OK)
        return rc;
    if (!rel[0]) {
        gmem_free(rel);
        return greader_error(r, err, "empty file name");
    }
    const char *dir = greader_dir(r);
    if (rel[0] == '/' || strcmp(dir, ".") == 0) {
        *out = rel;
    } else {
        size_t a = strlen(dir), b = strlen(rel);
        *out = gmem_alloc(a + b + 2);
        if (*out) {
            memcpy(*out, dir, a);
            (*out)[a] = '/';
            memcpy(*out + a + 1, rel, b + 1);
        }
        gmem_free(rel);
        if (!*out)
            return greader_error(r, err, "out of memory");
    }
    if (r->opt.confine_dir) { /* the file read is the resolved one that was checked */
        char *real = NULL;
        int rc = greader_confine(r->opt.confine_dir, *out, &real, err);
        gmem_free(*out);
        *out = real;
        if (rc != G_OK) {
            char msg[sizeof err->message];
            snprintf(msg, sizeof msg, "%s", err ? err->message : "");
            return greader_error_at(r, err, rc, r->ts.cur.tok.line, r->ts.cur.tok.col, "%s", msg);
        }
    }
    return G_OK;
}
