/* parse.c - the tracer's entries in the text format: objects, lights and the camera are types of the
 * kinds `object`, `light` and `camera`, registered at start-up with parse routines that use the reader
 * API, so a scene file is the same format as a material file (and may include one). Also builds the scene
 * from a loaded library.
 *
 *   object NAME? sphere   { center <x,y,z> radius R material M transform { ... } }
 *   object NAME? plane    { point P normal N material M ... }
 *   object NAME? box      { min P max Q ... }          surface index per face: -x +x -y +y -z +z = 0..5
 *   object NAME? disc     { center P normal N radius R ... }
 *   object NAME? cylinder { base P top Q radius R open BOOL ... }  surface 0 side, 1 base, 2 top
 *   object NAME? mesh     { file "model.obj" ... }
 *   object NAME? quad     { corner P edge1 E edge2 F ... }   P + u E + v F, (u,v) in [0,1]^2
 *   object NAME? triangle { a P b Q c R ... }                 (u,v) the barycentrics of Q and R
 *   object NAME? group    { OBJECT OBJECT ... transform { ... } }   members become prototypes
 *   object NAME? instance { of OBJECT transform { ... } material M }  M (optional) overrides
 *   (any shape: interior MEDIUM, the participating medium inside it, media/medium.c)
 *   transform { scale S | scale <x,y,z> | rotate <ax,ay,az> | rotate_axis <axis> DEG | translate <x,y,z> ... }
 *   light point       { position P intensity COLOR }
 *   light directional { direction D irradiance COLOR }
 *   light spot        { position P at Q intensity COLOR inner DEG outer DEG }
 *   light sphere      { center P radius R radiance COLOR samples N visible BOOL }
 *   light rectangle   { corner P edge1 E edge2 F radiance COLOR samples N visible BOOL }   lit side: edge1 x edge2
 *   light ambient     { color COLOR }        handed to every material's ambient()
 *   light background  { color COLOR }        radiance of rays that leave the scene
 *   light ies         { file "f.ies" position P direction D along A color COLOR scale K }
 *                     a photometric (IES LM-63) point light: candela / (683 lm/W x the colour's luminous sum)
 *   light probe       { file "x.hdr" technique T count N samples S rotate <x,y,z> scale K ... }
 *                     image-based lighting from an HDR probe (probe_light.c)
 *   camera pinhole    { from P at Q up U fov DEG width W height H spp N depth D cutoff W exposure STOPS bands K
 *                       medium M atmosphere MEDIUM }   atmosphere: the participating medium outside every object
 *   camera thinlens   { ...pinhole's... aperture A focus_distance F }
 *   camera orthographic { from P at Q up U size S width W height H ... }  (no fov)
 *   (any camera: frame MARGIN fits the view to the scene's bounds, camera_frame)
 * Spot cones are full opening angles in degrees (inner: full intensity, outer: none). cutoff: rays whose
 * weight in their pixel is below W are not traced (default 1e-3, 0 traces everything to the depth). */
#include "integrators/bands.h"
#include "parse.h"
#include "param_tables.h"
#include "geometry/geometry.h"
#include "scene/ies.h"
#include "media/medium.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* ---- transforms ---- */

static int parse_transform(GReader *r, Xform *xf, GError *err)
{
    static const char *const ops[] = {"translate", "rotate", "rotate_axis", "scale", NULL};
    int rc = greader_block_begin(r, err);
    while (rc == G_OK && (rc = greader_block_end(r, err)) == 0) {
        int op;
        if ((rc = greader_choice(r, ops, &op, err)) < 0)
            break;
        GVec3 v;
        double a = 0.0;
        if (op == 3) {
            GToken t;
            if ((rc = greader_peek(r, &t, err)) < 0)
                break;
            if (t.type == GTOK_LANGLE) {
                rc = greader_vec3(r, &v, err);
            } else {
                rc = greader_number(r, &a, err);
                v = gvec3(a, a, a);
                if (rc == G_OK && greader_at_number(r, err) == 1) {
                    v.x = a;
                    rc = greader_number(r, &v.y, err);
                    if (rc == G_OK)
                        rc = greader_number(r, &v.z, err);
                }
            }
        } else {
            rc = greader_vec3(r, &v, err);
            if (rc == G_OK && op == 2)
                rc = greader_number(r, &a, err);
        }
        if (rc < 0)
            break;
        int ok = G_OK;
        switch (op) {
        case 0: ok = xform_translate(xf, v); break;
        case 1:
            ok = xform_rotate(xf, gvec3(1, 0, 0), v.x);
            if (ok == G_OK)
                ok = xform_rotate(xf, gvec3(0, 1, 0), v.y);
            if (ok == G_OK)
                ok = xform_rotate(xf, gvec3(0, 0, 1), v.z);
            break;
        case 2: ok = xform_rotate(xf, v, a); break;
        default: ok = xform_scale(xf, v); break;
        }
        if (ok != G_OK) {
            rc = greader_error(r, err, "this %s makes the transform singular", ops[op]);
            break;
        }
    }
    return rc < 0 ? rc : G_OK;
}

