// ocio_display.cpp - display transforms through OpenColorIO 2 (generic/services/image.h, GImageDisplay): part of the
// OpenImageIO module (OpenImageIO links OpenColorIO itself, so the module maps nothing more), loaded only when a
// display transform is asked for. The config path comes resolved from the library (lib/image/image_display.c).
// Every LUT file the config names is checked before OpenColorIO reads any (check_config_files): a regular file
// found on the config's search path, at most 256 MiB, so that a FIFO blocks nothing and /dev/zero is not read, and
// under --confine (GImageDisplay.confine_dir) a file under the confined folder once links are resolved, as every
// search path of the config must be.
#include "generic/services/image.h"
#define GOIIO_MODULE_SOURCE
#include "oiio_module.h"

#include <OpenColorIO/OpenColorIO.h>

#include <climits>
#include <cstdlib>
#include <cstring>
#include <sys/stat.h>

#include <exception>
#include <new>
#include <string>
#include <vector>

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

// Largest LUT file a config may name (a 65^3 cube in text is about 10 MB).
constexpr long long max_lut_bytes = 256ll << 20;

// The confined folder, its links resolved ("" for none).
struct Confinement {
    std::string root;
    const char *named = nullptr; // as the caller gave it, for messages
};

// True when path (links resolved) is root or lies under it.
bool within(const Confinement &c, const char *real)
{
    size_t n = c.root.size();
    return std::strncmp(real, c.root.c_str(), n) == 0 && (real[n] == 0 || real[n] == '/' || c.root == "/");
}

// G_OK when there is no confinement or file lies under the confined folder once its links are resolved; else G_ERR_IO
// naming the config, what names the file and the folder.
int check_confined(const Confinement &c, const char *config, const std::string &holder, const std::string &file,
                   GError *err)
{
    if (c.root.empty())
        return G_OK;
    char real[PATH_MAX];
    if (!realpath(file.c_str(), real))
        return gerror_set(err, G_ERR_IO, "OpenColorIO config %s: %s names \"%s\", which cannot be read", config,
                          holder.c_str(), file.c_str());
    if (!within(c, real))
        return gerror_set(err, G_ERR_IO, "OpenColorIO config %s: %s names \"%s\", which lies outside the confined "
                          "folder %s (--confine)", config, holder.c_str(), file.c_str(), c.named);
    return G_OK;
}

