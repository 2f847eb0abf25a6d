// image.cpp - the OpenImageIO shim: float images in and out (see include/generic/services/image.h). Part of the module
// libgeneric_oiio.so, which the library loads on first use (lib/image/oiio_module.h): the library's own functions come
// through the host table.
#include "generic/services/image.h"
#include "generic/services/file.h"
#include "generic/memory.h"
#define GOIIO_MODULE_SOURCE
#include "oiio_module.h"
#include "image_oiio.hpp"
#include "image_format.h"
#include "exr_header.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <algorithm>
#include <string>
#include <utility>
#include <vector>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

using OIIO::ImageInput;
using OIIO::ImageOutput;
using OIIO::ImageSpec;
using OIIO::TypeDesc;

// OpenImageIO messages can span lines; keep the first non-empty one.
std::string goiio_first_line(const std::string &s)
{
    size_t b = s.find_first_not_of("\n ");
    if (b == std::string::npos)
        return "unknown reason";
    size_t e = s.find('\n', b);
    return s.substr(b, e == std::string::npos ? std::string::npos : e - b);
}

namespace {


bool is_integer(TypeDesc t)
{
    switch (t.basetype) {
    case TypeDesc::UINT8: case TypeDesc::INT8: case TypeDesc::UINT16: case TypeDesc::INT16:
    case TypeDesc::UINT32: case TypeDesc::INT32:
        return true;
    default:
        return false;
    }
}

// Transfer function of an integer file: 0 linear, 1 sRGB, or a power-law exponent > 1.
double file_transfer(const ImageSpec &spec)
{
    if (!is_integer(spec.format))
        return 0.0;
    std::string cs = spec.get_string_attribute("oiio:ColorSpace");
    const char *c = cs.c_str();
    if (!strcasecmp(c, "linear") || !strcasecmp(c, "scene_linear") || !strcasecmp(c, "lin_srgb") ||
        !strcasecmp(c, "lin_rec709"))
        return 0.0;
    const char *g = nullptr;
    if (!strncasecmp(c, "GammaCorrected", 14))
        g = c + 14;
    else if (!strncasecmp(c, "Gamma", 5))
        g = c + 5;
    if (g) {
        double gamma = atof(g);
        if (gamma > 0.1 && gamma < 10.0)
            return gamma == 1.0 ? 0.0 : gamma;
    }
    return 1.0; // sRGB, or untagged integer data, which is sRGB in practice
}

bool float_extension(const char *path)
{
    const char *dot = strrchr(path, '.');
    const char *slash = strrchr(path, '/');
    if (!dot || (slash && dot < slash))
        return false;
    return !strcasecmp(dot, ".exr") || !strcasecmp(dot, ".hdr") || !strcasecmp(dot, ".pfm");
}

// ---- the header's claim ----

// Refuses a header whose size is impossible, more than the file can hold, or more than the budget; before
// anything the size decides is allocated.
int check_claim(const char *path, const ImageSpec &spec, const char *format, long long file_size, GError *err)
{
    const long long w = spec.width, h = spec.height, nch = spec.nchannels;
    if (w <= 0 || h <= 0 || nch <= 0 || nch > 1024 || spec.depth > 1)
        return gerror_set(err, G_ERR_IO, "%s: invalid image size %lldx%lld with %lld channels", path, w, h, nch);
    const double pixels = (double)w * (double)h;
    if (!strcmp(format, "pnm") && spec.format == TypeDesc::FLOAT) { // PFM: uncompressed floats after the header
        double need = pixels * (double)nch * 4.0;
        if (need > (double)file_size)
            return gerror_set(err, G_ERR_IO,
                              "%s: the header claims %lldx%lld pixels (%.0f bytes of data), more than the file of "
                              "%lld bytes holds", path, w, h, need, file_size);
    }
    if (!strcmp(format, "png")) {
        // At least one filter byte and one bit per pixel a row, and deflate compresses at most 1032:1.
        double need = (double)h * (1.0 + std::ceil((double)w / 8.0));
        if (need > 1032.0 * (double)file_size)
            return gerror_set(err, G_ERR_IO,
                              "%s: the header claims %lldx%lld pixels, more than a PNG file of %lld bytes can hold",
                              path, w, h, file_size);
    }
    if (!strcmp(format, "hdr")) {
        // OpenImageIO's Radiance reader knows flat rows (4 bytes a pixel; always for widths below 8 or above
        // 32767) and run-length encoded ones (a 4-byte row header, then each of the 4 components in runs of
        // at most 127 bytes, 2 bytes a run); not the old-style repeat runs, which it refuses.
        double row = (w < 8 || w > 32767) ? 4.0 * (double)w : 4.0 + 8.0 * std::ceil((double)w / 127.0);
        if ((double)h * row > (double)file_size)
            return gerror_set(err, G_ERR_IO,
                              "%s: the header claims %lldx%lld pixels, more than a Radiance HDR file of %lld bytes "
                              "can hold", path, w, h, file_size);
    }
    if (w * h > (1LL << 31) / 4)
        return gerror_set(err, G_ERR_IO, "%s: unsupported image size %lldx%lld (more than 2^29 pixels)", path, w, h);
    const double bytes = pixels * (double)(nch > 3 ? nch : 3) * sizeof(float);
    const size_t budget = gimage_memory_budget();
    if (bytes > (double)budget)
        return gerror_set(err, G_ERR_NOMEM,
                          "%s: a %lldx%lld image with %lld channels needs %.0f MiB, more than the memory limit "
                          "of %zu MiB (--memory-limit, GENERIC_MEMORY_LIMIT_MB)", path, w, h, nch, bytes / 1048576.0,
                          budget >> 20);
    return G_OK;
}

} // namespace