int scene_parse_transform(GReader *r, Xform *xf, GError *err) { return parse_transform(r, xf, err); }

/* ---- objects ---- */

static const ShapeKind shape_kinds[] = {SHAPE_SPHERE, SHAPE_PLANE,    SHAPE_BOX,   SHAPE_DISC,    SHAPE_CYLINDER,
                                        SHAPE_MESH,   SHAPE_QUAD,     SHAPE_TRIANGLE, SHAPE_GROUP, SHAPE_INSTANCE};
#define NSHAPE_TYPES ((int)(sizeof shape_kinds / sizeof shape_kinds[0]))
static const char *const shape_params[] = {
    "center, radius, material, interior, transform",
    "point, normal, material, interior, transform",
    "min, max, material, interior, transform",
    "center, normal, radius, material, interior, transform",
    "base, top, radius, open, material, interior, transform",
    "file, material, interior, transform",
    "corner, edge1, edge2, material, interior, transform",
    "a, b, c, material, interior, transform",
    "",
    "of, material, transform",
};


/* An object given as a value (a nested entry or a name), which must be one of gtrace's. */
/* A mesh's own files (a glTF's buffers) are read by the scene's rules: under --confine when the load is confined. */
static int mesh_file_allowed(void *reader, const char *path, GError *err)
{
    return greader_path_allowed(reader, path, err);
}

static int read_object(GReader *r, Object **out, GError *err)
{
    void *obj = NULL;
    const GTypeInfo *t = NULL;
    int rc = greader_object(r, gtrace_kind_object, &obj, &t, err);
    if (rc < 0)
        return rc;
    if (!t || t->parse != scene_parse_object)
        return greader_error(r, err, "object type '%s' is not one gtrace renders", t ? t->name : "?");
    *out = obj;
    return G_OK;
}

/* The limits of nesting and expansion, checked where a group or an instance is defined. */
static int check_nesting(GReader *r, const Object *o, GError *err)
{
    if (o->nesting > GTRACE_MAX_NESTING)
        return greader_error(r, err, "groups and instances nest %d deep here, more than the limit of %d",
                             o->nesting, GTRACE_MAX_NESTING);
    if (o->expansion > GTRACE_MAX_INSTANCES)
        return greader_error(r, err, "this %s expands to %.6g placements, more than the limit of %d",
                             o->kind == SHAPE_GROUP ? "group" : "instance", o->expansion, GTRACE_MAX_INSTANCES);
    return G_OK;
}

/*   object NAME? group { OBJECT OBJECT ... transform { ... } }: members are nested entries or names. */
static int parse_group(GReader *r, Object *o, GError *err)
{
    Object **members = NULL;
    int n = 0, cap = 0;
    int rc = greader_block_begin(r, err);
    while (rc == G_OK && (rc = greader_block_end(r, err)) == 0) {
        GToken t;
        if ((rc = greader_peek(r, &t, err)) < 0)
            break;
        if (t.type == GTOK_IDENT && strcmp(t.text, "transform") == 0) {
            if ((rc = greader_next(r, &t, err)) < 0 || (rc = parse_transform(r, &o->xf, err)) < 0)
                break;
            o->has_xf = 1;
            continue;
        }
        if (n == cap) {
            int nc = cap ? 2 * cap : 8;
            Object **nm = gmem_realloc(members, (size_t)nc * sizeof *nm);
            if (!nm) {
                rc = greader_error(r, err, "out of memory for a group of %d objects", n);
                break;
            }
            members = nm;
            cap = nc;
        }
        if ((rc = read_object(r, &members[n], err)) < 0)
            break;
        n++;
    }
    if (rc >= 0 && n == 0)
        rc = greader_error(r, err, "a group needs at least one object");
    if (rc >= 0)
        rc = object_group(o, members, n, err) < 0 ? greader_locate(r, err) : G_OK;
    gmem_free(members);
    if (rc >= 0)
        rc = check_nesting(r, o, err);
    if (rc >= 0 && object_charge(o, err) != G_OK) /* its placements, against the memory budget */
        rc = greader_locate(r, err);
    return rc < 0 ? rc : G_OK;
}

