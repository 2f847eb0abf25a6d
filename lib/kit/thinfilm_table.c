/* thinfilm_table.c - a film's colours tabulated over the ambient cosine, read by cubic interpolation
 * (kit/thinfilm.h). */
#include "generic/kit/thinfilm.h"
#include "generic/memory.h"

#include <math.h>
#include <string.h>

struct GThinFilmTable {
    GThinFilm film;
    const GColorModel *model;
    int nodes;  /* at cos_ambient = (j / (nodes - 1))^2: dense towards grazing */
    int stride; /* floats a colour: the model's nvalues */
    float *r, *t; /* nodes x stride each, node-major */
    size_t charged; /* bytes reserved against the memory budget */
};

/* Nodes for the film: GTHINFILM_TABLE_NODES_PER_CYCLE per period of its phase over the cosine, twice that over
 * u = sqrt(cos), which runs at most twice as fast (dc / du = 2 u <= 2). The phase is
 * 4 pi d Re(n_1 cos theta_1) / lambda with n_1 cos theta_1 = sqrt(n_1^2 - 1 + c^2) (ambient 1; scaled otherwise),
 * whose slope in c, c / sqrt(n_1^2 - 1 + c^2), is largest at c = 1: 1 / n_1. */
static double table_nodes(const GThinFilm *f)
{
    double cycles = 2.0 * f->thickness * f->ambient * f->ambient / (GNM_MIN * f->n);
    return ceil(2.0 * GTHINFILM_TABLE_NODES_PER_CYCLE * cycles) + 33.0;
}

int gthinfilm_table_create(const GThinFilm *f, const GColorModel *model, GThinFilmTable **out)
{
    *out = NULL;
    double nodes = table_nodes(f);
    /* a substrate below the ambient by a float's rounding (a base of index 1 seen from inside) bends the curves only
     * within 0.1 degrees of grazing, inside the first interval */
    if (!(f->n > f->ambient) || !(f->substrate >= f->ambient * (1.0 - 1e-6)) || !(nodes <= GTHINFILM_TABLE_MAX_NODES) ||
        model->cls->fill)
        return G_ERR_UNSUPPORTED;
    GThinFilmTable *t = gmem_calloc(1, sizeof *t);
    GColor r = {0}, tr = {0};
    int rc = t ? gcolor_alloc(&r, model) : G_ERR_NOMEM;
    if (rc == G_OK)
        rc = gcolor_alloc(&tr, model);
    if (rc == G_OK) {
        t->film = *f, t->model = model, t->nodes = (int)nodes, t->stride = model->nvalues;
        size_t bytes = 2 * (size_t)t->nodes * (size_t)t->stride * sizeof *t->r; /* the thickness sizes it */
        rc = gmem_budget_reserve(bytes, "a thin film's table", NULL);
        t->charged = rc == G_OK ? bytes : 0;
    }
    if (rc == G_OK) {
        t->r = gmem_calloc((size_t)t->nodes * (size_t)t->stride, sizeof *t->r);
        t->t = gmem_calloc((size_t)t->nodes * (size_t)t->stride, sizeof *t->t);
        if (!t->r || !t->t)
            rc = G_ERR_NOMEM;
    }
    for (int j = 0; j < (rc == G_OK ? t->nodes : 0) && rc == G_OK; j++) {
        double u = (double)j / (t->nodes - 1);
        rc = gthinfilm_color(f, j == t->nodes - 1 ? 1.0 : u * u, &r, &tr);
        if (rc == G_OK && (r.kind != GCOLOR_VECTOR || tr.kind != GCOLOR_VECTOR))
            rc = G_ERR_UNSUPPORTED;
        if (rc == G_OK) {
            memcpy(t->r + (size_t)j * t->stride, r.v, (size_t)t->stride * sizeof *r.v);
            memcpy(t->t + (size_t)j * t->stride, tr.v, (size_t)t->stride * sizeof *tr.v);
        }
    }
    gcolor_free(&r);
    gcolor_free(&tr);
    if (rc != G_OK) {
        gthinfilm_table_destroy(t);
        return rc;
    }
    *out = t;
    return G_OK;
}

void gthinfilm_table_destroy(GThinFilmTable *t)
{
    if (!t)
        return;
    gmem_free(t->r);
    gmem_free(t->t);
    if (t->charged)
        gmem_budget_release(t->charged);
    gmem_free(t);
}

int gthinfilm_table_matches(const GThinFilmTable *t, const GThinFilm *f)
{
    const GThinFilm *g = &t->film;
    return g->thickness == f->thickness && g->n == f->n && g->k == f->k && g->ambient == f->ambient &&
           g->substrate == f->substrate;
}

/* out = the Catmull-Rom curve through the rows j - 1 .. j + 2 of table at x - j; beyond an end of the table the
 * missing row is extrapolated from the three nearest (3 p_0 - 3 p_1 + p_2), folded into the weights. */
static void interpolate(const GThinFilmTable *t, const float *table, double x, GColor *out)
{
    int last = t->nodes - 1, j = (int)x;
    j = j < last ? j : last - 1;
    double u = x - j, u2 = u * u, u3 = u2 * u;
    double w[4] = {0.5 * (-u3 + 2.0 * u2 - u), 0.5 * (3.0 * u3 - 5.0 * u2 + 2.0), 0.5 * (-3.0 * u3 + 4.0 * u2 + u),
                   0.5 * (u3 - u2)};
    int n = t->stride, first = j - 1;
    if (j == 0) /* p_-1 = 3 p_0 - 3 p_1 + p_2 */
        w[1] += 3.0 * w[0], w[2] -= 3.0 * w[0], w[3] += w[0], w[0] = 0.0, first = 0;
    if (j + 2 > last) /* p_last+1 = 3 p_last - 3 p_last-1 + p_last-2 */
        w[2] += 3.0 * w[3], w[1] -= 3.0 * w[3], w[0] += w[3], w[3] = 0.0, first = j - 1;
    const float *p1 = table + (size_t)j * n;
    if (u == 0.0) { /* on a node: its colour exactly */
        memcpy(out->v, p1, (size_t)n * sizeof *p1);
        out->kind = GCOLOR_VECTOR;
        return;
    }
    const float *p0 = table + (size_t)(first >= 0 ? first : 0) * n, *p2 = p1 + n;
    const float *p3 = j + 2 <= last ? p2 + n : p2;
    float fw[4] = {(float)w[0], (float)w[1], (float)w[2], (float)w[3]};
    for (int i = 0; i < n; i++)
        out->v[i] = fw[0] * p0[i] + fw[1] * p1[i] + fw[2] * p2[i] + fw[3] * p3[i];
    out->kind = GCOLOR_VECTOR;
}

int gthinfilm_table_color(const GThinFilmTable *t, double cos_ambient, GColor *reflectance, GColor *transmittance)
{
    if ((reflectance && reflectance->model != t->model) || (transmittance && transmittance->model != t->model))
        return G_ERR_MISMATCH;
    double c = cos_ambient > 0.0 ? (cos_ambient < 1.0 ? cos_ambient : 1.0) : 0.0;
    if (c < GTHINFILM_TABLE_COS_MIN) /* at grazing the film's colours change faster than the nodes resolve */
        return gthinfilm_color(&t->film, c, reflectance, transmittance);
    double x = sqrt(c) * (t->nodes - 1);
    if (reflectance)
        interpolate(t, t->r, x, reflectance);
    if (transmittance)
        interpolate(t, t->t, x, transmittance);
    return G_OK;
}
