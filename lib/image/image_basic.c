/* image_basic.c - the parts of image.h that need no codec: sRGB transfer functions, allocation, the memory
 * budget's old names; and the sanitizer defaults for OpenImageIO's own defects (they must be in the program, not in the
 * module that is loaded later). */
#include "generic/services/image.h"
#include "generic/memory.h"

#include <math.h>

double gimage_srgb_encode(double v)
{
    return v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1.0 / 2.4) - 0.055;
}

double gimage_srgb_decode(double v)
{
    return v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4);
}

int gimage_create(GImage *img, int width, int height, int channels, GError *err)
{
    if (!img)
        return gerror_set(err, G_ERR_INVALID, "no image given");
    img->width = img->height = img->channels = 0;
    img->pixels = NULL;
    if (width <= 0 || height <= 0 || channels < 1 || channels > 4 || (long long)width * height > (1LL << 31) / 4)
        return gerror_set(err, G_ERR_INVALID, "invalid image size %dx%d with %d channels", width, height, channels);
    img->pixels = gmem_calloc((size_t)width * height * channels, sizeof(float));
    if (!img->pixels)
        return gerror_set(err, G_ERR_NOMEM, "out of memory for a %dx%d image", width, height);
    img->width = width;
    img->height = height;
    img->channels = channels;
    return G_OK;
}

void gimage_free(GImage *img)
{
    if (!img)
        return;
    gmem_free(img->pixels);
    img->pixels = NULL;
    img->width = img->height = img->channels = 0;
}

void gimage_spectra_free(GImageSpectraBuf *s)
{
    if (!s)
        return;
    gmem_free(s->wavelengths);
    gmem_free(s->values);
    gmem_budget_release(s->charged);
    *s = (GImageSpectraBuf){0};
}

/* ---- the memory budget: the process-wide one of generic/memory.h ---- */

size_t gimage_memory_budget(void) { return gmem_budget_limit(); }

void gimage_set_memory_budget(size_t bytes) { gmem_budget_set_limit(bytes); }

#if defined(__SANITIZE_ADDRESS__)
/* OpenImageIO 2.4's TextureSystem::destroy deletes its implementation through the base class with a sized
 * delete of the wrong size: a mismatch inside that library, harmless with the C library's allocator, which
 * AddressSanitizer would otherwise report (and abort on) in every program that frees a texture system.
 * Weak, so a program may define its own options; visible (the library is built with -fvisibility=hidden), so
 * that the sanitizer's run-time finds it. */
__attribute__((weak, visibility("default"))) const char *__asan_default_options(void)
{
    return "new_delete_type_mismatch=0";
}
/* A leak inside OpenImageIO, not here: its PNG reader keeps the error message of a corrupt or truncated PNG in a
 * std::string across libpng's longjmp, which skips the destructor. With the fast unwinder the allocation's stack
 * stops in libstdc++'s string assignment, so that frame is suppressed too (the library's own C++ is the two shims,
 * which keep no strings beyond a call). Weak: a program (the fuzz harness) may name its own. */
__attribute__((weak, visibility("default"))) const char *__lsan_default_suppressions(void)
{
    return "leak:PNGInput::PngReadCallback\n"
           "leak:std::__cxx11::basic_string<char, std::char_traits<char>, std::allocator<char> >::_M_assign\n";
}
#endif