int scene_parse_object(GReader *r, const void *vtable, void **object, GError *err)
{
    ShapeKind kind = *(const ShapeKind *)vtable;
    GVec3 center = gvec3(0, 0, 0), normal = gvec3(0, 1, 0), lo = gvec3(-1, -1, -1), hi = gvec3(1, 1, 1);
    GVec3 top = gvec3(0, 1, 0);
    double radius = 1.0;
    int open = 0;
    char *file = NULL;
    GVec3 edge1 = gvec3(1, 0, 0), edge2 = gvec3(0, 1, 0), pc = gvec3(0, 1, 0);
    GMaterial *mat = NULL;
    Object *proto = NULL;
    Object *o = object_new(kind, NULL);
    if (!o)
        return greader_error(r, err, "out of memory");
    const char *key;
    int rc;
    if (kind == SHAPE_GROUP) {
        rc = parse_group(r, o, err);
        if (rc < 0)
            object_free(o);
        else
            *object = o;
        return rc;
    }
    if (kind == SHAPE_TRIANGLE)
        center = gvec3(0, 0, 0);
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "material") == 0) {
            rc = greader_material(r, &mat, err);
        } else if (strcmp(key, "transform") == 0) {
            rc = parse_transform(r, &o->xf, err);
            o->has_xf = 1;
        } else if (strcmp(key, "radius") == 0 &&
                   (kind == SHAPE_SPHERE || kind == SHAPE_DISC || kind == SHAPE_CYLINDER)) {
            rc = greader_number_in(r, 1e-12, 1e30, &radius, err);
        } else if (strcmp(key, "center") == 0 && (kind == SHAPE_SPHERE || kind == SHAPE_DISC)) {
            rc = greader_vec3(r, &center, err);
        } else if (strcmp(key, "point") == 0 && kind == SHAPE_PLANE) {
            rc = greader_vec3(r, &center, err);
        } else if (strcmp(key, "normal") == 0 && (kind == SHAPE_PLANE || kind == SHAPE_DISC)) {
            rc = greader_vec3(r, &normal, err);
        } else if (strcmp(key, "min") == 0 && kind == SHAPE_BOX) {
            rc = greader_vec3(r, &lo, err);
        } else if (strcmp(key, "max") == 0 && kind == SHAPE_BOX) {
            rc = greader_vec3(r, &hi, err);
        } else if (strcmp(key, "base") == 0 && kind == SHAPE_CYLINDER) {
            rc = greader_vec3(r, &center, err);
        } else if (strcmp(key, "top") == 0 && kind == SHAPE_CYLINDER) {
            rc = greader_vec3(r, &top, err);
        } else if (strcmp(key, "open") == 0 && kind == SHAPE_CYLINDER) {
            rc = greader_bool(r, &open, err);
        } else if (strcmp(key, "file") == 0 && kind == SHAPE_MESH) {
            rc = greader_path(r, &file, err);
        } else if ((strcmp(key, "corner") == 0 && kind == SHAPE_QUAD) ||
                   (strcmp(key, "a") == 0 && kind == SHAPE_TRIANGLE)) {
            rc = greader_vec3(r, &center, err);
        } else if ((strcmp(key, "edge1") == 0 && kind == SHAPE_QUAD) ||
                   (strcmp(key, "b") == 0 && kind == SHAPE_TRIANGLE)) {
            rc = greader_vec3(r, &edge1, err);
        } else if (strcmp(key, "edge2") == 0 && kind == SHAPE_QUAD) {
            rc = greader_vec3(r, &edge2, err);
        } else if (strcmp(key, "c") == 0 && kind == SHAPE_TRIANGLE) {
            rc = greader_vec3(r, &pc, err);
        } else if (strcmp(key, "of") == 0 && kind == SHAPE_INSTANCE) {
            rc = read_object(r, &proto, err);
        } else if (strcmp(key, "interior") == 0 && kind != SHAPE_INSTANCE) {
            void *med = NULL;
            if ((rc = greader_object(r, gtrace_kind_medium, &med, NULL, err)) == G_OK)
                o->interior = med;
        } else {
            rc = greader_unknown_param(r, shape_params[kind], err);
        }
        if (rc < 0)
            break;
    }
    if (rc == G_OK && kind == SHAPE_INSTANCE && !proto)
        rc = greader_error(r, err, "an instance needs the object it places (of NAME or a nested object)");
    if (rc == G_OK && !mat && kind != SHAPE_INSTANCE)
        rc = greader_error(r, err, "the object needs a material (material NAME or a nested material)");
    if (rc == G_OK && kind == SHAPE_MESH && !file)
        rc = greader_error(r, err, "a mesh needs a file (file \"name.obj\")");
    if (rc == G_OK) {
        switch (kind) {
        case SHAPE_SPHERE: rc = object_sphere(o, center, radius, err); break;
        case SHAPE_PLANE: rc = object_plane(o, center, normal, err); break;
        case SHAPE_BOX: rc = object_box(o, lo, hi, err); break;
        case SHAPE_DISC: rc = object_disc(o, center, normal, radius, err); break;
        case SHAPE_CYLINDER: rc = object_cylinder(o, center, top, radius, open, err); break;
        case SHAPE_MESH: rc = object_mesh_load_from(o, file, &(MeshFiles){mesh_file_allowed, r}, err); break;
        case SHAPE_QUAD: rc = object_quad(o, center, edge1, edge2, err); break;
        case SHAPE_TRIANGLE: rc = object_triangle(o, center, edge1, pc, err); break;
        case SHAPE_GROUP: break;
        case SHAPE_INSTANCE: rc = object_instance(o, proto, err); break;
        }
        if (rc == G_OK && kind == SHAPE_INSTANCE && (rc = check_nesting(r, o, err)) < 0) {
            gmem_free(file);
            object_free(o);
            return rc;
        }
        double reach = rc == G_OK ? object_extent_check(o) : 0.0;
        if (reach > 0.0)
            rc = greader_error(r, err, "the object reaches %g (after its transform), beyond the scene's limit of "
                               "%g: coordinates must be finite and within [-%g, %g]", reach, SCENE_MAX_COORD,
                               SCENE_MAX_COORD, SCENE_MAX_COORD);
        else if (rc < 0)
            rc = greader_locate(r, err);
        else if (object_charge(o, err) != G_OK) /* its share of the acceleration structure, or its placements */
            rc = greader_locate(r, err);
    }
    gmem_free(file);
    if (rc < 0) {
        object_free(o);
        return rc;
    }
    o->material = gmaterial_ref(mat);
    if (!(o = object_compact(o))) /* a plain sphere keeps its head alone */
        return greader_error(r, err, "out of memory");
    *object = o;
    return G_OK;
}

