/* cpg_path.c - closed contours of straight, Bézier, uniform B-spline and NURBS edges for CPG trees. Every
 * edge becomes rational Bézier segments (B-splines and NURBS span by span, through their blossoms), and
 * the inside test is the winding number of a ray towards +x, found by subdividing only the segments whose
 * control polygon straddles the ray near the point. */
#include "cpg_internal.h"

#include <math.h>
#include <string.h>

struct GCpgPath {
    GCpgSeg *segs;
    int n, cap;
    int curved; /* any edge other than straight lines */
};

int gcpg_path_create(GCpgPath **out, GError *err)
{
    *out = gmem_calloc(1, sizeof **out);
    return *out ? G_OK : gerror_set(err, G_ERR_NOMEM, "cpg path: out of memory");
}

void gcpg_path_destroy(GCpgPath *p)
{
    if (!p)
        return;
    gmem_free(p->segs);
    gmem_free(p);
}

static void bounds(GCpgSeg *s)
{
    s->xmin = s->ymin = INFINITY;
    s->xmax = s->ymax = -INFINITY;
    for (int i = 0; i <= s->degree; i++) {
        double x = s->hx[i] / s->hw[i], y = s->hy[i] / s->hw[i];
        s->xmin = fmin(s->xmin, x);
        s->xmax = fmax(s->xmax, x);
        s->ymin = fmin(s->ymin, y);
        s->ymax = fmax(s->ymax, y);
    }
}

static int push(GCpgPath *p, const GCpgSeg *s, GError *err)
{
    if (p->n == p->cap) {
        int cap = p->cap ? 2 * p->cap : 16;
        GCpgSeg *n = gmem_realloc(p->segs, (size_t)cap * sizeof *n);
        if (!n)
            return gerror_set(err, G_ERR_NOMEM, "cpg path: out of memory");
        p->segs = n;
        p->cap = cap;
    }
    p->segs[p->n] = *s;
    bounds(&p->segs[p->n]);
    p->n++;
    return G_OK;
}

static int check_points(const char *what, const double *xy, int n, GError *err)
{
    if (!xy)
        return gerror_set(err, G_ERR_INVALID, "cpg %s: no points given", what);
    for (int i = 0; i < 2 * n; i++)
        if (!isfinite(xy[i]))
            return gerror_set(err, G_ERR_INVALID, "cpg %s: point %d is not finite", what, i / 2 + 1);
    return G_OK;
}

static int line(GCpgPath *p, double x0, double y0, double x1, double y1, GError *err)
{
    GCpgSeg s = {.degree = 1, .hx = {x0, x1}, .hy = {y0, y1}, .hw = {1, 1}};
    return push(p, &s, err);
}

int gcpg_path_lines(GCpgPath *p, const double *xy, int n, GError *err)
{
    if (n < 1)
        return gerror_set(err, G_ERR_INVALID, "cpg lines: needs at least 1 point, got %d", n);
    int rc = check_points("lines", xy, n, err);
    if (rc != G_OK)
        return rc;
    /* the first point joins the previous edge (or starts the contour) through the gap rule */
    for (int i = 0; i + 1 < n && rc == G_OK; i++)
        rc = line(p, xy[2 * i], xy[2 * i + 1], xy[2 * i + 2], xy[2 * i + 3], err);
    if (rc == G_OK && n == 1) /* a lone point: a zero-length edge there, so the gap rule reaches it */
        rc = line(p, xy[0], xy[1], xy[0], xy[1], err);
    return rc;
}

int gcpg_path_bezier(GCpgPath *p, int degree, const double *xy, GError *err)
{
    if (degree < 1 || degree > GCPG_MAX_DEGREE)
        return gerror_set(err, G_ERR_INVALID, "cpg bezier: degree must be within 1..%d, got %d", GCPG_MAX_DEGREE,
                          degree);
    int rc = check_points("bezier", xy, degree + 1, err);
    if (rc != G_OK)
        return rc;
    GCpgSeg s = {.degree = degree};
    for (int i = 0; i <= degree; i++) {
        s.hx[i] = xy[2 * i];
        s.hy[i] = xy[2 * i + 1];
        s.hw[i] = 1.0;
    }
    p->curved |= degree > 1;
    return push(p, &s, err);
}

