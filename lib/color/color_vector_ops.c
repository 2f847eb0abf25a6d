/* color_vector_ops.c - the library's defaults for the generic colour operations that models may leave to it (fill,
 * axpy: color.h) and its copy and finiteness tests, on a vector read as nvalues plain samples (a matrix as its
 * capacity's floats for copy and the tests). */
#include "generic/color.h"
#include "generic/kit/spectral_kernels.h"

#include <math.h>
#include <string.h>

/* The floats a value holds: a matrix's capacity, a vector's nvalues. */
static size_t value_floats(const GColor *c)
{
    return (size_t)(c->kind == GCOLOR_MATRIX ? c->model->capacity : c->model->nvalues);
}

/* out = s * a + b through the class's scale and add; a temporary holds s * a because out may alias b. */
static int axpy_composed(const GColorModel *m, GColor *out, double s, const GColor *a, const GColor *b)
{
    if (out->v != b->v) {
        int rc = m->cls->scale(m, out, a, s);
        return rc ? rc : m->cls->add(m, out, out, b);
    }
    GScratch *arena = gscratch_thread();
    if (!arena)
        return G_ERR_NOMEM;
    GScratchMark mark = gscratch_mark(arena);
    GColor tmp;
    int rc = gcolor_scratch(&tmp, m, arena);
    if (rc == G_OK)
        rc = m->cls->scale(m, &tmp, a, s);
    if (rc == G_OK)
        rc = m->cls->add(m, out, &tmp, b);
    gscratch_release(arena, mark);
    return rc;
}

/* gcolor_axpy, gcolor_fill and the finiteness tests have two bodies as the kit's operations do (lib/color/spectral.c):
 * on 4-float vectors and, compiled for AVX2, on 8-float vectors, with the same results. */

/* The body of gcolor_axpy around its kernel (a macro, so that each body inlines its own kernel). */
#define AXPY_BODY(kernel)                                                                                      \
    do {                                                                                                       \
        if (a->model != b->model || out->model != a->model)                                                    \
            return G_ERR_MISMATCH;                                                                             \
        const GColorModel *m = a->model;                                                                       \
        if (m->cls->axpy)                                                                                      \
            return m->cls->axpy(m, out, s, a, b);                                                              \
        if (a->kind != GCOLOR_VECTOR || b->kind != GCOLOR_VECTOR)                                              \
            return axpy_composed(m, out, s, a, b);                                                             \
        kernel(out->v, s, a->v, b->v, m->nvalues);                                                             \
        out->kind = GCOLOR_VECTOR;                                                                             \
        return G_OK;                                                                                           \
    } while (0)

static int gcolor_axpy_v4(GColor *out, double s, const GColor *a, const GColor *b) { AXPY_BODY(gspectral_kaxpyd); }

/* The body of gcolor_copy around its copy of n floats (as AXPY_BODY). */
#define COPY_BODY(copy)                                                                                        \
    do {                                                                                                       \
        if (!dst->model || dst->model != src->model)                                                           \
            return G_ERR_MISMATCH;                                                                             \
        if (dst->v != src->v)                                                                                  \
            copy(dst->v, src->v, value_floats(src));                                                           \
        dst->kind = src->kind;                                                                                 \
        return G_OK;                                                                                           \
    } while (0)

#define COPY_MEMCPY(o, a, n) memcpy(o, a, (n) * sizeof(float))
static int gcolor_copy_v4(GColor *dst, const GColor *src) { COPY_BODY(COPY_MEMCPY); }
#undef COPY_MEMCPY

int gcolor_add_scaled(GColor *out, const GColor *a, double s) { return gcolor_axpy(out, s, a, out); }

/* The body of gcolor_fill around its kernel (as AXPY_BODY). */
#define FILL_BODY(kernel)                                                                                      \
    do {                                                                                                       \
        if (!isfinite(value))                                                                                  \
            return G_ERR_INVALID;                                                                              \
        const GColorModel *m = out->model;                                                                     \
        if (m->cls->fill)                                                                                      \
            return m->cls->fill(m, out, value);                                                                \
        kernel(out->v, (float)value, m->nvalues);                                                              \
        out->kind = GCOLOR_VECTOR;                                                                             \
        return G_OK;                                                                                           \
    } while (0)

