/* generators.h - constructors of the built-in texture generators (the files in textures/); each returns a
 * generator with one reference (ggenerator_unref). Writing a generator of one's own: texture.h (ggenerator_new),
 * noise.h and texture_parse.h. */
#ifndef GENERIC_GENERATORS_H
#define GENERIC_GENERATORS_H

#include "export.h"
#include "texture.h"
#include "kit/noise.h"
#include "kit/shapes.h"

#ifdef __cplusplus
extern "C" {
#endif

/** constant: the same value everywhere. */
GENERIC_API GENERIC_NODISCARD int ggenerator_constant_create(double value, GGenerator **out, GError *err);

/** checker: 1 on the cells of a checkerboard whose cell index sum is odd, 0 on the others; dims 2 in
 * (u, v), dims 3 in object space; `frequency` cells per unit (> 0). Box-filtered over the footprint
 * when it is known (in (u, v) the widths of gsurfpoint_uv_widths, separately along u and v; in object space
 * footprint), so far-away checkers fade to 0.5 instead of aliasing. */
GENERIC_API GENERIC_NODISCARD int ggenerator_checker_create(int dims, double frequency, GGenerator **out, GError *err);

/** perlin: improved Perlin noise (gnoise_perlin3) of the point in the chosen space times frequency. */
GENERIC_API GENERIC_NODISCARD int ggenerator_perlin_create(const GNoiseParams *p, GGenerator **out, GError *err);
/** fbm: fractional Brownian motion, sum of octaves of signed noise, normalised by the sum of amplitudes
 * and mapped to [0, 1]. */
GENERIC_API GENERIC_NODISCARD int ggenerator_fbm_create(const GNoiseParams *p, GGenerator **out, GError *err);
/** turbulence: Perlin's sum of |noise| over octaves, normalised to [0, 1]. */
GENERIC_API GENERIC_NODISCARD int ggenerator_turbulence_create(const GNoiseParams *p, GGenerator **out, GError *err);
/** wood: rings around the space's z axis, `rings` per unit of radius, displaced by `turbulence` rings of
 * fbm; within a ring the value rises smoothly from 0 (early wood) to 1 and falls back over the last
 * `latewood` fraction of the ring (0 < latewood < 1; 0 = default 0.2). Continuous everywhere. */
GENERIC_API GENERIC_NODISCARD int ggenerator_wood_create(const GNoiseParams *p, double rings, double turbulence,
                                                         double latewood, GGenerator **out, GError *err);
/** marble: 0.5 + 0.5 sin(2 pi (stripes * x + turbulence * T(p))), T Perlin's turbulence: veins across x. */
GENERIC_API GENERIC_NODISCARD int ggenerator_marble_create(const GNoiseParams *p, double stripes, double turbulence,
                                                           GGenerator **out, GError *err);

/** surface: the surface index of the point (sp->surface), for select nodes. */
GENERIC_API GENERIC_NODISCARD int ggenerator_surface_create(GGenerator **out, GError *err);

/** gradient: a linear field offset + slope . c, c = (u, v, 0) or the point in object or world space; its
 * gradient is slope (a height field for bump nodes, or a ramp for interpolate). */
GENERIC_API GENERIC_NODISCARD int ggenerator_gradient_create(GGeneratorSpace space, GVec3 slope, double offset,
                                                             GGenerator **out, GError *err);

/** csg: 1 inside the solid, 0 outside, at the point in object (or world) space. Takes ownership of the
 * tree, also when it fails. */
GENERIC_API GENERIC_NODISCARD int ggenerator_csg_create(GCsgShape *root, GGeneratorSpace space, GGenerator **out,
                                                        GError *err);

/** cpg: 1 inside the shape, 0 outside, at (u, v). Takes ownership of the tree, also when it fails. */
GENERIC_API GENERIC_NODISCARD int ggenerator_cpg_create(GCpgShape *root, GGenerator **out, GError *err);

#ifdef __cplusplus
}
#endif
#endif