// Every file a transform names (FileTransform), through its groups (an explicit stack: no recursion on nesting),
// resolved on the config's search path and checked as the library checks inputs: a regular file (never a FIFO, a
// device, a directory), at most max_lut_bytes. G_OK, or the refusal naming the config, the file and what holds it.
int check_files(const OCIO::ConstConfigRcPtr &cfg, const char *config, const Confinement &confined,
                OCIO::ConstTransformRcPtr top, const std::string &holder, GError *err)
{
    std::vector<OCIO::ConstTransformRcPtr> stack;
    if (top)
        stack.push_back(top);
    OCIO::ConstContextRcPtr ctx = cfg->getCurrentContext();
    while (!stack.empty()) {
        OCIO::ConstTransformRcPtr t = stack.back();
        stack.pop_back();
        if (auto g = OCIO_DYNAMIC_POINTER_CAST<const OCIO::GroupTransform>(t)) {
            for (int i = 0; i < g->getNumTransforms(); i++)
                stack.push_back(g->getTransform(i));
            continue;
        }
        auto f = OCIO_DYNAMIC_POINTER_CAST<const OCIO::FileTransform>(t);
        if (!f || !f->getSrc() || !*f->getSrc())
            continue;
        std::string file;
        try {
            file = ctx->resolveFileLocation(f->getSrc());
        } catch (const OCIO::Exception &e) {
            return gerror_set(err, G_ERR_IO, "OpenColorIO config %s: %s names \"%s\": %s", config, holder.c_str(),
                              f->getSrc(), e.what());
        }
        struct stat st;
        if (stat(file.c_str(), &st) != 0)
            return gerror_set(err, G_ERR_IO, "OpenColorIO config %s: %s names \"%s\", which cannot be read", config,
                              holder.c_str(), file.c_str());
        if (!S_ISREG(st.st_mode))
            return gerror_set(err, G_ERR_IO, "OpenColorIO config %s: %s names \"%s\", which is %s, not a regular file",
                              config, holder.c_str(), file.c_str(),
                              S_ISFIFO(st.st_mode) ? "a FIFO" : S_ISDIR(st.st_mode) ? "a directory"
                              : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device" : "special");
        if (st.st_size > max_lut_bytes)
            return gerror_set(err, G_ERR_IO, "OpenColorIO config %s: %s names \"%s\" of %lld bytes, more than the "
                              "limit of %lld", config, holder.c_str(), file.c_str(), (long long)st.st_size,
                              max_lut_bytes);
        int rc = check_confined(confined, config, holder, file, err);
        if (rc != G_OK)
            return rc;
    }
    return G_OK;
}

// check_files over every transform of the config: its colour spaces (both directions), looks, view transforms and
// named transforms, whether the display asked for uses them or not.
int check_config_files(const OCIO::ConstConfigRcPtr &cfg, const char *config, const Confinement &confined,
                       GError *err)
{
    int rc = G_OK;
    OCIO::ConstContextRcPtr ctx = cfg->getCurrentContext();
    for (int i = 0; i < ctx->getNumSearchPaths() && !confined.root.empty() && rc == G_OK; i++) {
        std::string dir = ctx->resolveStringVar(ctx->getSearchPath(i));
        if (!dir.empty() && dir[0] != '/' && ctx->getWorkingDir() && *ctx->getWorkingDir())
            dir = std::string(ctx->getWorkingDir()) + "/" + dir;
        char real[PATH_MAX];
        if (realpath(dir.c_str(), real) && !within(confined, real)) // a folder that is not there holds no file
            rc = gerror_set(err, G_ERR_IO, "OpenColorIO config %s: its search path \"%s\" lies outside the confined "
                            "folder %s (--confine)", config, ctx->getSearchPath(i), confined.named);
    }
    int n = cfg->getNumColorSpaces(OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL);
    for (int i = 0; i < n && rc == G_OK; i++) {
        const char *name = cfg->getColorSpaceNameByIndex(OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL, i);
        OCIO::ConstColorSpaceRcPtr cs = cfg->getColorSpace(name);
        std::string holder = std::string("colour space '") + name + "'";
        if (cs && (rc = check_files(cfg, config, confined, cs->getTransform(OCIO::COLORSPACE_DIR_TO_REFERENCE),
                                    holder, err)) == G_OK)
            rc = check_files(cfg, config, confined, cs->getTransform(OCIO::COLORSPACE_DIR_FROM_REFERENCE), holder,
                             err);
    }
    for (int i = 0; i < cfg->getNumLooks() && rc == G_OK; i++) {
        const char *name = cfg->getLookNameByIndex(i);
        OCIO::ConstLookRcPtr look = cfg->getLook(name);
        std::string holder = std::string("look '") + name + "'";
        if (look && (rc = check_files(cfg, config, confined, look->getTransform(), holder, err)) == G_OK)
            rc = check_files(cfg, config, confined, look->getInverseTransform(), holder, err);
    }
    for (int i = 0; i < cfg->getNumViewTransforms() && rc == G_OK; i++) {
        const char *name = cfg->getViewTransformNameByIndex(i);
        OCIO::ConstViewTransformRcPtr vt = cfg->getViewTransform(name);
        std::string holder = std::string("view transform '") + name + "'";
        if (vt && (rc = check_files(cfg, config, confined, vt->getTransform(OCIO::VIEWTRANSFORM_DIR_TO_REFERENCE),
                                    holder, err)) == G_OK)
            rc = check_files(cfg, config, confined, vt->getTransform(OCIO::VIEWTRANSFORM_DIR_FROM_REFERENCE), holder,
                             err);
    }
    int nt = cfg->getNumNamedTransforms(OCIO::NAMEDTRANSFORM_ALL);
    for (int i = 0; i < nt && rc == G_OK; i++) {
        const char *name = cfg->getNamedTransformNameByIndex(OCIO::NAMEDTRANSFORM_ALL, i);
        OCIO::ConstNamedTransformRcPtr t = cfg->getNamedTransform(name);
        std::string holder = std::string("named transform '") + name + "'";
        if (t && (rc = check_files(cfg, config, confined, t->getTransform(OCIO::TRANSFORM_DIR_FORWARD), holder,
                                   err)) == G_OK)
            rc = check_files(cfg, config, confined, t->getTransform(OCIO::TRANSFORM_DIR_INVERSE), holder, err);
    }
    return rc;
}

int transform(const char *config, const Confinement &confined, const char *display, const char *view, float *pixels,
              int width, int height, int channels, GError *err)
{
    OCIO::SetLoggingLevel(OCIO::LOGGING_LEVEL_NONE); // errors come as exceptions, into err
    OCIO::ConstConfigRcPtr cfg;
    try {
        cfg = OCIO::Config::CreateFromFile(config);
        cfg->validate();
    } catch (const OCIO::Exception &e) {
        return gerror_set(err, G_ERR_PARSE, "OpenColorIO config %s: %s", config, e.what());
    }
    int checked = check_config_files(cfg, config, confined, err); // before OpenColorIO opens any of them
    if (checked != G_OK)
        return checked;
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
int display_transform(const char *config, const char *confine_dir, const char *display, const char *view,
                      float *pixels, int width, int height, int channels, GError *err)
{
    if (!config || !*config)
        return gerror_set(err, G_ERR_INVALID, "no OpenColorIO config given");
    if (pixels && (width < 1 || height < 1 || (channels != 3 && channels != 4)))
        return gerror_set(err, G_ERR_INVALID, "a display transform needs an RGB or RGBA image");
    try {
        Confinement confined;
        if (confine_dir && *confine_dir) {
            char real[PATH_MAX];
            if (!realpath(confine_dir, real))
                return gerror_set(err, G_ERR_IO, "the confined folder %s cannot be read", confine_dir);
            confined.root = real;
            confined.named = confine_dir;
        }
        return transform(config, confined, display, view, pixels, width, height, channels, err);
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
