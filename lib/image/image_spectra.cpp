// image_spectra.cpp - reading the spectral channels of an OpenEXR in the layout of Fichet, Pacanowski and Wilkie
// 2021 (include/generic/services/image.h, GImageSpectraBuf); part of the OpenImageIO module libgeneric_oiio.so.
#include "generic/services/image.h"
#include "generic/memory.h"
#define GOIIO_MODULE_SOURCE
#include "oiio_module.h"
#include "image_oiio.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

using OIIO::ImageInput;
using OIIO::ImageSpec;
using OIIO::TypeDesc;

namespace {


// The channel-name prefix of a layer: S0. (emissive: the first Stokes component, the radiance) or T. (reflective).
const char *layer_prefix(GImageSpectraLayer layer)
{
    return layer == GIMAGE_SPECTRA_REFLECTIVE ? "T." : "S0.";
}

// The wavelength of a channel named PREFIX<digits>[,<digits>]nm (PREFIX: layer_prefix): 1 and *nm; 0 for a channel
// of no layer's diagonal (another prefix; in the reflective layer, a re-radiation channel T.<nm>nm.<nm>nm, which
// is not read); -1 for a name of the layer that is malformed, has more than 15 digits or gives 0 nm. The digits
// make an integer below 2^53, divided by an exact power of ten: the double nearest to the written decimal.
int spectral_wavelength(const std::string &name, GImageSpectraLayer layer, double *nm)
{
    const char *prefix = layer_prefix(layer);
    const size_t plen = strlen(prefix);
    if (name.compare(0, plen, prefix) != 0)
        return 0;
    static const double pow10[16] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                     1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
    long long digits = 0;
    int ndigits = 0, decimals = 0;
    bool comma = false;
    const char *p = name.c_str() + plen;
    for (;; p++) {
        if (*p >= '0' && *p <= '9') {
            if (++ndigits > 15)
                return -1;
            digits = digits * 10 + (*p - '0');
            decimals += comma;
        } else if (*p == ',' && !comma && ndigits > 0) {
            comma = true;
        } else {
            break;
        }
    }
    if (layer == GIMAGE_SPECTRA_REFLECTIVE && ndigits > 0 && strncmp(p, "nm.", 3) == 0)
        return 0; // re-radiation (bispectral) from this wavelength to another
    if (ndigits == 0 || (comma && decimals == 0) || strcmp(p, "nm") != 0 || digits == 0)
        return -1;
    *nm = (double)digits / pow10[decimals];
    return 1;
}

// gmem memory released when the holder goes (an error or an exception on the way).
struct GmemHold {
    void *p = nullptr;
    ~GmemHold() { gmem_free(p); }
};

// The budget's reservation for the values handed out, released when the holder goes (an error on the way).
struct BudgetHold {
    size_t bytes = 0;
    ~BudgetHold() { if (bytes) gmem_budget_release(bytes); }
};

int read_spectra_impl(const char *path, GImageSpectraLayer layer, GImageSpectraBuf *out, GError *err)
{
    std::unique_ptr<ImageInput> in;
    int rc = goiio_open_checked(path, nullptr, &in, err);
    if (rc != G_OK)
        return rc;
    const ImageSpec spec = in->spec();
    const int w = spec.width, h = spec.height, nch = spec.nchannels;
    std::vector<std::pair<double, int>> waves; // wavelength, channel
    for (int c = 0; c < nch && c < (int)spec.channelnames.size(); c++) {
        double nm = 0.0;
        int k = spectral_wavelength(spec.channelnames[c], layer, &nm);
        if (k < 0)
            return gerror_set(err, G_ERR_IO, "%s: channel '%s' is not a wavelength of the spectral layout "
                              "(%s<nm above 0, at most 15 digits, a comma before the decimals>nm, e.g. "
                              "%s550,000000nm)", path, spec.channelnames[c].c_str(), layer_prefix(layer),
                              layer_prefix(layer));
        if (k > 0)
            waves.emplace_back(nm, c);
    }
    const int n = (int)waves.size();
    if (n > GIMAGE_MAX_WAVELENGTHS)
        return gerror_set(err, G_ERR_IO, "%s: %d spectral channels, more than the %d wavelengths supported", path, n,
                          GIMAGE_MAX_WAVELENGTHS);
    std::sort(waves.begin(), waves.end());
    for (int k = 1; k < n; k++)
        if (waves[k].first == waves[k - 1].first)
            return gerror_set(err, G_ERR_IO, "%s: channels '%s' and '%s' are the same wavelength (%g nm)", path,
                              spec.channelnames[waves[k - 1].second].c_str(),
                              spec.channelnames[waves[k].second].c_str(), waves[k].first);
    if (n == 0) {
        *out = GImageSpectraBuf{w, h, 0, nullptr, nullptr, 0};
        return G_OK;
    }
    // open_checked has held w x h x nch floats to the budget already; the values alone must fit it too
    const size_t npix = (size_t)w * h, budget = gimage_memory_budget();
    if ((double)npix * n * sizeof(float) > (double)budget)
        return gerror_set(err, G_ERR_NOMEM, "%s: %d values per pixel of a %dx%d image need %.0f MiB, more than the "
                          "memory limit of %zu MiB (--memory-limit, GENERIC_MEMORY_LIMIT_MB)", path, n, w, h,
                          (double)npix * n * sizeof(float) / 1048576.0, budget >> 20);
    // The channels from the first spectral one to the last are decoded a band of rows at a time (a tiled file
    // at once), then put in the order of their wavelengths.
    int c0 = nch, c1 = 0;
    for (const auto &wv : waves) {
        c0 = std::min(c0, wv.second);
        c1 = std::max(c1, wv.second + 1);
    }
    const int span = c1 - c0, band = spec.tile_width > 0 ? h : std::min(h, 64);
    // the values outlive this call: held to the budget from before their allocation until gimage_spectra_free
    BudgetHold held;
    char what[96];
    snprintf(what, sizeof what, "the spectra of a %dx%d image at %d wavelengths", w, h, n);
    if ((rc = gmem_budget_reserve(npix * n * sizeof(float), what, err)) != G_OK)
        return rc;
    held.bytes = npix * n * sizeof(float);
    GmemHold wl, vals, scratch;
    wl.p = gmem_alloc((size_t)n * sizeof(double));
    vals.p = gmem_alloc(npix * n * sizeof(float));
    scratch.p = gmem_alloc((size_t)w * band * span * sizeof(float));
    if (!wl.p || !vals.p || !scratch.p)
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory for the spectra of a %dx%d image", path, w, h);
    float *v = (float *)vals.p, *raw = (float *)scratch.p;
    for (int y = 0; y < h; y += band) {
        const int y1 = std::min(y + band, h);
        const bool ok = spec.tile_width > 0 ? in->read_image(0, 0, c0, c1, TypeDesc::FLOAT, raw)
                                            : in->read_scanlines(0, 0, spec.y + y, spec.y + y1, 0, c0, c1,
                                                                 TypeDesc::FLOAT, raw);
        if (!ok)
            return gerror_set(err, G_ERR_IO, "%s: cannot decode image: %s", path,
                              goiio_first_line(in->geterror()).c_str());
        for (size_t i = 0; i < (size_t)(y1 - y) * w; i++) {
            const float *s = raw + i * span;
            float *d = v + ((size_t)y * w + i) * n;
            for (int k = 0; k < n; k++)
                d[k] = s[waves[k].second - c0];
        }
    }
    in->close();
    double *l = (double *)wl.p;
    for (int k = 0; k < n; k++)
        l[k] = waves[k].first;
    *out = GImageSpectraBuf{w, h, n, l, v, held.bytes};
    wl.p = vals.p = nullptr; // now out's
    held.bytes = 0;
    return G_OK;
}


int image_read_spectra(const char *path, GImageSpectraLayer layer, GImageSpectraBuf *out, GError *err)
{
    if (!out)
        return gerror_set(err, G_ERR_INVALID, "no spectra given");
    *out = GImageSpectraBuf{0, 0, 0, nullptr, nullptr, 0};
    if (!path || !*path)
        return gerror_set(err, G_ERR_INVALID, "no image file name given");
    return goiio_guarded(path, "reading the spectra", "read image", err,
                         [&] { return read_spectra_impl(path, layer, out, err); });
}

} // namespace

void goiio_spectra_ops(GOiioOps *ops)
{
    ops->image_read_spectra = image_read_spectra;
}
