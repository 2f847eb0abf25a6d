/* fuzz_scene_entry.h - the entry point of gtrace's scene files, shared by the libFuzzer target tests/fuzz/fuzz_scene.c
 * and the regression replay tests/test_regress.c (both link gtrace whole and Embree):
 *
 *   gfuzz_scene  the bytes loaded as a scene (greader_load_string with gtrace's kinds and types registered, then
 *                scene_from_library) in two colour models: the file's own (its `colormodel` line, rgb without one)
 *                or rgb, then spectrum (5 nm), spectrum9 or bispectral (by the input's size); a scene that loads is
 *                built (its acceleration structure) and rendered in this process with the Whitted and the path
 *                integrator, one thread, one sample per pixel.
 *
 * Promises checked: a refusal is an error with a message, a loader's refusal at FILE:LINE:COL (a refusal of the
 * whole scene, scene_from_library's, names the file); a failed load leaves no library; a loaded scene renders
 * finite pixels (a non-finite sample is black and counted) or fails with a message; every reservation against
 * the memory budget is returned when the scene is destroyed; an input the generator made wrong by construction
 * (GFUZZ_MUST_FAIL, large mode) is refused. Leaks and memory errors are the sanitizers'. GFUZZ_VERBOSE=1 in the
 * environment prints each refusal.
 *
 * Several files in one input. A line "#@file NAME" (GFUZZ_SCENE_MARK) starts a file of that name: the bytes up
 * to the next such line (or the end) are written into the private directory before the load and removed after it,
 * so that an input can include files of its own, in chains, and name meshes, IES and probe files that lie. The
 * bytes before the first such line are the scene. NAME is 1 to 48 of [A-Za-z0-9._-], not starting with '.', and
 * not a fixture's name; at most GFUZZ_SCENE_MAX_FILES files. A file whose content (or name) sends it to assimp
 * (PLY, STL, glTF: mesh_format_detect) is not written: assimp reads those in gtrace-mesh, a process of its own,
 * which tests/fuzz/run_mesh_generated.sh fuzzes; here (GENERIC_DECODE=inprocess) it would run in the fuzzer. Grid
 * media find no OpenVDB reader (GTRACE_VDB_READER names none): their files are refused, their text is fuzzed.
 *
 * Confinement. The load runs in the private directory with GReaderOptions.confine_dir set to it, the reader's own
 * rule, so no include, mesh, IES, probe or image path resolves outside it (absolute paths and '..' included:
 * they are refused at their position); plug-in statements are refused (no_plugins). Fixtures beside the input:
 * gfuzz_setup's (common.mat, tiny.BFC, tex.png, tex.hdr, grey.pfm) and tri.obj, lamp.ies and common.scene.
 *
 * Cost. The render is a GFUZZ_SCENE_CROP_W x GFUZZ_SCENE_CROP_H crop of the camera's image (its full size sets
 * the view; only the crop is allocated and traced), depth at most GFUZZ_SCENE_DEPTH, GFUZZ_SCENE_MAX_RAYS
 * secondary rays per camera sample. An input over GFUZZ_SCENE_RENDER_INPUT bytes (the generated ones of large
 * mode) is loaded in the first model only and renders one pixel with the Whitted integrator only; a scene whose
 * lights take more than GFUZZ_SCENE_MAX_LIGHT_SAMPLES shadow samples per shading point is loaded and built but not
 * rendered. The memory budget of the process is GFUZZ_SCENE_BUDGET over what is reserved at set-up (the texture
 * system's cache): the camera's full framebuffer is reserved and allocated once (never touched), so that an image
 * size over the budget must be refused by it, cleanly, as gtrace refuses it. */
#ifndef GENERIC_TESTS_FUZZ_SCENE_ENTRY_H
#define GENERIC_TESTS_FUZZ_SCENE_ENTRY_H

#include "fuzz_entry.h"

#include "film/framebuffer.h"
#include "geometry/mesh_format.h"
#include "render/render.h"
#include "scene/accel.h"
#include "scenefile/parse.h"

#define GFUZZ_SCENE_MARK "#@file "
#define GFUZZ_SCENE_MAX_FILES 100
#define GFUZZ_SCENE_CROP_W 4
#define GFUZZ_SCENE_CROP_H 3
#define GFUZZ_SCENE_DEPTH 3
#define GFUZZ_SCENE_MAX_RAYS 16
#define GFUZZ_SCENE_MAX_LIGHT_SAMPLES 512
#define GFUZZ_SCENE_RENDER_INPUT (64u * 1024u)
#define GFUZZ_SCENE_BUDGET ((size_t)256 << 20)

