// image.cpp - the OpenImageIO shim: float images in and out (see include/generic/image.h).
#include "generic/image.h"
#include "generic/memory.h"

#include <OpenImageIO/imageio.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

using OIIO::ImageInput;
using OIIO::ImageOutput;
using OIIO::ImageSpec;
using OIIO::TypeDesc;

namespace {

// OpenImageIO messages can span lines; keep the first non-empty one.
std::string first_line(const std::string &s)
{
    size_t b = s.find_first_not_of("\n ");
    if (b == std::string::npos)
        return "unknown reason";
    size_t e = s.find('\n', b);
    return s.substr(b, e == std::string::npos ? std::string::npos : e - b);
}

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

mode_t process_umask()
{
    mode_t mask = 022;
    if (FILE *f = fopen("/proc/self/status", "r")) {
        char line[256];
        while (fgets(line, sizeof line, f))
            if (!strncmp(line, "Umask:", 6)) {
                mask = (mode_t)strtol(line + 6, nullptr, 8);
                break;
            }
        fclose(f);
    }
    return mask;
}

int read_impl(const char *path, unsigned flags, GImage *img, GError *err)
{
    ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1); // keep straight alpha as the file stores it
    auto in = ImageInput::open(path, &config);
    if (!in)
        return gerror_set(err, G_ERR_IO, "%s: cannot read image: %s", path, first_line(OIIO::geterror()).c_str());
    const ImageSpec spec = in->spec();
    const int w = spec.width, h = spec.height, nch = spec.nchannels;
    if (w <= 0 || h <= 0 || nch <= 0 || (long long)w * h > (1LL << 31) / 4)
        return gerror_set(err, G_ERR_IO, "%s: unsupported image size %dx%d with %d channels", path, w, h, nch);
    const size_t npix = (size_t)w * h;
    float *raw = (float *)gmem_calloc(npix * nch, sizeof(float));
    if (!raw)
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory for a %dx%d image", path, w, h);
    if (!in->read_image(0, 0, 0, nch, TypeDesc::FLOAT, raw)) {
        std::string msg = first_line(in->geterror());
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

// Writes the encoded pixels with `out` to tmp; returns a status with the message set.
int write_pixels(ImageOutput *out, const char *path, const char *tmp, const GImage *img, double scale,
                 bool float_out, GError *err)
{
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
            if (!is_alpha)
                v = gimage_srgb_encode(v);
            if (v > 1.0)
                v = 1.0;
            buf[i * out_ch + c] = (unsigned char)(v * 255.0 + 0.5);
        }
    }
    int rc = G_OK;
    if (!out->open(tmp, spec))
        rc = gerror_set(err, G_ERR_IO, "%s: cannot write image: %s", path, first_line(out->geterror()).c_str());
    else if (!out->write_image(float_out ? TypeDesc::FLOAT : TypeDesc::UINT8, buf) || !out->close())
        rc = gerror_set(err, G_ERR_IO, "%s: cannot write image: %s", path, first_line(out->geterror()).c_str());
    gmem_free(buf);
    return rc;
}

int write_impl(const char *path, const GImage *img, const GImageWriteOptions *opt, GError *err)
{
    double exposure = opt ? opt->exposure : 0.0;
    if (!std::isfinite(exposure))
        return gerror_set(err, G_ERR_INVALID, "%s: exposure must be finite", path);
    auto out = ImageOutput::create(path);
    if (!out)
        return gerror_set(err, G_ERR_IO, "%s: cannot write image: %s", path, first_line(OIIO::geterror()).c_str());

    // A temporary in the same directory, keeping the extension, renamed over path when complete.
    std::string p(path);
    size_t slash = p.rfind('/');
    std::string dir = slash == std::string::npos ? std::string() : p.substr(0, slash + 1);
    std::string base = slash == std::string::npos ? p : p.substr(slash + 1);
    size_t dot = base.rfind('.');
    std::string ext = dot == std::string::npos || dot == 0 ? std::string() : base.substr(dot);
    std::string tmpl = dir + "." + base + ".XXXXXX" + ext;
    std::string tmp(tmpl);
    int fd = mkstemps(&tmp[0], (int)ext.size());
    if (fd < 0)
        return gerror_set(err, G_ERR_IO, "%s: cannot create a temporary file next to it: %s", path, strerror(errno));
    struct stat st;
    mode_t mode = stat(path, &st) == 0 ? (st.st_mode & 07777) : (0666 & ~process_umask());
    fchmod(fd, mode);
    close(fd);

    int rc;
    try {
        rc = write_pixels(out.get(), path, tmp.c_str(), img, exp2(exposure), float_extension(path), err);
    } catch (const std::exception &e) {
        rc = gerror_set(err, G_ERR_IO, "%s: cannot write image: %s", path, e.what());
    }
    if (rc == G_OK && rename(tmp.c_str(), path) != 0)
        rc = gerror_set(err, G_ERR_IO, "%s: cannot rename the finished image into place: %s", path, strerror(errno));
    if (rc != G_OK)
        unlink(tmp.c_str());
    return rc;
}

} // namespace

