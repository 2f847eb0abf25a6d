/* probe_light.c - the `light probe` entry: image-based lighting from an HDR light probe.
 *
 *   light probe { file "sky.hdr" technique irradiance count 32 rotate <-90, 0, 0> scale 1 }
 *   light probe { file "sky.hdr" technique reference samples 256 shadows on background on }
 *
 * file        the probe (anything gprobe_load reads; relative paths resolve against the scene file's
 *             directory); format auto | latlong | angular (default auto: 2:1 lat-long, square angular map)
 * technique   mediancut | adaptive | kmeans | irradiance: `count` directional lights made by the library's
 *             technique (include/generic/services/probe.h), each casting shadow rays like any directional light;
 *             reference: the whole probe, Monte Carlo with importance sampling, `samples` directions per
 *             shading point (probe_sample.c). Default adaptive, count 16, samples 64.
 *             sh | sh-hanning | ambientcube | sg-naive | sg-ls | sg-nnls | sg-ambient: a basis of `count`
 *             coefficients or lobes (include/generic/services/probe.h) whose irradiance E(n) at the shading normal
 *             lights the surface as an ambient term, without shadows: the material reflects a light of
 *             irradiance E(n) arriving along the normal (exactly the diffuse response for Lambert).
 * rotate      degrees about x, then y, then z turning the probe into the scene (gprobe_rotation_xyz):
 *             radiance the probe has from direction d arrives from R d. The probe's zenith is +z, so a
 *             y-up scene uses rotate <-90, 0, 0> (as `gprobe approx --rotate -90,0,0`). The techniques run on
 *             the probe as stored and their lights are turned afterwards, so no resampling blurs the
 *             probe and the median cuts follow the probe's own latitude and longitude.
 * scale       multiplies the radiance (lights, background and reference alike).
 * background  on (default): rays that leave the scene see the probe, looked up by direction with the same
 *             convention (bilinear between pixel centres).
 * shadows     reference only: off skips the shadow rays (the unoccluded image that shows where the shadows
 *             are, see `gprobe compare --unshadowed`).
 * fit_normals irradiance only: normals the fit uses (default: the library's, 2000).
 *
 * The probe's pixels become colours of the scene's model through the library (gprobe_pixel_color and
 * friends, which read them as lights), so the tracer stays free of any colour model. The entry owns the
 * probe and the lights it makes; the scene only points at them. */
#include "scenefile/parse.h"
#include "probe_env.h"
#include "film/progress.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define PROBE_MAX_COUNT 4096
#define PROBE_ERROR_NORMALS 2000

static const char *technique_name(int t)
{
    if (PROBE_IS_BASIS(t))
        return gprobe_basis_name((GProbeBasisKind)(t - PROBE_BASIS(0)));
    return t == PROBE_REFERENCE ? "reference" : gprobe_technique_name((GProbeTechnique)t);
}

/* Technique for a keyword: a library technique or "reference"; G_ERR_NOTFOUND with the names listed. */
static int technique_from_name(const char *name, int *t, GError *err)
{
    if (strcmp(name, "reference") == 0) {
        *t = PROBE_REFERENCE;
        return G_OK;
    }
    GProbeTechnique pt;
    GProbeBasisKind bk;
    GError e;
    if (gprobe_basis_parse(name, &bk, &e) == G_OK) {
        *t = PROBE_BASIS(bk);
        return G_OK;
    }
    if (gprobe_technique_parse(name, &pt, &e) != G_OK)
        return gerror_set(err, G_ERR_NOTFOUND, "unknown probe technique '%s' (expected mediancut, adaptive, kmeans, "
                          "irradiance, variance, reference, or a basis: sh, sh-hanning, ambientcube, sg-naive, "
                          "sg-ls, sg-nnls, sg-ambient)", name);
    *t = (int)pt;
    return G_OK;
}

/* The settings that do not fit together (the text is a complete sentence for a message). */
#define G_STR_(x) #x
#define G_STR(x) G_STR_(x)

