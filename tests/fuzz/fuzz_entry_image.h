/* fuzz_entry_image.h - the image and light-probe entry points of fuzz_entry.h (gfuzz_image, gfuzz_probe): the bytes
 * written as an image file of the format their magic number names, read with gimage_read, through the image node and
 * as a probe. Included once, by fuzz_entry.h, after its helpers. */
#ifndef GENERIC_TESTS_FUZZ_ENTRY_IMAGE_H
#define GENERIC_TESTS_FUZZ_ENTRY_IMAGE_H

/* An extension OpenImageIO recognises for the bytes (by their magic number). */
static const char *gfuzz_image_ext(const uint8_t *d, size_t n)
{
    if (n >= 4 && !memcmp(d, "\x89PNG", 4))
        return ".png";
    if (n >= 2 && d[0] == 'P' && (d[1] == 'F' || d[1] == 'f'))
        return ".pfm";
    if (n >= 2 && d[0] == 'P' && d[1] >= '1' && d[1] <= '6')
        return ".ppm";
    if (n >= 2 && d[0] == '#' && d[1] == '?')
        return ".hdr";
    if (n >= 2 && d[0] == 'B' && d[1] == 'M')
        return ".bmp";
    if (n >= 4 && (!memcmp(d, "II*\0", 4) || !memcmp(d, "MM\0*", 4)))
        return ".tif";
    if (n >= 2 && d[0] == 0xff && d[1] == 0xd8)
        return ".jpg";
    if (n >= 4 && !memcmp(d, "\x76\x2f\x31\x01", 4))
        return ".exr";
    return ".tga";
}

/* Writes the bytes as private/input-N.EXT (name: its last path component): 0 to go on, 1 to skip the input (it
 * cannot be written, or its header claims more than gfuzz_max_pixels), -1 when gimage_info accepts a header
 * with a size below 1. The caller removes the file. */
static int gfuzz_image_file(const uint8_t *data, size_t size, const char *ext, char *path, size_t pathsize,
                            char *name, size_t namesize)
{
    snprintf(name, namesize, "input-%lu%s", ++gfuzz_serial, ext);
    if (gfuzz_write(name, data, size, path, pathsize) != 0) {
        unlink(path);
        return 1;
    }
    int w = 0, h = 0, ch = 0;
    GError err;
    int rc = gimage_info(path, &w, &h, &ch, &err);
    if (rc == G_OK && (w <= 0 || h <= 0 || ch < 1))
        return gfuzz_violation("gimage_info accepted a size of %dx%d with %d channels", w, h, ch);
    if (rc == G_OK && gfuzz_max_pixels >= 0 && (long)w * h > gfuzz_max_pixels)
        return 1;
    return 0;
}

static int gfuzz_pixels_ok(const float *p, size_t n, int nonneg, const char *what)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(p[i]) || (nonneg && p[i] < 0.0f))
            return gfuzz_violation("%s: value %zu is %g", what, i, p[i]);
    return 0;
}

