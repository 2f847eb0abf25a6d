/* grid_parse.c - the medium type grid:
 *
 *   medium NAME? grid { file "x.vdb" grid density sigma_a COLOUR sigma_s COLOUR phase PHASE scale S
 *                       transform { ... } }
 *
 * The coefficients are per unit of the grid's density (a float grid of an OpenVDB file, read by grid_load.c in a
 * process of its own), placed in the world by the file's transform followed by the entry's. The density is read
 * when the entry is, and every refusal of the file is reported at the file's name in the scene file. */
#include "grid_load.h"
#include "medium.h"
#include "scenefile/parse.h"

#include <generic/memory.h>
#include <generic/reader.h>

#include <string.h>

/* The largest band value of sigma_t. */
static double largest_band(const GColor *c)
{
    double top = 0.0;
    for (int b = 0; b < gcolormodel_band_count(c->model); b++) {
        double v = gcolor_band_value(c, b);
        top = v > top ? v : top;
    }
    return top;
}

static int parse_grid(GReader *r, const void *vtable, void **object, GError *err)
{
    (void)vtable;
    Medium *m = gmem_calloc(1, sizeof *m);
    Grid *g = gmem_calloc(1, sizeof *g);
    if (!m || !g) {
        gmem_free(m);
        gmem_free(g);
        return greader_error(r, err, "out of memory");
    }
    m->phase = phase_isotropic();
    double scale = 1.0;
    char *file = NULL, grid_name[128] = "density";
    int file_line = 0, file_col = 0, rc = G_OK;
    Xform place;
    xform_identity(&place);
    const char *key;
    while ((rc = greader_param(r, &key, err)) > 0) {
        if (strcmp(key, "file") == 0) {
            GToken t;
            gmem_free(file);
            file = NULL;
            if ((rc = greader_peek(r, &t, err)) == G_OK && (rc = greader_path(r, &file, err)) == G_OK) {
                file_line = t.line;
                file_col = t.col;
            }
        } else if (strcmp(key, "grid") == 0) {
            GToken t;
            char *name = NULL;
            if ((rc = greader_peek(r, &t, err)) == G_OK && t.type == GTOK_STRING)
                rc = greader_string(r, &name, err);
            else if (rc == G_OK)
                rc = greader_ident(r, grid_name, sizeof grid_name, err);
            if (rc == G_OK && name) {
                if (!*name || strlen(name) >= sizeof grid_name)
                    rc = greader_error_at(r, err, G_ERR_INVALID, t.line, t.col, "grid: a grid name has 1 to %zu "
                                          "characters", sizeof grid_name - 1);
                else
                    strcpy(grid_name, name);
            }
            gmem_free(name);
        } else if (strcmp(key, "transform") == 0) {
            rc = scene_parse_transform(r, &place, err);
        } else if ((rc = medium_read_param(r, "grid", key, m, &scale, err)) == 0) {
            rc = greader_unknown_param(r, "file, grid, sigma_a, sigma_s, phase, scale, transform", err);
        }
        if (rc < 0)
            break;
    }
    if (rc == G_OK && !file)
        rc = greader_error(r, err, "grid: a grid medium needs its OpenVDB file (file \"NAME.vdb\")");
    if (rc == G_OK)
        rc = medium_complete(r, "grid", m, scale, err);
    if (rc == G_OK && (rc = grid_load(file, grid_name, g, err)) != G_OK) {
        char why[sizeof err->message];
        strcpy(why, err ? err->message : "");
        rc = greader_error_at(r, err, rc, file_line, file_col, "grid: %s", why);
    }
    if (rc == G_OK) {
        Xform inner = g->place;
        xform_compose(&place, &inner, &g->place);
        m->sigma_t_max = largest_band(&m->sigma_t);
        double top = m->sigma_t_max * g->max_density;
        if (!(top <= MEDIUM_MAX_SIGMA))
            rc = greader_error_at(r, err, G_ERR_INVALID, file_line, file_col, "grid: its largest density %g times "
                                  "sigma_t %g is %g, beyond the largest extinction accepted (%g)", g->max_density,
                                  m->sigma_t_max, top, MEDIUM_MAX_SIGMA);
    }
    gmem_free(file);
    m->grid = g;
    if (rc < 0) {
        medium_free(m);
        return rc;
    }
    *object = m;
    return G_OK;
}

static void destroy_grid(void *p) { medium_free(p); }

static const GParamInfo grid_params[] = {
    {"file", GPARAM_NAMED, "path", NULL, "an OpenVDB file",
     "the file holding the density grid (read in a separate process, bounded by the memory budget)"},
    {"grid", GPARAM_NAMED, "string", "density", "a float grid of the file (a name or a quoted string)",
     "the grid of the file to read"},
    {"sigma_a", GPARAM_NAMED, "color", "0", ">= 0 per band",
     "the absorption coefficient per unit density per scene unit"},
    {"sigma_s", GPARAM_NAMED, "color", "0", ">= 0 per band",
     "the scattering coefficient per unit density per scene unit"},
    {"phase", GPARAM_NAMED, "phase", "isotropic", "a phase entry: isotropic, hg { g G }",
     "the distribution of scattered directions"},
    {"scale", GPARAM_NAMED, "number", "1", "[0, 1e9]", "multiplies both coefficients"},
    {"transform", GPARAM_NAMED, "block", "none",
     "{ translate <x, y, z>  rotate <ax, ay, az>  rotate_axis <axis> DEG  scale S | <x, y, z> ... }",
     "places the grid after the file's own transform of its index space: the steps in the order written"},
    {NULL},
};

int media_register_grid(GKind medium_kind, GError *err)
{
    if (gregistry_find(medium_kind, "grid"))
        return G_OK;
    static const int grid_tag = 0;
    GTypeInfo t = {.kind = medium_kind, .name = "grid", .vtable = &grid_tag, .parse = parse_grid,
                   .summary = "heterogeneous participating medium: the density of an OpenVDB grid times absorption "
                              "and scattering coefficients, a phase function",
                   .destroy = destroy_grid, .params = grid_params};
    return gregistry_add(&t, err);
}
