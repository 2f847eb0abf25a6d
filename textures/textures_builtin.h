/* textures_builtin.h - the built-in texture node and generator classes (textures/), registered by
 * its type record (GENERIC_TYPE) under GKIND_NODE and GKIND_GENERATOR, with their parse routines (the parse_*.c files).
 * The constructors are public in generic/textures.h. */
#ifndef GENERIC_TEXTURES_BUILTIN_H
#define GENERIC_TEXTURES_BUILTIN_H

#include "generic/material.h"
#include "generic/registry.h"
#include "generic/texture.h"

/* ---- node classes ---- */
extern const GMaterialClass gnode_interpolate_class;     /**< textures/interpolate.c */
extern const GMaterialClass gnode_interpolate_one_class; /**< textures/interpolate.c */
extern const GMaterialClass gnode_select_class;          /**< textures/select.c */
extern const GMaterialClass gnode_spline_class;          /**< textures/spline.c */
extern const GMaterialClass gnode_bump_class;            /**< textures/bump.c */
extern const GMaterialClass gnode_scale_class;           /**< textures/scale.c */
extern const GMaterialClass gnode_image_class;           /**< textures/image.c */
extern const GMaterialClass gnode_transform_class;       /**< textures/transform.c */

/* ---- generator classes ---- */
extern const GGeneratorClass ggen_constant_class;   /**< textures/constant.c */
extern const GGeneratorClass ggen_checker_class;    /**< textures/checker.c */
extern const GGeneratorClass ggen_perlin_class;     /**< textures/perlin.c */
extern const GGeneratorClass ggen_fbm_class;        /**< textures/turbulence.c */
extern const GGeneratorClass ggen_turbulence_class; /**< textures/turbulence.c */
extern const GGeneratorClass ggen_wood_class;       /**< textures/wood.c */
extern const GGeneratorClass ggen_marble_class;     /**< textures/marble.c */
extern const GGeneratorClass ggen_surface_class;    /**< textures/surface.c */
extern const GGeneratorClass ggen_gradient_class;   /**< textures/gradient.c */
extern const GGeneratorClass ggen_csg_class;        /**< textures/csg.c */
extern const GGeneratorClass ggen_cpg_class;        /**< textures/cpg.c */

/* ---- parse routines (GParseFn, registry.h): textures/parse_nodes.c, parse_generators.c, parse_shapes.c ---- */
int gtexparse_interpolate(GReader *r, const void *vtable, void **object, GError *err);
int gtexparse_interpolate_one(GReader *r, const void *vtable, void **object, GError *err);
int gtexparse_select(GReader *r, const void *vtable, void **object, GError *err);
int gtexparse_spline(GReader *r, const void *vtable, void **object, GError *err);
int gtexparse_bump(GReader *r, const void *vtable, void **object, GError *err);
int gtexparse_scale(GReader *r, const void *vtable, void **object, GError *err);
int gtexparse_image(GReader *r, const void *vtable, void **object, GError *err);
int gtexparse_transform(GReader *r, const void *vtable, void **object, GError *err);
int gtexparse_constant(GReader *r, const void *vtable, void **object, GError *err);
int gtexparse_checker(GReader *r, const void *vtable, void **object, GError *err);
int gtexparse_perlin(GReader *r, const void *vtable, void **object, GError *err);
int gtexparse_fbm(GReader *r, const void *vtable, void **object, GError *err);
int gtexparse_turbulence(GReader *r, const void *vtable, void **object, GError *err);
int gtexparse_wood(GReader *r, const void *vtable, void **object, GError *err);
int gtexparse_marble(GReader *r, const void *vtable, void **object, GError *err);
int gtexparse_surface(GReader *r, const void *vtable, void **object, GError *err);
int gtexparse_gradient(GReader *r, const void *vtable, void **object, GError *err);
int gtexparse_csg(GReader *r, const void *vtable, void **object, GError *err);
int gtexparse_cpg(GReader *r, const void *vtable, void **object, GError *err);

/** Creates an interpolate node of class cls blending every method (only = -1) or the one GNodeMethod `only`
 * (textures/interpolate.c). */
int gtexnode_interpolate_make(const GMaterialClass *cls, GMaterial *a, GMaterial *b, GGenerator *t, int only,
                              GMaterial **out, GError *err);

#endif
