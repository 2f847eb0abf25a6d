// texture_srgb.cpp - GSrgbDecodeInput (texture_srgb.h): an sRGB-encoded image read through another reader and
// served as linear halfs (8-bit files) or floats (any other), decoded before the texture cache MIP-maps and filters
// it.
#include "texture_srgb.h"
#include "generic/services/image.h"
#define GOIIO_MODULE_SOURCE
#include "oiio_module.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

using namespace OIIO;

namespace {

// The linear value of every 8-bit code as a half (the bits of OpenImageIO's half type), decoded (u8) and as it is
// (a8, for alpha), and of every 16-bit code as a float, computed once.
//
// Half is 8-bit data's cached type. Its relative rounding error is at most 2^-11 = 4.88e-4 for a normal half; over
// the 255 nonzero codes it is 4.57e-4 at most (code 139), and 6.6e-5 for the darkest, code 1, which decodes to
// 3.04e-4, above the smallest normal half, 6.10e-5. Rounding the decode to float first gives the nearest half of
// the exact decode for every code. Neighbouring codes decode 0.90% of the lower value apart at least (codes 254 and
// 255), about 20 times that error: half keeps every code apart, its rounding lies far below the file's own steps,
// and it takes half the memory of float.
//
// 16-bit and other integer sources are served as floats: near 1 neighbouring 16-bit codes decode 3.5e-5 apart, 14
// times finer than half's spacing there (2^-11), which would merge them; their precision is what such files are
// for, and it comes before their memory.
struct DecodeTables {
    uint16_t u8[256], a8[256];
    float u16[65536];
    DecodeTables()
    {
        float f8[256], l8[256];
        for (int i = 0; i < 256; i++) {
            f8[i] = (float)gimage_srgb_decode(i / 255.0);
            l8[i] = (float)i / 255.0f;
        }
        convert_types(TypeDesc::FLOAT, f8, TypeDesc::HALF, u8, 256);
        convert_types(TypeDesc::FLOAT, l8, TypeDesc::HALF, a8, 256);
        for (int i = 0; i < 65536; i++)
            u16[i] = (float)gimage_srgb_decode(i / 65535.0);
    }
};

const DecodeTables &tables()
{
    static const DecodeTables t; // thread-safe initialisation
    return t;
}

// The type a level of the real file is served as: half for 8-bit data alike in every channel, else float.
TypeDesc served_type(const ImageSpec &real)
{
    return real.channelformats.empty() && real.format == TypeDesc::UINT8 ? TypeDesc::HALF : TypeDesc::FLOAT;
}

// The spec the cache sees: the real one as linear halfs or floats (served_type), without what describes the encoded
// values. The cache keeps a file's half data as half (it converts only when its "forcefloat" attribute is set,
// which lib/image/texture_oiio.cpp leaves off).
ImageSpec linear_spec(const ImageSpec &real)
{
    ImageSpec s = real;
    s.set_format(served_type(real)); // also drops per-channel formats
    for (const char *name : {"oiio:ColorSpace", "oiio:Gamma", "oiio:BitsPerSample", "oiio:SHA-1",
                             "oiio:ConstantColor", "oiio:AverageColor"})
        s.erase_attribute(name);
    s.attribute("oiio:ColorSpace", "Linear");
    return s;
}

} // namespace

int GSrgbDecodeInput::supports(string_view feature) const
{
    if (feature == "ioproxy") // a proxy would have to reach the real reader: never offered
        return 0;
    return m_in ? m_in->supports(feature) : 0;
}

bool GSrgbDecodeInput::open(const std::string &name, ImageSpec &newspec)
{
    return open(name, newspec, ImageSpec());
}

bool GSrgbDecodeInput::open(const std::string &name, ImageSpec &newspec, const ImageSpec &config)
{
    close();
    try {
        m_in.reset(m_real ? m_real() : nullptr);
    } catch (...) {
        m_in.reset();
    }
    if (!m_in) {
        errorfmt("{}", "no reader for the file");
        return false;
    }
    ImageSpec real;
    if (!m_in->open(name, real, config)) {
        errorfmt("{}", m_in->geterror());
        m_in.reset();
        return false;
    }
    m_spec = linear_spec(m_in->spec());
    m_subimage = m_in->current_subimage();
    m_miplevel = m_in->current_miplevel();
    newspec = m_spec;
    return true;
}

bool GSrgbDecodeInput::close()
{
    if (m_in)
        m_in->close();
    m_in.reset();
    m_subimage = m_miplevel = -1;
    return true;
}

