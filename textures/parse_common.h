/* parse_common.h - pieces shared by the texture parse routines (textures/parse_common.c). Internal. */
#ifndef GENERIC_TEXTURES_PARSE_COMMON_H
#define GENERIC_TEXTURES_PARSE_COMMON_H

#include "generic/reader.h"
#include "generic/textures.h"

/** Reads `{ MATERIAL ... }` into a gmem array of borrowed materials (*list freed first; free it after). */
int gtexparse_materials(GReader *r, GMaterial ***list, int *n, GError *err);
/** Reads `{ number ... }` into a gmem array (*list freed first; free it after). */
int gtexparse_numbers(GReader *r, double **list, int *n, GError *err);
/** Reads `{ translate U V  rotate DEG  scale S [S2] ... }`: the steps composed in the order written (each
 * moves the result of the ones before). */
int gtexparse_uv_steps(GReader *r, GAffine2 *out, GError *err);
/** Reads `{ translate X Y Z  rotate AXIS DEG  scale S | X Y Z ... }` composed in order. */
int gtexparse_xyz_steps(GReader *r, GAffine3 *out, GError *err);

#endif
