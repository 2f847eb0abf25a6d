/* grid.c - a grid medium's density grid (grid.h): trilinear density, majorant bricks, the walk along a ray.
 *
 * The walk runs in the grid's index space shifted by one voxel, w = index - min + 1, where the density can be
 * non-zero only inside (0, n + 1) along each axis (the trilinear reach of the voxels 0..n-1). Brick c of an axis
 * covers w in [c B, (c + 1) B] (B = GRID_BRICK); its majorant and minorant are the largest and smallest density of
 * the voxels whose trilinear reach meets it: c B - 1 to (c + 1) B, clipped to the grid (the minorant is 0 where
 * the brick reaches beyond w in [1, n], where voxels outside the grid count). Bricks are visited in the order the
 * ray crosses them (Amanatides and Woo 1987, "A fast voxel traversal algorithm for ray tracing"). */
#include "grid.h"

#include <generic/memory.h>

#include <math.h>
#include <stdio.h>

static size_t grid_index(const Grid *g, int i, int j, int k) { return ((size_t)k * g->n[1] + j) * g->n[0] + i; }

int grid_build_bricks(Grid *g, const char *path, GError *err)
{
    size_t count = 1;
    for (int a = 0; a < 3; a++) {
        g->nb[a] = (g->n[a] + 1 + GRID_BRICK - 1) / GRID_BRICK;
        count *= (size_t)g->nb[a];
    }
    char what[600];
    snprintf(what, sizeof what, "%s: the majorants of a %dx%dx%d grid", path, g->n[0], g->n[1], g->n[2]);
    int rc = gmem_budget_reserve(2 * count * sizeof(float), what, err);
    if (rc != G_OK)
        return rc;
    g->charged += 2 * count * sizeof(float);
    g->brick = gmem_calloc(count, sizeof(float));
    g->brick_min = gmem_alloc(count * sizeof(float));
    if (!g->brick || !g->brick_min)
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory for the majorants of its grid", path);
    for (size_t i = 0; i < count; i++)
        g->brick_min[i] = INFINITY;
    g->max_density = 0.0;
    for (int k = 0; k < g->n[2]; k++)
        for (int j = 0; j < g->n[1]; j++)
            for (int i = 0; i < g->n[0]; i++) {
                float v = g->density[grid_index(g, i, j, k)];
                if (v > g->max_density)
                    g->max_density = v;
                /* voxel i reaches w in (i, i + 2): the bricks from floor(i / B) to floor((i + 1) / B) */
                int lo[3] = {i / GRID_BRICK, j / GRID_BRICK, k / GRID_BRICK};
                int hi[3] = {(i + 1) / GRID_BRICK, (j + 1) / GRID_BRICK, (k + 1) / GRID_BRICK};
                for (int c = lo[2]; c <= hi[2] && c < g->nb[2]; c++)
                    for (int b = lo[1]; b <= hi[1] && b < g->nb[1]; b++)
                        for (int a = lo[0]; a <= hi[0] && a < g->nb[0]; a++) {
                            size_t at = ((size_t)c * g->nb[1] + b) * g->nb[0] + a;
                            g->brick[at] = v > g->brick[at] ? v : g->brick[at];
                            g->brick_min[at] = v < g->brick_min[at] ? v : g->brick_min[at];
                        }
            }
    for (int c = 0; c < g->nb[2]; c++) /* a brick reaching beyond [1, n] meets the zeros outside the grid */
        for (int b = 0; b < g->nb[1]; b++)
            for (int a = 0; a < g->nb[0]; a++) {
                const int cb[3] = {a, b, c};
                for (int x = 0; x < 3; x++)
                    if (cb[x] * GRID_BRICK < 1 || (cb[x] + 1) * GRID_BRICK > g->n[x])
                        g->brick_min[((size_t)c * g->nb[1] + b) * g->nb[0] + a] = 0.0f;
            }
    return G_OK;
}

void grid_release(Grid *g)
{
    gmem_free(g->density);
    gmem_free(g->brick);
    gmem_free(g->brick_min);
    if (g->charged)
        gmem_budget_release(g->charged);
    g->density = NULL;
    g->brick = g->brick_min = NULL;
    g->charged = 0;
}

/* The voxel's density, 0 outside the copy. */
static double voxel(const Grid *g, int i, int j, int k)
{
    if (i < 0 || j < 0 || k < 0 || i >= g->n[0] || j >= g->n[1] || k >= g->n[2])
        return 0.0;
    return g->density[grid_index(g, i, j, k)];
}

