/* material_parsers.c - text format parse routines of the built-in materials: each reads its parameter block
 * and calls the public constructor of generic/materials.h in the file's colour model. */
#include "material_parsers.h"
#include "generic/materials.h"

#include <stdio.h>
#include <string.h>

#define MAX_KEYS 8

/* Where each parameter was given, so a constructor's complaint about one points at it. */
typedef struct Seen {
    const char *material;
    char keys[MAX_KEYS][32];
    int line[MAX_KEYS], col[MAX_KEYS];
    int n;
} Seen;

static void seen_add(GReader *r, Seen *s, const char *key)
{
    if (s->n == MAX_KEYS)
        return;
    snprintf(s->keys[s->n], sizeof s->keys[0], "%s", key);
    greader_position(r, &s->line[s->n], &s->col[s->n]);
    s->n++;
}

/* Places a constructor's message ("<material>: <param> ...") at its parameter, else at the last token. */
static int locate(GReader *r, const Seen *s, int rc, GError *err)
{
    size_t ml = strlen(s->material);
    if (err && strncmp(err->message, s->material, ml) == 0 && strncmp(err->message + ml, ": ", 2) == 0) {
        const char *p = err->message + ml + 2;
        for (int i = 0; i < s->n; i++) {
            size_t kl = strlen(s->keys[i]);
            if (strncmp(p, s->keys[i], kl) == 0 && (p[kl] == ' ' || p[kl] == ':' || p[kl] == '\0')) {
                char msg[sizeof err->message];
                snprintf(msg, sizeof msg, "%s", err->message);
                return greader_error_at(r, err, rc, s->line[i], s->col[i], "%s", msg);
            }
        }
    }
    greader_locate(r, err);
    return rc;
}

/* A colour from an sRGB triple in the file's model (for defaults). */
static int default_color(GReader *r, double v, GColorRole role, GColor *c, GError *err)
{
    if (c->v)
        return G_OK;
    const GColorModel *m = greader_colormodel(r);
    double rgb[3] = {v, v, v};
    if (!m || gcolor_alloc(c, m) != G_OK)
        return greader_error(r, err, "out of memory");
    return gcolor_from_rgb(c, rgb, role) == G_OK ? G_OK : greader_error(r, err, "invalid default colour");
}

static int finish(int rc, GMaterial *m, void **object)
{
    if (rc == G_OK)
        *object = m;
    return rc;
}

/* The constructor of a material with one reflectance parameter (glambert_create, gmirror_create). */
typedef int (*ReflectorCreate)(const GColorModel *model, const GColor *reflectance, GMaterial **out, GError *err);

/* `NAME { reflectance COLOR }`: the parameter block of a material whose only parameter is its reflectance
 * (grey `def` by default), made with create. */
static int parse_reflector(GReader *r, const char *name, double def, ReflectorCreate create, void **object,
                           GError *err)
{
    Seen s = {.material = name};
    GColor refl = {0};
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        seen_add(r, &s, key);
        if (strcmp(key, "reflectance") == 0)
            rc = greader_color(r, GCOLOR_REFLECTANCE, &refl, err);
        else
            rc = greader_unknown_param(r, "reflectance", err);
        if (rc < 0)
            break;
    }
    if (rc == G_OK)
        rc = default_color(r, def, GCOLOR_REFLECTANCE, &refl, err);
    GMaterial *m = NULL;
    if (rc == G_OK && (rc = create(greader_colormodel(r), &refl, &m, err)) != G_OK)
        rc = locate(r, &s, rc, err);
    gcolor_free(&refl);
    return finish(rc, m, object);
}

int gparse_lambert(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    return parse_reflector(r, "lambert", 0.8, glambert_create, object, err);
}

