/* colorparse.h - the built-in colour literal types (lib/colorparse.c), listed by lib/builtins.c. Private. */
#ifndef GENERIC_LIB_COLORPARSE_H
#define GENERIC_LIB_COLORPARSE_H

#include "generic/registry.h"

/** rgb R G B */
extern const GTypeInfo gcolortype_rgb;
/** spectrum { NM VALUE ... } */
extern const GTypeInfo gcolortype_spectrum;
/** blackbody KELVIN */
extern const GTypeInfo gcolortype_blackbody;
/** illuminant D65|A|E */
extern const GTypeInfo gcolortype_illuminant;
/** line NM [POWER] */
extern const GTypeInfo gcolortype_line;
/** bfc "FILE" */
extern const GTypeInfo gcolortype_bfc;
/** scale FACTOR COLOR */
extern const GTypeInfo gcolortype_scale;

#endif
