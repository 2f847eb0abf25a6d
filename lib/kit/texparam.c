/* texparam.c - textured parameters (generic/kit/texparam.h): reading numbers and colours that are constants,
 * generators, mixes or image lookups, and their values at a surface point. */
#include "generic/kit/texparam.h"
#include "generic/kit/texture_parse.h"
#include "texparam_image.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* ---- numbers ---- */

void gtexparam_number_release(GTexNumber *p)
{
    ggenerator_unref(p->gen);
    *p = gtexparam_number_const(0.0);
}

void gtexparam_number_copy(GTexNumber *out, const GTexNumber *p)
{
    *out = *p;
    ggenerator_ref(out->gen);
}

void gtexparam_number_bounds(const GTexNumber *p, double *min, double *max)
{
    if (!p->gen) {
        *min = *max = p->value;
        return;
    }
    double a, b;
    ggenerator_declared_range(p->gen, &a, &b);
    *min = fmin(fmax(a, p->lo), p->hi);
    *max = fmin(fmax(b, p->lo), p->hi);
}

/* 1 when t begins a generator: the name of a generator type (a nested entry) or of a generator the file defined. */
static int starts_generator(GReader *r, const GToken *t)
{
    return t->type == GTOK_IDENT &&
           (gregistry_find(GKIND_GENERATOR, t->text) || greader_lookup(r, GKIND_GENERATOR, t->text));
}

int gtexparam_read_number(GReader *r, double lo, double hi, int constant_only, const char *material,
                          const char *param, const char *why, GTexNumber *out, GError *err)
{
    gtexparam_number_release(out);
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    if (!starts_generator(r, &t)) { /* a number, a defined constant, or the reader's complaint about the token */
        double v;
        rc = greader_number_in(r, lo, hi, &v, err);
        if (rc == G_OK)
            *out = gtexparam_number_const(v);
        return rc;
    }
    if (constant_only)
        return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col,
                                "%s: %s must be a constant number%s%s%s, not a generator", material, param,
                                why ? " (it decides " : "", why ? why : "", why ? ")" : "");
    GGenerator *g;
    if ((rc = gtexparse_generator(r, &g, err)) != G_OK)
        return rc;
    double a, b;
    ggenerator_declared_range(g, &a, &b);
    if (!(a >= lo && b <= hi))
        return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col,
                                "%s: %s takes values in [%g, %g]; the generator's range is [%g, %g] (set it with "
                                "`range LO HI`)", material, param, lo, hi, a, b);
    *out = (GTexNumber){a, ggenerator_ref(g), lo, hi};
    return G_OK;
}

int gtexparam_read_constant(GReader *r, double lo, double hi, const char *material, const char *param,
                            const char *why, double *out, GError *err)
{
    GTexNumber n = gtexparam_number_const(0.0);
    int rc = gtexparam_read_number(r, lo, hi, 1, material, param, why, &n, err);
    if (rc == G_OK)
        *out = n.value;
    return rc;
}

int gtexparam_refuse_generator(GReader *r, const char *material, const char *param, const char *why, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK || !starts_generator(r, &t))
        return rc;
    return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col, "%s: %s must be constant (%s), not a generator",
                            material, param, why);
}

/* ---- colours ---- */

void gtexparam_color_release(GTexColor *p)
{
    gcolor_free(&p->a);
    gcolor_free(&p->b);
    ggenerator_unref(p->by);
    gtexparam_image_free(p->image);
    memset(p, 0, sizeof *p);
}

int gtexparam_unit_color(const GColorModel *m, GColor *c)
{
    int rc = gcolor_alloc(c, m);
    if (rc != G_OK)
        return rc;
    for (int i = 0; i < m->nvalues; i++)
        c->v[i] = 1.0f;
    return G_OK;
}

/* A colour of a mix, read in role: a vector ("<what> must be a vector colour" at it otherwise). */
static int read_vector(GReader *r, GColorRole role, const char *what, GColor *c, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc == G_OK)
        rc = greader_color(r, role, c, err);
    if (rc == G_OK && c->kind != GCOLOR_VECTOR)
        rc = greader_error_at(r, err, G_ERR_PARSE, t.line, t.col,
                              "mix: %s is a re-radiation matrix (a textured colour must be a vector)", what);
    return rc;
}

