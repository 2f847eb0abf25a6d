/* reader_color.c - reading colours: a literal of a colour type, or the name of a colour entry, as a GColorSpec, and
 * converted into the file's colour model in the role of its use. */
#include "reader_entry.h"

#include "generic/kit/texparam.h"
#include "generic/memory.h"

#include <stdio.h>
#include <string.h>

int greader_color_spec(GReader *r, GColorSpec **out, GError *err)
{
    *out = NULL;
    void *obj = NULL;
    const GTypeInfo *type = NULL;
    int owned = 0;
    int rc = greader_value(r, GKIND_COLOR, 0, &obj, &type, &owned, err);
    if (rc != G_OK)
        return rc;
    (void)type;
    if (owned) { /* a new literal: every colour type makes its spec with gcolorspec_create */
        *out = obj;
        return G_OK;
    }
    rc = gcolorspec_copy(obj, out, err);
    return rc ? greader_locate(r, err) : G_OK;
}

/* The entry frame of a material being read, when first (the token at the value) opens a textured colour. */
static GReaderFrame *textured_frame(GReader *r, const GToken *first)
{
    if (first->type != GTOK_IDENT || (strcmp(first->text, "image") != 0 && strcmp(first->text, "mix") != 0))
        return NULL;
    GReaderFrame *f = r->nframes ? &r->frames[r->nframes - 1] : NULL;
    if (!f || f->is_block || !f->type || f->type->kind != GKIND_MATERIAL || !f->nkeys)
        return NULL;
    return f;
}

/* A textured colour where a material's parse routine reads a colour (`image { ... }`, `mix { ... }`): read into
 * the entry's frame; the routine gets the unit colour, and greader_invoke scales the material it makes
 * (gtexparam_texture_material). One such parameter per entry. */
static int read_textured(GReader *r, GReaderFrame *f, GColorRole role, const GToken *first, GColor *out,
                         GError *err)
{
    const GReaderKey *k = &f->keys[f->nkeys - 1];
    if (f->texcolor)
        return greader_error_at(r, err, G_ERR_PARSE, first->line, first->col,
                                "material %s: only one colour parameter can be textured here (%s already is)",
                                f->type->name, f->tex_param);
    if (!(f->texcolor = gmem_calloc(1, sizeof *f->texcolor)) || !(f->tex_param = gmem_strdup(k->name)))
        return greader_error(r, err, "out of memory");
    f->tex_line = k->line;
    f->tex_col = k->col;
    int rc = gtexparam_read_color(r, role, f->texcolor, err);
    if (rc != G_OK)
        return rc;
    for (int i = 0; i < out->model->nvalues; i++)
        out->v[i] = 1.0f;
    return G_OK;
}

int greader_color(GReader *r, GColorRole role, GColor *out, GError *err)
{
    const GColorModel *m = greader_colormodel(r);
    if (!m)
        return greader_error(r, err, "out of memory creating the colour model");
    if (out->v && out->model != m)
        gcolor_free(out);
    if (!out->v && gcolor_alloc(out, m) != G_OK)
        return greader_error(r, err, "out of memory");
    GColorSpec *s = NULL;
    GToken first;
    int rc = greader_peek(r, &first, err);
    GReaderFrame *tf = rc == G_OK ? textured_frame(r, &first) : NULL;
    if (tf)
        return read_textured(r, tf, role, &first, out, err);
    if (rc == G_OK)
        rc = greader_color_spec(r, &s, err);
    if (rc != G_OK)
        return rc;
    rc = gcolorspec_to_color(s, role, out, err);
    gcolorspec_destroy(s);
    if (rc != G_OK) { /* a conversion error is the whole literal's: point at its start */
        char msg[sizeof err->message];
        snprintf(msg, sizeof msg, "%s", err ? err->message : "");
        gcolor_black(out);
        return greader_error_at(r, err, rc, first.line, first.col, "%s", msg);
    }
    return G_OK;
}