// The format of an open file from its first bytes: G_OK when it is one the library reads, else G_ERR_IO naming it.
static int sniff_fd(const char *path, int fd, GImageFormat *format, GError *err)
{
    unsigned char head[GIMAGE_SNIFF_BYTES];
    ssize_t got = pread(fd, head, sizeof head, 0);
    *format = gimage_sniff(head, got > 0 ? (size_t)got : 0);
    if (format->oiio)
        return G_OK;
    if (!strcmp(format->name, "unknown"))
        return gerror_set(err, G_ERR_IO, "%s: cannot read image: its content is not one of the formats read (%s)",
                          path, GIMAGE_READ_FORMATS);
    return gerror_set(err, G_ERR_IO, "%s: cannot read image: its content is %s, not one of the formats read (%s)",
                      path, format->name, GIMAGE_READ_FORMATS);
}

int goiio_image_format(const char *path, GImageFormat *format, GError *err)
{
    int fd = gfile_open_input(path, err);
    if (fd < 0)
        return fd;
    int rc = sniff_fd(path, fd, format, err);
    close(fd);
    return rc;
}

// The file must be a regular file (never a FIFO or a device); its size bounds what its header may claim.
int goiio_open_checked(const char *path, ImageSpec *config, std::unique_ptr<ImageInput> *in, GError *err)
{
    int fd = gfile_open_input(path, err);
    if (fd < 0)
        return fd;
    struct stat st;
    long long size = fstat(fd, &st) == 0 ? (long long)st.st_size : 0;
    GImageFormat format;
    int rc = sniff_fd(path, fd, &format, err);
    // OpenEXR allocates what its header claims while it reads it: a claim beyond the file is refused first
    char why[256];
    if (rc == G_OK && !strcmp(format.oiio, "openexr") && gimage_exr_header_check(fd, size, why, sizeof why) != 0)
        rc = gerror_set(err, G_ERR_IO, "%s: cannot read image: %s", path, why);
    close(fd);
    if (rc != G_OK)
        return rc;
    // The reader of the format found, and no other: OpenImageIO's guessing never reaches its other readers.
    *in = ImageInput::create(format.oiio);
    ImageSpec opened;
    if (!*in || !(*in)->open(path, opened, config ? *config : ImageSpec())) {
        std::string why = *in ? (*in)->geterror() : OIIO::geterror();
        in->reset();
        return gerror_set(err, G_ERR_IO, "%s: cannot read image: %s", path, goiio_first_line(why).c_str());
    }
    return check_claim(path, (*in)->spec(), (*in)->format_name(), size, err);
}

