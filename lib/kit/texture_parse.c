/* texture_parse.c - pieces of the texture parse routines shared by nodes, generators and shape trees
 * (generic/kit/texture_parse.h): nested generators, lists of materials and numbers, 2D/3D transform steps, spaces,
 * the noise parameters. */
#include "generic/kit/texture_parse.h"

#include <string.h>

int gtexparse_finish(GReader *r, int rc, void *obj, void **object, GError *err)
{
    if (rc != G_OK)
        return greader_locate(r, err);
    *object = obj;
    return G_OK;
}

int gtexparse_generator(GReader *r, GGenerator **g, GError *err)
{
    void *obj = NULL;
    int rc = greader_object(r, GKIND_GENERATOR, &obj, NULL, err);
    *g = rc == G_OK ? obj : NULL;
    return rc;
}

int gtexparse_space(GReader *r, GGeneratorSpace *space, GError *err)
{
    static const char *const names[] = {"object", "world", "uv", NULL};
    static const GGeneratorSpace spaces[] = {GGENERATOR_SPACE_OBJECT, GGENERATOR_SPACE_WORLD, GGENERATOR_SPACE_UV};
    int i, rc = greader_choice(r, names, &i, err);
    if (rc == G_OK)
        *space = spaces[i];
    return rc;
}

int gtexparse_noise_param(GReader *r, const char *key, GNoiseParams *p, GError *err)
{
    int rc;
    if (strcmp(key, "space") == 0)
        rc = gtexparse_space(r, &p->space, err);
    else if (strcmp(key, "frequency") == 0)
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

int gtexparse_materials(GReader *r, GMaterial ***list, int *n, GError *err)
{
    gmem_free(*list);
    *list = NULL;
    *n = 0;
    int cap = 0, rc = greader_block_begin(r, err);
    while (rc == G_OK && (rc = greader_block_end(r, err)) == 0) {
        GMaterial *m;
        rc = greader_material(r, &m, err);
        if (rc != G_OK)
            break;
        if (*n == cap) {
            cap = cap ? 2 * cap : 8;
            GMaterial **grown = gmem_realloc(*list, (size_t)cap * sizeof *grown);
            if (!grown) {
                rc = greader_error(r, err, "out of memory");
                break;
            }
            *list = grown;
        }
        (*list)[(*n)++] = m;
    }
    return rc < 0 ? rc : G_OK;
}

int gtexparse_numbers(GReader *r, double **list, int *n, GError *err)
{
    gmem_free(*list);
    *list = NULL;
    *n = 0;
    int cap = 0, rc = greader_block_begin(r, err);
    while (rc == G_OK && (rc = greader_block_end(r, err)) == 0) {
        double v;
        rc = greader_number(r, &v, err);
        if (rc != G_OK)
            break;
        if (*n == cap) {
            cap = cap ? 2 * cap : 16;
            double *grown = gmem_realloc(*list, (size_t)cap * sizeof *grown);
            if (!grown) {
                rc = greader_error(r, err, "out of memory");
                break;
            }
            *list = grown;
        }
        (*list)[(*n)++] = v;
    }
    return rc < 0 ? rc : G_OK;
}

/* `uv { translate U V  rotate DEG  scale S [S2] ... }`: the steps composed in order. */
int gtexparse_uv_steps(GReader *r, GAffine2 *out, GError *err)
{
    static const char *const ops[] = {"translate", "rotate", "scale", NULL};
    *out = gaffine2_identity();
    int rc = greader_block_begin(r, err);
    while (rc == G_OK && (rc = greader_block_end(r, err)) == 0) {
        int op;
        double a = 0, b = 0;
        rc = greader_choice(r, ops, &op, err);
        if (rc == G_OK)
            rc = greader_number(r, &a, err);
        if (rc == G_OK && op == 0)
            rc = greader_number(r, &b, err);
        if (rc == G_OK && op == 2) {
            b = a;
            int more = greader_at_number(r, err);
            rc = more < 0 ? more : more ? greader_number(r, &b, err) : G_OK;
        }
        if (rc != G_OK)
            break;
        GAffine2 s = op == 0 ? gaffine2_translate(a, b) : op == 1 ? gaffine2_rotate(a) : gaffine2_scale(a, b);
        *out = gaffine2_mul(&s, out);
    }
    return rc < 0 ? rc : G_OK;
}

/* `xyz { translate X Y Z  rotate AXIS DEG  scale S | X Y Z ... }` */
int gtexparse_xyz_steps(GReader *r, GAffine3 *out, GError *err)
{
    static const char *const ops[] = {"translate", "rotate", "scale", NULL};
    *out = gaffine3_identity();
    int rc = greader_block_begin(r, err);
    while (rc == G_OK && (rc = greader_block_end(r, err)) == 0) {
        int op;
        GVec3 v = gvec3(0, 0, 0);
        double a = 0;
        rc = greader_choice(r, ops, &op, err);
        if (rc == G_OK && op == 2) { /* a single number scales uniformly */
            rc = greader_number(r, &a, err);
            int more = rc == G_OK ? greader_at_number(r, err) : rc;
            v = gvec3(a, a, a);
            if (more > 0) {
                v.x = a;
                rc = greader_number(r, &v.y, err);
                if (rc == G_OK)
                    rc = greader_number(r, &v.z, err);
            } else if (more < 0)
                rc = more;
        } else if (rc == G_OK) {
            rc = greader_vec3(r, &v, err);
            if (rc == G_OK && op == 1)
                rc = greader_number(r, &a, err);
        }
        if (rc != G_OK)
            break;
        GAffine3 s = op == 0 ? gaffine3_translate(v) : op == 1 ? gaffine3_rotate(v, a) : gaffine3_scale(v);
        *out = gaffine3_mul(&s, out);
    }
    return rc < 0 ? rc : G_OK;
}

int gtexparse_noise(GReader *r, GNoiseParams *p, GError *err)
{
    memset(p, 0, sizeof *p);
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        rc = gtexparse_noise_param(r, key, p, err);
        if (rc == 0)
            rc = greader_unknown_param(r, GTEXPARSE_NOISE_KEYS, err);
        if (rc < 0)
            return rc;
    }
    return rc;
}
