/* phase.c - the isotropic and the Henyey-Greenstein phase function (Henyey & Greenstein 1941), sampled exactly by
 * inverting the cumulative distribution of the cosine; their types of the kind `phase`:
 *
 *   phase NAME? isotropic { }
 *   phase NAME? hg { g G }      G in (-1, 1): the mean cosine, > 0 forward scattering */
#include "phase.h"

#include <generic/memory.h>
#include <generic/material.h>
#include <generic/reader.h>

#include <math.h>
#include <string.h>

GKind gtrace_kind_phase = GKIND_MAX;

/* The direction at cosine ct from axis w, azimuth phi. */
static GVec3 around(GVec3 w, double ct, double phi)
{
    GVec3 t1, t2;
    goptics_frame(w, &t1, &t2);
    double st = sqrt(fmax(0.0, 1.0 - ct * ct));
    return gvec3_add(gvec3_scale(w, ct), gvec3_add(gvec3_scale(t1, st * cos(phi)), gvec3_scale(t2, st * sin(phi))));
}

static double iso_eval(const Phase *self, GVec3 in, GVec3 out)
{
    (void)self, (void)in, (void)out;
    return 0.25 / M_PI;
}

static double iso_sample(const Phase *self, GVec3 in, double u1, double u2, GVec3 *out)
{
    (void)self;
    *out = around(in, 1.0 - 2.0 * u1, 2.0 * M_PI * u2);
    return 0.25 / M_PI;
}

static double hg_density(double g, double ct)
{
    double d = 1.0 + g * g - 2.0 * g * ct;
    return 0.25 / M_PI * (1.0 - g * g) / (d * sqrt(d));
}

static double hg_eval(const Phase *self, GVec3 in, GVec3 out) { return hg_density(self->g, gvec3_dot(in, out)); }

static double hg_sample(const Phase *self, GVec3 in, double u1, double u2, GVec3 *out)
{
    double g = self->g, ct;
    if (fabs(g) < 1e-3)
        ct = 1.0 - 2.0 * u1;
    else {
        double s = (1.0 - g * g) / (1.0 - g + 2.0 * g * u1);
        ct = (1.0 + g * g - s * s) / (2.0 * g);
    }
    ct = fmin(1.0, fmax(-1.0, ct));
    *out = around(in, ct, 2.0 * M_PI * u2);
    return hg_density(g, ct);
}

static const PhaseClass isotropic_class = {iso_eval, iso_sample};
static const PhaseClass hg_class = {hg_eval, hg_sample};

double phase_eval(const Phase *phase, GVec3 in, GVec3 out) { return phase->kind->eval(phase, in, out); }

double phase_sample(const Phase *phase, GVec3 in, double u1, double u2, GVec3 *out)
{
    return phase->kind->sample(phase, in, u1, u2, out);
}

const Phase *phase_isotropic(void)
{
    static const Phase iso = {&isotropic_class, 0.0};
    return &iso;
}

static int parse_phase(GReader *r, const void *vtable, void **object, GError *err)
{
    const PhaseClass *cls = vtable;
    Phase *ph = gmem_calloc(1, sizeof *ph);
    if (!ph)
        return greader_error(r, err, "out of memory");
    ph->kind = cls;
    const char *key;
    int rc;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "g") == 0 && cls == &hg_class) {
            GToken t;
            double g = 0.0;
            if ((rc = greader_peek(r, &t, err)) == G_OK && (rc = greader_number(r, &g, err)) == G_OK &&
                !(g > -1.0 && g < 1.0))
                rc = greader_error_at(r, err, G_ERR_INVALID, t.line, t.col,
                                      "hg: g (%g) must lie in (-1, 1), the open interval of mean cosines", g);
            ph->g = g;
        } else {
            rc = greader_unknown_param(r, cls == &hg_class ? "g" : "(none)", err);
        }
        if (rc < 0)
            break;
    }
    if (rc < 0) {
        gmem_free(ph);
        return rc;
    }
    *object = ph;
    return G_OK;
}

static void destroy_phase(void *p) { gmem_free(p); }

static const GParamInfo isotropic_params[] = {{NULL}};
static const GParamInfo hg_params[] = {
    {"g", GPARAM_NAMED, "number", "0", "(-1, 1)",
     "the mean cosine of the scattering angle: > 0 scatters forward, < 0 backward, 0 is isotropic"},
    {NULL},
};

int phase_register_types(GKind kind, GError *err)
{
    const GTypeInfo types[] = {
        {.kind = kind, .name = "isotropic", .vtable = &isotropic_class, .parse = parse_phase,
         .summary = "isotropic phase function: every direction equally likely", .destroy = destroy_phase,
         .params = isotropic_params},
        {.kind = kind, .name = "hg", .vtable = &hg_class, .parse = parse_phase,
         .summary = "Henyey-Greenstein phase function of mean cosine g", .destroy = destroy_phase,
         .params = hg_params},
    };
    for (int i = 0; i < 2; i++)
        if (!gregistry_find(kind, types[i].name)) {
            int rc = gregistry_add(&types[i], err);
            if (rc < 0)
                return rc;
        }
    return G_OK;
}
