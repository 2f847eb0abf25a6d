/* reader_color.c - reading colours: a literal of a colour type, or the name of a colour entry, as a GColorSpec, and
 * converted into the file's colour model in the role of its use. */
#include "reader_entry.h"

#include <stdio.h>

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
