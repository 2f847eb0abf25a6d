/* varying_index_material.h - a material class of the tests (test_material_media_flags.c, test_gtrace_relindex.c)
 * whose refraction index follows the point: 1.3 + 0.2 u, 1.3 for no point. Its only method is refraction_index, so
 * gmaterial_init gives it every bit a missing slot gives but GMAT_CONSTANT_INDEX. Make an instance with gmem_calloc
 * (a GMaterial's size) and gmaterial_init. */
#ifndef VARYING_INDEX_MATERIAL_H
#define VARYING_INDEX_MATERIAL_H

#include "generic/color.h"
#include "generic/material.h"
#include "generic/memory.h"
#include "generic/surfpoint.h"

static void varying_index_destroy(GMaterial *self) { gmem_free(self); }

static int varying_index(const GMaterial *self, GSurfPoint *sp, GColor *result)
{
    (void)self;
    return gcolor_fill(result, 1.3 + (sp ? 0.2 * sp->u : 0.0));
}

static const GMaterialClass varying_index_class = {
    .abi_version = GMATERIAL_ABI_VERSION, .name = "varying-index", .description = "index 1.3 + 0.2 u (tests)",
    .destroy = varying_index_destroy, .refraction_index = varying_index,
};

#endif