extern "C" {

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
    img->pixels = nullptr;
    if (width <= 0 || height <= 0 || channels < 1 || channels > 4 || (long long)width * height > (1LL << 31) / 4)
        return gerror_set(err, G_ERR_INVALID, "invalid image size %dx%d with %d channels", width, height, channels);
    img->pixels = (float *)gmem_calloc((size_t)width * height * channels, sizeof(float));
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
    img->pixels = nullptr;
    img->width = img->height = img->channels = 0;
}

int gimage_read(const char *path, unsigned flags, GImage *img, GError *err)
{
    if (!img)
        return gerror_set(err, G_ERR_INVALID, "no image given");
    img->width = img->height = img->channels = 0;
    img->pixels = nullptr;
    if (!path || !*path)
        return gerror_set(err, G_ERR_INVALID, "no image file name given");
    if ((flags & GIMAGE_READ_RGB) && (flags & GIMAGE_READ_RGBA))
        return gerror_set(err, G_ERR_INVALID, "%s: GIMAGE_READ_RGB and GIMAGE_READ_RGBA exclude each other", path);
    try {
        return read_impl(path, flags, img, err);
    } catch (const std::exception &e) {
        return gerror_set(err, G_ERR_IO, "%s: cannot read image: %s", path, e.what());
    } catch (...) {
        return gerror_set(err, G_ERR_IO, "%s: cannot read image", path);
    }
}

int gimage_info(const char *path, int *width, int *height, int *channels, GError *err)
{
    if (!path || !*path)
        return gerror_set(err, G_ERR_INVALID, "no image file name given");
    try {
        auto in = ImageInput::open(path);
        if (!in)
            return gerror_set(err, G_ERR_IO, "%s: cannot read image: %s", path, first_line(OIIO::geterror()).c_str());
        const ImageSpec &spec = in->spec();
        if (spec.width <= 0 || spec.height <= 0 || spec.nchannels < 1)
            return gerror_set(err, G_ERR_IO, "%s: invalid image size %dx%d with %d channels", path, spec.width,
                              spec.height, spec.nchannels);
        if (width)
            *width = spec.width;
        if (height)
            *height = spec.height;
        if (channels)
            *channels = spec.nchannels;
        return G_OK;
    } catch (const std::exception &e) {
        return gerror_set(err, G_ERR_IO, "%s: cannot read image: %s", path, e.what());
    }
}

int gimage_write(const char *path, const GImage *img, const GImageWriteOptions *opt, GError *err)
{
    if (!path || !*path)
        return gerror_set(err, G_ERR_INVALID, "no image file name given");
    if (!img || !img->pixels || img->width <= 0 || img->height <= 0 || img->channels < 1 || img->channels > 4)
        return gerror_set(err, G_ERR_INVALID, "%s: invalid image to write", path);
    try {
        return write_impl(path, img, opt, err);
    } catch (const std::exception &e) {
        return gerror_set(err, G_ERR_IO, "%s: cannot write image: %s", path, e.what());
    } catch (...) {
        return gerror_set(err, G_ERR_IO, "%s: cannot write image", path);
    }
}

} // extern "C"