static void destroy_object(void *p) { object_free(p); }

/* ---- lights ---- */

enum { L_POINT, L_DIRECTIONAL, L_SPOT, L_SPHERE, L_RECT, L_AMBIENT, L_BACKGROUND, L_IES };
static const int light_types[] = {L_POINT, L_DIRECTIONAL, L_SPOT, L_SPHERE, L_RECT, L_AMBIENT, L_BACKGROUND, L_IES};
static const char *const light_params[] = {
    "position, intensity",
    "direction, irradiance",
    "position, at, intensity, inner, outer",
    "center, radius, radiance, samples, visible",
    "corner, edge1, edge2, radiance, samples, visible",
    "color",
    "color",
    "file, position, direction, along, color, scale",
};
static const LightKind light_kinds[] = {LIGHT_POINT, LIGHT_DIRECTIONAL, LIGHT_SPOT,       LIGHT_SPHERE,
                                        LIGHT_RECT,  LIGHT_AMBIENT,     LIGHT_BACKGROUND, LIGHT_IES};
static const char *const light_color_key[] = {"intensity", "irradiance", "intensity", "radiance",
                                              "radiance",  "color",      "color",     "color"};

/* An IES light's table and frame, and its colour made the light of one candela: the colour scaled so that 683 lm/W
 * times its luminous sum (the sum of its power times ybar, 1 nm steps over 380..780 nm) is 1 cd
 * (times scale); the light's colour is then per W/(sr nm) and the candela of the table multiply it. */