static const char *check_settings(const ProbeEnv *e)
{
    if (e->technique == GPROBE_MEDIANCUT && (e->count & (e->count - 1)) != 0)
        return "median cut makes a power of two lights: give count 1, 2, 4, 8, ...";
    if (PROBE_IS_BASIS(e->technique) &&
        !gprobe_basis_size_ok((GProbeBasisKind)(e->technique - PROBE_BASIS(0)), e->count))
        return "a basis takes count 4, 9, 16 or 25 (sh), 6 (ambientcube) or 1.." G_STR(GPROBE_SG_MAX_LOBES) " (sg)";
    if (!e->shadows && e->technique != PROBE_REFERENCE)
        return "shadows off is only for technique reference (directional lights always cast shadows)";
    if (e->technique == GPROBE_IRRADIANCE && e->count > GPROBE_FIT_MAX_LIGHTS)
        return "technique irradiance fits at most " G_STR(GPROBE_FIT_MAX_LIGHTS) " lights (its time grows with the "
               "cube of the count): give a smaller count, or mediancut, adaptive or kmeans";
    if (e->technique == GPROBE_IRRADIANCE &&
        (long)e->count * (e->fit_normals ? e->fit_normals : 2000) > GPROBE_FIT_MAX_PAIRS)
        return "technique irradiance: count x fit_normals exceeds the limit of " G_STR(GPROBE_FIT_MAX_PAIRS);
    return NULL;
}

static void release_products(ProbeEnv *e)
{
    for (int i = 0; i < e->nlights; i++)
        light_free(e->lights[i]);
    gmem_free(e->lights);
    e->lights = NULL;
    e->nlights = 0;
    probe_dist_free(&e->dist);
    probe_dist_free(&e->nee_dist);
    gprobe_basis_free(&e->basis);
    gprobe_destroy(e->probe);
    e->probe = NULL;
}

void probe_light_destroy(void *object)
{
    ProbeEnv *e = object;
    if (!e)
        return;
    release_products(e);
    gmem_free(e->file);
    gmem_free(e);
}

int probe_light_parse(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    ProbeEnv *e = gmem_calloc(1, sizeof *e);
    if (!e)
        return greader_error(r, err, "out of memory");
    e->technique = GPROBE_ADAPTIVE;
    e->count = 16;
    e->samples = 64;
    e->scale = 1.0;
    e->background = 1;
    e->shadows = 1;
    e->format = GPROBE_AUTO;
    int line = 0, col = 0;
    greader_position(r, &line, &col);
    snprintf(e->where, sizeof e->where, "%.200s:%d:%d", greader_file(r), line, col);
    static const char *const formats[] = {"auto", "latlong", "angular", NULL};
    const char *key;
    long v;
    int rc, fmt;
    char name[64];
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "file") == 0) {
            gmem_free(e->file);
            e->file = NULL;
            rc = greader_path(r, &e->file, err);
        } else if (strcmp(key, "technique") == 0) {
            GError te;
            if ((rc = greader_ident(r, name, sizeof name, err)) == G_OK &&
                technique_from_name(name, &e->technique, &te) < 0)
                rc = greader_error(r, err, "%s", te.message);
        } else if (strcmp(key, "count") == 0) {
            rc = (rc = greader_int(r, 1, PROBE_MAX_COUNT, &v, err)) < 0 ? rc : (e->count = (int)v, 0);
        } else if (strcmp(key, "samples") == 0) {
            rc = (rc = greader_int(r, 1, 65536, &v, err)) < 0 ? rc : (e->samples = (int)v, 0);
        } else if (strcmp(key, "fit_normals") == 0) {
            rc = (rc = greader_int(r, 16, 1000000, &v, err)) < 0 ? rc : (e->fit_normals = (int)v, 0);
        } else if (strcmp(key, "rotate") == 0) {
            rc = greader_vec3(r, &e->rotate, err);
        } else if (strcmp(key, "scale") == 0) {
            rc = greader_number_in(r, 0.0, 1e30, &e->scale, err);
        } else if (strcmp(key, "background") == 0) {
            rc = greader_bool(r, &e->background, err);
        } else if (strcmp(key, "shadows") == 0) {
            rc = greader_bool(r, &e->shadows, err);
        } else if (strcmp(key, "format") == 0) {
            rc = (rc = greader_choice(r, formats, &fmt, err)) < 0 ? rc : (e->format = (GProbeFormat)fmt, 0);
        } else {
            rc = greader_unknown_param(r, "file, technique, count, samples, rotate, scale, background, shadows, "
                                          "format, fit_normals", err);
        }
        if (rc < 0)
            break;
    }
    const char *bad = NULL;
    if (rc == G_OK && !e->file)
        rc = greader_error(r, err, "a light probe needs its image (file \"probe.hdr\")");
    if (rc == G_OK && (bad = check_settings(e)) != NULL)
        rc = greader_error(r, err, "%s", bad);
    if (rc < 0) {
        probe_light_destroy(e);
        return rc;
    }
    *object = e;
    return G_OK;
}

