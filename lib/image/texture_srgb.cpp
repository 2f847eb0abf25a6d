// texture_srgb.cpp - GSrgbDecodeInput (texture_srgb.h): an sRGB-encoded image read through another reader and
// served as linear floats, decoded before the texture cache MIP-maps and filters it.
#include "texture_srgb.h"
#include "generic/services/image.h"
#define GOIIO_MODULE_SOURCE
#include "oiio_module.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

using namespace OIIO;

namespace {

// The linear value of every 8-bit and every 16-bit code, computed once.
struct DecodeTables {
    float u8[256];
    float u16[65536];
    DecodeTables()
    {
        for (int i = 0; i < 256; i++)
            u8[i] = (float)gimage_srgb_decode(i / 255.0);
        for (int i = 0; i < 65536; i++)
            u16[i] = (float)gimage_srgb_decode(i / 65535.0);
    }
};

const DecodeTables &tables()
{
    static const DecodeTables t; // thread-safe initialisation
    return t;
}

// The spec the cache sees: the real one as linear floats, without what describes the encoded values.
ImageSpec linear_spec(const ImageSpec &real)
{
    ImageSpec s = real;
    s.set_format(TypeDesc::FLOAT); // also drops per-channel formats
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
// through the tables), else floats (decoded one by one).
TypeDesc GSrgbDecodeInput::read_type() const
{
    const ImageSpec &real = m_in->spec();
    if (real.channelformats.empty() && (real.format == TypeDesc::UINT8 || real.format == TypeDesc::UINT16))
        return real.format;
    return TypeDesc::FLOAT;
}

// Decodes the pixels the real reader wrote at the start of data as type: in place, from the last value down, since
// each float takes at least as many bytes as the value it replaces (the value i of an 8- or 16-bit type lies at or
// before the bytes of float i, and every value after it has been read already).
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
    for (size_t i = n; i-- > 0;) {
        const int c = (int)(i % (size_t)nch);
        const bool decode = c != m_spec.alpha_channel && c != m_spec.z_channel;
        float f;
        if (type == TypeDesc::UINT8) {
            const unsigned v = bytes[i];
            f = decode ? t.u8[v] : (float)v / 255.0f;
        } else if (type == TypeDesc::UINT16) {
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