/* The Bézier segment of span [U[i], U[i+1]] from the homogeneous control points pw (3 per point) through
 * the blossom: control point j is f(a^(p-j), b^j). */
static void span_to_bezier(int p, const double *pw, const double *U, int i, GCpgSeg *s)
{
    double a = U[i], b = U[i + 1];
    s->degree = p;
    for (int j = 0; j <= p; j++) {
        double d[GCPG_MAX_DEGREE + 1][3];
        for (int k = 0; k <= p; k++)
            memcpy(d[k], pw + 3 * (i - p + k), sizeof d[k]);
        for (int r = 1; r <= p; r++) {
            double u = r <= p - j ? a : b;
            for (int k = p; k >= r; k--) {
                int g = i - p + k; /* global index of d[k] */
                double alpha = (u - U[g]) / (U[g + p + 1 - r] - U[g]);
                for (int c = 0; c < 3; c++)
                    d[k][c] = (1.0 - alpha) * d[k - 1][c] + alpha * d[k][c];
            }
        }
        s->hx[j] = d[p][0];
        s->hy[j] = d[p][1];
        s->hw[j] = d[p][2];
    }
}

int gcpg_path_nurbs(GCpgPath *p, int degree, const double *xy, const double *weights, int n, const double *knots,
                    GError *err)
{
    if (degree < 1 || degree > GCPG_MAX_DEGREE)
        return gerror_set(err, G_ERR_INVALID, "cpg nurbs: degree must be within 1..%d, got %d", GCPG_MAX_DEGREE,
                          degree);
    if (n <= degree)
        return gerror_set(err, G_ERR_INVALID, "cpg nurbs: degree %d needs more than %d control points, got %d", degree,
                          degree, n);
    int rc = check_points("nurbs", xy, n, err);
    if (rc != G_OK)
        return rc;
    for (int i = 0; weights && i < n; i++)
        if (!(weights[i] > 0.0) || !isfinite(weights[i]))
            return gerror_set(err, G_ERR_INVALID, "cpg nurbs: weight %d is %g; weights must be positive and finite",
                              i + 1, weights[i]);
    int m = n + degree + 1;
    double *U = gmem_calloc((size_t)m, sizeof *U);
    double *pw = gmem_calloc((size_t)n * 3, sizeof *pw);
    if (!U || !pw) {
        gmem_free(U);
        gmem_free(pw);
        return gerror_set(err, G_ERR_NOMEM, "cpg nurbs: out of memory");
    }
    if (knots) {
        for (int i = 0; i < m && rc == G_OK; i++) {
            U[i] = knots[i];
            if (!isfinite(U[i]) || (i > 0 && U[i] < U[i - 1]))
                rc = gerror_set(err, G_ERR_INVALID, "cpg nurbs: knot %d (%g) is not finite or decreases", i + 1, U[i]);
        }
        if (rc == G_OK && !(U[degree] < U[n]))
            rc = gerror_set(err, G_ERR_INVALID, "cpg nurbs: the knots give an empty domain [%g, %g]", U[degree], U[n]);
    } else { /* clamped uniform */
        for (int i = 0; i < m; i++)
            U[i] = i <= degree ? 0.0 : i >= n ? (double)(n - degree) : (double)(i - degree);
    }
    for (int i = 0; i < n; i++) {
        double w = weights ? weights[i] : 1.0;
        pw[3 * i] = w * xy[2 * i];
        pw[3 * i + 1] = w * xy[2 * i + 1];
        pw[3 * i + 2] = w;
    }
    for (int i = degree; i < n && rc == G_OK; i++) {
        if (!(U[i] < U[i + 1]))
            continue;
        GCpgSeg s;
        span_to_bezier(degree, pw, U, i, &s);
        rc = push(p, &s, err);
    }
    p->curved |= degree > 1;
    gmem_free(U);
    gmem_free(pw);
    return rc;
}