static int gcolor_fill_v4(GColor *out, double value) { FILL_BODY(gspectral_kfill); }

static int gcolor_is_finite_v4(const GColor *c) { return gspectral_kfinite(c->v, (int)value_floats(c), 0); }

static int gcolor_is_nonnegative_v4(const GColor *c) { return gspectral_kfinite(c->v, (int)value_floats(c), 1); }

#ifdef GSPECTRAL_AVX2
/* The 8-float kernels on the common grids' lengths as constants (GSPECTRAL_ON_COMMON_LENGTH), as the kit's operations
 * take them (lib/color/spectral.c): straight-line code on those grids, the kernels' jump on any other length; the
 * same kernels either way, so the same results bit for bit. */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 void axpy8(float *o, double s, const float *a,
                                                                             const float *b, int n)
{
#define AXPY(len) gspectral_kaxpyd8(o, s, a, b, len)
    GSPECTRAL_ON_COMMON_LENGTH(n, AXPY);
#undef AXPY
}

__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 void fill8(float *o, float value, int n)
{
    if (n < 8) { /* rgb's 3: no tests of the common lengths first */
        gspectral_kfill(o, value, n);
        return;
    }
#define FILL(len) gspectral_kfill8(o, value, len)
    GSPECTRAL_ON_COMMON_LENGTH(n, FILL);
#undef FILL
}

/* from 8 floats on, the 8-float blocks the kernels load (spectral_kernels8.h), not libc's pieces; fewer (rgb's 3)
 * as memcpy stores them, which is how the models of so few values read them back */
__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 void copy8(float *o, const float *a, size_t n)
{
    if (n < 8) {
        memcpy(o, a, n * sizeof(float));
        return;
    }
#define COPY(len) gspectral_kcopy8(o, a, (int)(len))
    GSPECTRAL_ON_COMMON_LENGTH(n, COPY);
#undef COPY
}

__attribute__((always_inline)) static inline GSPECTRAL_TARGET_AVX2 int finite8(const float *a, int n, int nonnegative)
{
    if (n < 8)
        return gspectral_kfinite(a, n, nonnegative);
#define FINITE(len) gspectral_kfinite8(a, len, nonnegative)
    return GSPECTRAL_ON_COMMON_LENGTH(n, FINITE);
#undef FINITE
}

static GSPECTRAL_TARGET_AVX2 int gcolor_axpy_v8(GColor *out, double s, const GColor *a, const GColor *b)
{
    AXPY_BODY(axpy8);
}

static GSPECTRAL_TARGET_AVX2 int gcolor_fill_v8(GColor *out, double value) { FILL_BODY(fill8); }

static GSPECTRAL_TARGET_AVX2 int gcolor_copy_v8(GColor *dst, const GColor *src) { COPY_BODY(copy8); }

static GSPECTRAL_TARGET_AVX2 int gcolor_is_finite_v8(const GColor *c) { return finite8(c->v, (int)value_floats(c), 0); }

static GSPECTRAL_TARGET_AVX2 int gcolor_is_nonnegative_v8(const GColor *c)
{
    return finite8(c->v, (int)value_floats(c), 1);
}

GSPECTRAL_PICK(gcolor_axpy);
GSPECTRAL_PICK(gcolor_fill);
GSPECTRAL_PICK(gcolor_copy);
GSPECTRAL_PICK(gcolor_is_finite);
GSPECTRAL_PICK(gcolor_is_nonnegative);
#else
int gcolor_axpy(GColor *out, double s, const GColor *a, const GColor *b) { return gcolor_axpy_v4(out, s, a, b); }

int gcolor_fill(GColor *out, double value) { return gcolor_fill_v4(out, value); }

int gcolor_copy(GColor *dst, const GColor *src) { return gcolor_copy_v4(dst, src); }

int gcolor_is_finite(const GColor *c) { return gcolor_is_finite_v4(c); }

int gcolor_is_nonnegative(const GColor *c) { return gcolor_is_nonnegative_v4(c); }
#endif
