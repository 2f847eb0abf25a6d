/* reader_entry.c - entries: calling parse routines, nested values and references to named entries. */
#include "reader_entry.h"
#include "generic/memory.h"
#include "generic/texture.h"
#include "generic/kit/texparam.h"

#include <stdio.h>
#include <string.h>

const GTypeInfo *greader_find_type(GKind kind, const char *name)
{
    const GTypeInfo *t = gregistry_find(kind, name);
    GKind space = gkind_namespace(kind);
    for (int k = 0, n = gkind_count(); !t && k < n; k++)
        if ((GKind)k != kind && gkind_namespace((GKind)k) == space)
            t = gregistry_find((GKind)k, name);
    return t;
}

void greader_type_names(GKind kind, char *buf, size_t size)
{
    gregistry_names(kind, buf, size);
    GKind space = gkind_namespace(kind);
    for (int k = 0, n = gkind_count(); k < n; k++) {
        if ((GKind)k == kind || gkind_namespace((GKind)k) != space)
            continue;
        size_t used = strlen(buf);
        if (used + 3 >= size)
            return;
        gregistry_names((GKind)k, buf + used + 2, size - used - 2);
        if (buf[used + 2] && used)
            buf[used] = ',', buf[used + 1] = ' ';
        else if (buf[used + 2])
            memmove(buf, buf + used + 2, strlen(buf + used + 2) + 1);
    }
}

/* A generator read with `range LO HI` (greader_param): *obj, made by type, becomes a range generator over it
 * (ggenerator_range_create), released as the kind releases generators. A type with a release of its own cannot
 * be wrapped: its release would be handed the wrapper. */
static int apply_range(GReader *r, const GTypeInfo *type, const GReaderFrame *f, int line, int col, void **obj,
                       GError *err)
{
    if (f->range_lo == 0.0 && f->range_hi == 1.0) /* the default: the generator as it is */
        return G_OK;
    if (type->destroy && type->destroy != ggenerator_release) {
        gtypeinfo_release(type, *obj);
        *obj = NULL;
        return greader_error_at(r, err, G_ERR_UNSUPPORTED, line, col,
                                "generator %s: range cannot be applied (the type releases its generators itself)",
                                type->name);
    }
    GGenerator *g = NULL;
    int rc = ggenerator_range_create(*obj, f->range_lo, f->range_hi, &g, err);
    ggenerator_unref(*obj); /* the wrapper holds its own reference */
    *obj = g;
    if (rc != G_OK) {
        char msg[sizeof err->message];
        snprintf(msg, sizeof msg, "%s", err ? err->message : "range");
        return greader_error_at(r, err, rc, line, col, "%s", msg);
    }
    return G_OK;
}

/* A material whose parse routine read a textured colour (reader_color.c): *obj, made with the unit colour, scaled
 * by the texture (gtexparam_texture_material); a refusal is placed at the parameter. */
static int apply_texcolor(GReader *r, const GTypeInfo *type, GReaderFrame *f, void **obj, GError *err)
{
    GMaterial *m = NULL;
    int rc = gtexparam_texture_material(*obj, f->texcolor, type->name, f->tex_param, &m, err);
    *obj = m;
    if (rc == G_OK)
        return G_OK;
    char msg[sizeof err->message];
    snprintf(msg, sizeof msg, "%s", err ? err->message : "texture");
    return greader_error_at(r, err, rc, f->tex_line, f->tex_col, "%s", msg);
}

int greader_invoke(GReader *r, const GTypeInfo *type, int line, int col, void **object, GError *err)
{
    *object = NULL;
    int base = r->nframes;
    int rc = greader_push_frame(r, 0, type, line, col, err);
    if (rc != G_OK)
        return rc;
    if (!type->parse) {
        greader_pop_frames(r, base);
        return greader_error_at(r, err, G_ERR_UNSUPPORTED, line, col, "%s type '%s' cannot be read from text",
                                gkind_name(type->kind), type->name);
    }
    void *obj = NULL;
    rc = type->parse(r, type->vtable, &obj, err);
    if (rc > 0)
        rc = G_ERR_PARSE;
    if (rc == G_OK && !obj)
        rc = greader_error_at(r, err, G_ERR_INVALID, line, col, "%s %s made no object", gkind_name(type->kind),
                              type->name);
    if (rc == G_OK && r->frames[base].state == 1) { /* the routine left its block open */
        GToken t;
        rc = greader_peek(r, &t, err);
        if (rc == G_OK) {
            char found[96];
            glexer_describe(&t, found, sizeof found);
            rc = greader_error_at(r, err, G_ERR_PARSE, t.line, t.col, "%s %s: expected '}', found %s",
                                  gkind_name(type->kind), type->name, found);
        }
        gtypeinfo_release(type, obj);
    }
    if (rc != G_OK) { /* a failing routine has freed what it made */
        int placed = greader_locate(r, err); /* rc stays the routine's status */
        (void)placed;
        greader_pop_frames(r, base);
        return rc;
    }
    if (r->frames[base].texcolor && (rc = apply_texcolor(r, type, &r->frames[base], &obj, err)) != G_OK) {
        greader_pop_frames(r, base);
        return rc;
    }
    if (r->frames[base].has_range && (rc = apply_range(r, type, &r->frames[base], line, col, &obj, err)) != G_OK) {
        greader_pop_frames(r, base);
        return rc;
    }
    greader_pop_frames(r, base);
    *object = obj;
    return G_OK;
}

