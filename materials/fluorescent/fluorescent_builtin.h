/* fluorescent_builtin.h - the fluorescent material classes, whose type records (and the parametric matrix's)
 * are in materials/fluorescent/parsers.c. */
#ifndef GENERIC_FLUORESCENT_BUILTIN_H
#define GENERIC_FLUORESCENT_BUILTIN_H

#include "generic/material.h"

/** fluorescent-phong (materials/fluorescent/fluorescent_phong.c). */
extern const GMaterialClass gmaterial_fluorescent_phong;
/** fluorescent-varnish (materials/fluorescent/fluorescent_varnish.c). */
extern const GMaterialClass gmaterial_fluorescent_varnish;

#endif
