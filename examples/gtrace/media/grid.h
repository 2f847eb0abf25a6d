/* grid.h - the density grid of a grid medium (grid.c): a dense copy of an OpenVDB float grid that gtrace owns
 * (read by grid_load.c), placed in the world by an affine map, with a coarse grid of majorants and minorants (the
 * largest and smallest density of each brick of GRID_BRICK^3 voxels and their neighbours) and the walk along a ray
 * that delta and ratio tracking (medium_grid.c) take through it.
 *
 * Voxel (i, j, k) of the copy has its centre at index min + (i, j, k); the density between centres is trilinear,
 * and 0 beyond the copy (a voxel outside it counts as 0). A ray's parameter t is the same in world and index space
 * (the map is affine), so the walk works in index space with the world's distances. */
#ifndef GTRACE_GRID_H
#define GTRACE_GRID_H

#include "camera/rng.h"
#include "geometry/transform.h"

#include <generic/error.h>
#include <generic/vec.h>

#include <stddef.h>
#include <stdint.h>

/** Voxels along each edge of a majorant brick. */
#define GRID_BRICK 4
/** Tentative collisions one tracking may take before it gives up (the path ends there): bounds the work a grid of
 * a few very dense voxels among thin ones can ask of a ray. */
#define GRID_MAX_EVENTS (1 << 20)

/** A density grid. */
typedef struct Grid {
    float *density;         /**< n[0] * n[1] * n[2] values >= 0, x fastest */
    int n[3];               /**< voxels of the copy along x, y, z */
    int min[3];             /**< index of voxel (0, 0, 0) in the file */
    Xform place;            /**< index space (relative to min) to world space */
    float *brick;           /**< nb[0] * nb[1] * nb[2] majorants */
    float *brick_min;       /**< nb[0] * nb[1] * nb[2] minorants (0 for a brick that reaches beyond the voxels) */
    int nb[3];              /**< bricks along x, y, z */
    double max_density;     /**< the largest density of the copy */
    uint64_t active_voxels; /**< the file grid's active voxel count */
    size_t charged;         /**< bytes reserved against the memory budget for density and brick */
} Grid;

/** Builds the majorant and minorant bricks of g (density, n filled) and max_density. G_OK, or G_ERR_NOMEM (path
 * names the file in the message); reserves their bytes against the memory budget first (g->charged counts them). */
int grid_build_bricks(Grid *g, const char *path, GError *err);
/** Frees the grid's arrays and releases its budget; g itself is the caller's. */
void grid_release(Grid *g);
/** The trilinear density at a world point. */
double grid_density(const Grid *g, GVec3 p);

/** A walk along a ray through the bricks the density can be non-zero in, from one tentative collision to the next
 * (fill with grid_tracker_begin). */
typedef struct GridTracker {
    const Grid *g;
    double o[3], d[3];     /**< the ray in index space relative to min, shifted by one voxel (see grid.c) */
    int cell[3], step[3];  /**< the brick and the direction of the walk */
    double next[3], delta[3];
    double t, tb, tend;    /**< where the walk is, the end of the current brick's stretch, the end of the ray */
    double majorant;       /**< the current brick's majorant */
    double minorant;       /**< the current brick's minorant */
    double tau;            /**< the integral of the majorant along the ray up to t */
    double tau_min;        /**< the integral of the minorant along the ray up to t */
    int residual;          /**< collisions come at the rate majorant - minorant (residual ratio tracking) */
    int live;              /**< 0 once the ray has left the grid or reached tend */
    long events;           /**< tentative collisions so far */
} GridTracker;

/** Starts a walk along the world ray o + t d for t in (0, tmax) (tmax may be INFINITY); residual: collisions come
 * at the rate majorant - minorant instead of the majorant. */
void grid_tracker_begin(GridTracker *k, const Grid *g, GVec3 o, GVec3 d, double tmax, int residual);
/** Moves on by the optical depth `depth` of the collision rate (the integral of the majorant, or of majorant -
 * minorant for a residual walk, over the distance; INFINITY to the end). Returns 1 at a tentative collision, with
 * *t, the density there and the brick's rate (> 0); 0 at the end of the ray (k->tau and k->tau_min then hold the
 * whole integrals), or -1 after GRID_MAX_EVENTS collisions. */
int grid_tracker_advance(GridTracker *k, double depth, double *t, double *density, double *rate);

#endif
