/* scene_load.c - a scene from a loaded library (its objects, lights and camera, the camera's `frame`) and from a
 * scene file. */
#include "integrators/bands.h"
#include "parse.h"
#include "media/medium.h"
#include "param_tables.h"
#include "geometry/geometry.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

/* The camera's `frame`: the view fitted to the world bounds of the objects rendered directly (planes, unbounded,
 * are left out) at the camera's own image size (main.c fits it again when the command line sets another). */
static int frame_camera(Scene *s, const char *name, GError *err)
{
    GVec3 lo = gvec3(INFINITY, INFINITY, INFINITY), hi = gvec3(-INFINITY, -INFINITY, -INFINITY);
    for (int i = 0; i < s->nobjects; i++) {
        const Object *o = s->objects[i];
        if (o->is_part || o->kind == SHAPE_PLANE)
            continue;
        GVec3 a, b;
        object_world_bounds(o, &a, &b);
        lo = gvec3(fmin(lo.x, a.x), fmin(lo.y, a.y), fmin(lo.z, a.z));
        hi = gvec3(fmax(hi.x, b.x), fmax(hi.y, b.y), fmax(hi.z, b.z));
    }
    if (!(lo.x <= hi.x))
        return gerror_set(err, G_ERR_INVALID, "%s: the camera's frame needs an object other than a plane", name);
    int rc = camera_frame(&s->camera, lo, hi, s->camera.width, s->camera.height, err);
    if (rc < 0 && err) {
        char msg[sizeof err->message];
        snprintf(msg, sizeof msg, "%s", err->message);
        gerror_set(err, rc, "%s: %s", name, msg);
    }
    return rc;
}

int scene_from_library(GLibrary *lib, const char *name, Scene **out, GError *err)
{
    *out = NULL;
    Scene *s;
    int rc = scene_create(glibrary_colormodel(lib), &s, err);
    if (rc < 0) {
        glibrary_destroy(lib);
        return rc;
    }
    s->lib = lib;
    int n = glibrary_count(lib, gtrace_kind_object);
    for (int i = 0; i < n && rc == G_OK; i++) {
        const GTypeInfo *t;
        void *o = glibrary_entry(lib, gtrace_kind_object, i, NULL, &t);
        if (t && t->parse == scene_parse_object)
            rc = scene_add_object(s, o, err);
        else
            rc = gerror_set(err, G_ERR_UNSUPPORTED, "%s: object type '%s' is not one gtrace renders", name,
                            t ? t->name : "?");
    }
    double placements = 0.0;
    for (int i = 0; i < s->nobjects; i++)
        if (!s->objects[i]->is_part && !object_is_shape(s->objects[i]))
            placements += s->objects[i]->expansion;
    if (rc == G_OK && placements > GTRACE_MAX_INSTANCES)
        rc = gerror_set(err, G_ERR_INVALID, "%s: the scene's groups and instances expand to %.6g placements, more "
                        "than the limit of %d", name, placements, GTRACE_MAX_INSTANCES);
    n = glibrary_count(lib, gtrace_kind_light);
    for (int i = 0; i < n && rc == G_OK; i++) {
        const GTypeInfo *t;
        Light *l = glibrary_entry(lib, gtrace_kind_light, i, NULL, &t);
        if (t && t->parse == probe_light_parse) {
            rc = probe_attach(s, (ProbeEnv *)(void *)l, err);
            continue;
        }
        if (!t || t->parse != scene_parse_light) {
            rc = gerror_set(err, G_ERR_UNSUPPORTED, "%s: light type '%s' is not one gtrace renders", name,
                            t ? t->name : "?");
            break;
        }
        if (l->kind == LIGHT_AMBIENT) {
            rc = gcolor_add(&s->ambient, &s->ambient, &l->color);
            s->have_ambient = 1;
        } else if (l->kind == LIGHT_BACKGROUND) {
            rc = gcolor_copy(&s->background, &l->color);
        } else {
            rc = scene_add_light(s, l, err);
        }
        if (rc < 0 && err && !err->message[0])
            gerror_set(err, rc, "light %d: %s", i, gstatus_string(rc));
    }
    n = glibrary_count(lib, gtrace_kind_camera);
    if (rc == G_OK && n > 1)
        rc = gerror_set(err, G_ERR_INVALID, "%s: the scene defines %d cameras; give one", name, n);
    if (rc == G_OK && n == 1) {
        const GTypeInfo *t;
        const Camera *c = glibrary_entry(lib, gtrace_kind_camera, 0, NULL, &t);
        if (t && t->parse == scene_parse_camera) {
            s->camera = *c;
            s->have_camera = 1;
            s->medium = gmaterial_ref(c->medium);
            s->atmosphere = c->atmosphere;
            if (c->frame >= 0.0)
                rc = frame_camera(s, name, err);
        } else {
            rc = gerror_set(err, G_ERR_UNSUPPORTED, "%s: camera type '%s' is not one gtrace renders", name,
                            t ? t->name : "?");
        }
    }
    if (rc == G_OK)
        rc = media_bind_scene(s, name, err);
    if (rc < 0) {
        scene_destroy(s);
        return rc;
    }
    *out = s;
    return G_OK;
}

int scene_load(const char *path, const char *colormodel, Scene **out, GError *err)
{
    return scene_load_with(path, colormodel, NULL, out, err);
}

int scene_load_with(const char *path, const char *colormodel, const ProbeOverride *ov, Scene **out, GError *err)
{
    return scene_load_opts(path, colormodel, ov, NULL, out, err);
}

int scene_load_opts(const char *path, const char *colormodel, const ProbeOverride *ov, const GReaderOptions *base,
                    Scene **out, GError *err)
{
    *out = NULL;
    int rc = gtrace_register_types(err);
    if (rc < 0)
        return rc;
    GReaderOptions opt = {0};
    if (base)
        opt = *base;
    opt.colormodel = colormodel;
    GLibrary *lib = NULL;
    rc = greader_load_file(path, &opt, &lib, err);
    if (rc < 0)
        return rc;
    if ((rc = probe_override_apply(lib, ov, err)) < 0) {
        glibrary_destroy(lib);
        return rc;
    }
    return scene_from_library(lib, path, out, err);
}
