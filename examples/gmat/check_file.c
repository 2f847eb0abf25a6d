/* check_file.c - `gmat check` of a file's material as a function: the file read, the context inspect() of main.c
 * sets up, gmat_check. */
#include "check_file.h"
#include "gmat.h"

#include <generic/builtins.h>

#include <stdio.h>

int gmat_check_file(const char *file, const char *material, const char *colormodel, int samples, int allow_plugins,
                    GError *err)
{
    if (!file || !material)
        return gerror_set(err, G_ERR_INVALID, "gmat_check_file: no file or material given");
    int rc = generic_register_builtins(err);
    if (rc != G_OK)
        return rc;
    GReaderOptions opt = {.colormodel = colormodel, .allow_plugins = allow_plugins};
    GLibrary *lib;
    if ((rc = greader_load_file(file, &opt, &lib, err)) != G_OK)
        return rc;
    GmatContext ctx = {.lib = lib, .model = glibrary_colormodel(lib), .material_name = material,
                       .material = glibrary_material(lib, material)};
    const double one[3] = {1.0, 1.0, 1.0};
    if (!ctx.material)
        rc = gerror_set(err, G_ERR_NOTFOUND, "%s defines no material named '%s'", file, material);
    else if (!(ctx.scratch = gscratch_create(0)) || gcolor_alloc(&ctx.white, ctx.model) != G_OK ||
             gcolor_alloc(&ctx.result, ctx.model) != G_OK || gcolor_from_rgb(&ctx.white, one, GCOLOR_LIGHT) != G_OK)
        rc = gerror_set(err, G_ERR_NOMEM, "gmat check: out of memory");
    else
        rc = gmat_check(&ctx, samples);
    fflush(stdout);
    gcolor_free(&ctx.white);
    gcolor_free(&ctx.result);
    gscratch_destroy(ctx.scratch);
    glibrary_destroy(lib);
    return rc;
}
