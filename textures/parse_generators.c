/* parse_generators.c - text format parse routines of the scalar generators:
 *
 *   generator NAME constant   { value V }
 *   generator NAME checker    { dims 2|3  frequency F }
 *   generator NAME perlin     { NOISE }            NOISE: space object|world|uv  frequency F  seed N
 *   generator NAME fbm        { NOISE }                   octaves N  lacunarity L  gain G
 *   generator NAME turbulence { NOISE }
 *   generator NAME wood       { NOISE  rings R  turbulence T  latewood W }
 *   generator NAME marble     { NOISE  stripes S  turbulence T }
 *   generator NAME surface
 *   generator NAME gradient   { space uv|object|world  slope X Y Z  offset O }
 * (csg and cpg are in parse_shapes.c). */
#include "generic/reader.h"
#include "generic/textures.h"
#include "textures_builtin.h"

#include <string.h>

static int finish(GReader *r, int rc, GGenerator *g, void **object, GError *err)
{
    if (rc != G_OK)
        return greader_locate(r, err);
    *object = g;
    return G_OK;
}

static const char *const space_names[] = {"object", "world", "uv", NULL};
static const GGeneratorSpace spaces[] = {GGENERATOR_SPACE_OBJECT, GGENERATOR_SPACE_WORLD, GGENERATOR_SPACE_UV};

/* Reads a parameter shared by the noise generators; 0 when the key is not one of them. */
static int noise_param(GReader *r, const char *key, GNoiseParams *p, GError *err)
{
    int rc;
    if (strcmp(key, "space") == 0) {
        int i;
        rc = greader_choice(r, space_names, &i, err);
        if (rc == G_OK)
            p->space = spaces[i];
    } else if (strcmp(key, "frequency") == 0)
        rc = greader_number_in(r, 1e-9, 1e9, &p->frequency, err);
    else if (strcmp(key, "seed") == 0) {
        long s;
        rc = greader_int(r, 0, 4294967295L, &s, err);
        p->seed = (unsigned)s;
    } else if (strcmp(key, "octaves") == 0) {
        long n;
        rc = greader_int(r, 1, 16, &n, err);
        p->octaves = (int)n;
    } else if (strcmp(key, "lacunarity") == 0)
        rc = greader_number_in(r, 1e-3, 1e3, &p->lacunarity, err);
    else if (strcmp(key, "gain") == 0)
        rc = greader_number_in(r, 1e-6, 1e3, &p->gain, err);
    else
        return 0;
    return rc < 0 ? rc : 1;
}

#define NOISE_KEYS "space, frequency, seed, octaves, lacunarity, gain"

int gtexparse_constant(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    double v = 0.0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        rc = strcmp(key, "value") == 0 ? greader_number(r, &v, err) : greader_unknown_param(r, "value", err);
        if (rc < 0)
            return rc;
    }
    if (rc < 0)
        return rc;
    GGenerator *g = NULL;
    rc = ggen_constant_create(v, &g, err);
    return finish(r, rc, g, object, err);
}

int gtexparse_checker(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    long dims = 2;
    double f = 1.0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "dims") == 0)
            rc = greader_int(r, 2, 3, &dims, err);
        else if (strcmp(key, "frequency") == 0)
            rc = greader_number_in(r, 1e-9, 1e9, &f, err);
        else
            rc = greader_unknown_param(r, "dims, frequency", err);
        if (rc < 0)
            return rc;
    }
    if (rc < 0)
        return rc;
    GGenerator *g = NULL;
    rc = ggen_checker_create((int)dims, f, &g, err);
    return finish(r, rc, g, object, err);
}

/* perlin, fbm, turbulence, wood and marble: the noise parameters plus a few of their own. */
static int noise_common(GReader *r, const char *type, void **object, GError *err)
{
    GNoiseParams p;
    memset(&p, 0, sizeof p);
    int wood = strcmp(type, "wood") == 0, marble = strcmp(type, "marble") == 0;
    double rings = 8.0, stripes = 1.0, turbulence = wood ? 0.5 : 2.0, latewood = 0.2;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        rc = noise_param(r, key, &p, err);
        if (rc == 0) {
            if (wood && strcmp(key, "rings") == 0)
                rc = greader_number_in(r, 1e-9, 1e9, &rings, err);
            else if (wood && strcmp(key, "latewood") == 0)
                rc = greader_number_in(r, 0.001, 0.999, &latewood, err);
            else if (marble && strcmp(key, "stripes") == 0)
                rc = greader_number(r, &stripes, err);
            else if ((wood || marble) && strcmp(key, "turbulence") == 0)
                rc = greader_number(r, &turbulence, err);
            else
                rc = greader_unknown_param(r,
                                           wood     ? NOISE_KEYS ", rings, turbulence, latewood"
                                           : marble ? NOISE_KEYS ", stripes, turbulence"
                                                    : NOISE_KEYS,
                                           err);
        }
        if (rc < 0)
            return rc;
    }
    if (rc < 0)
        return rc;
    GGenerator *g = NULL;
    if (wood)
        rc = ggen_wood_create(&p, rings, turbulence, latewood, &g, err);
    else if (marble)
        rc = ggen_marble_create(&p, stripes, turbulence, &g, err);
    else if (strcmp(type, "fbm") == 0)
        rc = ggen_fbm_create(&p, &g, err);
    else if (strcmp(type, "turbulence") == 0)
        rc = ggen_turbulence_create(&p, &g, err);
    else
        rc = ggen_perlin_create(&p, &g, err);
    return finish(r, rc, g, object, err);
}

int gtexparse_perlin(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    return noise_common(r, "perlin", object, err);
}

int gtexparse_fbm(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    return noise_common(r, "fbm", object, err);
}

int gtexparse_turbulence(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    return noise_common(r, "turbulence", object, err);
}

int gtexparse_wood(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    return noise_common(r, "wood", object, err);
}

int gtexparse_marble(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    return noise_common(r, "marble", object, err);
}

int gtexparse_surface(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    const char *key;
    int rc;
    if ((rc = greader_param(r, &key, err)) > 0)
        return greader_unknown_param(r, "(none)", err);
    if (rc < 0)
        return rc;
    GGenerator *g = NULL;
    rc = ggen_surface_create(&g, err);
    return finish(r, rc, g, object, err);
}

int gtexparse_gradient(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GGeneratorSpace space = GGENERATOR_SPACE_UV;
    GVec3 slope = gvec3(1, 0, 0);
    double offset = 0.0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "space") == 0) {
            int i;
            rc = greader_choice(r, space_names, &i, err);
            if (rc == G_OK)
                space = spaces[i];
        } else if (strcmp(key, "slope") == 0)
            rc = greader_vec3(r, &slope, err);
        else if (strcmp(key, "offset") == 0)
            rc = greader_number(r, &offset, err);
        else
            rc = greader_unknown_param(r, "space, slope, offset", err);
        if (rc < 0)
            return rc;
    }
    if (rc < 0)
        return rc;
    GGenerator *g = NULL;
    rc = ggen_gradient_create(space, slope, offset, &g, err);
    return finish(r, rc, g, object, err);
}