namespace {

// Decodes the pixels as floats. Scanline files are read a band of rows at a time, so that OpenImageIO holds
// no second copy of the whole image and a file that ends early fails at its first missing row, before the
// memory for the rows it does not have is touched.
bool decode(ImageInput *in, const ImageSpec &spec, float *raw)
{
    const int nch = spec.nchannels;
    if (spec.tile_width > 0)
        return in->read_image(0, 0, 0, nch, TypeDesc::FLOAT, raw);
    const size_t row = (size_t)spec.width * nch;
    const int band = 64;
    for (int y = 0; y < spec.height; y += band) {
        int y1 = y + band < spec.height ? y + band : spec.height;
        if (!in->read_scanlines(0, 0, spec.y + y, spec.y + y1, 0, 0, nch, TypeDesc::FLOAT, raw + (size_t)y * row))
            return false;
    }
    return true;
}

int read_impl(const char *path, unsigned flags, GImage *img, GError *err)
{
    ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1); // keep straight alpha as the file stores it
    std::unique_ptr<ImageInput> in;
    int rc = goiio_open_checked(path, &config, &in, err);
    if (rc != G_OK)
        return rc;
    const ImageSpec spec = in->spec();
    const int w = spec.width, h = spec.height, nch = spec.nchannels;
    const size_t npix = (size_t)w * h;
    float *raw = (float *)gmem_alloc(npix * nch * sizeof(float)); // not zeroed: decode() writes every value, and
                                                                  // a failure leaves the untouched pages unused
    if (!raw)
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory for a %dx%d image", path, w, h);
    bool decoded;
    try {
        decoded = decode(in.get(), spec, raw);
    } catch (...) {
        gmem_free(raw);
        throw;
    }
    if (!decoded) {
        std::string msg = goiio_first_line(in->geterror());
        gmem_free(raw);
        return gerror_set(err, G_ERR_IO, "%s: cannot decode image: %s", path, msg.c_str());
    }
    in->close();

    // Colour channels are the non-alpha ones in file order; alpha is the one the spec names.
    int alpha = spec.alpha_channel >= 0 && spec.alpha_channel < nch ? spec.alpha_channel : -1;
    if (alpha < 0 && (nch == 2 || nch == 4))
        alpha = nch - 1;
    int colour[3] = {-1, -1, -1}, ncolour = 0;
    for (int c = 0; c < nch && ncolour < 3; c++)
        if (c != alpha)
            colour[ncolour++] = c;
    if (ncolour == 1)
        colour[1] = colour[2] = colour[0];
    int out_ch = (flags & GIMAGE_READ_RGB) ? 3 : (flags & GIMAGE_READ_RGBA) ? 4 : (alpha >= 0 ? 4 : 3);

    float *pix = (float *)gmem_calloc(npix * out_ch, sizeof(float));
    if (!pix) {
        gmem_free(raw);
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory for a %dx%d image", path, w, h);
    }
    const double transfer = (flags & GIMAGE_READ_RAW) ? 0.0 : file_transfer(spec);
    for (size_t i = 0; i < npix; i++) {
        const float *s = raw + i * nch;
        float *d = pix + i * out_ch;
        for (int c = 0; c < 3; c++) {
            double v = colour[c] >= 0 ? s[colour[c]] : 0.0;
            if (transfer == 1.0)
                v = gimage_srgb_decode(v);
            else if (transfer > 1.0)
                v = v > 0.0 ? pow(v, transfer) : 0.0;
            d[c] = (float)v;
        }
        if (out_ch == 4)
            d[3] = alpha >= 0 ? s[alpha] : 1.0f;
    }
    gmem_free(raw);
    img->width = w;
    img->height = h;
    img->channels = out_ch;
    img->pixels = pix;
    return G_OK;
}

