/* parse_common.c - pieces of the texture parse routines shared by nodes and shape trees: lists of
 * materials and numbers, and 2D/3D transform steps. */
#include "parse_common.h"

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