/* `mix { by GENERATOR  a COLOR  b COLOR }` after the keyword. */
static int read_mix(GReader *r, GColorRole role, GTexColor *out, GError *err)
{
    out->kind = GTEXCOLOR_MIX;
    int rc = greader_block_begin(r, err);
    char key[16];
    while (rc == G_OK && (rc = greader_block_end(r, err)) == 0) {
        int line, col;
        if ((rc = greader_ident(r, key, sizeof key, err)) != G_OK)
            break;
        greader_position(r, &line, &col);
        int twice = (strcmp(key, "by") == 0 && out->by) || (strcmp(key, "a") == 0 && out->a.v) ||
                    (strcmp(key, "b") == 0 && out->b.v);
        if (twice)
            rc = greader_error_at(r, err, G_ERR_PARSE, line, col, "mix: '%s' is given twice", key);
        else if (strcmp(key, "by") == 0) {
            GGenerator *g;
            if ((rc = gtexparse_generator(r, &g, err)) == G_OK)
                out->by = ggenerator_ref(g);
        } else if (strcmp(key, "a") == 0)
            rc = read_vector(r, role, "a", &out->a, err);
        else if (strcmp(key, "b") == 0)
            rc = read_vector(r, role, "b", &out->b, err);
        else
            rc = greader_error_at(r, err, G_ERR_PARSE, line, col,
                                  "mix: unknown parameter '%s' (expected one of: by, a, b)", key);
    }
    if (rc < 0)
        return rc;
    if (!out->by || !out->a.v || !out->b.v)
        return greader_error(r, err, "mix: needs by, a and b");
    return G_OK;
}

int gtexparam_read_color(GReader *r, GColorRole role, GTexColor *out, GError *err)
{
    gtexparam_color_release(out);
    out->role = role;
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    if (t.type == GTOK_IDENT && strcmp(t.text, "mix") == 0) {
        if ((rc = greader_next(r, NULL, err)) == G_OK)
            rc = read_mix(r, role, out, err);
    } else if (t.type == GTOK_IDENT && strcmp(t.text, "image") == 0) {
        out->kind = GTEXCOLOR_IMAGE;
        if ((rc = greader_next(r, NULL, err)) == G_OK)
            rc = gtexparam_image_read(r, greader_colormodel(r), role, &out->image, err);
    } else {
        out->kind = GTEXCOLOR_CONSTANT;
        rc = greader_color(r, role, &out->a, err);
    }
    if (rc != G_OK)
        gtexparam_color_release(out);
    return rc;
}

int gtexparam_color_at(const GTexColor *p, GSurfPoint *sp, GColor *out)
{
    switch (p->kind) {
    case GTEXCOLOR_CONSTANT:
        return gcolor_copy(out, &p->a);
    case GTEXCOLOR_MIX: {
        double t = ggenerator_cached_value(p->by, sp);
        t = t > 0.0 ? (t < 1.0 ? t : 1.0) : 0.0; /* NaN too: a */
        int rc = gcolor_scale(out, &p->a, 1.0 - t);
        return rc != G_OK ? rc : gcolor_add_scaled(out, &p->b, t);
    }
    case GTEXCOLOR_IMAGE:
        return gtexparam_image_color(p->image, sp, p->role, out);
    }
    return G_ERR_INVALID;
}

int gtexparam_color_extremes(const GTexColor *p, GColor out[2], int *n, GError *err)
{
    *n = 0;
    int rc = G_OK;
    switch (p->kind) {
    case GTEXCOLOR_CONSTANT:
        rc = gcolor_alloc(&out[0], p->a.model);
        if (rc == G_OK && (rc = gcolor_copy(&out[0], &p->a)) == G_OK)
            *n = 1;
        break;
    case GTEXCOLOR_MIX:
        for (int i = 0; i < 2 && rc == G_OK; i++) {
            const GColor *src = i ? &p->b : &p->a;
            rc = gcolor_alloc(&out[i], src->model);
            if (rc == G_OK && (rc = gcolor_copy(&out[i], src)) == G_OK)
                *n = i + 1;
        }
        break;
    case GTEXCOLOR_IMAGE:
        rc = gtexparam_image_max(p->image, p->role, &out[0], err);
        if (rc == G_OK)
            *n = 1;
        break;
    }
    if (rc != G_OK) {
        for (int i = 0; i < *n; i++)
            gcolor_free(&out[i]);
        *n = 0;
        return err && err->code ? rc : gerror_set(err, rc, "textured colour: out of memory");
    }
    return G_OK;
}

int gtexparam_number_reads_uv(const GTexNumber *p) { return p->gen && p->gen->space == GGENERATOR_SPACE_UV; }

int gtexparam_color_reads_uv(const GTexColor *p)
{
    return p->kind == GTEXCOLOR_IMAGE || (p->kind == GTEXCOLOR_MIX && p->by->space == GGENERATOR_SPACE_UV);
}
