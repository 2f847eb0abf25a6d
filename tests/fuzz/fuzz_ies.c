/* fuzz_ies.c - libFuzzer target: IES LM-63 photometric files (gtrace's examples/gtrace/scene/ies.c, compiled into
 * this target): ies_parse on the bytes; a parsed table must hold finite, non-negative candela on increasing angles,
 * give finite intensities in every direction and a finite flux; a refusal must carry a message with the file's
 * position; an input the generator made wrong (GFUZZ_MUST_FAIL) must be refused. `make fuzz` builds and runs it. */
#define GFUZZ_TARGET ies
#include "fuzz_entry.h"

#include "../../examples/gtrace/scene/ies.c"

static int gfuzz_ies(const uint8_t *data, size_t size)
{
    if (size > gfuzz_max_input)
        return 0;
    char *text = malloc(size ? size : 1); /* an exact-size copy, so reading past the end is caught */
    if (!text)
        return 0;
    if (size)
        memcpy(text, data, size);
    IesData d;
    GError err;
    gerror_clear(&err);
    int rc = ies_parse(text, size, "fuzz.ies", &d, &err), bad = 0;
    if (rc != G_OK) {
        bad = gfuzz_error_ok(rc, &err, "ies_parse");
        if (!bad && (d.cd || d.v || d.h))
            bad = gfuzz_violation("a failed parse left tables behind");
        if (!bad && rc != G_ERR_NOMEM && strncmp(err.message, "fuzz.ies:", 9) != 0)
            bad = gfuzz_violation("the message has no position: %s", err.message);
    } else if (gfuzz_must_fail(data, size)) {
        bad = gfuzz_violation("a file wrong by construction (" GFUZZ_MUST_FAIL ") parsed (%d x %d)", d.nh, d.nv);
    } else {
        for (int i = 1; i < d.nv && !bad; i++)
            if (!(d.v[i] > d.v[i - 1]))
                bad = gfuzz_violation("vertical angles %d, %d do not increase", i - 1, i);
        for (size_t i = 0; i < (size_t)d.nv * (size_t)d.nh && !bad; i++)
            if (!(isfinite(d.cd[i]) && d.cd[i] >= 0.0))
                bad = gfuzz_violation("candela value %zu is %g", i, d.cd[i]);
        GVec3 aim = gvec3(0, -1, 0), along = gvec3(1, 0, 0), third = gvec3(0, 0, 1);
        for (int k = 0; k < 64 && !bad; k++) { /* directions over the sphere */
            double z = 1.0 - (k + 0.5) / 32.0, rr = sqrt(fmax(0.0, 1.0 - z * z)), ph = 2.399963 * k;
            double cd = ies_candela_dir(&d, gvec3(rr * cos(ph), z, rr * sin(ph)), aim, along, third);
            if (!(isfinite(cd) && cd >= 0.0))
                bad = gfuzz_violation("the intensity towards direction %d is %g", k, cd);
        }
        if (!bad && (size_t)d.nv * (size_t)d.nh <= 4096) { /* the flux costs 10^6 lookups: small tables only */
            double f = ies_flux(&d);
            if (!(isfinite(f) && f >= 0.0))
                bad = gfuzz_violation("the flux is %g", f);
        }
    }
    ies_free(&d);
    free(text);
    return bad;
}

#include "fuzz_target.h"
