/* output.c - writes the framebuffer through the library's image shim (generic/services/image.h), which picks the
 * encoding by extension and writes a temporary file that is renamed only when complete. Float formats
 * (.exr, .hdr, .pfm) get the linear values as rendered; 8-bit formats get the exposure, then the shim's
 * display encoding with clamping. A crop is written as the region it is: in OpenEXR, the data window inside the
 * full image's display window. */
#include "output.h"

#include <generic/services/image.h>

#include <string.h>
#include <strings.h>

static int is_float_format(const char *path)
{
    const char *dot = strrchr(path, '.');
    const char *slash = strrchr(path, '/');
    if (!dot || (slash && dot < slash))
        return 0;
    return strcasecmp(dot, ".exr") == 0 || strcasecmp(dot, ".hdr") == 0 || strcasecmp(dot, ".pfm") == 0;
}

int output_is_float(const char *path)
{
    return is_float_format(path);
}

int output_is_exr(const char *path)
{
    const char *dot = strrchr(path, '.');
    const char *slash = strrchr(path, '/');
    return dot && (!slash || dot > slash) && strcasecmp(dot, ".exr") == 0;
}

int output_check(const char *path, GError *err)
{
    return gimage_check_output(path, err);
}

int output_write(const char *path, const Framebuffer *fb, double exposure, const GImageDisplay *display, GError *err)
{
    return output_write_piece(path, fb, exposure, display, NULL, err);
}

int output_write_piece(const char *path, const Framebuffer *fb, double exposure, const GImageDisplay *display,
                       const char *note, GError *err)
{
    GImage img = {.width = fb->width, .height = fb->height, .channels = 3, .pixels = fb->pixels};
    GImageWriteOptions opt = {.exposure = is_float_format(path) ? 0.0 : exposure, .display = display};
    if (fb->full_width > 0 && (fb->width != fb->full_width || fb->height != fb->full_height)) { /* a crop */
        opt.x = fb->x;
        opt.y = fb->y;
        opt.full_width = fb->full_width;
        opt.full_height = fb->full_height;
        opt.note = note;
    }
    GImageSpectra waves = {.count = fb->nwaves, .wavelengths = fb->wavelengths, .values = fb->waves};
    if (fb->waves)
        opt.spectra = &waves;
    return gimage_write(path, &img, &opt, err);
}
