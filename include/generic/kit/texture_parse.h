/* texture_parse.h - reading the parameters of texture nodes and generators from text (textures/parse_common.c),
 * for the parse routines of the built-in types and of one's own (GParseFn, registry.h; the reader API is
 * reader.h): nested generators, lists of materials and numbers, transform steps, generator spaces, the noise
 * parameters, and placing a constructor's complaint in the file. */
#ifndef GENERIC_TEXTURE_PARSE_H
#define GENERIC_TEXTURE_PARSE_H

#include "../export.h"
#include "affine.h"
#include "../error.h"
#include "../material.h"
#include "noise.h"
#include "../reader.h"
#include "../texture.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Reads a GENERATOR value (a nested entry or the name of an earlier one) into *g, borrowed from the library
 * (a node's constructor takes its own reference). */
GENERIC_API GENERIC_NODISCARD int gtexparse_generator(GReader *r, GGenerator **g, GError *err);

/** Reads `{ MATERIAL ... }` into a gmem array of borrowed materials (*list freed first; free it after). */
GENERIC_API GENERIC_NODISCARD int gtexparse_materials(GReader *r, GMaterial ***list, int *n, GError *err);

/** Reads `{ number ... }` into a gmem array (*list freed first; free it after). */
GENERIC_API GENERIC_NODISCARD int gtexparse_numbers(GReader *r, double **list, int *n, GError *err);

/** Reads `{ translate U V  rotate DEG  scale S [S2] ... }`: the steps composed in the order written (each
 * moves the result of the ones before). */
GENERIC_API GENERIC_NODISCARD int gtexparse_uv_steps(GReader *r, GAffine2 *out, GError *err);

/** Reads `{ translate X Y Z  rotate AXIS DEG  scale S | X Y Z ... }` composed in order. */
GENERIC_API GENERIC_NODISCARD int gtexparse_xyz_steps(GReader *r, GAffine3 *out, GError *err);

/** Reads a generator space keyword: object, world or uv. */
GENERIC_API GENERIC_NODISCARD int gtexparse_space(GReader *r, GGeneratorSpace *space, GError *err);

/** The keys gtexparse_noise_param reads, for "expected one of" lists. */
#define GTEXPARSE_NOISE_KEYS "space, frequency, seed, octaves, lacunarity, gain"

/** The rows of a parameter table (GParamInfo, registry.h) for space, frequency and seed, the noise parameters every
 * noise generator uses. */
#define GTEXPARSE_NOISE_BASE_PARAMS                                                                                    \
    {"space", GPARAM_NAMED, "choice", "object", "object, world, uv",                                                 \
     "the coordinates: the object-space point, the world point, or (u, v, 0)"},                                       \
    {"frequency", GPARAM_NAMED, "number", "1", "[1e-9, 1e9]", "features per unit"},                                   \
    {"seed", GPARAM_NAMED, "integer", "0", "[0, 4294967295]", "picks the noise (the same in every run)"}
/** The rows for octaves, lacunarity and gain, the noise parameters of the generators that sum octaves. */
#define GTEXPARSE_NOISE_OCTAVE_PARAMS                                                                                  \
    {"octaves", GPARAM_NAMED, "integer", "4", "[1, 16]", "the number of octaves summed"},                             \
    {"lacunarity", GPARAM_NAMED, "number", "2", "[1e-3, 1e3]", "the frequency factor from one octave to the next"}, \
    {"gain", GPARAM_NAMED, "number", "0.5", "[1e-6, 1e3]", "the amplitude factor from one octave to the next"}

/** Reads the value of `key` when it is one of the noise parameters (GTEXPARSE_NOISE_KEYS: space, frequency
 * in [1e-9, 1e9], seed, octaves in 1..16, lacunarity, gain) into p: 1 when read, 0 when key is none of them
 * (nothing read), a negative status on an error. */
GENERIC_API GENERIC_NODISCARD int gtexparse_noise_param(GReader *r, const char *key, GNoiseParams *p, GError *err);
/** Reads a parameter block of noise parameters and nothing else into *p (zeroed first: the defaults). */
GENERIC_API GENERIC_NODISCARD int gtexparse_noise(GReader *r, GNoiseParams *p, GError *err);

/** The end of a parse routine that called a constructor: on success stores obj in *object and returns G_OK;
 * on failure (rc < 0) places the constructor's message in err at the last token read and returns rc. */
GENERIC_API GENERIC_NODISCARD int gtexparse_finish(GReader *r, int rc, void *obj, void **object, GError *err);

#ifdef __cplusplus
}
#endif
#endif
