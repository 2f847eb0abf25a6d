/* fuzz_medium.c - libFuzzer target: gtrace's participating-media entries (examples/gtrace/media/phase.c and
 * medium_parse.c, compiled into this target): the bytes loaded as text with the kinds `medium` and `phase`
 * registered; a loaded medium must hold finite coefficients >= 0 in every band with sigma_t = sigma_a + sigma_s and
 * a phase function whose density is finite and >= 0 and whose sampling returns unit directions; a refusal must
 * carry the file's position; an input the generator made wrong (GFUZZ_MUST_FAIL) must be refused. `make fuzz`
 * builds and runs it. */
#define GFUZZ_TARGET medium
#include "fuzz_entry.h"

#include "../../examples/gtrace/media/medium_parse.c"
#include "../../examples/gtrace/media/phase.c"

/* The grid type reads its file through gtrace's scene transforms and the OpenVDB reader's process, which this
 * target does not link: it fuzzes the text of homogeneous media and phase functions, and `grid` is not registered
 * here (test_gtrace_media_grid tests the grid entries, corrupted files among them). No medium here has a grid. */
int media_register_grid(GKind medium_kind, GError *err)
{
    (void)medium_kind;
    (void)err;
    return G_OK;
}

void grid_release(Grid *g) { (void)g; }

/* 0 when the phase function is a density and samples unit directions, else a violation. */
static int phase_ok(const Phase *ph)
{
    GVec3 in = gvec3(0, 0, 1);
    for (int k = 0; k < 16; k++) {
        GVec3 out;
        double pdf = phase_sample(ph, in, (k + 0.5) / 16.0, (k * 7 % 16 + 0.5) / 16.0, &out);
        double len = gvec3_length(out), f = phase_eval(ph, in, out);
        if (!(isfinite(pdf) && pdf >= 0.0 && isfinite(f) && f >= 0.0))
            return gfuzz_violation("phase sample %d: density %g, evaluation %g", k, pdf, f);
        if (!(fabs(len - 1.0) < 1e-6))
            return gfuzz_violation("phase sample %d has length %g", k, len);
    }
    return 0;
}

static int medium_ok(const Medium *m)
{
    if (!(m->bands >= 1) || !m->phase)
        return gfuzz_violation("a medium with %d bands, phase %p", m->bands, (const void *)m->phase);
    for (int b = 0; b < m->bands; b++) {
        double a = gcolor_band_value(&m->sigma_a, b), s = gcolor_band_value(&m->sigma_s, b);
        double t = gcolor_band_value(&m->sigma_t, b);
        if (!(a >= 0.0 && s >= 0.0 && t <= MEDIUM_MAX_SIGMA && fabs(t - (a + s)) <= 1e-5 * (1.0 + t)))
            return gfuzz_violation("band %d: sigma_a %g, sigma_s %g, sigma_t %g", b, a, s, t);
    }
    return phase_ok(m->phase);
}

static int gfuzz_medium(const uint8_t *data, size_t size)
{
    if (size > gfuzz_max_input || memchr(data, '/', size))
        return 0;
    GError err;
    gerror_clear(&err);
    if (media_register_types(&err) != G_OK)
        return gfuzz_violation("registering the media types: %s", err.message);
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    GReaderOptions opt = {.model = size % 4 ? gfuzz_models[size % 4] : NULL, .no_plugins = 1,
                          .max_file_size = gfuzz_max_input > (1u << 20) ? gfuzz_max_input : 1u << 20};
    GLibrary *lib = NULL;
    int rc = greader_load_string(text, "fuzz.scene", &opt, &lib, &err), bad = 0;
    if (rc != G_OK) {
        bad = gfuzz_load_refused(rc, &err, lib, 1);
    } else if (gfuzz_must_fail(data, size)) {
        bad = gfuzz_violation("a file wrong by construction (" GFUZZ_MUST_FAIL ") loaded");
    } else {
        int n = glibrary_count(lib, gtrace_kind_medium);
        for (int i = 0; i < n && !bad; i++)
            bad = medium_ok(glibrary_entry(lib, gtrace_kind_medium, i, NULL, NULL));
        n = glibrary_count(lib, gtrace_kind_phase);
        for (int i = 0; i < n && !bad; i++)
            bad = phase_ok(glibrary_entry(lib, gtrace_kind_phase, i, NULL, NULL));
    }
    glibrary_destroy(lib);
    free(text);
    return bad;
}

#include "fuzz_target.h"