// An IOProxy over the temporary's descriptor that notes every failed write. A failed write is reported to the
// encoder as done, so that no encoder takes its own error path (libjpeg's ends the process): the first error
// is reported after the encoder has finished, and the output is then discarded.
class FdWriter final : public OIIO::Filesystem::IOProxy {
public:
    FdWriter(const std::string &name, int fd) : IOProxy(name, Write), fd_(fd) {}
    const char *proxytype() const override { return "generic-fd"; }
    void close() override { m_mode = Closed; } // the descriptor belongs to the GFileOutput
    bool seek(int64_t offset) override
    {
        if (offset < 0)
            return false;
        m_pos = offset;
        return true;
    }
    size_t read(void *buf, size_t size) override // libtiff reads back what it wrote
    {
        size_t n = pread(buf, size, m_pos);
        m_pos += (int64_t)n;
        return n;
    }
    size_t pread(void *buf, size_t size, int64_t offset) override
    {
        size_t done = 0;
        while (done < size) {
            ssize_t n = ::pread(fd_, (char *)buf + done, size - done, (off_t)(offset + (int64_t)done));
            if (n < 0 && errno == EINTR)
                continue;
            if (n <= 0)
                break;
            done += (size_t)n;
        }
        return done;
    }
    size_t write(const void *buf, size_t size) override
    {
        size_t n = pwrite(buf, size, m_pos);
        m_pos += (int64_t)n;
        return n;
    }
    size_t pwrite(const void *buf, size_t size, int64_t offset) override
    {
        const char *p = (const char *)buf;
        size_t done = 0;
        while (done < size && errno_ == 0) {
            ssize_t n = ::pwrite(fd_, p + done, size - done, (off_t)(offset + (int64_t)done));
            if (n < 0 && errno == EINTR)
                continue;
            if (n <= 0)
                errno_ = n < 0 ? errno : ENOSPC;
            else
                done += (size_t)n;
        }
        if ((int64_t)(offset + size) > end_)
            end_ = offset + (int64_t)size;
        return size;
    }
    size_t size() const override { return (size_t)end_; }
    int error_number() const { return errno_; }
    int64_t end() const { return end_; }

private:
    int fd_;
    int errno_ = 0;
    int64_t end_ = 0;
};

// The channel name of wavelength nm in the spectral layout (image.h): S0.550,000000nm.
std::string spectral_channel(double nm)
{
    char num[64];
    snprintf(num, sizeof num, "%.6f", nm);
    for (char *p = num; *p; p++)
        if (*p == '.')
            *p = ',';
    return std::string("S0.") + num + "nm";
}

// Writes the colour channels and the spectra (opt->spectra, OpenEXR only) row by row: no second copy of the
// whole image.
int write_spectral(ImageOutput *out, const char *path, const char *tmp, const GImage *img, double scale,
                   const GImageWriteOptions *opt, GError *err)
{
    const GImageSpectra *sp = opt->spectra;
    const int w = img->width, h = img->height, ch = img->channels, n = sp->count, nch = ch + n;
    ImageSpec spec(w, h, nch, TypeDesc::FLOAT);
    spec.alpha_channel = ch == 2 || ch == 4 ? ch - 1 : -1;
    spec.channelnames.resize((size_t)ch);
    for (int k = 0; k < n; k++)
        spec.channelnames.push_back(spectral_channel(sp->wavelengths[k]));
    if (opt->full_width > 0) {
        spec.x = opt->x;
        spec.y = opt->y;
        spec.full_x = spec.full_y = 0;
        spec.full_width = opt->full_width;
        spec.full_height = opt->full_height;
    }
    if (opt->full_width > 0 && opt->note)
        spec.attribute("generic:note", opt->note);
    spec.attribute("oiio:ColorSpace", "Linear");
    spec.attribute("spectralLayoutVersion", "1.0");
    spec.attribute("emissiveUnits", "W.m^-2.sr^-1");
    float *row = (float *)gmem_alloc((size_t)w * nch * sizeof(float));
    if (!row)
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory encoding a %dx%d image", path, w, h);
    int rc = G_OK;
    if (!out->open(tmp, spec))
        rc = gerror_set(err, G_ERR_IO, "%s: cannot write image: %s", path, goiio_first_line(out->geterror()).c_str());
    for (int y = 0; y < h && rc == G_OK; y++) {
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            float *d = row + (size_t)x * nch;
            for (int c = 0; c < ch; c++)
                d[c] = c == spec.alpha_channel ? img->pixels[i * ch + c] : (float)(img->pixels[i * ch + c] * scale);
            for (int k = 0; k < n; k++)
                d[ch + k] = (float)(sp->values[i * n + k] * scale);
        }
        if (!out->write_scanline(spec.y + y, 0, TypeDesc::FLOAT, row))
            rc = gerror_set(err, G_ERR_IO, "%s: cannot write image: %s", path,
                            goiio_first_line(out->geterror()).c_str());
    }
    if (rc == G_OK && !out->close())
        rc = gerror_set(err, G_ERR_IO, "%s: cannot write image: %s", path, goiio_first_line(out->geterror()).c_str());
    gmem_free(row);
    return rc;
}