bool GSrgbDecodeInput::seek_subimage(int subimage, int miplevel)
{
    if (!m_in)
        return false;
    if (subimage == m_subimage && miplevel == m_miplevel)
        return true;
    if (!m_in->seek_subimage(subimage, miplevel))
        return false;
    m_spec = linear_spec(m_in->spec());
    m_subimage = subimage;
    m_miplevel = miplevel;
    return true;
}

// The type the real reader is asked for: its own when it is 8- or 16-bit integers alike in every channel (decoded
// through the tables, 8-bit to halfs, 16-bit to floats), else floats (decoded one by one).
TypeDesc GSrgbDecodeInput::read_type() const
{
    const ImageSpec &real = m_in->spec();
    if (real.channelformats.empty() && (real.format == TypeDesc::UINT8 || real.format == TypeDesc::UINT16))
        return real.format;
    return TypeDesc::FLOAT;
}

// Decodes the pixels the real reader wrote at the start of data as type into the served type (m_spec.format): in
// place, from the last value down, since each served value takes at least as many bytes as the value it replaces
// (the value i of the read type lies at or before the bytes of served value i, and every value after it has been
// read already).
bool GSrgbDecodeInput::finish(bool ok, TypeDesc type, size_t pixels, void *data)
{
    if (!ok) {
        errorfmt("{}", m_in->geterror());
        return false;
    }
    const int nch = m_spec.nchannels;
    const size_t n = pixels * (size_t)nch;
    unsigned char *bytes = static_cast<unsigned char *>(data);
    const DecodeTables &t = tables();
    if (type == TypeDesc::UINT8) { // served as halfs
        for (size_t i = n; i-- > 0;) {
            const int c = (int)(i % (size_t)nch);
            const unsigned v = bytes[i];
            const uint16_t h = c != m_spec.alpha_channel && c != m_spec.z_channel ? t.u8[v] : t.a8[v];
            memcpy(bytes + 2 * i, &h, sizeof h);
        }
        return true;
    }
    for (size_t i = n; i-- > 0;) { // served as floats
        const int c = (int)(i % (size_t)nch);
        const bool decode = c != m_spec.alpha_channel && c != m_spec.z_channel;
        float f;
        if (type == TypeDesc::UINT16) {
            uint16_t v;
            memcpy(&v, bytes + 2 * i, sizeof v);
            f = decode ? t.u16[v] : (float)v / 65535.0f;
        } else {
            memcpy(&f, bytes + 4 * i, sizeof f);
            if (decode)
                f = (float)gimage_srgb_decode(f);
        }
        memcpy(bytes + 4 * i, &f, sizeof f);
    }
    return true;
}

bool GSrgbDecodeInput::read_native_scanline(int subimage, int miplevel, int y, int z, void *data)
{
    return read_native_scanlines(subimage, miplevel, y, y + 1, z, data);
}

bool GSrgbDecodeInput::read_native_scanlines(int subimage, int miplevel, int ybegin, int yend, int z, void *data)
{
    lock_guard lock(*this);
    if (!seek_subimage(subimage, miplevel))
        return false;
    yend = std::min(yend, m_spec.y + m_spec.height);
    if (yend <= ybegin)
        return true;
    TypeDesc type = read_type(); // an 8- or 16-bit file's own type is asked for as UNKNOWN: read without a copy
    bool ok = m_in->read_scanlines(subimage, miplevel, ybegin, yend, z, 0, m_spec.nchannels,
                                   type == TypeDesc::FLOAT ? type : TypeDesc(TypeDesc::UNKNOWN), data);
    return finish(ok, type, (size_t)(yend - ybegin) * (size_t)m_spec.width, data);
}

bool GSrgbDecodeInput::read_native_tile(int subimage, int miplevel, int x, int y, int z, void *data)
{
    lock_guard lock(*this);
    if (!seek_subimage(subimage, miplevel))
        return false;
    const int depth = std::max(m_spec.tile_depth, 1);
    return read_native_tiles(subimage, miplevel, x, x + m_spec.tile_width, y, y + m_spec.tile_height, z, z + depth,
                             data);
}

bool GSrgbDecodeInput::read_native_tiles(int subimage, int miplevel, int xbegin, int xend, int ybegin, int yend,
                                         int zbegin, int zend, void *data)
{
    lock_guard lock(*this);
    if (!seek_subimage(subimage, miplevel))
        return false;
    TypeDesc type = read_type();
    bool ok = m_in->read_tiles(subimage, miplevel, xbegin, xend, ybegin, yend, zbegin, zend, 0, m_spec.nchannels,
                               type, data);
    size_t pixels = (size_t)std::max(xend - xbegin, 0) * (size_t)std::max(yend - ybegin, 0) *
                    (size_t)std::max(zend - zbegin, 0);
    return finish(ok, type, pixels, data);
}
