// texture_srgb.h - a reader that serves another reader's sRGB-encoded image as linear halfs or floats, so that
// OpenImageIO's texture cache (lib/image/texture_oiio.cpp) MIP-maps and filters linear light. Part of the module
// libgeneric_oiio.so (lib/image/oiio_module.h).
#ifndef GENERIC_TEXTURE_SRGB_H
#define GENERIC_TEXTURE_SRGB_H

#include <OpenImageIO/imageio.h>

#include <string>

/** Reads a file through the reader `real` makes and gives the same image with each colour channel decoded from the
 * sRGB curve (gimage_srgb_decode) to linear, marked "oiio:ColorSpace" Linear: 8-bit values through a 256-entry table
 * as HALF data (the nearest half of the exact decode, within a relative 4.6e-4 of it), 16-bit ones through a
 * 65536-entry table as FLOAT data, any other type converted to float by OpenImageIO and then decoded, as FLOAT. The
 * alpha and depth channels keep their values (scaled to [0, 1] like any integer data). The fingerprint, constant
 * and average colour that maketx writes describe the encoded values and are left out, so that the cache never
 * shares tiles with, or answers from, the encoded file. */
class GSrgbDecodeInput final : public OIIO::ImageInput {
public:
    explicit GSrgbDecodeInput(OIIO::ImageInput::Creator real) : m_real(real) {}
    ~GSrgbDecodeInput() override { close(); }

    const char *format_name() const override { return m_in ? m_in->format_name() : "srgb-decode"; }
    int supports(OIIO::string_view feature) const override;
    bool open(const std::string &name, OIIO::ImageSpec &newspec) override;
    bool open(const std::string &name, OIIO::ImageSpec &newspec, const OIIO::ImageSpec &config) override;
    bool close() override;
    int current_subimage() const override { return m_in ? m_in->current_subimage() : 0; }
    int current_miplevel() const override { return m_in ? m_in->current_miplevel() : 0; }
    bool seek_subimage(int subimage, int miplevel) override;

    using OIIO::ImageInput::read_native_scanlines;
    using OIIO::ImageInput::read_native_tiles;
    bool read_native_scanline(int subimage, int miplevel, int y, int z, void *data) override;
    bool read_native_scanlines(int subimage, int miplevel, int ybegin, int yend, int z, void *data) override;
    bool read_native_tile(int subimage, int miplevel, int x, int y, int z, void *data) override;
    bool read_native_tiles(int subimage, int miplevel, int xbegin, int xend, int ybegin, int yend, int zbegin,
                           int zend, void *data) override;

private:
    OIIO::TypeDesc read_type() const;
    bool finish(bool ok, OIIO::TypeDesc type, size_t pixels, void *data);

    OIIO::ImageInput::Creator m_real;
    OIIO::ImageInput::unique_ptr m_in; // the real reader, while open
    int m_subimage = -1, m_miplevel = -1; // the level m_spec describes
};

#endif