// How the colour channels of 8-bit files are encoded: the sRGB transfer function, or as they are (display
// values already, from a display transform).
enum Encoding { ENCODE_SRGB, ENCODE_AS_IS };

int write_pixels(ImageOutput *out, const char *path, const char *tmp, const GImage *img, double scale,
                 bool float_out, Encoding enc, const GImageWriteOptions *opt, GError *err)
{
    if (opt && opt->spectra) {
        if (strcmp(out->format_name(), "openexr") != 0)
            return gerror_set(err, G_ERR_INVALID, "%s: only OpenEXR files store spectra, not %s files", path,
                              out->format_name());
        return write_spectral(out, path, tmp, img, scale, opt, err);
    }
    const int w = img->width, h = img->height;
    int ch = img->channels;
    int alpha = (ch == 2 || ch == 4) ? ch - 1 : -1;
    int out_ch = ch;
    if (alpha >= 0 && !out->supports("alpha")) { // e.g. JPEG, HDR: drop alpha
        out_ch = ch - 1;
        alpha = -1;
    }
    ImageSpec spec(w, h, out_ch, float_out ? TypeDesc::FLOAT : TypeDesc::UINT8);
    spec.alpha_channel = alpha;
    if (opt && opt->full_width > 0 && out->supports("displaywindow")) { // a crop: data window inside the display
        spec.x = opt->x;
        spec.y = opt->y;
        spec.full_x = spec.full_y = 0;
        spec.full_width = opt->full_width;
        spec.full_height = opt->full_height;
        if (opt->note)
            spec.attribute("generic:note", opt->note);
    }
    spec.attribute("oiio:ColorSpace", float_out ? "Linear" : "sRGB");
    if (alpha >= 0 && !float_out)
        spec.attribute("oiio:UnassociatedAlpha", 1); // our pixels carry straight alpha
    const size_t npix = (size_t)w * h;
    const size_t bytes = npix * out_ch * (float_out ? sizeof(float) : 1);
    unsigned char *buf = (unsigned char *)gmem_alloc(bytes);
    if (!buf)
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory encoding a %dx%d image", path, w, h);
    for (size_t i = 0; i < npix; i++) {
        const float *s = img->pixels + i * ch;
        for (int c = 0; c < out_ch; c++) {
            bool is_alpha = c == alpha;
            double v = is_alpha ? s[c] : s[c] * scale;
            if (float_out) {
                ((float *)buf)[i * out_ch + c] = (float)v;
                continue;
            }
            if (!(v > 0.0)) // also NaN
                v = 0.0;
            if (!is_alpha && enc == ENCODE_SRGB)
                v = gimage_srgb_encode(v);
            if (v > 1.0)
                v = 1.0;
            buf[i * out_ch + c] = (unsigned char)(v * 255.0 + 0.5);
        }
    }
    int rc = G_OK;
    if (!out->open(tmp, spec))
        rc = gerror_set(err, G_ERR_IO, "%s: cannot write image: %s", path, goiio_first_line(out->geterror()).c_str());
    else if (!out->write_image(float_out ? TypeDesc::FLOAT : TypeDesc::UINT8, buf) || !out->close())
        rc = gerror_set(err, G_ERR_IO, "%s: cannot write image: %s", path, goiio_first_line(out->geterror()).c_str());
    gmem_free(buf);
    return rc;
}

// Decodes a file written by name in full: a write error the writer missed shows as a short or broken file.
int verify_written(const char *path, const char *tmp, const GImage *img, GError *err)
{
    auto in = ImageInput::open(tmp);
    if (!in)
        return gerror_set(err, G_ERR_IO, "%s: cannot write image: the written file does not read back: %s", path,
                          goiio_first_line(OIIO::geterror()).c_str());
    const ImageSpec &spec = in->spec();
    std::vector<unsigned char> scratch;
    bool ok = spec.width == img->width && spec.height == img->height;
    if (ok) {
        scratch.resize((size_t)spec.width * spec.height * spec.nchannels * spec.format.size());
        ok = in->read_image(0, 0, 0, spec.nchannels, spec.format, scratch.data());
    }
    if (!ok)
        return gerror_set(err, G_ERR_IO, "%s: cannot write image: the written file does not read back: %s", path,
                          goiio_first_line(in->geterror()).c_str());
    return G_OK;
}