int gcpg_path_bspline(GCpgPath *p, int degree, const double *xy, int n, int periodic, GError *err)
{
    if (degree < 1 || degree > GCPG_MAX_DEGREE)
        return gerror_set(err, G_ERR_INVALID, "cpg bspline: degree must be within 1..%d, got %d", GCPG_MAX_DEGREE,
                          degree);
    if (n <= degree)
        return gerror_set(err, G_ERR_INVALID, "cpg bspline: degree %d needs more than %d control points, got %d",
                          degree, degree, n);
    int rc = check_points("bspline", xy, n, err);
    if (rc != G_OK)
        return rc;
    int count = periodic ? n + degree : n; /* a periodic curve repeats its first `degree` points */
    double *pts = gmem_calloc((size_t)count * 2, sizeof *pts);
    double *U = gmem_calloc((size_t)(count + degree + 1), sizeof *U);
    if (!pts || !U) {
        gmem_free(pts);
        gmem_free(U);
        return gerror_set(err, G_ERR_NOMEM, "cpg bspline: out of memory");
    }
    for (int i = 0; i < count; i++) {
        pts[2 * i] = xy[2 * (i % n)];
        pts[2 * i + 1] = xy[2 * (i % n) + 1];
    }
    for (int i = 0; i < count + degree + 1; i++)
        U[i] = (double)i;
    rc = gcpg_path_nurbs(p, degree, pts, NULL, count, U, err);
    gmem_free(pts);
    gmem_free(U);
    return rc;
}

/* ---- closing ---- */

static void seg_start(const GCpgSeg *s, double *x, double *y)
{
    *x = s->hx[0] / s->hw[0];
    *y = s->hy[0] / s->hw[0];
}

static void seg_end(const GCpgSeg *s, double *x, double *y)
{
    *x = s->hx[s->degree] / s->hw[s->degree];
    *y = s->hy[s->degree] / s->hw[s->degree];
}

int gcpg_path_close(GCpgPath *p, GCpgShape **out, GError *err)
{
    *out = NULL;
    if (!p)
        return gerror_set(err, G_ERR_INVALID, "cpg path: no path given");
    GCpgPath closed = {0};
    int rc = G_OK;
    if (p->n == 0)
        rc = gerror_set(err, G_ERR_INVALID, "cpg path: the contour has no edges");
    for (int i = 0; i < p->n && rc == G_OK; i++) {
        const GCpgSeg *s = &p->segs[i], *next = &p->segs[(i + 1) % p->n];
        double x0, y0, x1, y1;
        seg_end(s, &x0, &y0);
        seg_start(next, &x1, &y1);
        rc = push(&closed, s, err);
        if (rc == G_OK && (x0 != x1 || y0 != y1))
            rc = line(&closed, x0, y0, x1, y1, err);
    }
    if (rc == G_OK && !p->curved) { /* a polygon needs three distinct corners */
        double px[3];
        double py[3];
        int distinct = 0;
        for (int i = 0; i < closed.n && distinct < 3; i++) {
            double x, y;
            seg_start(&closed.segs[i], &x, &y);
            int seen = 0;
            for (int k = 0; k < distinct; k++)
                seen |= px[k] == x && py[k] == y;
            if (!seen) {
                px[distinct] = x;
                py[distinct++] = y;
            }
        }
        if (distinct < 3)
            rc = gerror_set(err, G_ERR_INVALID, "cpg polygon: needs at least 3 distinct points, got %d", distinct);
    }
    gcpg_path_destroy(p);
    if (rc != G_OK) {
        gmem_free(closed.segs);
        return rc;
    }
    GCpgContour c = {closed.segs, closed.n, INFINITY, -INFINITY, INFINITY, -INFINITY};
    for (int i = 0; i < c.n; i++) {
        c.xmin = fmin(c.xmin, c.segs[i].xmin);
        c.xmax = fmax(c.xmax, c.segs[i].xmax);
        c.ymin = fmin(c.ymin, c.segs[i].ymin);
        c.ymax = fmax(c.ymax, c.segs[i].ymax);
    }
    return gtexcpg_shape_from_contour(&c, out, err);
}

