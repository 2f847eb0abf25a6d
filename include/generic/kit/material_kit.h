/* material_kit.h - building a material instance: allocating it, the material whose one parameter is a colour,
 * and the cosine every BRDF starts from. With material_params.h (included) it is what a material's file needs
 * beside material.h and reader.h; docs/guide.md ("A first material of your own") shows a complete one. */
#ifndef GENERIC_MATERIAL_KIT_H
#define GENERIC_MATERIAL_KIT_H

#include "../export.h"
#include <stddef.h>
#include "../color.h"
#include "../error.h"
#include "../material.h"
#include "material_params.h"
#include "../surfpoint.h"
#include "../vec.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Allocates a zeroed material of `size` bytes (a struct that begins with its GMaterial) of class cls in
 * model into *out: G_ERR_NOMEM "<class>: out of memory", G_ERR_VERSION for a class of another version. Until
 * it is complete, the material is freed with its class's destroy (or gmem_free). */
GENERIC_API GENERIC_NODISCARD int gmaterial_new(const GMaterialClass *cls, const GColorModel *model, size_t size,
                                                GMaterial **out, GError *err);

/** Work a material does on its first use rather than at creation (tables only its methods read, so that a
 * material that is defined but never rendered costs nothing); a member of the material's struct, zeroed with it. */
typedef struct GMaterialOnce {
    int state;  /**< 1 once the work has run (read and written atomically by gmaterial_once) */
    int status; /**< what the work returned */
} GMaterialOnce;
/** Runs work(arg) for once the first time it is called and returns work's G_ status, then and on every later call;
 * a thread that calls while another runs the work waits for it. Safe from any number of threads (the material's
 * methods); work may call gmaterial_once for other materials, not for the same once. */
GENERIC_API int gmaterial_once(GMaterialOnce *once, int (*work)(void *arg), void *arg);

/** The state of a material whose one parameter is a colour (lambert, mirror; emitter adds a flag after it). */
typedef struct GMaterialOneColor {
    GMaterial base;
    GColor c; /**< the parameter, in the material's model */
} GMaterialOneColor;
/** The destroy method of the materials whose struct begins with a GMaterialOneColor (frees c and the struct). */
GENERIC_API void gmaterial_one_color_destroy(GMaterial *self);
/** Creates a material of class cls whose struct (`size` bytes) begins with a GMaterialOneColor, its colour being
 * src checked and converted by gmaterial_param_color (role, max; complaints "<class>: <param> ..." name param).
 * G_ERR_INVALID "<class>: no colour model given" without a model. */
GENERIC_API GENERIC_NODISCARD int gmaterial_one_color_create(const GMaterialClass *cls, const GColorModel *model,
                                                             size_t size, const GColor *src, GColorRole role,
                                                             double max, const char *param, GMaterial **out,
                                                             GError *err);

/** 1 when in and out lie where one interface can join them, by the geometric normal (material.h): out on its
 * incident side, and in on that side too for a reflection (transmit = 0) or on the other for a refraction
 * (transmit = 1). About a shading normal a bump tilts, an ideal ray may point back across the surface; such a pair
 * passes on nothing. */
GENERIC_API int gmaterial_sides_agree(const GSurfPoint *sp, GVec3 in, GVec3 out, int transmit);
/** Cosine of `in` with the shading normal when in and out are both on the incident side of the geometric
 * normal (gmaterial_sides_agree for a reflection), else 0 (clamped at 0); *n receives the shading normal
 * (gsurfpoint_normal). */
GENERIC_API double gmaterial_cos_in(GSurfPoint *sp, GVec3 in, GVec3 out, GVec3 *n);

/** The weight of a sampled direction (material.h): weight = value(in, white, out) / pdf, value being the
 * material's reflection() (transmit == 0) or refraction() with rel_index (transmit != 0), white from sp's arena
 * (or the thread's). For a material's sample(): its weight is then consistent with its methods by construction. */
GENERIC_API GENERIC_NODISCARD int gmaterial_sample_weight(const GMaterial *self, GSurfPoint *sp, GVec3 in, GVec3 out,
                                                     const GColor *rel_index, int transmit, double pdf,
                                                     GColor *weight);

/** Picks lobe i of n (weights w[i] >= 0, not all 0) with probability w[i] / sum from u in [0, 1) and remaps u to
 * [0, 1) within the lobe (*u); returns i and the probability in *p. */
GENERIC_API GENERIC_NODISCARD int gmaterial_pick_lobe(const double *w, int n, double *u, double *p);

#ifdef __cplusplus
}
#endif
#endif
