/* parse_nodes.c - text format parse routines of the texture nodes. Children and generators are nested
 * entries or names of earlier ones (borrowed from the library; the node constructors take their own
 * references):
 *
 *   node NAME interpolate     { a MATERIAL  b MATERIAL  t GENERATOR }
 *   node NAME interpolate-one { a MATERIAL  b MATERIAL  t GENERATOR  method refraction_index }
 *   node NAME select          { index GENERATOR  children { MATERIAL ... } }
 *   node NAME spline          { t GENERATOR  basis catmull-rom|bspline|linear  children { MATERIAL ... } }
 *   node NAME bump            { child MATERIAL  height GENERATOR  strength 1 }
 *   node NAME scale           { child MATERIAL  factor GENERATOR }
 *   node NAME image           { child MATERIAL  file "name.png"  wrap periodic|clamp|black|mirror
 *                               swrap ...  twrap ...  colorspace auto|srgb|linear  blur 0 }
 *   node NAME transform       { child MATERIAL  uv { translate U V  rotate DEG  scale S [S2] ... }
 *                               xyz { translate X Y Z  rotate AXIS DEG  scale S | X Y Z ... } }
 * Transform steps apply in the order written, each moving the pattern further. */
#include "generic/reader.h"
#include "generic/textures.h"
#include "textures_builtin.h"
#include "parse_common.h"

#include <string.h>

/* A constructor's message ("interpolate: ...") placed at the last token read. */
static int finish(GReader *r, int rc, GMaterial *m, void **object, GError *err)
{
    if (rc != G_OK)
        return greader_locate(r, err);
    *object = m;
    return G_OK;
}

static int generator(GReader *r, GGenerator **g, GError *err)
{
    void *obj = NULL;
    int rc = greader_object(r, GKIND_GENERATOR, &obj, NULL, err);
    *g = rc == G_OK ? obj : NULL;
    return rc;
}

static int interp_common(GReader *r, int one, void **object, GError *err)
{
    GMaterial *a = NULL, *b = NULL;
    GGenerator *t = NULL;
    int method = -1;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "a") == 0)
            rc = greader_material(r, &a, err);
        else if (strcmp(key, "b") == 0)
            rc = greader_material(r, &b, err);
        else if (strcmp(key, "t") == 0)
            rc = generator(r, &t, err);
        else if (one && strcmp(key, "method") == 0) {
            char name[32];
            rc = greader_ident(r, name, sizeof name, err);
            if (rc == G_OK && (method = gnode_method_from_name(name)) < 0)
                rc = greader_error(r, err,
                                   "unknown method '%s' (reflection, refraction, refraction_index, reflection_dir, "
                                   "refraction_dir, emission, ambient, absorption, normal, diffuse, opaque)",
                                   name);
        } else
            rc = greader_unknown_param(r, one ? "a, b, t, method" : "a, b, t", err);
        if (rc < 0)
            return rc;
    }
    if (rc < 0)
        return rc;
    const char *name = one ? "interpolate-one" : "interpolate";
    if (!a || !b || !t)
        return greader_error(r, err, "%s: needs a, b and t", name);
    if (one && method < 0)
        return greader_error(r, err, "interpolate-one: needs a method");
    GMaterial *m = NULL;
    rc = one ? gnode_interpolate_one_create(a, b, t, (GNodeMethod)method, &m, err)
             : gnode_interpolate_create(a, b, t, &m, err);
    return finish(r, rc, m, object, err);
}

int gtexparse_interpolate(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    return interp_common(r, 0, object, err);
}

int gtexparse_interpolate_one(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    return interp_common(r, 1, object, err);
}

static const char *const basis_names[] = {"catmull-rom", "bspline", "linear", NULL};

static int list_common(GReader *r, int spline, void **object, GError *err)
{
    GMaterial **kids = NULL;
    int n = 0, basis = GSPLINE_CATMULL_ROM, have_kids = 0;
    GGenerator *g = NULL;
    const char *gen_key = spline ? "t" : "index";
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, gen_key) == 0)
            rc = generator(r, &g, err);
        else if (strcmp(key, "children") == 0) {
            rc = gtexparse_materials(r, &kids, &n, err);
            have_kids = 1;
        } else if (spline && strcmp(key, "basis") == 0)
            rc = greader_choice(r, basis_names, &basis, err);
        else
            rc = greader_unknown_param(r, spline ? "t, basis, children" : "index, children", err);
        if (rc < 0)
            break;
    }
    if (rc == 0 && !g)
        rc = greader_error(r, err, "%s: needs %s", spline ? "spline" : "select", gen_key);
    else if (rc == 0 && !have_kids)
        rc = greader_error(r, err, "%s: needs children { ... }", spline ? "spline" : "select");
    GMaterial *m = NULL;
    if (rc == 0) {
        rc = spline ? gnode_spline_create(kids, n, g, (GSplineBasis)basis, &m, err)
                    : gnode_select_create(kids, n, g, &m, err);
        rc = finish(r, rc, m, object, err);
    }
    gmem_free(kids);
    return rc;
}