const GParamInfo probe_light_params[] = {
    {"file", GPARAM_NAMED, "path", NULL, "an image gprobe_load reads (e.g. .hdr, .exr, .pfm)",
     "the light probe: a 2:1 latitude-longitude or a square angular map"},
    {"technique", GPARAM_NAMED, "choice", "adaptive",
     "mediancut, adaptive, kmeans, irradiance, variance, reference, sh, sh-hanning, ambientcube, sg-naive, sg-ls, "
     "sg-nnls, sg-ambient",
     "the techniques make count directional lights; reference samples the whole probe; a basis (sh...sg-ambient) "
     "lights the surface as an ambient term, without shadows"},
    {"count", GPARAM_NAMED, "integer", "16",
     "[1, 4096]; mediancut a power of 2; irradiance at most 128; sh 4, 9, 16, 25; ambientcube 6; sg at most 128",
     "the number of lights, coefficients or lobes"},
    {"samples", GPARAM_NAMED, "integer", "64", "[1, 65536]", "reference: directions sampled per shading point"},
    {"rotate", GPARAM_NAMED, "vector", "<0, 0, 0>", NULL,
     "degrees about x, then y, then z turning the probe into the scene (its zenith is +z: y-up scenes say "
     "<-90, 0, 0>)"},
    {"scale", GPARAM_NAMED, "number", "1", "[0, 1e30]", "multiplies the probe's radiance"},
    {"background", GPARAM_NAMED, "bool", "yes", NULL, "rays that leave the scene see the probe"},
    {"shadows", GPARAM_NAMED, "bool", "yes", "off only with technique reference",
     "reference: no shows the unoccluded image"},
    {"format", GPARAM_NAMED, "choice", "auto", "auto, latlong, angular",
     "the probe's mapping; auto: 2:1 latitude-longitude, square angular"},
    {"fit_normals", GPARAM_NAMED, "integer", "2000", "[16, 1000000], count x fit_normals at most 524288",
     "irradiance: the normals the fit uses"},
    {NULL},
};

int probe_override_apply(GLibrary *lib, const ProbeOverride *ov, GError *err)
{
    if (!ov)
        return G_OK;
    int technique = -1;
    if (ov->technique && technique_from_name(ov->technique, &technique, err) < 0)
        return err ? err->code : G_ERR_NOTFOUND;
    int found = 0, n = glibrary_count(lib, gtrace_kind_light);
    for (int i = 0; i < n; i++) {
        const GTypeInfo *t;
        ProbeEnv *e = glibrary_entry(lib, gtrace_kind_light, i, NULL, &t);
        if (!t || t->parse != probe_light_parse)
            continue;
        found++;
        if (ov->file) {
            char *f = gmem_strdup(ov->file);
            if (!f)
                return gerror_set(err, G_ERR_NOMEM, "out of memory");
            gmem_free(e->file);
            e->file = f;
        }
        if (technique >= 0)
            e->technique = technique;
        if (ov->count > 0)
            e->count = ov->count;
        if (ov->samples > 0)
            e->samples = ov->samples;
        if (ov->scale > 0.0)
            e->scale = ov->scale;
        if (ov->shadows >= 0)
            e->shadows = ov->shadows;
        const char *bad = check_settings(e);
        if (bad)
            return gerror_set(err, G_ERR_INVALID, "%s: light probe: %s", e->where, bad);
    }
    int any = ov->file || ov->technique || ov->count > 0 || ov->samples > 0 || ov->scale > 0.0 || ov->shadows >= 0;
    if (any && !found)
        return gerror_set(err, G_ERR_INVALID, "the scene has no `light probe` entry for the --probe options to change");
    return G_OK;
}

GVec3 probe_to_world(const ProbeEnv *e, GVec3 v)
{
    const double *R = e->R;
    return gvec3(R[0] * v.x + R[1] * v.y + R[2] * v.z, R[3] * v.x + R[4] * v.y + R[5] * v.z,
                 R[6] * v.x + R[7] * v.y + R[8] * v.z);
}

/* The inverse turn (R is a rotation: its transpose). */
GVec3 probe_from_world(const ProbeEnv *e, GVec3 v)
{
    const double *R = e->R;
    return gvec3(R[0] * v.x + R[3] * v.y + R[6] * v.z, R[1] * v.x + R[4] * v.y + R[7] * v.z,
                 R[2] * v.x + R[5] * v.y + R[8] * v.z);
}