static int ies_light_setup(GReader *r, Light *l, const char *file, GVec3 dir, const GVec3 *along, double scale,
                           GColor *color, GError *err)
{
    if (!file)
        return greader_error(r, err, "an IES light needs its file (file \"luminaire.ies\")");
    double len = gvec3_length(dir);
    if (!(len > 0.0 && isfinite(len)))
        return greader_error(r, err, "the direction must be finite and not zero");
    l->direction = gvec3_scale(dir, 1.0 / len);
    GVec3 a = along ? *along : fabs(l->direction.x) < 0.9 ? gvec3(1, 0, 0) : gvec3(0, 0, 1);
    a = gvec3_sub(a, gvec3_scale(l->direction, gvec3_dot(a, l->direction)));
    double la = gvec3_length(a);
    if (!(la > 1e-9 * gvec3_length(along ? *along : a) && isfinite(la)))
        return greader_error(r, err, "`along` must be finite and not parallel to the direction");
    l->along = gvec3_scale(a, 1.0 / la);
    l->third = gvec3_cross(l->direction, l->along);
    double xyz[3], ysum = 0.0, cmf[3];
    for (int nm = GNM_MIN; nm <= GNM_MAX; nm++) {
        gcie_cmf(nm, cmf);
        ysum += cmf[1];
    }
    int rc = gcolor_to_xyz(color, GCOLOR_LIGHT, xyz);
    if (rc != G_OK || !(xyz[1] > 0.0))
        return greader_error(r, err, "an IES light's color gives its power over wavelength: its luminance must be "
                             "> 0");
    if ((rc = gcolor_scale(color, color, scale / (683.0 * xyz[1] * ysum))) != G_OK)
        return greader_error(r, err, "the colour cannot be scaled: %s", gstatus_string(rc));
    l->ies = gmem_calloc(1, sizeof *l->ies);
    if (!l->ies)
        return greader_error(r, err, "out of memory");
    return ies_read(file, l->ies, err); /* its messages name the IES file and line */
}

/* 1 when the light's points (a sphere's extent, a rectangle's four corners, a spot's target) lie within the
 * scene's limit. */
static int light_within_limits(const Light *l, int type, GVec3 at)
{
    GVec3 p = l->position, e1 = l->edge1, e2 = l->edge2, rr = gvec3(l->radius, l->radius, l->radius);
    if (!scene_coord_ok(p) || !scene_coord_ok(at))
        return 0;
    if (type == L_SPHERE)
        return scene_coord_ok(gvec3_add(p, rr)) && scene_coord_ok(gvec3_sub(p, rr));
    if (type == L_RECT)
        return scene_coord_ok(gvec3_add(p, e1)) && scene_coord_ok(gvec3_add(p, e2)) &&
               scene_coord_ok(gvec3_add(gvec3_add(p, e1), e2));
    return 1;
}