int check_output_impl(const char *path, GError *err)
{
    if (!path || !*path)
        return gerror_set(err, G_ERR_INVALID, "no image file name given");
    int rc = gfile_check_output(path, err);
    if (rc != G_OK)
        return rc;
    try {
        auto out = ImageOutput::create(path);
        if (!out) {
            const char *dot = strrchr(path, '.'), *slash = strrchr(path, '/');
            std::string why = goiio_first_line(OIIO::geterror());
            if (dot && (!slash || dot > slash))
                return gerror_set(err, G_ERR_IO, "%s: cannot write image: this OpenImageIO has no writer for '%s' "
                                  "files (%s)", path, dot, why.c_str());
            return gerror_set(err, G_ERR_IO, "%s: cannot write image: no extension to choose the format by", path);
        }
        return G_OK;
    } catch (...) {
        return gerror_set(err, G_ERR_IO, "%s: cannot write image: OpenImageIO failed", path);
    }
}

// shown = img's pixels times scale through the display transform d (RGB or RGBA; grey is refused).
int display_pixels(const char *path, const GImage *img, double scale, const GImageDisplay *d, GImage *shown,
                   GError *err)
{
    if (img->channels != 3 && img->channels != 4)
        return gerror_set(err, G_ERR_INVALID, "%s: a display transform needs an RGB or RGBA image", path);
    const size_t n = (size_t)img->width * img->height * img->channels;
    float *p = (float *)gmem_alloc(n * sizeof(float));
    if (!p)
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory for the display transform", path);
    for (size_t i = 0; i < n; i++)
        p[i] = img->channels == 4 && i % 4 == 3 ? img->pixels[i] : (float)(img->pixels[i] * scale);
    GOiioOps ops;
    goiio_display_ops(&ops);
    int rc = ops.display_transform(d->config, d->confine_dir, d->display, d->view, p, img->width, img->height,
                                   img->channels, err);
    if (rc != G_OK) {
        gmem_free(p);
        return rc;
    }
    *shown = GImage{img->width, img->height, img->channels, p};
    return G_OK;
}

int write_impl(const char *path, const GImage *img, const GImageWriteOptions *opt, GError *err)
{
    double exposure = opt ? opt->exposure : 0.0;
    if (!std::isfinite(exposure))
        return gerror_set(err, G_ERR_INVALID, "%s: exposure must be finite", path);
    int rc = check_output_impl(path, err);
    if (rc != G_OK)
        return rc;
    double scale = exp2(exposure);
    Encoding enc = ENCODE_SRGB;
    GImage shown = {0, 0, 0, nullptr}; // the pixels through the display transform
    if (opt && opt->display) {
        if ((rc = display_pixels(path, img, scale, opt->display, &shown, err)) != G_OK)
            return rc;
        img = &shown;
        scale = 1.0;
        enc = ENCODE_AS_IS;
    }
    struct Release { GImage *g; ~Release() { gmem_free(g->pixels); } } release{&shown};
    auto out = ImageOutput::create(path);
    if (!out)
        return gerror_set(err, G_ERR_IO, "%s: cannot write image: %s", path,
                          goiio_first_line(OIIO::geterror()).c_str());
    GFileOutput file;
    if ((rc = gfile_output_begin(&file, path, err)) != G_OK)
        return rc;
    FdWriter proxy(file.temp, file.fd);
    // OpenImageIO 2.4's TIFF writer links its EXIF directory wrongly through a proxy: it writes the
    // temporary by name (libtiff checks its writes), and the result is decoded again before it is kept.
    const bool by_name = !strcmp(out->format_name(), "tiff") || !out->supports("ioproxy");
    try {
        if (!by_name && !out->set_ioproxy(&proxy))
            rc = gerror_set(err, G_ERR_IO, "%s: cannot write image: the %s writer cannot write through a descriptor",
                            path, out->format_name());
        else
            rc = write_pixels(out.get(), path, file.temp, img, scale, float_extension(path), enc, opt, err);
        out.reset(); // before the proxy goes
        if (rc == G_OK && by_name)
            rc = verify_written(path, file.temp, img, err);
    } catch (...) {
        gfile_output_abort(&file);
        throw;
    }
    if (rc == G_OK && proxy.error_number())
        rc = gerror_set(err, G_ERR_IO, "%s: cannot write image: %s", path, strerror(proxy.error_number()));
    if (rc == G_OK)
        rc = gfile_output_commit(&file, by_name ? -1 : (long long)proxy.end(), path, err);
    else
        gfile_output_abort(&file);
    return rc;
}

