// image_oiio.hpp - what the OpenImageIO module's image files (image.cpp, image_spectra.cpp) share: the checked
// opening of an untrusted file, OpenImageIO's messages, and the guard that keeps exceptions out of the C entries.
#ifndef GENERIC_IMAGE_OIIO_HPP
#define GENERIC_IMAGE_OIIO_HPP

#include "generic/error.h"
#include "oiio_module.h"

#include <OpenImageIO/imageio.h>

#include <exception>
#include <memory>
#include <new>
#include <string>

/** The first non-empty line of an OpenImageIO message ("unknown reason" for none). */
std::string goiio_first_line(const std::string &s);

/** Opens path for reading: a regular file only (never a FIFO or a device), whose header may claim no more pixels
 * than the file can hold nor more memory than the image budget. G_OK with *in open, or the error in err. */
int goiio_open_checked(const char *path, OIIO::ImageSpec *config, std::unique_ptr<OIIO::ImageInput> *in,
                       GError *err);

/** Runs f() (returning a status) so that no exception leaves it: out of memory becomes G_ERR_NOMEM "PATH: out of
 * memory OOM_DOING", any other exception G_ERR_IO "PATH: cannot FAIL_VERB[: what]". */
template <class F> int goiio_guarded(const char *path, const char *oom_doing, const char *fail_verb, GError *err, F &&f)
{
    try {
        return f();
    } catch (const std::bad_alloc &) {
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory %s", path, oom_doing);
    } catch (const std::exception &e) {
        return gerror_set(err, G_ERR_IO, "%s: cannot %s: %s", path, fail_verb, e.what());
    } catch (...) {
        return gerror_set(err, G_ERR_IO, "%s: cannot %s", path, fail_verb);
    }
}

/** image_spectra.cpp's part of the module's table (image_read_spectra). */
void goiio_spectra_ops(GOiioOps *ops);

#endif
