// ocio_display.cpp - display transforms through OpenColorIO 2 (generic/services/image.h, GImageDisplay): part of the
// OpenImageIO module (OpenImageIO links OpenColorIO itself, so the module maps nothing more), loaded only when a
// display transform is asked for. The config path comes resolved from the library (lib/image/image_display.c).
#include "generic/services/image.h"
#define GOIIO_MODULE_SOURCE
#include "oiio_module.h"

#include <OpenColorIO/OpenColorIO.h>

#include <exception>
#include <new>
#include <string>

namespace OCIO = OCIO_NAMESPACE;

namespace {

// "A, B, C" of the config's displays, or of one display's views.
std::string names(const OCIO::ConstConfigRcPtr &cfg, const char *display)
{
    std::string s;
    int n = display ? cfg->getNumViews(display) : cfg->getNumDisplays();
    for (int i = 0; i < n; i++) {
        s += i ? ", " : "";
        s += display ? cfg->getView(display, i) : cfg->getDisplay(i);
    }
    return s.empty() ? std::string("none") : s;
}

bool has_name(const OCIO::ConstConfigRcPtr &cfg, const char *display, const char *name)
{
    int n = display ? cfg->getNumViews(display) : cfg->getNumDisplays();
    for (int i = 0; i < n; i++)
        if (std::string(display ? cfg->getView(display, i) : cfg->getDisplay(i)) == name)
            return true;
    return false;
}

int transform(const char *config, const char *display, const char *view, float *pixels, int width, int height,
              int channels, GError *err)
{
    OCIO::SetLoggingLevel(OCIO::LOGGING_LEVEL_NONE); // errors come as exceptions, into err
    OCIO::ConstConfigRcPtr cfg;
    try {
        cfg = OCIO::Config::CreateFromFile(config);
        cfg->validate();
    } catch (const OCIO::Exception &e) {
        return gerror_set(err, G_ERR_PARSE, "OpenColorIO config %s: %s", config, e.what());
    }
    const char *d = display && *display ? display : cfg->getDefaultDisplay();
    if (!d || !*d || !has_name(cfg, nullptr, d))
        return gerror_set(err, G_ERR_NOTFOUND, "OpenColorIO config %s has no display '%s' (its displays: %s)", config,
                          d ? d : "", names(cfg, nullptr).c_str());
    const char *v = view && *view ? view : cfg->getDefaultView(d);
    if (!v || !*v || !has_name(cfg, d, v))
        return gerror_set(err, G_ERR_NOTFOUND, "OpenColorIO config %s: display '%s' has no view '%s' (its views: %s)",
                          config, d, v ? v : "", names(cfg, d).c_str());
    try {
        auto dvt = OCIO::DisplayViewTransform::Create();
        dvt->setSrc(OCIO::ROLE_SCENE_LINEAR);
        dvt->setDisplay(d);
        dvt->setView(v);
        OCIO::ConstCPUProcessorRcPtr cpu = cfg->getProcessor(dvt)->getDefaultCPUProcessor();
        if (pixels) {
            OCIO::PackedImageDesc desc(pixels, width, height, channels);
            cpu->apply(desc);
        }
    } catch (const OCIO::Exception &e) {
        return gerror_set(err, G_ERR_PARSE, "OpenColorIO config %s, display '%s', view '%s': %s", config, d, v,
                          e.what());
    }
    return G_OK;
}

// The entry from C: no exception leaves it.
int display_transform(const char *config, const char *display, const char *view, float *pixels, int width,
                      int height, int channels, GError *err)
{
    if (!config || !*config)
        return gerror_set(err, G_ERR_INVALID, "no OpenColorIO config given");
    if (pixels && (width < 1 || height < 1 || (channels != 3 && channels != 4)))
        return gerror_set(err, G_ERR_INVALID, "a display transform needs an RGB or RGBA image");
    try {
        return transform(config, display, view, pixels, width, height, channels, err);
    } catch (const std::bad_alloc &) {
        return gerror_set(err, G_ERR_NOMEM, "out of memory in OpenColorIO");
    } catch (const std::exception &e) {
        return gerror_set(err, G_ERR_IO, "OpenColorIO config %s: %s", config, e.what());
    } catch (...) {
        return gerror_set(err, G_ERR_IO, "OpenColorIO config %s: failed", config);
    }
}

} // namespace

void goiio_display_ops(GOiioOps *ops)
{
    ops->display_transform = display_transform;
}