int scene_parse_light(GReader *r, const void *vtable, void **object, GError *err)
{
    int type = *(const int *)vtable;
    const GColorModel *model = greader_colormodel(r);
    Light *l = light_new(model, light_kinds[type]);
    if (!l)
        return greader_error(r, err, "out of memory");
    GColor color = {0};
    GVec3 at = gvec3(0, 0, 0), dir = gvec3(0, -1, 0), along = gvec3(0, 0, 0);
    double inner = 20.0, outer = 30.0, scale = 1.0;
    char *ies_file = NULL;
    int have_along = 0;
    long samples = 16;
    int have_at = 0, color_line = 0, color_col = 0;
    l->radius = 1.0;
    l->edge1 = gvec3(1, 0, 0);
    l->edge2 = gvec3(0, 0, -1);
    if (type == L_RECT)
        l->position = gvec3(-0.5, 2, 0.5);
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, light_color_key[type]) == 0) {
            gcolor_free(&color);
            GToken lit;
            if ((rc = greader_peek(r, &lit, err)) == G_OK) {
                color_line = lit.line, color_col = lit.col;
                rc = greader_color(r, GCOLOR_LIGHT, &color, err);
            }
        } else if (strcmp(key, "file") == 0 && type == L_IES) {
            gmem_free(ies_file);
            ies_file = NULL;
            rc = greader_path(r, &ies_file, err);
        } else if (strcmp(key, "along") == 0 && type == L_IES) {
            rc = greader_vec3(r, &along, err);
            have_along = 1;
        } else if (strcmp(key, "scale") == 0 && type == L_IES) {
            rc = greader_number_in(r, 0.0, 1e30, &scale, err);
        } else if ((strcmp(key, "position") == 0 && (type == L_POINT || type == L_SPOT || type == L_IES)) ||
                   (strcmp(key, "center") == 0 && type == L_SPHERE) || (strcmp(key, "corner") == 0 && type == L_RECT)) {
            rc = greader_vec3(r, &l->position, err);
        } else if (strcmp(key, "direction") == 0 && (type == L_DIRECTIONAL || type == L_IES)) {
            rc = greader_vec3(r, &dir, err);
        } else if (strcmp(key, "at") == 0 && type == L_SPOT) {
            rc = greader_vec3(r, &at, err);
            have_at = 1;
        } else if (strcmp(key, "inner") == 0 && type == L_SPOT) {
            rc = greader_number_in(r, 0.0, 180.0, &inner, err);
        } else if (strcmp(key, "outer") == 0 && type == L_SPOT) {
            rc = greader_number_in(r, 0.0, 180.0, &outer, err);
        } else if (strcmp(key, "radius") == 0 && type == L_SPHERE) {
            rc = greader_number_in(r, 1e-9, 1e30, &l->radius, err);
        } else if (strcmp(key, "edge1") == 0 && type == L_RECT) {
            rc = greader_vec3(r, &l->edge1, err);
        } else if (strcmp(key, "edge2") == 0 && type == L_RECT) {
            rc = greader_vec3(r, &l->edge2, err);
        } else if (strcmp(key, "samples") == 0 && (type == L_SPHERE || type == L_RECT)) {
            rc = greader_int(r, 1, 256, &samples, err);
        } else if (strcmp(key, "visible") == 0 && (type == L_SPHERE || type == L_RECT)) {
            rc = greader_bool(r, &l->visible, err);
        } else {
            rc = greader_unknown_param(r, light_params[type], err);
        }
        if (rc < 0)
            break;
    }
    if (rc == G_OK && !color.v)
        rc = greader_error(r, err, "the light needs its %s (a colour)", light_color_key[type]);
    /* out of the model's gamut (a line light in a tristimulus model): its negative samples to 0, one warning */
    int mapped = 0;
    double xyz[3] = {0, 0, 0};
    if (rc == G_OK && (gcolor_to_xyz(&color, GCOLOR_LIGHT, xyz) != G_OK || !(xyz[1] >= 0.0) ||
                       gcolor_clip_light_to_gamut(&color, &mapped) != G_OK))
        rc = greader_error(r, err, "the light's %s must be finite and of luminance >= 0", light_color_key[type]);
    if (rc == G_OK && mapped)
        fprintf(stderr, "%s:%d:%d: warning: the light's %s lies outside the gamut of colour model '%s': its "
                "negative samples are set to 0\n",
                greader_file(r), color_line, color_col, light_color_key[type], gcolormodel_name(model));
    if (rc == G_OK && !light_within_limits(l, type, at))
        rc = greader_error(r, err, "the light lies beyond the scene's limit of %g: coordinates must be finite "
                           "and within [-%g, %g]", SCENE_MAX_COORD, SCENE_MAX_COORD, SCENE_MAX_COORD);
    if (rc == G_OK && type == L_DIRECTIONAL) {
        if (!(gvec3_length(dir) > 0.0 && isfinite(gvec3_length(dir))))
            rc = greader_error(r, err, "the direction must be finite and not zero");
        l->direction = gvec3_normalize(dir);
    }
    if (rc == G_OK && type == L_SPOT) {
        if (!have_at || gvec3_length(gvec3_sub(at, l->position)) == 0.0)
            rc = greader_error(r, err, "a spot light needs `at`, a point other than its position");
        else if (outer < inner)
            rc = greader_error(r, err, "outer (%g) must not be smaller than inner (%g)", outer, inner);
        l->direction = gvec3_normalize(gvec3_sub(at, l->position));
        l->cos_inner = cos(0.5 * inner * M_PI / 180.0);
        l->cos_outer = cos(0.5 * outer * M_PI / 180.0);
    }
    if (rc == G_OK && type == L_IES)
        rc = ies_light_setup(r, l, ies_file, dir, have_along ? &along : NULL, scale, &color, err);
    gmem_free(ies_file);
    if (rc == G_OK && type == L_RECT && gvec3_length(gvec3_cross(l->edge1, l->edge2)) == 0.0)
        rc = greader_error(r, err, "the rectangle's edges must not be parallel");
    l->samples = (int)samples;
    if (rc == G_OK)
        rc = gcolor_copy(&l->color, &color) == G_OK ? G_OK : greader_error(r, err, "colour of another model");
    gcolor_free(&color);
    if (rc < 0) {
        light_free(l);
        return rc;
    }
    *object = l;
    return G_OK;
}

static void destroy_light(void *p) { light_free(p); }

/* ---- camera ---- */

