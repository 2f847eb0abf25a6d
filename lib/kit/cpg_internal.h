/* cpg_internal.h - closed contours of rational Bézier segments shared by lib/kit/cpg_shape.c and
 * lib/kit/cpg_path.c. Internal. */
#ifndef GENERIC_TEXTURES_CPG_INTERNAL_H
#define GENERIC_TEXTURES_CPG_INTERNAL_H

#include "generic/export.h"
#include "generic/memory.h"
#include "generic/kit/shapes.h"

/** A rational Bézier segment in homogeneous form: control point i is (hx[i], hy[i]) / hw[i], hw[i] > 0. */
typedef struct GCpgSeg {
    int degree;
    double hx[GCPG_MAX_DEGREE + 1], hy[GCPG_MAX_DEGREE + 1], hw[GCPG_MAX_DEGREE + 1];
    double xmin, xmax, ymin, ymax; /* bounds of the control points (contain the segment) */
} GCpgSeg;

/** A closed contour: segments joined end to start, the last to the first. */
typedef struct GCpgContour {
    GCpgSeg *segs;
    int n;
    double xmin, xmax, ymin, ymax;
} GCpgContour;

/** Winding number of the contour around (x, y) (points on the contour may count either way). */
int gtexcpg_winding(const GCpgContour *c, double x, double y);
/** Frees the segments of a contour. */
void gtexcpg_contour_free(GCpgContour *c);
/** Makes a shape of a finished contour (the shape takes the segments). */
GENERIC_NODISCARD int gtexcpg_shape_from_contour(GCpgContour *c, GCpgShape **out, GError *err);

#endif