int gtexparse_select(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    return list_common(r, 0, object, err);
}

int gtexparse_spline(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    return list_common(r, 1, object, err);
}

int gtexparse_bump(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GMaterial *child = NULL;
    GGenerator *h = NULL;
    double strength = 1.0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "child") == 0)
            rc = greader_material(r, &child, err);
        else if (strcmp(key, "height") == 0)
            rc = generator(r, &h, err);
        else if (strcmp(key, "strength") == 0)
            rc = greader_number(r, &strength, err);
        else
            rc = greader_unknown_param(r, "child, height, strength", err);
        if (rc < 0)
            return rc;
    }
    if (rc < 0)
        return rc;
    if (!child || !h)
        return greader_error(r, err, "bump: needs child and height");
    GMaterial *m = NULL;
    rc = gnode_bump_create(child, h, strength, &m, err);
    return finish(r, rc, m, object, err);
}

int gtexparse_scale(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GMaterial *child = NULL;
    GGenerator *g = NULL;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "child") == 0)
            rc = greader_material(r, &child, err);
        else if (strcmp(key, "factor") == 0)
            rc = generator(r, &g, err);
        else
            rc = greader_unknown_param(r, "child, factor", err);
        if (rc < 0)
            return rc;
    }
    if (rc < 0)
        return rc;
    if (!child || !g)
        return greader_error(r, err, "scale: needs child and factor");
    GMaterial *m = NULL;
    rc = gnode_scale_create(child, g, &m, err);
    return finish(r, rc, m, object, err);
}

static const char *const wrap_names[] = {"periodic", "clamp", "black", "mirror", NULL};
static const char *const space_names[] = {"auto", "srgb", "linear", NULL};

int gtexparse_image(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GMaterial *child = NULL;
    char *path = NULL;
    GImageNodeOptions o;
    memset(&o, 0, sizeof o);
    int w, file_line = 0, file_col = 0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "child") == 0)
            rc = greader_material(r, &child, err);
        else if (strcmp(key, "file") == 0) {
            rc = greader_path(r, &path, err);
            greader_position(r, &file_line, &file_col);
        } else if (strcmp(key, "wrap") == 0) {
            rc = greader_choice(r, wrap_names, &w, err);
            o.swrap = o.twrap = (GTexWrap)w;
        } else if (strcmp(key, "swrap") == 0) {
            rc = greader_choice(r, wrap_names, &w, err);
            o.swrap = (GTexWrap)w;
        } else if (strcmp(key, "twrap") == 0) {
            rc = greader_choice(r, wrap_names, &w, err);
            o.twrap = (GTexWrap)w;
        } else if (strcmp(key, "colorspace") == 0) {
            rc = greader_choice(r, space_names, &w, err);
            o.colorspace = (GTexColorSpace)w;
        } else if (strcmp(key, "blur") == 0)
            rc = greader_number_in(r, 0.0, 1.0, &o.blur, err);
        else
            rc = greader_unknown_param(r, "child, file, wrap, swrap, twrap, colorspace, blur", err);
        if (rc < 0)
            break;
    }
    if (rc == 0 && (!child || !path))
        rc = greader_error(r, err, "image: needs child and file");
    if (rc == 0) {
        GMaterial *m = NULL;
        rc = gnode_image_create(child, path, &o, &m, err);
        if (rc != G_OK) { /* a file that cannot be read is reported at its name */
            char msg[sizeof err->message];
            strcpy(msg, err->message);
            rc = greader_error_at(r, err, rc, file_line, file_col, "%s", msg);
        } else {
            *object = m;
        }
    }
    gmem_free(path);
    return rc;
}

int gtexparse_transform(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    GMaterial *child = NULL;
    GAffine2 uv;
    GAffine3 xyz;
    int have_uv = 0, have_xyz = 0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "child") == 0)
            rc = greader_material(r, &child, err);
        else if (strcmp(key, "uv") == 0) {
            rc = gtexparse_uv_steps(r, &uv, err);
            have_uv = 1;
        } else if (strcmp(key, "xyz") == 0) {
            rc = gtexparse_xyz_steps(r, &xyz, err);
            have_xyz = 1;
        } else
            rc = greader_unknown_param(r, "child, uv, xyz", err);
        if (rc < 0)
            return rc;
    }
    if (rc < 0)
        return rc;
    if (!child)
        return greader_error(r, err, "transform: needs child");
    GMaterial *m = NULL;
    rc = gnode_transform_create(child, have_uv ? &uv : NULL, have_xyz ? &xyz : NULL, &m, err);
    return finish(r, rc, m, object, err);
}
