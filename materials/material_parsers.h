/* material_parsers.h - parse routines of the built-in materials (materials/material_parsers.c), listed in
 * the materials section of its type record (GENERIC_TYPE). Parameters are documented in README.md, "Text format". */
#ifndef GENERIC_MATERIAL_PARSERS_H
#define GENERIC_MATERIAL_PARSERS_H

#include "generic/reader.h"

/** lambert { reflectance COLOR } */
int gparse_lambert(GReader *r, const void *vtable, void **object, GError *err);
/** phong { diffuse COLOR specular COLOR exponent N mirror COLOR } */
int gparse_phong(GReader *r, const void *vtable, void **object, GError *err);
/** mirror { reflectance COLOR } */
int gparse_mirror(GReader *r, const void *vtable, void **object, GError *err);
/** dielectric { index N | cauchy A B [C] | sellmeier B1 B2 B3 C1 C2 C3  absorption COLOR  tint COLOR } */
int gparse_dielectric(GReader *r, const void *vtable, void **object, GError *err);
/** emitter { radiance COLOR two_sided BOOL } */
int gparse_emitter(GReader *r, const void *vtable, void **object, GError *err);

#endif