/** The bytes as a light probe file (.pfm or .hdr by magic), loaded and approximated by lights. */
GFUZZ_FN int gfuzz_probe(const uint8_t *data, size_t size)
{
    if (size > gfuzz_max_input)
        return 0;
    const char *ext = size >= 2 && data[0] == 'P' ? ".pfm" : ".hdr";
    char path[4200], name[64];
    int skip = gfuzz_image_file(data, size, ext, path, sizeof path, name, sizeof name);
    if (skip) {
        unlink(path);
        return skip < 0 ? -1 : 0;
    }
    GProbeFormat format = size % 3 == 0 ? GPROBE_AUTO : size % 3 == 1 ? GPROBE_LATLONG : GPROBE_ANGULAR;
    GProbe *p = NULL;
    GError err;
    gerror_clear(&err);
    int rc = gprobe_load(path, format, format == GPROBE_ANGULAR ? 4 : 0, &p, &err);
    unlink(path);
    if (rc != G_OK)
        return gfuzz_error_ok(rc, &err, "gprobe_load") || (p ? gfuzz_violation("a failed load gave a probe") : 0);
    int bad = 0;
    int w = gprobe_width(p), h = gprobe_height(p);
    if (w != 2 * h || h < 2)
        bad = gfuzz_violation("probe of %dx%d", w, h);
    if (!bad)
        bad = gfuzz_pixels_ok(gprobe_pixels(p), (size_t)w * h * 3, 1, "probe pixels");
    /* pixels above GPROBE_MAX_RADIANCE are clamped, so the weights and the lights are always finite */
    for (size_t i = 0; !bad && i < (size_t)w * h * 3; i++)
        if (gprobe_pixels(p)[i] > GPROBE_MAX_RADIANCE)
            bad = gfuzz_violation("pixel %zu is %g, above GPROBE_MAX_RADIANCE", i, gprobe_pixels(p)[i]);
    if (!bad)
        bad = gfuzz_pixels_ok(gprobe_weights(p), (size_t)w * h * 3, 1, "probe weights");
    if (!bad && gprobe_clamped_count(p) < 0)
        bad = gfuzz_violation("negative clamped count");
    GProbeLight lights[8];
    GProbeOptions po = {.max_iterations = 4};
    static const struct {
        GProbeTechnique t;
        int n;
    } runs[] = {{GPROBE_MEDIANCUT, 4}, {GPROBE_ADAPTIVE, 3}, {GPROBE_KMEANS, 3}};
    for (int r = 0; r < 3 && !bad; r++) {
        gerror_clear(&err);
        rc = gprobe_approximate(p, runs[r].t, runs[r].n, &po, lights, &err);
        if (rc != G_OK) {
            bad = gfuzz_error_ok(rc, &err, gprobe_technique_name(runs[r].t));
            continue;
        }
        for (int i = 0; i < runs[r].n && !bad; i++) {
            if (gfuzz_vec_ok(lights[i].dir, "light direction") || !isfinite(lights[i].rgb[0]) ||
                !isfinite(lights[i].rgb[1]) || !isfinite(lights[i].rgb[2]) || lights[i].rgb[0] < 0 ||
                lights[i].rgb[1] < 0 || lights[i].rgb[2] < 0)
                bad = gfuzz_violation("%s light %d: dir %g %g %g rgb %g %g %g", gprobe_technique_name(runs[r].t), i,
                                      lights[i].dir.x, lights[i].dir.y, lights[i].dir.z, lights[i].rgb[0],
                                      lights[i].rgb[1], lights[i].rgb[2]);
        }
    }
    GVec3 normals[6];
    double E[18];
    gprobe_fibonacci(6, normals);
    if (!bad && gprobe_irradiance(p, normals, 6, E, &err) == G_OK)
        for (int i = 0; i < 18 && !bad; i++)
            if (!isfinite(E[i]) || E[i] < 0)
                bad = gfuzz_violation("irradiance %d is %g", i, E[i]);
    gprobe_destroy(p);
    return bad;
}

/** The bytes as an image file: gimage_read with flags from the size, and the image node evaluated. */
GFUZZ_FN int gfuzz_image(const uint8_t *data, size_t size)
{
    if (size > gfuzz_max_input)
        return 0;
    const char *ext = gfuzz_image_ext(data, size);
    char path[4200], name[64];
    int skip = gfuzz_image_file(data, size, ext, path, sizeof path, name, sizeof name);
    if (skip) {
        unlink(path);
        return skip < 0 ? -1 : 0;
    }
    static const unsigned flags[4] = {0, GIMAGE_READ_RAW, GIMAGE_READ_RGB, GIMAGE_READ_RGBA | GIMAGE_READ_RAW};
    GImage img;
    GError err;
    gerror_clear(&err);
    int rc = gimage_read(path, flags[size % 4], &img, &err);
    int bad = 0;
    if (rc != G_OK) {
        bad = gfuzz_error_ok(rc, &err, "gimage_read");
        if (!bad && (img.pixels || img.width || img.height))
            bad = gfuzz_violation("a failed read left an image behind");
    } else {
        if (img.width <= 0 || img.height <= 0 || (img.channels != 3 && img.channels != 4) || !img.pixels ||
            (flags[size % 4] & GIMAGE_READ_RGB && img.channels != 3) ||
            (flags[size % 4] & GIMAGE_READ_RGBA && img.channels != 4))
            bad = gfuzz_violation("gimage_read gave %dx%d with %d channels", img.width, img.height, img.channels);
        gimage_free(&img);
    }
    /* the image node (OpenImageIO's texture system) over the same file, in the rgb model */
    char text[256];
    snprintf(text, sizeof text,
             "node n image { child lambert { reflectance rgb 0.8 0.8 0.8 } file \"%s\" wrap %s }\n", name,
             size % 2 ? "clamp" : "periodic");
    GReaderOptions opt = {.model = gfuzz_models[0], .no_plugins = 1};
    /* every file, also one whose header states a size below 1 (the image node must refuse it, not abort):
     * the node's colours are finite (NaN and infinite texels become 0) */
    int here = bad ? -1 : gfuzz_enter();
    if (here >= 0) {
        GLibrary *lib = NULL;
        gerror_clear(&err);
        rc = greader_load_string(text, "fuzz.mat", &opt, &lib, &err);
        if (rc != G_OK)
            bad = gfuzz_error_ok(rc, &err, "image node");
        else
            bad = gfuzz_eval_material(glibrary_material(lib, "n"), "image node");
        glibrary_destroy(lib);
        if (fchdir(here) != 0 && !bad)
            bad = gfuzz_violation("cannot return to the working directory");
    }
    if (here >= 0)
        close(here);
    unlink(path);
    return bad;
}

#endif