int gparse_phong(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    Seen s = {.material = "phong"};
    GColor kd = {0}, ks = {0}, mirror = {0};
    double exponent = 20.0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        seen_add(r, &s, key);
        if (strcmp(key, "diffuse") == 0)
            rc = greader_color(r, GCOLOR_REFLECTANCE, &kd, err);
        else if (strcmp(key, "specular") == 0)
            rc = greader_color(r, GCOLOR_REFLECTANCE, &ks, err);
        else if (strcmp(key, "exponent") == 0)
            rc = greader_number_in(r, 0.0, 1e6, &exponent, err);
        else if (strcmp(key, "mirror") == 0)
            rc = greader_color(r, GCOLOR_REFLECTANCE, &mirror, err);
        else
            rc = greader_unknown_param(r, "diffuse, specular, exponent, mirror", err);
        if (rc < 0)
            break;
    }
    if (rc == G_OK && !kd.v && !ks.v)
        rc = default_color(r, 0.5, GCOLOR_REFLECTANCE, &kd, err);
    GMaterial *m = NULL;
    if (rc == G_OK) {
        GPhongParams p = {kd.v ? &kd : NULL, ks.v ? &ks : NULL, exponent, mirror.v ? &mirror : NULL};
        if ((rc = gphong_create(greader_colormodel(r), &p, &m, err)) != G_OK)
            rc = locate(r, &s, rc, err);
    }
    gcolor_free(&kd);
    gcolor_free(&ks);
    gcolor_free(&mirror);
    return finish(rc, m, object);
}

int gparse_mirror(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    return parse_reflector(r, "mirror", 1.0, gmirror_create, object, err);
}

/* index N | index cauchy A B [C] | index sellmeier B1 B2 B3 C1 C2 C3 */
static int read_index(GReader *r, GDispersion *d, GError *err)
{
    GToken t;
    int rc = greader_peek(r, &t, err);
    if (rc != G_OK)
        return rc;
    if (t.type == GTOK_NUMBER) {
        double n;
        rc = greader_number_in(r, 0.01, 100.0, &n, err);
        if (rc == G_OK)
            *d = gdispersion_constant(n);
        return rc;
    }
    static const char *const forms[] = {"cauchy", "sellmeier", NULL};
    int which = 0;
    if ((rc = greader_choice(r, forms, &which, err)) != G_OK)
        return rc;
    double c[6] = {0, 0, 0, 0, 0, 0};
    int n = which == 0 ? 2 : 6;
    for (int i = 0; i < n && rc == G_OK; i++)
        rc = greader_number(r, &c[i], err);
    if (rc == G_OK && which == 0 && (rc = greader_at_number(r, err)) == 1)
        rc = greader_number(r, &c[2], err);
    if (rc != G_OK)
        return rc;
    *d = which == 0 ? gdispersion_cauchy(c[0], c[1], c[2]) : gdispersion_sellmeier(c, c + 3);
    GError check;
    if (gdispersion_check(d, &check) != G_OK)
        return greader_error(r, err, "%s", check.message);
    return G_OK;
}

int gparse_dielectric(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    Seen s = {.material = "dielectric"};
    GColor absorption = {0}, tint = {0};
    GDispersion index = gdispersion_constant(1.5);
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        seen_add(r, &s, key);
        if (strcmp(key, "index") == 0)
            rc = read_index(r, &index, err);
        else if (strcmp(key, "absorption") == 0)
            rc = greader_color(r, GCOLOR_REFLECTANCE, &absorption, err);
        else if (strcmp(key, "tint") == 0)
            rc = greader_color(r, GCOLOR_REFLECTANCE, &tint, err);
        else
            rc = greader_unknown_param(r, "index, absorption, tint", err);
        if (rc < 0)
            break;
    }
    GMaterial *m = NULL;
    if (rc == G_OK) {
        GDielectricParams p = {index, absorption.v ? &absorption : NULL, tint.v ? &tint : NULL};
        if ((rc = gdielectric_create(greader_colormodel(r), &p, &m, err)) != G_OK)
            rc = locate(r, &s, rc, err);
    }
    gcolor_free(&absorption);
    gcolor_free(&tint);
    return finish(rc, m, object);
}

int gparse_emitter(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    Seen s = {.material = "emitter"};
    GColor radiance = {0};
    int two_sided = 0;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        seen_add(r, &s, key);
        if (strcmp(key, "radiance") == 0)
            rc = greader_color(r, GCOLOR_LIGHT, &radiance, err);
        else if (strcmp(key, "two_sided") == 0)
            rc = greader_bool(r, &two_sided, err);
        else
            rc = greader_unknown_param(r, "radiance, two_sided", err);
        if (rc < 0)
            break;
    }
    if (rc == G_OK)
        rc = default_color(r, 1.0, GCOLOR_LIGHT, &radiance, err);
    GMaterial *m = NULL;
    if (rc == G_OK && (rc = gemitter_create(greader_colormodel(r), &radiance, two_sided, &m, err)) != G_OK)
        rc = locate(r, &s, rc, err);
    gcolor_free(&radiance);
    return finish(rc, m, object);
}