void gtexcpg_contour_free(GCpgContour *c)
{
    gmem_free(c->segs);
    c->segs = NULL;
    c->n = 0;
}

/* ---- winding number ---- */

/* Crossing of the ray y = y0, x > x0 by a straight piece, half-open in y (+1 upwards, -1 downwards). */
static int line_crossing(double xa, double ya, double xb, double yb, double x0, double y0)
{
    if (ya <= y0) {
        if (yb > y0 && (xb - xa) * (y0 - ya) - (x0 - xa) * (yb - ya) > 0.0)
            return 1;
    } else if (yb <= y0 && (xb - xa) * (y0 - ya) - (x0 - xa) * (yb - ya) < 0.0) {
        return -1;
    }
    return 0;
}

static int piece_crossing(int p, const double *hx, const double *hy, const double *hw, double x0, double y0,
                          int depth)
{
    /* the signs of w (x - x0) and w (y - y0) at the control points bound the curve (w > 0) */
    int above = 0, below = 0, right = 0, left = 0;
    for (int i = 0; i <= p; i++) {
        double cy = hy[i] - y0 * hw[i], cx = hx[i] - x0 * hw[i];
        above += cy > 0.0;
        below += cy <= 0.0;
        right += cx > 0.0;
        left += cx < 0.0;
    }
    if (above == p + 1 || below == p + 1 || left == p + 1)
        return 0;
    double xa = hx[0] / hw[0], ya = hy[0] / hw[0], xb = hx[p] / hw[p], yb = hy[p] / hw[p];
    if (right == p + 1) /* wholly right of the point: only the ends decide */
        return (ya <= y0 && yb > y0) ? 1 : (yb <= y0 && ya > y0) ? -1 : 0;
    if (depth >= 60)
        return line_crossing(xa, ya, xb, yb, x0, y0);
    /* de Casteljau at t = 1/2 in homogeneous coordinates */
    double L[3][GCPG_MAX_DEGREE + 1], R[3][GCPG_MAX_DEGREE + 1], t[3][GCPG_MAX_DEGREE + 1];
    for (int i = 0; i <= p; i++) {
        t[0][i] = hx[i];
        t[1][i] = hy[i];
        t[2][i] = hw[i];
    }
    for (int c = 0; c < 3; c++) {
        L[c][0] = t[c][0];
        R[c][p] = t[c][p];
    }
    for (int r = 1; r <= p; r++) {
        for (int i = 0; i <= p - r; i++)
            for (int c = 0; c < 3; c++)
                t[c][i] = 0.5 * (t[c][i] + t[c][i + 1]);
        for (int c = 0; c < 3; c++) {
            L[c][r] = t[c][0];
            R[c][p - r] = t[c][p - r];
        }
    }
    return piece_crossing(p, L[0], L[1], L[2], x0, y0, depth + 1) +
           piece_crossing(p, R[0], R[1], R[2], x0, y0, depth + 1);
}

int gtexcpg_winding(const GCpgContour *c, double x, double y)
{
    if (!(x <= c->xmax && y >= c->ymin && y < c->ymax && x >= c->xmin))
        return 0;
    int w = 0;
    for (int i = 0; i < c->n; i++) {
        const GCpgSeg *s = &c->segs[i];
        if (y < s->ymin || y >= s->ymax || x > s->xmax)
            continue;
        if (s->degree == 1)
            w += line_crossing(s->hx[0] / s->hw[0], s->hy[0] / s->hw[0], s->hx[1] / s->hw[1], s->hy[1] / s->hw[1],
                               x, y);
        else
            w += piece_crossing(s->degree, s->hx, s->hy, s->hw, x, y, 0);
    }
    return w;
}
