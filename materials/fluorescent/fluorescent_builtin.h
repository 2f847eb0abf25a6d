/* fluorescent_builtin.h - the fluorescent material classes and their parse routines, registered under
 * GKIND_MATERIAL (and the parametric matrix under GKIND_COLOR) by lib/builtins.c. */
#ifndef GENERIC_FLUORESCENT_BUILTIN_H
#define GENERIC_FLUORESCENT_BUILTIN_H

#include "generic/material.h"
#include "generic/registry.h"

/** fluorescent-phong (materials/fluorescent/fluorescent_phong.c). */
extern const GMaterialClass gmaterial_fluorescent_phong;
/** fluorescent-varnish (materials/fluorescent/fluorescent_varnish.c). */
extern const GMaterialClass gmaterial_fluorescent_varnish;

/** The registered types (materials/fluorescent/parsers.c): the `reradiation` colour literal and the two
 * materials. */
extern const GTypeInfo gfluor_type_reradiation;
extern const GTypeInfo gfluor_type_phong;
extern const GTypeInfo gfluor_type_varnish;
/** Entries for lib/builtins.c's table. */
#define GFLUOR_BUILTIN_TYPES &gfluor_type_reradiation, &gfluor_type_phong, &gfluor_type_varnish,

#endif