static const char gfuzz_scene_obj[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
                                      "f 1/1/1 2/2/1 3/3/1\nf 2 4 3\n";
static const char gfuzz_scene_ies[] = "IESNA:LM-63-2002\n[TEST] fixture\nTILT=NONE\n1 1000 1 3 1 1 2 0.1 0.1 0\n"
                                      "1 1 50\n0 45 90\n0\n100 80 10\n";
static const char gfuzz_scene_common[] = "include \"common.mat\"\n"
                                         "object ball sphere { center <0, 0, 0> radius 1 material base }\n"
                                         "light key point { position <2, 3, 4> intensity rgb 20 20 20 }\n"
                                         "camera pinhole { from <0, 0, 5> at <0, 0, 0> width 8 height 6 }\n";
static const char *const gfuzz_scene_fixtures[] = {"tri.obj", "lamp.ies", "common.scene", "tiny.BFC", "common.mat",
                                                    "tex.png", "tex.hdr", "grey.pfm", NULL};
static char gfuzz_scene_dir[sizeof gfuzz_dir]; /* the private directory the fixtures were written to */

/* gfuzz_setup, then the scene fixtures (gfuzz_cleanup removes them), gtrace's types and the memory budget; 0 on
 * success. */
static int gfuzz_scene_setup(void)
{
    if (gfuzz_dir[0] && strcmp(gfuzz_scene_dir, gfuzz_dir) == 0)
        return 0;
    if (gfuzz_setup() != 0)
        return -1;
    GError err;
    if (gtrace_register_types(&err) != G_OK) {
        fprintf(stderr, "gfuzz_scene_setup: %s\n", err.message);
        return -1;
    }
    char path[4200];
    if (gfuzz_write("tri.obj", gfuzz_scene_obj, sizeof gfuzz_scene_obj - 1, path, sizeof path) ||
        gfuzz_write("lamp.ies", gfuzz_scene_ies, sizeof gfuzz_scene_ies - 1, path, sizeof path) ||
        gfuzz_write("common.scene", gfuzz_scene_common, sizeof gfuzz_scene_common - 1, path, sizeof path))
        return -1;
    gmem_budget_set_limit(gmem_budget_used() + GFUZZ_SCENE_BUDGET); /* over what is kept (the texture cache) */
    /* grid media: no OpenVDB reader process, wherever the build put one (a refusal at the grid's file) */
    snprintf(path, sizeof path, "%s/no-vdb-reader", gfuzz_dir);
    setenv("GTRACE_VDB_READER", path, 1);
    snprintf(gfuzz_scene_dir, sizeof gfuzz_scene_dir, "%s", gfuzz_dir);
    return 0;
}

/* 1 when name may be written as an input's file. */
static int gfuzz_scene_name_ok(const char *name, size_t len)
{
    if (len < 1 || len > 48 || name[0] == '.')
        return 0;
    for (size_t i = 0; i < len; i++)
        if (!((name[i] >= 'a' && name[i] <= 'z') || (name[i] >= 'A' && name[i] <= 'Z') ||
              (name[i] >= '0' && name[i] <= '9') || name[i] == '.' || name[i] == '_' || name[i] == '-'))
            return 0;
    for (int i = 0; gfuzz_scene_fixtures[i]; i++)
        if (strlen(gfuzz_scene_fixtures[i]) == len && memcmp(gfuzz_scene_fixtures[i], name, len) == 0)
            return 0;
    return 1;
}

/* Cuts text (NUL-terminated, size bytes) at its "#@file NAME" lines: writes each file into the private directory,
 * records its name in names (nfiles of them), and ends the scene's text at the first mark. */
static void gfuzz_scene_files(char *text, size_t size, char names[][64], int *nfiles)
{
    *nfiles = 0;
    const size_t mark = sizeof GFUZZ_SCENE_MARK - 1;
    char *p = text, *end = text + size, *scene_end = NULL;
    while (p < end) {
        char *line = p;
        char *nl = memchr(p, '\n', (size_t)(end - p));
        p = nl ? nl + 1 : end;
        if ((size_t)(end - line) < mark || memcmp(line, GFUZZ_SCENE_MARK, mark) != 0)
            continue;
        if (!scene_end)
            scene_end = line;
        /* this file's bytes: up to the next mark at the start of a line */
        char *body = p, *q = p;
        while (q < end && !((size_t)(end - q) >= mark && memcmp(q, GFUZZ_SCENE_MARK, mark) == 0)) {
            char *n2 = memchr(q, '\n', (size_t)(end - q));
            q = n2 ? n2 + 1 : end;
        }
        p = q;
        char *name = line + mark;
        size_t len = (size_t)((nl ? nl : end) - name);
        while (len && (name[len - 1] == '\r' || name[len - 1] == ' '))
            len--;
        size_t blen = (size_t)(q - body);
        if (*nfiles >= GFUZZ_SCENE_MAX_FILES || !gfuzz_scene_name_ok(name, len) || memchr(body, '\0', blen))
            continue;
        char fname[64], what[64], path[4200];
        memcpy(fname, name, len);
        fname[len] = '\0';
        MeshFormat f = mesh_format_detect((const unsigned char *)body, blen < 512 ? blen : 512, blen, fname, what,
                                          sizeof what);
        if (f == MESH_FORMAT_PLY || f == MESH_FORMAT_STL || f == MESH_FORMAT_GLTF)
            continue;
        if (gfuzz_write(fname, body, blen, path, sizeof path) == 0)
            memcpy(names[(*nfiles)++], fname, len + 1);
        else
            unlink(path);
    }
    if (scene_end)
        *scene_end = '\0';
}

/* Whether a refusal of the whole scene names it: "fuzz.scene: ..." or a position in some file. */
static int gfuzz_scene_named(const char *message)
{
    return strncmp(message, "fuzz.scene: ", 12) == 0 || gfuzz_has_position(message);
}

/* The shadow samples per shading point of the scene's lights. */
static long gfuzz_scene_light_samples(const Scene *s)
{
    long n = 0;
    for (int i = 0; i < s->nlights; i++)
        n += s->lights[i]->samples > 1 ? s->lights[i]->samples : 1;
    return n;
}

/* Renders a crop of the scene with one integrator and checks its pixels; 0, or a violation. */
static int gfuzz_scene_render(Scene *s, int integrator, int pixels_w, int pixels_h, const char *model)
{
    const Camera *cam = &s->camera;
    int w = cam->width, h = cam->height;
    int cw = pixels_w < w ? pixels_w : w, ch = pixels_h < h ? pixels_h : h;
    int x0 = (w - cw) / 2, y0 = (h - ch) / 2;
    RenderSettings rs = {.width = w, .height = h, .spp = 1, .depth = cam->depth < GFUZZ_SCENE_DEPTH ? cam->depth :
                         GFUZZ_SCENE_DEPTH, .threads = 1, .quiet = 1, .cutoff = cam->cutoff, .bands = cam->bands,
                         .max_rays = GFUZZ_SCENE_MAX_RAYS, .integrator = integrator,
                         .crop = {x0, y0, x0 + cw, y0 + ch}};
    Framebuffer fb = {0};
    RenderStats st = {0};
    GError err;
    gerror_clear(&err);
    int rc = render_image(s, &rs, &fb, &st, &err), bad = 0;
    char what[96];
    snprintf(what, sizeof what, "render_image (%s, %s)", integrator == RENDER_PATH ? "path" : "whitted", model);
    if (rc != G_OK) {
        bad = gfuzz_error_ok(rc, &err, what);
    } else if (!fb.pixels || fb.width != cw || fb.height != ch) {
        bad = gfuzz_violation("%s: a %dx%d framebuffer for a %dx%d crop", what, fb.width, fb.height, cw, ch);
    } else {
        for (size_t i = 0; i < (size_t)cw * (size_t)ch * 3 && !bad; i++)
            if (!isfinite(fb.pixels[i]))
                bad = gfuzz_violation("%s: pixel value %zu is %g", what, i, fb.pixels[i]);
    }
    if (getenv("GFUZZ_VERBOSE"))
        fprintf(stderr, "gfuzz_scene: %s: %s, %d objects, %d lights, %llu rays\n", what,
                rc == G_OK ? "rendered" : err.message, s->nobjects, s->nlights, (unsigned long long)st.rays);
    framebuffer_free(&fb);
    return bad;
}

/* The camera's full framebuffer, reserved and allocated (pages never touched) and freed: within the budget it is
 * made, over it refused with a message. */
static int gfuzz_scene_full_image(const Scene *s)
{
    Framebuffer fb = {.width = s->camera.width, .height = s->camera.height};
    GError err;
    gerror_clear(&err);
    int rc = framebuffer_alloc(&fb, &err), bad = 0;
    if (rc != G_OK)
        bad = gfuzz_error_ok(rc, &err, "the camera's framebuffer");
    else if (!fb.pixels)
        bad = gfuzz_violation("a %dx%d framebuffer without pixels", fb.width, fb.height);
    framebuffer_free(&fb);
    return bad;
}

/* One load of text in one model (NULL: the file's own), then the scene built and rendered. */
static int gfuzz_scene_once(const char *text, const GColorModel *model, int large_input, int must_fail)
{
    size_t budget_before = gmem_budget_used();
    GReaderOptions opt = {.model = model, .no_plugins = 1, .confine_dir = gfuzz_dir,
                          .max_file_size = gfuzz_max_input > (1u << 20) ? gfuzz_max_input : 1u << 20};
    GLibrary *lib = (GLibrary *)&opt; /* must be set to NULL on failure */
    GError err;
    gerror_clear(&err);
    int rc = greader_load_string(text, "fuzz.scene", &opt, &lib, &err), bad = 0;
    if (rc != G_OK && getenv("GFUZZ_VERBOSE"))
        fprintf(stderr, "gfuzz_scene: %s\n", err.message);
    if (rc != G_OK)
        return gfuzz_load_refused(rc, &err, lib, 0);
    const char *mname = gcolormodel_name(glibrary_colormodel(lib));
    Scene *s = NULL;
    gerror_clear(&err);
    rc = scene_from_library(lib, "fuzz.scene", &s, &err); /* the scene owns lib, also on failure */
    if (rc != G_OK && getenv("GFUZZ_VERBOSE"))
        fprintf(stderr, "gfuzz_scene: %s\n", err.message);
    if (rc != G_OK) {
        bad = gfuzz_error_ok(rc, &err, "scene_from_library");
        if (!bad && s)
            bad = gfuzz_violation("a failed scene_from_library returned a scene");
        if (!bad && !gfuzz_scene_named(err.message))
            bad = gfuzz_violation("scene_from_library's message names neither the file nor a position: %s",
                                  err.message);
    } else if (must_fail) {
        bad = gfuzz_violation("a scene wrong by construction (" GFUZZ_MUST_FAIL ") loaded");
    } else {
        s->accel_threads = 1;
        int lit = gfuzz_scene_light_samples(s) <= GFUZZ_SCENE_MAX_LIGHT_SAMPLES;
        bad = gfuzz_scene_full_image(s);
        gerror_clear(&err);
        rc = bad ? G_OK : accel_build_for(s, (double)GFUZZ_SCENE_CROP_W * GFUZZ_SCENE_CROP_H, &err);
        if (rc != G_OK)
            bad = gfuzz_error_ok(rc, &err, "accel_build_for");
        else if (!bad && lit && large_input)
            bad = gfuzz_scene_render(s, RENDER_WHITTED, 1, 1, mname);
        else if (!bad && lit)
            bad = gfuzz_scene_render(s, RENDER_WHITTED, GFUZZ_SCENE_CROP_W, GFUZZ_SCENE_CROP_H, mname) ||
                  gfuzz_scene_render(s, RENDER_PATH, GFUZZ_SCENE_CROP_W, GFUZZ_SCENE_CROP_H, mname);
    }
    scene_destroy(s);
    if (!bad && gmem_budget_used() != budget_before)
        bad = gfuzz_violation("the memory budget kept %zd bytes after the scene was destroyed (%s)",
                              (ssize_t)(gmem_budget_used() - budget_before), mname);
    return bad;
}

/** The bytes as a gtrace scene (with its files), loaded, built and rendered in two colour models. */
GFUZZ_FN int gfuzz_scene(const uint8_t *data, size_t size)
{
    if (size > gfuzz_max_input)
        return 0;
    if (gfuzz_scene_setup() != 0)
        return gfuzz_violation("cannot set up the scene fixtures");
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    int here = gfuzz_enter();
    if (here < 0) {
        free(text);
        return gfuzz_violation("cannot enter %s", gfuzz_dir);
    }
    static char names[GFUZZ_SCENE_MAX_FILES][64];
    int nfiles = 0;
    gfuzz_scene_files(text, size, names, &nfiles);
    int must_fail = gfuzz_must_fail(data, size), large_input = size > GFUZZ_SCENE_RENDER_INPUT;
    const GColorModel *first = size % 2 ? gfuzz_models[0] : NULL, *second = gfuzz_models[1 + size % 3];
    int bad = gfuzz_scene_once(text, first, large_input, must_fail);
    if (!bad && !large_input)
        bad = gfuzz_scene_once(text, second, large_input, must_fail);
    for (int i = 0; i < nfiles; i++)
        unlink(names[i]);
    if (fchdir(here) != 0 && !bad)
        bad = gfuzz_violation("cannot return to the working directory");
    close(here);
    free(text);
    return bad;
}

#endif
