/* image_node_fixture.h - what the image node's tests share: a temporary directory for their image files, an rgb
 * model, a scratch arena, a texture system, a white lambert for image nodes to sit on and a colour for results;
 * the node over that lambert. Included by one test file each (static functions). */
#ifndef GENERIC_TESTS_IMAGE_NODE_FIXTURE_H
#define GENERIC_TESTS_IMAGE_NODE_FIXTURE_H

#include <generic/materials.h>
#include <generic/services/texsys.h>

#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

typedef struct ImageNodeFix {
    char dir[64];
    GColorModel *rgb;
    GScratch *scratch;
    GTextureSystem *ts;
    GMaterial *white;
    GColor c;
} ImageNodeFix;

/* Makes the directory from the mkdtemp template tmpl (e.g. "/tmp/gtexXXXXXX") and the rest; 0 on success. */
static int image_node_fix_open(ImageNodeFix *f, const char *tmpl)
{
    GError err;
    snprintf(f->dir, sizeof f->dir, "%s", tmpl);
    if (!mkdtemp(f->dir) || gcolormodel_create("rgb", NULL, &f->rgb, &err) || gtexsys_create(&f->ts, &err))
        return -1;
    f->scratch = gscratch_create(0);
    GColor one;
    if (!f->scratch || gcolor_alloc(&one, f->rgb) != G_OK)
        return -1;
    int rc = gcolor_from_rgb(&one, (double[3]){1, 1, 1}, GCOLOR_REFLECTANCE);
    if (rc == G_OK)
        rc = glambert_create(f->rgb, &one, &f->white, &err);
    gcolor_free(&one);
    return rc == G_OK && gcolor_alloc(&f->c, f->rgb) == G_OK ? 0 : -1;
}

/* Removes the n files and the directory, and releases the rest. */
static void image_node_fix_close(ImageNodeFix *f, const char *const *files, size_t n)
{
    for (size_t i = 0; i < n; i++)
        unlink(files[i]);
    rmdir(f->dir);
    gmaterial_unref(f->white);
    gtexsys_unref(f->ts);
    gcolor_free(&f->c);
    gscratch_destroy(f->scratch);
    gcolormodel_destroy(f->rgb);
}

/* An image node of path over the white lambert, in the fixture's texture system (the test fails if it cannot be
 * made). */
static GMaterial *image_node(ImageNodeFix *f, const char *path, GTexWrap wrap, GTexColorSpace cs)
{
    GImageNodeOptions o = {.texsys = f->ts, .swrap = wrap, .twrap = wrap, .colorspace = cs};
    GMaterial *m;
    GError err;
    int rc = gnode_image_create(f->white, path, &o, &m, &err);
    if (rc != G_OK)
        print_error("%s\n", err.message);
    assert_int_equal(rc, G_OK);
    return m;
}

#endif