/* The trilinear density at index-space point u (relative to min). */
static double density_at(const Grid *g, const double u[3])
{
    double f[3];
    int c[3];
    for (int a = 0; a < 3; a++) {
        if (!(u[a] > -1.0 && u[a] < g->n[a]))
            return 0.0;
        double fl = floor(u[a]);
        c[a] = (int)fl;
        f[a] = u[a] - fl;
    }
    double v = 0.0;
    for (int corner = 0; corner < 8; corner++) {
        int di = corner & 1, dj = (corner >> 1) & 1, dk = corner >> 2;
        double w = (di ? f[0] : 1.0 - f[0]) * (dj ? f[1] : 1.0 - f[1]) * (dk ? f[2] : 1.0 - f[2]);
        if (w > 0.0)
            v += w * voxel(g, c[0] + di, c[1] + dj, c[2] + dk);
    }
    return v;
}

double grid_density(const Grid *g, GVec3 p)
{
    GVec3 q = xform_inv_point(&g->place, p);
    const double u[3] = {q.x, q.y, q.z};
    return density_at(g, u);
}

/* ---- the walk ---- */

/* Enters brick c: its majorant and minorant. */
static void enter_brick(GridTracker *k)
{
    const Grid *g = k->g;
    size_t at = ((size_t)k->cell[2] * g->nb[1] + k->cell[1]) * g->nb[0] + k->cell[0];
    k->majorant = g->brick[at];
    k->minorant = g->brick_min[at];
}

/* The rate collisions come at in the current brick. */
static double collision_rate(const GridTracker *k) { return k->residual ? k->majorant - k->minorant : k->majorant; }

/* Moves the walk to t within the current brick, integrating the majorant and the minorant. */
static void move_to(GridTracker *k, double t)
{
    double dt = t - k->t;
    if (dt > 0.0) {
        k->tau += k->majorant * dt;
        k->tau_min += k->minorant * dt;
    }
    k->t = t;
}

static double min3(const double v[3]) { return fmin(v[0], fmin(v[1], v[2])); }

void grid_tracker_begin(GridTracker *k, const Grid *g, GVec3 o, GVec3 d, double tmax, int residual)
{
    GVec3 uo = xform_inv_point(&g->place, o), ud = xform_inv_vector(&g->place, d);
    *k = (GridTracker){.g = g, .o = {uo.x + 1.0, uo.y + 1.0, uo.z + 1.0}, .d = {ud.x, ud.y, ud.z},
                       .residual = residual};
    double t0 = 0.0, t1 = tmax;
    for (int a = 0; a < 3; a++) {
        double hi = g->n[a] + 1.0;
        if (k->d[a] == 0.0) {
            if (!(k->o[a] > 0.0 && k->o[a] < hi))
                return;
            continue;
        }
        double ta = (0.0 - k->o[a]) / k->d[a], tb = (hi - k->o[a]) / k->d[a];
        t0 = fmax(t0, fmin(ta, tb));
        t1 = fmin(t1, fmax(ta, tb));
    }
    if (!(t0 < t1))
        return;
    for (int a = 0; a < 3; a++) {
        double w = k->o[a] + t0 * k->d[a];
        int c = (int)floor(w / GRID_BRICK);
        k->cell[a] = c < 0 ? 0 : c >= g->nb[a] ? g->nb[a] - 1 : c;
        k->step[a] = k->d[a] > 0.0 ? 1 : k->d[a] < 0.0 ? -1 : 0;
        if (k->step[a] == 0) {
            k->next[a] = k->delta[a] = INFINITY;
            continue;
        }
        double edge = (double)(k->cell[a] + (k->step[a] > 0)) * GRID_BRICK;
        k->next[a] = (edge - k->o[a]) / k->d[a];
        k->delta[a] = GRID_BRICK / fabs(k->d[a]);
    }
    k->t = t0;
    k->tend = t1;
    k->tb = fmax(fmin(min3(k->next), t1), t0);
    enter_brick(k);
    k->live = 1;
}

int grid_tracker_advance(GridTracker *k, double depth, double *t, double *density, double *rate)
{
    while (k->live) {
        double r = collision_rate(k), seg = r * (k->tb - k->t);
        if (depth < seg) {
            move_to(k, k->t + depth / r);
            if (++k->events > GRID_MAX_EVENTS) {
                k->live = 0;
                return -1;
            }
            const double u[3] = {k->o[0] + k->t * k->d[0] - 1.0, k->o[1] + k->t * k->d[1] - 1.0,
                                 k->o[2] + k->t * k->d[2] - 1.0};
            *t = k->t;
            *density = density_at(k->g, u);
            *rate = r;
            return 1;
        }
        if (seg > 0.0)
            depth -= seg;
        move_to(k, k->tb);
        if (!(k->tb < k->tend))
            break;
        int a = k->next[0] <= k->next[1] ? (k->next[0] <= k->next[2] ? 0 : 2) : (k->next[1] <= k->next[2] ? 1 : 2);
        k->cell[a] += k->step[a];
        if (k->cell[a] < 0 || k->cell[a] >= k->g->nb[a])
            break;
        k->next[a] += k->delta[a];
        k->tb = fmax(fmin(min3(k->next), k->tend), k->t);
        enter_brick(k);
    }
    k->live = 0;
    return 0;
}
