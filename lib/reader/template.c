/* template.c - recording where a named entry wrote its parameters, for entries derived from it with `like`. */
#include "template.h"
#include "generic/error.h"
#include "generic/memory.h"

void gtemplate_free(GTemplate *t)
{
    if (!t)
        return;
    for (int i = 0; i < t->nparams; i++)
        gmem_free(t->params[i].name);
    gmem_free(t->params);
    gmem_free(t->base);
    gmem_free(t);
}

void gtemplate_add_token(GTemplate *t, GSpan token)
{
    t->last_text = token.text;
    t->last_end = token.end;
    if (t->whole_state == 0) {
        t->whole = token;
        t->whole_state = 1;
    } else if (t->whole_state == 1 && t->whole.text == token.text && token.end >= t->whole.end) {
        t->whole.end = token.end;
    } else {
        t->whole_state = -1;
    }
}

void gtemplate_end_param(GTemplate *t)
{
    if (t->open_param) {
        t->params[t->open_param - 1].span.end = t->last_end;
        t->open_param = 0;
    }
}

int gtemplate_add_param(GTemplate *t, const char *name, GSpan at)
{
    gtemplate_end_param(t);
    if (t->nparams == t->capparams) {
        int cap = t->capparams ? t->capparams * 2 : 8;
        GTemplateParam *p = gmem_realloc(t->params, (size_t)cap * sizeof *p);
        if (!p)
            return G_ERR_NOMEM;
        t->params = p;
        t->capparams = cap;
    }
    char *copy = gmem_strdup(name);
    if (!copy)
        return G_ERR_NOMEM;
    t->params[t->nparams].name = copy;
    t->params[t->nparams].span = at;
    t->open_param = ++t->nparams;
    return G_OK;
}
