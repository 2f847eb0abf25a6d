/* builtins.c - the table of built-in types the registry loads on first use. This is the one file in
 * lib/ that names concrete models: it is where the library is composed. Each section lists the types
 * of one directory; colormodels/colormodels.h, materials/materials_builtin.h and
 * textures/textures_builtin.h declare their vtables and parse routines. */
#include "builtins.h"
#include "colormodels/colormodels.h"
#include "materials/materials_builtin.h"
#include "materials/material_parsers.h"

/* ---- colour models ---- */
static const GTypeInfo colormodel_rgb = {.kind = GKIND_COLORMODEL, .name = "rgb", .vtable = &gcolormodel_rgb,
                                         .summary = "linear sRGB (Rec.709 primaries, D65 white)"};
static const GTypeInfo colormodel_spectrum9 = {.kind = GKIND_COLORMODEL, .name = "spectrum9",
                                               .vtable = &gcolormodel_spectrum9,
                                               .summary = "9 samples 380..780 nm every 50 nm, natural cubic spline"};
static const GTypeInfo colormodel_spectrum = {.kind = GKIND_COLORMODEL, .name = "spectrum",
                                              .vtable = &gcolormodel_spectrum,
                                              .summary = "spectrum sampled every step_nm (default 380..780 nm at 5 nm)"};
static const GTypeInfo colormodel_bispectral = {.kind = GKIND_COLORMODEL, .name = "bispectral",
                                                .vtable = &gcolormodel_bispectral,
                                                .summary = "spectra and fluorescent re-radiation matrices (10 nm)"};
/* (end of colour models) */

/* ---- materials ---- */
static const GTypeInfo material_lambert = {.kind = GKIND_MATERIAL, .name = "lambert", .vtable = &gmaterial_lambert,
                                           .parse = gparse_lambert, .summary = "ideal diffuse reflector"};
static const GTypeInfo material_phong = {.kind = GKIND_MATERIAL, .name = "phong", .vtable = &gmaterial_phong,
                                         .parse = gparse_phong, .summary = "energy-normalised Phong with an optional mirror ray"};
static const GTypeInfo material_mirror = {.kind = GKIND_MATERIAL, .name = "mirror", .vtable = &gmaterial_mirror,
                                          .parse = gparse_mirror, .summary = "perfect specular reflector"};
static const GTypeInfo material_dielectric = {.kind = GKIND_MATERIAL, .name = "dielectric",
                                              .vtable = &gmaterial_dielectric, .parse = gparse_dielectric,
                                              .summary = "smooth dielectric (Fresnel, dispersion, absorption)"};
static const GTypeInfo material_emitter = {.kind = GKIND_MATERIAL, .name = "emitter", .vtable = &gmaterial_emitter,
                                           .parse = gparse_emitter, .summary = "emitting surface"};
/* fluorescent materials and the parametric re-radiation matrix (materials/fluorescent/) */
#include "materials/fluorescent/fluorescent_builtin.h"
/* (end of materials) */

/* ---- texture nodes and generators ---- */
#include "textures/textures_builtin.h"
#define TEXNODE(var, kw, cls, fn, text) \
    static const GTypeInfo var = {.kind = GKIND_NODE, .name = kw, .vtable = &cls, .parse = fn, .summary = text};
#define TEXGEN(var, kw, cls, fn, text)                                                                      \
    static const GTypeInfo var = {.kind = GKIND_GENERATOR, .name = kw, .vtable = &cls, .parse = fn, .summary = text, \
                                  .destroy = ggenerator_release};
TEXNODE(node_interpolate, "interpolate", gnode_interpolate_class, gtexparse_interpolate,
        "two children blended by a generator value")
TEXNODE(node_interpolate_one, "interpolate-one", gnode_interpolate_one_class, gtexparse_interpolate_one,
        "one method blended by a generator, the rest from the first child")
TEXNODE(node_select, "select", gnode_select_class, gtexparse_select, "one of n children picked by an integer generator")
TEXNODE(node_spline, "spline", gnode_spline_class, gtexparse_spline, "n children blended by a spline over a generator")
TEXNODE(node_bump, "bump", gnode_bump_class, gtexparse_bump, "normal perturbed by a height field's gradient")
TEXNODE(node_scale, "scale", gnode_scale_class, gtexparse_scale, "the child's light times a generator value")
TEXNODE(node_image, "image", gnode_image_class, gtexparse_image, "the child's light times an image's colour at (u, v)")
TEXNODE(node_transform, "transform", gnode_transform_class, gtexparse_transform, "moves the patterns of its subtree")
TEXGEN(gen_constant, "constant", ggen_constant_class, gtexparse_constant, "the same value everywhere")
TEXGEN(gen_checker, "checker", ggen_checker_class, gtexparse_checker, "checkerboard 0/1 in 2D or 3D")
TEXGEN(gen_perlin, "perlin", ggen_perlin_class, gtexparse_perlin, "improved Perlin noise in [0, 1]")
TEXGEN(gen_fbm, "fbm", ggen_fbm_class, gtexparse_fbm, "fractional Brownian motion in [0, 1]")
TEXGEN(gen_turbulence, "turbulence", ggen_turbulence_class, gtexparse_turbulence, "Perlin's turbulence in [0, 1]")
TEXGEN(gen_wood, "wood", ggen_wood_class, gtexparse_wood, "growth rings displaced by noise")
TEXGEN(gen_marble, "marble", ggen_marble_class, gtexparse_marble, "sine veins displaced by turbulence")
TEXGEN(gen_surface, "surface", ggen_surface_class, gtexparse_surface, "the index of the surface hit")
TEXGEN(gen_gradient, "gradient", ggen_gradient_class, gtexparse_gradient, "linear field (height field or ramp)")
TEXGEN(gen_csg, "csg", ggen_csg_class, gtexparse_csg, "1 inside a CSG solid, 0 outside")
TEXGEN(gen_cpg, "cpg", ggen_cpg_class, gtexparse_cpg, "1 inside a 2D shape tree at (u, v), 0 outside")
#define TEXTURE_TYPES &node_interpolate, &node_interpolate_one, &node_select, &node_spline, &node_bump, &node_scale, \
                      &node_image, &node_transform, &gen_constant, &gen_checker, &gen_perlin, &gen_fbm,            \
                      &gen_turbulence, &gen_wood, &gen_marble, &gen_surface, &gen_gradient, &gen_csg, &gen_cpg,
/* (end of textures) */

/* ---- colour literals (lib/colorparse.c) ---- */
#include "colorparse.h"
#define COLOR_LITERALS &gcolortype_rgb, &gcolortype_spectrum, &gcolortype_blackbody, &gcolortype_illuminant, \
                       &gcolortype_line, &gcolortype_bfc, &gcolortype_scale,
/* (end of colour literals) */

static const GTypeInfo *const builtin_types[] = {
    /* colour literals */
    COLOR_LITERALS
    /* colour models */
    &colormodel_rgb,
    &colormodel_spectrum9,
    &colormodel_spectrum,
    &colormodel_bispectral,
    /* materials */
    &material_lambert,
    &material_phong,
    &material_mirror,
    &material_dielectric,
    &material_emitter,
    GFLUOR_BUILTIN_TYPES
    /* texture nodes and generators */
    TEXTURE_TYPES
    NULL,
};

const GTypeInfo *const *gbuiltin_types(void) { return builtin_types; }