/* Keeps a light the entry made and hands it to the scene. */
static int give_light(Scene *s, ProbeEnv *e, Light *l, GError *err)
{
    if (!l)
        return gerror_set(err, G_ERR_NOMEM, "%s: light probe: out of memory", e->where);
    e->lights[e->nlights++] = l;
    return scene_add_light(s, l, err);
}

/* Mean irradiance error of the lights against the probe's ground truth (percent, the paper's measure). */
static double lights_error(const GProbe *p, const GProbeLight *lights, int n)
{
    GVec3 *normals = gmem_alloc(PROBE_ERROR_NORMALS * sizeof *normals);
    double *truth = gmem_alloc(PROBE_ERROR_NORMALS * 3 * sizeof *truth);
    double *approx = gmem_alloc(PROBE_ERROR_NORMALS * 3 * sizeof *approx);
    double result = NAN;
    GError e;
    if (normals && truth && approx) {
        gprobe_fibonacci(PROBE_ERROR_NORMALS, normals);
        if (gprobe_irradiance(p, normals, PROBE_ERROR_NORMALS, truth, &e) == G_OK) {
            gprobe_lights_irradiance(lights, n, normals, PROBE_ERROR_NORMALS, approx);
            GProbeErrors errs;
            gprobe_compare(truth, approx, PROBE_ERROR_NORMALS, &errs);
            result = errs.mean_rel;
        }
    }
    gmem_free(normals);
    gmem_free(truth);
    gmem_free(approx);
    return result;
}

/* The technique's lights, turned into the scene and converted into its colour model. */
static int make_lights(Scene *s, ProbeEnv *e, GError *err)
{
    GProbeLight *pl = gmem_calloc((size_t)e->count, sizeof *pl);
    e->lights = gmem_calloc((size_t)e->count, sizeof *e->lights);
    if (!pl || !e->lights) {
        gmem_free(pl);
        return gerror_set(err, G_ERR_NOMEM, "%s: light probe: out of memory for %d lights", e->where, e->count);
    }
    GProbeOptions opt = {0};
    opt.fit_normals = e->fit_normals;
    int rc = gprobe_approximate(e->probe, (GProbeTechnique)e->technique, e->count, &opt, pl, err);
    if (rc < 0) {
        char msg[sizeof err->message];
        snprintf(msg, sizeof msg, "%s", err ? err->message : "");
        gmem_free(pl);
        return gerror_set(err, rc, "%s: light probe: %s", e->where, msg);
    }
    e->error_mean = lights_error(e->probe, pl, e->count);
    for (int i = 0; i < e->count && rc == G_OK; i++) {
        Light *l = light_new(s->model, LIGHT_DIRECTIONAL);
        if (l && ((rc = gprobe_light_color(&pl[i], &l->color)) < 0 ||
                  (rc = gcolor_scale(&l->color, &l->color, e->scale)) < 0)) {
            light_free(l);
            rc = gerror_set(err, rc, "%s: light probe: light %d: %s", e->where, i, gstatus_string(rc));
            break;
        }
        if (l && gcolor_brightness(&l->color) <= 0.0) { /* a light without energy: no shadow rays for nothing */
            light_free(l);
            continue;
        }
        if (l)
            l->direction = gvec3_neg(gvec3_normalize(probe_to_world(e, pl[i].dir)));
        rc = give_light(s, e, l, err);
    }
    gmem_free(pl);
    return rc;
}

/* A basis as one LIGHT_PROBE light: its irradiance is the ambient term (probe_sample.c). */
static int make_basis(Scene *s, ProbeEnv *e, GError *err)
{
    GError le;
    int rc = gprobe_basis_fit(e->probe, (GProbeBasisKind)(e->technique - PROBE_BASIS(0)), e->count, &e->basis, &le);
    if (rc < 0)
        return gerror_set(err, rc, "%s: light probe: %s", e->where, le.message);
    e->error_mean = NAN;
    GVec3 *normals = gmem_alloc(PROBE_ERROR_NORMALS * sizeof *normals);
    double *truth = gmem_alloc(PROBE_ERROR_NORMALS * 3 * sizeof *truth);
    double *approx = gmem_alloc(PROBE_ERROR_NORMALS * 3 * sizeof *approx);
    if (normals && truth && approx) {
        gprobe_fibonacci(PROBE_ERROR_NORMALS, normals);
        if (gprobe_irradiance(e->probe, normals, PROBE_ERROR_NORMALS, truth, &le) == G_OK) {
            GProbeErrors errs;
            gprobe_basis_irradiance(&e->basis, normals, PROBE_ERROR_NORMALS, approx);
            gprobe_compare(truth, approx, PROBE_ERROR_NORMALS, &errs);
            e->error_mean = errs.mean_rel;
        }
    }
    gmem_free(normals);
    gmem_free(truth);
    gmem_free(approx);
    if (!(e->lights = gmem_calloc(1, sizeof *e->lights)))
        return gerror_set(err, G_ERR_NOMEM, "%s: light probe: out of memory", e->where);
    Light *l = light_new(s->model, LIGHT_PROBE);
    if (l)
        l->env = e;
    return give_light(s, e, l, err);
}

