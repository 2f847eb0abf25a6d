/* materials_builtin.h - the built-in material classes (one .c file each in materials/), registered
 * under GKIND_MATERIAL by its type record (GENERIC_TYPE). Their constructors are public in generic/materials.h. */
#ifndef GENERIC_MATERIALS_BUILTIN_H
#define GENERIC_MATERIALS_BUILTIN_H

#include "generic/material.h"

/** Ideal diffuse reflector (materials/lambert.c). */
extern const GMaterialClass gmaterial_lambert;
/** Energy-normalised Phong with an optional mirror ray (materials/phong.c). */
extern const GMaterialClass gmaterial_phong;
/** Perfect specular reflector (materials/mirror.c). */
extern const GMaterialClass gmaterial_mirror;
/** Smooth dielectric: Fresnel, dispersion formulas, Beer-Lambert absorption (materials/dielectric.c). */
extern const GMaterialClass gmaterial_dielectric;
/** Emitting surface (materials/emitter.c). */
extern const GMaterialClass gmaterial_emitter;

#endif
