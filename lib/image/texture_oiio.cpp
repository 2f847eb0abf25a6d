// texture_oiio.cpp - OpenImageIO's TextureSystem behind a C interface: reference-counted texture systems
// (one per scene, or the shared default), opening files, and filtered lookups with per-thread state. Part of the
// module libgeneric_oiio.so (lib/image/oiio_module.h).
#include "generic/services/texsys.h"
#include "generic/services/image.h"
#include "generic/memory.h"
#define GOIIO_MODULE_SOURCE
#include "oiio_module.h"
#include "image_format.h"
#include "texture_srgb.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagecache.h>
#include <OpenImageIO/texture.h>

#include <cctype>
#include <cstring>
#include <mutex>
#include <new>
#include <string>

using namespace OIIO;

// (The sanitizer options for OpenImageIO's own defects are in lib/image/image_basic.c: they must be in the program.)

struct GTextureSystem {
    TextureSystem *ts;
    ImageCache *cache; // the system's own, into which every file is added with the reader of its content
    int refs;
};

namespace {
std::mutex refs_lock; // guards every refcount and the default system (not on the lookup path)
GTextureSystem *default_system = nullptr;

// The most memory a texture system's cache holds, charged to the memory budget while the system exists.
constexpr float cache_mb = 512.0f;

GTextureSystem *make(GError *err)
{
    if (gmem_budget_reserve((size_t)cache_mb << 20, "a texture system's cache", err) != G_OK)
        return nullptr;
    void *mem = gmem_alloc(sizeof(GTextureSystem));
    if (!mem) {
        gmem_budget_release((size_t)cache_mb << 20);
        gerror_set(err, G_ERR_NOMEM, "texture system: out of memory");
        return nullptr;
    }
    TextureSystem *ts = nullptr;
    ImageCache *cache = nullptr;
    try {
        cache = ImageCache::create(false);
        ts = cache ? TextureSystem::create(false, cache) : nullptr;
    } catch (...) {
        ts = nullptr;
    }
    if (!ts) {
        if (cache)
            ImageCache::destroy(cache, true);
        gmem_free(mem);
        gmem_budget_release((size_t)cache_mb << 20);
        gerror_set(err, G_ERR_NOMEM, "texture system: OpenImageIO could not create one");
        return nullptr;
    }
    try {
        ts->attribute("automip", 1);     // MIP levels for files that have none (PNG, JPEG, ...)
        ts->attribute("gray_to_rgb", 1); // grey files answer 3-channel lookups
        ts->attribute("max_memory_MB", cache_mb);
        // "forcefloat" stays off: the cache keeps 8-bit, 16-bit and half data in their own type, the halfs of
        // decoded 8-bit sRGB files (texture_srgb.h) among them
    } catch (...) {
        TextureSystem::destroy(ts, true);
        ImageCache::destroy(cache, true);
        gmem_free(mem);
        gmem_budget_release((size_t)cache_mb << 20);
        gerror_set(err, G_ERR_NOMEM, "texture system: OpenImageIO could not set it up");
        return nullptr;
    }
    return new (mem) GTextureSystem{ts, cache, 1};
}

void release(GTextureSystem *s)
{
    TextureSystem::destroy(s->ts, true);
    ImageCache::destroy(s->cache, true); // the system's own cache, which would otherwise stay allocated
    s->~GTextureSystem();
    gmem_free(s);
    gmem_budget_release((size_t)cache_mb << 20);
}

TextureOpt::Wrap wrap_of(GTexWrap w)
{
    switch (w) {
    case GTEX_WRAP_CLAMP: return TextureOpt::WrapClamp;
    case GTEX_WRAP_BLACK: return TextureOpt::WrapBlack;
    case GTEX_WRAP_MIRROR: return TextureOpt::WrapMirror;
    default: return TextureOpt::WrapPeriodic;
    }
}

// The readers a texture file is opened with: the one of its content's format (image_format.h), never another; and
// the same reader behind GSrgbDecodeInput, for a file whose values are sRGB-encoded.
ImageInput *make_exr() { return ImageInput::create("openexr").release(); }
ImageInput *make_hdr() { return ImageInput::create("hdr").release(); }
ImageInput *make_pnm() { return ImageInput::create("pnm").release(); }
ImageInput *make_png() { return ImageInput::create("png").release(); }
ImageInput *make_jpeg() { return ImageInput::create("jpeg").release(); }
ImageInput *make_tiff() { return ImageInput::create("tiff").release(); }

template <ImageInput::Creator Real> ImageInput *make_decoded()
{
    try {
        return new GSrgbDecodeInput(Real);
    } catch (...) { // std::bad_alloc: the cache reports the file as not opened
        return nullptr;
    }
}

struct Readers {
    ImageInput::Creator plain, decoded;
};

Readers readers_of(const char *oiio)
{
    static const struct {
        const char *name;
        Readers make;
    } table[] = {{"openexr", {make_exr, make_decoded<make_exr>}}, {"hdr", {make_hdr, make_decoded<make_hdr>}},
                 {"pnm", {make_pnm, make_decoded<make_pnm>}},     {"png", {make_png, make_decoded<make_png>}},
                 {"jpeg", {make_jpeg, make_decoded<make_jpeg>}},  {"tiff", {make_tiff, make_decoded<make_tiff>}}};
    for (const auto &t : table)
        if (oiio && !strcmp(oiio, t.name))
            return t.make;
    return {nullptr, nullptr};
}

bool says_linear(std::string cs)
{
    for (auto &c : cs)
        c = (char)std::tolower((unsigned char)c);
    return cs.find("linear") != std::string::npos || cs == "scene_linear" || cs == "raw";
}

// The cache's names of a file: each a spelling of the file's own path, so that the cache opens the file itself by
// it, but those of its sRGB-decoded values (decoded_name) hold "/./" and those of its values as they are
// (plain_name) never do, so that no path, as given, names one kind's entry for the other.
std::string plain_name(const char *path)
{
    std::string name(path);
    for (size_t at = name.find("/./"); at != std::string::npos; at = name.find("/./"))
        name.erase(at, 2); // "a/./b" reads "a/b"
    return name;
}

std::string decoded_name(const std::string &plain)
{
    size_t slash = plain.rfind('/');
    return slash == std::string::npos ? "././" + plain : plain.substr(0, slash) + "/." + plain.substr(slash);
}

// OpenImageIO's message with every mention of the cache's name given as the path.
std::string named_as_path(std::string why, const std::string &name, const char *path)
{
    const size_t len = strlen(path);
    if (name != path)
        for (size_t at = why.find(name); at != std::string::npos; at = why.find(name, at + len))
            why.replace(at, name.size(), path);
    return why;
}

// Every function below is an entry from C: no exception may leave it.

int texsys_create(GTextureSystem **out, GError *err)
{
    *out = make(err);
    return *out ? G_OK : err ? err->code : G_ERR_NOMEM;
}

GTextureSystem *texsys_ref(GTextureSystem *ts)
{
    if (ts) {
        try {
            std::lock_guard<std::mutex> g(refs_lock);
            ts->refs++;
        } catch (...) { // std::system_error from a broken mutex
            return nullptr;
        }
    }
    return ts;
}

void texsys_unref(GTextureSystem *ts)
{
    if (!ts)
        return;
    try {
        {
            std::lock_guard<std::mutex> g(refs_lock);
            if (--ts->refs > 0)
                return;
            if (ts == default_system)
                default_system = nullptr;
        }
        release(ts);
    } catch (...) { // OpenImageIO failed while freeing: the system is lost, the program goes on
    }
}

GTextureSystem *texsys_default(GError *err)
{
    try {
        std::lock_guard<std::mutex> g(refs_lock);
        if (default_system) {
            default_system->refs++;
            return default_system;
        }
        default_system = make(err);
        return default_system;
    } catch (...) {
        gerror_set(err, G_ERR_NOMEM, "texture system: OpenImageIO could not create one");
        return nullptr;
    }
}

int texsys_open(GTextureSystem *ts, const char *path, GTexColorSpace space, GTexFile **file, int *channels,
                int *srgb, GError *err)
{
    *file = nullptr;
    if (!ts || !path || !path[0])
        return gerror_set(err, G_ERR_INVALID, "image: no file name given");
    try {
        if (!Filesystem::exists(path))
            return gerror_set(err, G_ERR_IO, "image '%s': no such file", path);
        // The header first: OpenImageIO 2.4's cache asserts (aborts) on a file whose header gives a size
        // below 1, such as a PFM with a negative width.
        GError head;
        if (goiio_image_info(path, nullptr, nullptr, nullptr, &head) != G_OK) {
            /* gimage_info's message reads "PATH: [cannot read image: ]REASON"; ours names the path already */
            const char *why = head.message;
            size_t len = strlen(path);
            if (strncmp(why, path, len) == 0 && strncmp(why + len, ": ", 2) == 0)
                why += len + 2;
            if (strncmp(why, "cannot read image: ", 19) == 0)
                why += 19;
            return gerror_set(err, head.code, "image '%s' cannot be read: %s", path, why);
        }
        GImageFormat format;
        if (goiio_image_format(path, &format, err) != G_OK)
            return err ? err->code : G_ERR_IO;
        Readers make = readers_of(format.oiio);
        if (!make.plain)
            return gerror_set(err, G_ERR_IO,
                              "image '%s' cannot be read: its content is not one of the formats read (%s)", path,
                              GIMAGE_READ_FORMATS);
        std::string plain = plain_name(path);
        ustring name(plain);
        ts->cache->add_file(name, make.plain); // no effect when the file is in the cache already, opened the same way
        TextureSystem::Perthread *pt = ts->ts->get_perthread_info();
        TextureSystem::TextureHandle *h = ts->ts->get_texture_handle(name, pt);
        ImageSpec spec;
        if (!h || !ts->ts->good(h) || !ts->ts->get_imagespec(h, pt, 0, spec)) {
            std::string why = named_as_path(ts->ts->geterror(), plain, path);
            return gerror_set(err, G_ERR_IO, "image '%s' cannot be read: %s", path,
                              why.empty() ? "not an image OpenImageIO can decode" : why.c_str());
        }
        *channels = spec.nchannels;
        bool is_float = spec.format.basetype == TypeDesc::FLOAT || spec.format.basetype == TypeDesc::HALF ||
                        spec.format.basetype == TypeDesc::DOUBLE;
        bool decode = space == GTEX_COLORSPACE_SRGB ||
                      (space == GTEX_COLORSPACE_AUTO && !is_float &&
                       !says_linear(spec.get_string_attribute("oiio:ColorSpace")));
        if (decode) { /* the decoded file: its own cache entry, which filters linear values */
            std::string key = decoded_name(plain);
            ustring dname(key);
            ts->cache->add_file(dname, make.decoded);
            ts->cache->close(name); // the encoded entry gave its header only: its file need not stay open
            h = ts->ts->get_texture_handle(dname, pt);
            if (!h || !ts->ts->good(h) || !ts->ts->get_imagespec(h, pt, 0, spec)) {
                std::string why = named_as_path(ts->ts->geterror(), key, path);
                return gerror_set(err, G_ERR_IO, "image '%s' cannot be read: %s", path,
                                  why.empty() ? "not an image OpenImageIO can decode" : why.c_str());
            }
        }
        *srgb = decode;
        *file = reinterpret_cast<GTexFile *>(h);
        return G_OK;
    } catch (const std::exception &e) {
        return gerror_set(err, G_ERR_IO, "image '%s': %s", path, e.what());
    } catch (...) {
        return gerror_set(err, G_ERR_IO, "image '%s': OpenImageIO failed", path);
    }
}

int texsys_lookup(GTextureSystem *ts, GTexFile *file, GTexWrap swrap, GTexWrap twrap, double s, double t,
                   const double deriv[4], double blur, float rgb[3])
{
    TextureOpt opt;
    opt.swrap = wrap_of(swrap);
    opt.twrap = wrap_of(twrap);
    opt.mipmode = TextureOpt::MipModeAniso; // trilinear along the ellipse's short axis, several taps along the long one
    opt.anisotropic = 16;
    opt.interpmode = TextureOpt::InterpBilinear;
    opt.sblur = opt.tblur = (float)blur;
    try {
        TextureSystem::Perthread *pt = ts->ts->get_perthread_info();
        if (ts->ts->texture(reinterpret_cast<TextureSystem::TextureHandle *>(file), pt, opt, (float)s, (float)t,
                            (float)deriv[0], (float)deriv[1], (float)deriv[2], (float)deriv[3], 3, rgb))
            return G_OK;
        ts->ts->geterror();
    } catch (...) { // std::bad_alloc from the cache, or any other failure inside OpenImageIO
    }
    rgb[0] = rgb[1] = rgb[2] = 0.0f;
    return G_ERR_IO;
}

} // namespace

void goiio_texsys_ops(GOiioOps *ops)
{
    ops->texsys_create = texsys_create;
    ops->texsys_ref = texsys_ref;
    ops->texsys_unref = texsys_unref;
    ops->texsys_default = texsys_default;
    ops->texsys_open = texsys_open;
    ops->texsys_lookup = texsys_lookup;
}