static const char *const camera_params[] = {
    "from, at, up, fov, frame, width, height, spp, depth, cutoff, exposure, medium, atmosphere, bands",
    "from, at, up, fov, frame, aperture, focus_distance, width, height, spp, depth, cutoff, exposure, medium, "
    "atmosphere, bands",
    "from, at, up, size, frame, width, height, spp, depth, cutoff, exposure, medium, atmosphere, bands",
};

int scene_parse_camera(GReader *r, const void *vtable, void **object, GError *err)
{
    CameraProjection proj = *(const CameraProjection *)vtable;
    Camera *c = gmem_calloc(1, sizeof *c);
    if (!c)
        return greader_error(r, err, "out of memory");
    camera_defaults(c);
    c->projection = proj;
    const char *key;
    int rc;
    long v;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "from") == 0)
            rc = greader_vec3(r, &c->from, err);
        else if (strcmp(key, "at") == 0)
            rc = greader_vec3(r, &c->at, err);
        else if (strcmp(key, "up") == 0)
            rc = greader_vec3(r, &c->up, err);
        else if (strcmp(key, "fov") == 0 && proj != CAMERA_ORTHOGRAPHIC)
            rc = greader_number_in(r, 0.01, 179.0, &c->fov, err);
        else if (strcmp(key, "aperture") == 0 && proj == CAMERA_THINLENS)
            rc = greader_number_in(r, 0.0, 1e6, &c->aperture, err);
        else if (strcmp(key, "focus_distance") == 0 && proj == CAMERA_THINLENS)
            rc = greader_number_in(r, 1e-9, 1e15, &c->focus_distance, err);
        else if (strcmp(key, "size") == 0 && proj == CAMERA_ORTHOGRAPHIC)
            rc = greader_number_in(r, 1e-9, 1e15, &c->size, err);
        else if (strcmp(key, "frame") == 0)
            rc = greader_number_in(r, 0.0, 10.0, &c->frame, err);
        else if (strcmp(key, "width") == 0)
            rc = (rc = greader_int(r, 1, 65536, &v, err)) < 0 ? rc : (c->width = (int)v, 0);
        else if (strcmp(key, "height") == 0)
            rc = (rc = greader_int(r, 1, 65536, &v, err)) < 0 ? rc : (c->height = (int)v, 0);
        else if (strcmp(key, "spp") == 0)
            rc = (rc = greader_int(r, 1, 65536, &v, err)) < 0 ? rc : (c->spp = (int)v, 0);
        else if (strcmp(key, "depth") == 0)
            rc = (rc = greader_int(r, 0, 1000, &v, err)) < 0 ? rc : (c->depth = (int)v, 0);
        else if (strcmp(key, "exposure") == 0)
            rc = greader_number_in(r, -30.0, 30.0, &c->exposure, err);
        else if (strcmp(key, "cutoff") == 0)
            rc = greader_number_in(r, 0.0, 1.0, &c->cutoff, err);
        else if (strcmp(key, "medium") == 0)
            rc = greader_material(r, &c->medium, err);
        else if (strcmp(key, "atmosphere") == 0) {
            void *med = NULL;
            if ((rc = greader_object(r, gtrace_kind_medium, &med, NULL, err)) == G_OK)
                c->atmosphere = med;
        }
        else if (strcmp(key, "bands") == 0)
            rc = (rc = greader_int(r, 1, BANDS_LIMIT, &v, err)) < 0 ? rc : (c->bands = (int)v, 0);
        else
            rc = greader_unknown_param(r, camera_params[proj], err);
        if (rc < 0)
            break;
    }
    if (rc == G_OK && (!scene_coord_ok(c->from) || !scene_coord_ok(c->at) || !scene_coord_ok(c->up)))
        rc = greader_error(r, err, "the camera's from, at and up must be finite and within [-%g, %g] (the "
                           "scene's limit)", SCENE_MAX_COORD, SCENE_MAX_COORD);
    if (rc == G_OK && gvec3_length(gvec3_sub(c->at, c->from)) == 0.0)
        rc = greader_error(r, err, "the camera looks from the point it looks at");
    if (rc < 0) {
        gmem_free(c);
        return rc;
    }
    *object = c;
    return G_OK;
}

/* ---- registration ---- */

static const char *const shape_names[] = {"sphere", "plane", "box",      "disc",  "cylinder",
                                          "mesh",   "quad",  "triangle", "group", "instance"};
