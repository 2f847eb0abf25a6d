/* phase.h - phase functions of participating media (phase.c): the kind `phase`, whose types are registered like
 * any other (isotropic and Henyey-Greenstein built in; a module adds one by registering a type of the kind
 * gkind_find("phase") whose objects begin with a Phase). */
#ifndef GTRACE_PHASE_H
#define GTRACE_PHASE_H

#include <generic/error.h>
#include <generic/registry.h>
#include <generic/vec.h>

struct Phase;

/** What a phase function does. Directions are unit vectors of propagation: `in` the direction the light travelled
 * before the scattering, `out` after it, so forward scattering is out == in. */
typedef struct PhaseClass {
    /** The density of out given in, per steradian (integrates to 1 over the sphere). */
    double (*eval)(const struct Phase *self, GVec3 in, GVec3 out);
    /** Draws out given in from u1, u2 in [0, 1) with exactly the density eval gives; returns that density. */
    double (*sample)(const struct Phase *self, GVec3 in, double u1, double u2, GVec3 *out);
} PhaseClass;

/** A phase function: its class (kind) first (a type's own fields follow in its object). */
typedef struct Phase {
    const PhaseClass *kind;
    double g; /**< Henyey-Greenstein's mean cosine (0 for isotropic) */
} Phase;

/** The density of out given in (phase->kind->eval). */
double phase_eval(const Phase *phase, GVec3 in, GVec3 out);
/** Draws out given in; returns its density (phase->kind->sample). */
double phase_sample(const Phase *phase, GVec3 in, double u1, double u2, GVec3 *out);
/** The isotropic phase function, for a medium that names none (static, never released). */
const Phase *phase_isotropic(void);

/** The kind `phase`, numbered by media_register (GKIND_MAX before). */
extern GKind gtrace_kind_phase;
/** Registers the phase types isotropic and hg with the kind kind (idempotent). */
int phase_register_types(GKind kind, GError *err);

#endif
