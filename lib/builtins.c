/* builtins.c - the table of built-in types the registry loads on first use. This is the one file in
 * lib/ that names concrete models: it is where the library is composed. Each section lists the types
 * of one directory; colormodels/colormodels.h, materials/materials_builtin.h and
 * textures/textures_builtin.h declare their vtables and parse routines. */
#include "builtins.h"
#include "colormodels/colormodels.h"

/* ---- colour models ---- */
static const GTypeInfo colormodel_rgb = {GKIND_COLORMODEL, "rgb", &gcolormodel_rgb, NULL,
                                         "linear sRGB (Rec.709 primaries, D65 white)"};
/* (end of colour models) */

/* ---- materials ---- */
/* (end of materials) */

/* ---- texture nodes and generators ---- */
/* (end of textures) */

static const GTypeInfo *const builtin_types[] = {
    /* colour models */
    &colormodel_rgb,
    /* materials */
    /* texture nodes and generators */
    NULL,
};

const GTypeInfo *const *gbuiltin_types(void) { return builtin_types; }