int probe_attach(Scene *s, ProbeEnv *e, GError *err)
{
    release_products(e);
    double t0 = now_seconds();
    GError le;
    gerror_clear(&le);
    int rc = gprobe_load(e->file, e->format, 0, &e->probe, &le);
    if (rc < 0)
        return gerror_set(err, rc, "%s: light probe: %s", e->where, le.message);
    gprobe_rotation_xyz(e->rotate.x, e->rotate.y, e->rotate.z, e->R);
    if (e->technique == PROBE_REFERENCE) {
        if ((rc = probe_dist_build(&e->dist, e->probe, s->model, &le)) < 0 ||
            (rc = probe_dist_build_compensated(&e->nee_dist, e->probe, s->model, &le)) < 0)
            return gerror_set(err, rc, "%s: light probe: %s", e->where, le.message);
        e->lights = gmem_calloc(1, sizeof *e->lights);
        if (!e->lights)
            return gerror_set(err, G_ERR_NOMEM, "%s: light probe: out of memory", e->where);
        Light *l = light_new(s->model, LIGHT_PROBE);
        if (l) {
            l->env = e;
            l->samples = e->samples;
        }
        rc = give_light(s, e, l, err);
        e->error_mean = 0.0;
    } else if (PROBE_IS_BASIS(e->technique)) {
        rc = make_basis(s, e, err);
    } else {
        rc = make_lights(s, e, err);
    }
    if (rc < 0)
        return rc;
    if (e->background) {
        if (s->env)
            return gerror_set(err, G_ERR_INVALID, "%s: light probe: another probe is already the background "
                              "(give this one `background off`)", e->where);
        s->env = e;
    }
    e->seconds = now_seconds() - t0;
    return G_OK;
}

int probe_background(const ProbeEnv *env, GVec3 d, GColor *out)
{
    int rc = gprobe_radiance_color(env->probe, probe_from_world(env, d), out);
    if (rc == G_OK && env->scale != 1.0)
        rc = gcolor_scale(out, out, env->scale);
    return rc;
}

void probe_describe(const Scene *s, FILE *f)
{
    if (!s->lib)
        return;
    int n = glibrary_count(s->lib, gtrace_kind_light);
    for (int i = 0; i < n; i++) {
        const GTypeInfo *t;
        const ProbeEnv *e = glibrary_entry(s->lib, gtrace_kind_light, i, NULL, &t);
        if (!t || t->parse != probe_light_parse || !e->probe)
            continue;
        fprintf(f, "gtrace: probe %s (%dx%d): %s", e->file, gprobe_width(e->probe), gprobe_height(e->probe),
                technique_name(e->technique));
        if (e->technique == PROBE_REFERENCE)
            fprintf(f, ", %d samples per shading point%s", e->samples, e->shadows ? "" : ", no shadows");
        else if (PROBE_IS_BASIS(e->technique))
            fprintf(f, ", %d %s as an ambient term (no shadows), mean irradiance error %.2f%%", e->count,
                    gprobe_basis_unit((GProbeBasisKind)(e->technique - PROBE_BASIS(0))), e->error_mean);
        else
            fprintf(f, ", %d lights (%d with energy), mean irradiance error %.2f%%", e->count, e->nlights,
                    e->error_mean);
        fprintf(f, ", prepared in %.3f s\n", e->seconds);
        if (gprobe_clamped_count(e->probe) > 0)
            fprintf(f, "gtrace: warning: probe %s: %ld pixels had negative, NaN, infinite or too large values, "
                    "clamped\n", e->file, gprobe_clamped_count(e->probe));
    }
}