/* 1 when a type's first parameter is written without its name (`blackbody 5000`): such a type keyword is never
 * read as a defined name. */
static int takes_positional(const GTypeInfo *ty)
{
    return ty->params && ty->params[0].name && ty->params[0].form == GPARAM_POSITIONAL;
}

int greader_value(GReader *r, GKind kind, int add, void **object, const GTypeInfo **type, int *owned, GError *err)
{
    *object = NULL;
    if (owned)
        *owned = 0;
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    const char *kn = gkind_name(kind);
    if (t.type != GTOK_IDENT) {
        char found[96];
        glexer_describe(&t, found, sizeof found);
        return greader_error_at(r, err, G_ERR_PARSE, t.line, t.col,
                                "expected a %s (a type or a defined name), found %s", kn, found);
    }
    const GTypeInfo *ty = greader_find_type(kind, t.text);
    void *named = ty && !takes_positional(ty) ? glibrary_find(r->lib, kind, t.text) : NULL;
    if (named) { /* a name that is also a type keyword: the type only where its block follows */
        greader_take(r, NULL); /* the token peeked above */
        GToken n;
        if ((rc = greader_peek(r, &n, err)) != G_OK)
            return rc;
        if (n.type != GTOK_LBRACE) {
            *object = named;
            if (type)
                *type = glibrary_find_type(r->lib, kind, t.text);
            return G_OK;
        }
    } else if (ty) {
        greader_take(r, NULL); /* the token peeked above */
    }
    if (ty) {
        void *obj = NULL;
        rc = greader_invoke(r, ty, t.line, t.col, &obj, err);
        if (rc == G_OK && add) {
            rc = glibrary_put(r->lib, ty, NULL, obj, 1, 0, err);
            if (rc != G_OK)
                rc = greader_locate(r, err);
        }
        if (rc != G_OK)
            return rc;
        *object = obj;
        if (type)
            *type = ty;
        if (owned)
            *owned = !add;
        return G_OK;
    }
    void *obj = glibrary_find(r->lib, kind, t.text);
    if (obj) {
        greader_take(r, NULL); /* the token peeked above */
        *object = obj;
        if (type)
            *type = glibrary_find_type(r->lib, kind, t.text);
        return G_OK;
    }
    for (int k = 0, n = gkind_count(); k < n; k++)
        if (glibrary_find(r->lib, (GKind)k, t.text))
            return greader_error_at(r, err, G_ERR_NOTFOUND, t.line, t.col, "'%s' is a %s, not a %s", t.text,
                                    gkind_name((GKind)k), kn);
    char types[512], names[512];
    greader_type_names(kind, types, sizeof types);
    glibrary_names(r->lib, kind, names, sizeof names);
    return greader_error_at(r, err, G_ERR_NOTFOUND, t.line, t.col,
                            "unknown %s '%s': neither a %s type (%s) nor a defined %s (defined: %s)", kn, t.text, kn,
                            types[0] ? types : "none registered", kn, names);
}

int greader_object(GReader *r, GKind kind, void **object, const GTypeInfo **type, GError *err)
{
    if (!gkind_info(kind) || kind == GKIND_COLORMODEL)
        return greader_error(r, err, "objects of kind %s cannot be nested", gkind_name(kind));
    return greader_value(r, kind, 1, object, type, NULL, err);
}

int greader_material(GReader *r, GMaterial **out, GError *err)
{
    void *obj = NULL;
    const GTypeInfo *t = NULL;
    int rc = greader_object(r, GKIND_MATERIAL, &obj, &t, err);
    *out = rc == G_OK ? obj : NULL;
    return rc;
}

void *greader_lookup(GReader *r, GKind kind, const char *name) { return glibrary_find(r->lib, kind, name); }

int greader_define(GReader *r, const GTypeInfo *type, const char *name, void *object, GError *err)
{
    int rc = glibrary_put(r->lib, type, name, object, 1, name != NULL, err);
    return rc ? greader_locate(r, err) : G_OK;
}

const GColorModel *greader_colormodel(GReader *r)
{
    r->model_fixed = 1;
    return glibrary_colormodel(r->lib);
}