static const char *const shape_summaries[] = {
    "sphere (analytic)", "infinite plane (bounded at 1e5)", "axis-aligned box, a surface index per face",
    "disc", "cylinder with optional caps", "triangle mesh from a Wavefront OBJ file",
    "parallelogram (an Embree quad)", "triangle (an Embree triangle)",
    "group of objects (one Embree scene, placed by instances)",
    "instance of an object or group: own transform, optional material override",
};
static const char *const light_names[] = {"point",   "directional", "spot",      "sphere",
                                          "rectangle", "ambient",   "background", "ies"};
static const char *const light_summaries[] = {
    "point light (intensity)", "directional light (irradiance)", "spot light with a smooth cone",
    "spherical area light (radiance), soft shadows", "rectangular area light (radiance), soft shadows",
    "ambient light for material.ambient", "radiance of rays that leave the scene",
    "photometric point light from an IES LM-63 file (candela)",
};
static const CameraProjection camera_kinds[] = {CAMERA_PINHOLE, CAMERA_THINLENS, CAMERA_ORTHOGRAPHIC};
static const char *const camera_names[] = {"pinhole", "thinlens", "orthographic"};
static const char *const camera_summaries[] = {
    "pinhole camera: look-at, vertical field of view, image settings",
    "thin-lens camera: a pinhole's settings plus aperture and focus_distance (depth of field)",
    "orthographic camera: parallel rays through a window `size` units high",
};

/* Registers a type unless its kind already has one of that name (so registering twice is harmless). */
static int register_once(const GTypeInfo *t, GError *err)
{
    int rc = gregistry_find(t->kind, t->name) ? G_OK : gregistry_add(t, err);
    return rc < 0 ? rc : G_OK;
}

GKind gtrace_kind_object = GKIND_MAX, gtrace_kind_light = GKIND_MAX, gtrace_kind_camera = GKIND_MAX;

int gtrace_register_kinds(GError *err)
{
    static const GKindInfo objects = {"object", NULL, 0}, lights = {"light", NULL, 0}, cameras = {"camera", NULL, 0};
    int rc = gregistry_add_kind(&objects, &gtrace_kind_object, err);
    if (rc == G_OK)
        rc = gregistry_add_kind(&lights, &gtrace_kind_light, err);
    if (rc == G_OK)
        rc = gregistry_add_kind(&cameras, &gtrace_kind_camera, err);
    return rc == G_OK ? media_register_kinds(err) : rc;
}

_Static_assert(sizeof shape_names / sizeof *shape_names == SCENE_SHAPE_TYPES, "a table for every shape");
_Static_assert(sizeof light_names / sizeof *light_names == SCENE_LIGHT_TYPES, "a table for every light");
_Static_assert(sizeof camera_names / sizeof *camera_names == SCENE_CAMERA_TYPES, "a table for every camera");

int gtrace_register_types(GError *err)
{
    int rc = gtrace_register_kinds(err);
    if (rc == G_OK)
        rc = media_register_types(err);
    for (int i = 0; i < NSHAPE_TYPES && rc == G_OK; i++) {
        GTypeInfo t = {.kind = gtrace_kind_object, .name = shape_names[i], .vtable = &shape_kinds[i],
                       .parse = scene_parse_object, .summary = shape_summaries[i], .destroy = destroy_object,
                       .params = scene_shape_tables[i]};
        rc = register_once(&t, err);
    }
    for (int i = 0; i < SCENE_LIGHT_TYPES && rc == G_OK; i++) {
        GTypeInfo t = {.kind = gtrace_kind_light, .name = light_names[i], .vtable = &light_types[i],
                       .parse = scene_parse_light, .summary = light_summaries[i], .destroy = destroy_light,
                       .params = scene_light_tables[i]};
        rc = register_once(&t, err);
    }
    GTypeInfo probe = {.kind = gtrace_kind_light, .name = "probe", .vtable = NULL, .parse = probe_light_parse,
                       .summary = "HDR light probe: directional lights of a technique, or Monte Carlo reference",
                       .destroy = probe_light_destroy, .params = probe_light_params};
    if (rc == G_OK)
        rc = register_once(&probe, err);
    for (int i = 0; i < SCENE_CAMERA_TYPES && rc == G_OK; i++) {
        GTypeInfo cam = {.kind = gtrace_kind_camera, .name = camera_names[i], .vtable = &camera_kinds[i],
                         .parse = scene_parse_camera, .summary = camera_summaries[i], .params = scene_camera_tables[i]};
        rc = register_once(&cam, err);
    }
    return rc;
}