// ---- the entries from C: no exception may leave them ----

int image_read(const char *path, unsigned flags, GImage *img, GError *err)
{
    if (!img)
        return gerror_set(err, G_ERR_INVALID, "no image given");
    img->width = img->height = img->channels = 0;
    img->pixels = nullptr;
    if (!path || !*path)
        return gerror_set(err, G_ERR_INVALID, "no image file name given");
    if ((flags & GIMAGE_READ_RGB) && (flags & GIMAGE_READ_RGBA))
        return gerror_set(err, G_ERR_INVALID, "%s: GIMAGE_READ_RGB and GIMAGE_READ_RGBA exclude each other", path);
    return goiio_guarded(path, "reading the image", "read image", err,
                         [&] { return read_impl(path, flags, img, err); });
}

// A file's windows and channel count, with open_checked's checks.
int read_header(const char *path, GImageWindow *win, int *channels, GError *err)
{
    return goiio_guarded(path, "reading the image header", "read image", err, [&] {
        std::unique_ptr<ImageInput> in;
        int rc = goiio_open_checked(path, nullptr, &in, err);
        if (rc != G_OK)
            return rc;
        const ImageSpec &spec = in->spec();
        *win = GImageWindow{spec.x - spec.full_x, spec.y - spec.full_y, spec.width, spec.height, spec.full_width,
                            spec.full_height, {0}};
        std::string note = spec.get_string_attribute("generic:note");
        snprintf(win->note, sizeof win->note, "%s", note.c_str());
        *channels = spec.nchannels;
        return (int)G_OK;
    });
}

int image_info(const char *path, int *width, int *height, int *channels, GError *err)
{
    if (!path || !*path)
        return gerror_set(err, G_ERR_INVALID, "no image file name given");
    GImageWindow win;
    int nch, rc = read_header(path, &win, &nch, err);
    if (rc != G_OK)
        return rc;
    if (width)
        *width = win.width;
    if (height)
        *height = win.height;
    if (channels)
        *channels = nch;
    return G_OK;
}

int image_window(const char *path, GImageWindow *win, GError *err)
{
    int nch;
    return read_header(path, win, &nch, err);
}

int image_write(const char *path, const GImage *img, const GImageWriteOptions *opt, GError *err)
{
    if (!path || !*path)
        return gerror_set(err, G_ERR_INVALID, "no image file name given");
    if (!img || !img->pixels || img->width <= 0 || img->height <= 0 || img->channels < 1 || img->channels > 4)
        return gerror_set(err, G_ERR_INVALID, "%s: invalid image to write", path);
    return goiio_guarded(path, "writing the image", "write image", err,
                         [&] { return write_impl(path, img, opt, err); });
}

} // namespace

const GOiioHost *goiio_host;

int goiio_image_info(const char *path, int *width, int *height, int *channels, GError *err)
{
    return image_info(path, width, height, channels, err);
}

extern "C" __attribute__((visibility("default"))) int generic_oiio_module(unsigned abi, const GOiioHost *host,
                                                                          GOiioOps *ops)
{
    if (abi != GOIIO_MODULE_ABI || !host || !ops)
        return -1;
    goiio_host = host;
    ops->image_read = image_read;
    ops->image_info = image_info;
    ops->image_write = image_write;
    ops->image_check_output = check_output_impl;
    ops->image_window = image_window;
    goiio_texsys_ops(ops);
    goiio_display_ops(ops);
    goiio_spectra_ops(ops);
    return 0;
}
