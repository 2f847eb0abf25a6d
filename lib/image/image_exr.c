/* image_exr.c - OpenEXR output through OpenEXRCore (see image_exr.h). */
#include "image_exr.h"

#include "exr_core_lib.h"
#include "image_sink.h"

#include "generic/memory.h"

#include <stdio.h>
#include <string.h>

/* OpenEXRCore writes at offsets: the chunks, then the table of their offsets after the header. The sink's message
 * is OpenEXRCore's first error. */
static int64_t sink_write(exr_const_context_t ctxt, void *user, const void *buffer, uint64_t n, uint64_t offset,
                          exr_stream_error_func_ptr_t error_cb)
{
    GImageSink *s = user;
    if (gimage_sink_write(s, buffer, (size_t)n, (long long)offset) != 0) {
        error_cb(ctxt, EXR_ERR_WRITE_IO, "%s", strerror(s->error));
        return -1;
    }
    return (int64_t)n;
}

/* The sink of the write this thread is encoding: OpenEXRCore calls the error handler with the context's lock held,
 * so the handler may not ask the context for its user data (exr_get_user_data takes that lock: a deadlock). */
static _Thread_local GImageSink *current_sink;

static void on_error(exr_const_context_t ctxt, exr_result_t code, const char *msg)
{
    (void)ctxt;
    GImageSink *s = current_sink;
    if (!s || s->message[0])
        return;
    const ExrCoreLib *api = exr_core_lib("", NULL); /* loaded: the context exists */
    snprintf(s->message, sizeof s->message, "%s", msg ? msg : api ? api->get_default_error_message(code) : "error");
}

/* The channel names, by channel count, as OpenImageIO names them (image.h's layouts). */
static const char *const names[4][4] = {{"Y"}, {"R", "G"}, {"R", "G", "B"}, {"R", "G", "B", "A"}};

/* The header: one scanline part, its windows, float channels, ZIP, the crop's note. */
static exr_result_t write_header(const ExrCoreLib *api, exr_context_t ctx, const GImage *img,
                                 const GImageWriteOptions *opt)
{
    const int crop = opt && opt->full_width > 0;
    const int x = crop ? opt->x : 0, y = crop ? opt->y : 0;
    exr_attr_box2i_t display, data;
    display.min.x = display.min.y = 0;
    display.max.x = (crop ? opt->full_width : img->width) - 1;
    display.max.y = (crop ? opt->full_height : img->height) - 1;
    data.min.x = x;
    data.min.y = y;
    data.max.x = x + img->width - 1;
    data.max.y = y + img->height - 1;
    exr_attr_v2f_t centre;
    centre.x = centre.y = 0.0f;
    int part = 0;
    exr_result_t rv = api->add_part(ctx, NULL, EXR_STORAGE_SCANLINE, &part);
    if (rv == EXR_ERR_SUCCESS)
        rv = api->initialize_required_attr(ctx, part, &display, &data, 1.0f, &centre, 1.0f, EXR_LINEORDER_INCREASING_Y,
                                          EXR_COMPRESSION_ZIP);
    for (int c = 0; c < img->channels && rv == EXR_ERR_SUCCESS; c++)
        rv = api->add_channel(ctx, part, names[img->channels - 1][c], EXR_PIXEL_FLOAT, EXR_PERCEPTUALLY_LOGARITHMIC,
                             1, 1);
    if (rv == EXR_ERR_SUCCESS && crop && opt->note)
        rv = api->attr_set_string(ctx, part, "generic:note", opt->note);
    return rv == EXR_ERR_SUCCESS ? api->write_header(ctx) : rv;
}

/* The channel index of the encoder's channel by its name (the file lists channels sorted by name). */
static int channel_index(const char *name, int channels)
{
    for (int c = 0; c < channels; c++)
        if (!strcmp(name, names[channels - 1][c]))
            return c;
    return -1;
}

/* Encodes the pixels a chunk of scanlines at a time, copied scaled into buf (lines rows). Unscaled values are copied
 * as they are: every bit, a signalling NaN's too (a product would quiet it). */
static exr_result_t write_chunks(const ExrCoreLib *api, exr_context_t ctx, const GImage *img, int y0, double scale,
                                 int lines, float *buf)
{
    const int ch = img->channels, alpha = (ch == 2 || ch == 4) ? ch - 1 : -1;
    const size_t stride = (size_t)img->width * ch;
    exr_encode_pipeline_t enc = EXR_ENCODE_PIPELINE_INITIALIZER;
    int started = 0;
    exr_result_t rv = EXR_ERR_SUCCESS;
    for (int y = 0; y < img->height && rv == EXR_ERR_SUCCESS; y += lines) {
        const int n = img->height - y < lines ? img->height - y : lines;
        const float *src = img->pixels + (size_t)y * stride;
        for (size_t i = 0; i < (size_t)n * stride; i += (size_t)ch)
            for (int k = 0; k < ch; k++)
                buf[i + k] = k == alpha || scale == 1.0 ? src[i + k] : (float)(src[i + k] * scale);
        exr_chunk_info_t info;
        rv = api->write_scanline_chunk_info(ctx, 0, y0 + y, &info);
        if (rv == EXR_ERR_SUCCESS)
            rv = started ? api->encoding_update(ctx, 0, &info, &enc) : api->encoding_initialize(ctx, 0, &info, &enc);
        if (rv != EXR_ERR_SUCCESS)
            break;
        for (int c = 0; c < enc.channel_count; c++) {
            exr_coding_channel_info_t *out = &enc.channels[c];
            int k = channel_index(out->channel_name, ch);
            if (k < 0)
                return EXR_ERR_INVALID_ARGUMENT;
            out->encode_from_ptr = (const uint8_t *)(buf + k);
            out->user_pixel_stride = (int32_t)(ch * sizeof(float));
            out->user_line_stride = (int32_t)(stride * sizeof(float));
            out->user_bytes_per_element = sizeof(float);
            out->user_data_type = EXR_PIXEL_FLOAT;
        }
        if (!started && (rv = api->encoding_choose_default_routines(ctx, 0, &enc)) != EXR_ERR_SUCCESS)
            break;
        started = 1;
        rv = api->encoding_run(ctx, 0, &enc);
    }
    exr_result_t rd = started ? api->encoding_destroy(ctx, &enc) : EXR_ERR_SUCCESS;
    return rv != EXR_ERR_SUCCESS ? rv : rd;
}

/* Writes the file into the open temporary: G_OK or G_ERR_IO/G_ERR_NOMEM. */
static int encode_exr(const ExrCoreLib *api, GImageSink *sink, const char *path, const GImage *img,
                      const GImageWriteOptions *opt, double scale, GError *err)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = on_error;
    init.alloc_fn = gmem_alloc;
    init.free_fn = gmem_free;
    init.user_data = sink;
    init.write_fn = sink_write;
    exr_context_t ctx = NULL;
    current_sink = sink;
    exr_result_t rv = api->start_write(&ctx, path, EXR_WRITE_FILE_DIRECTLY, &init);
    if (rv == EXR_ERR_SUCCESS)
        rv = write_header(api, ctx, img, opt);
    int32_t lines = 0;
    if (rv == EXR_ERR_SUCCESS)
        rv = api->get_scanlines_per_chunk(ctx, 0, &lines);
    if (rv == EXR_ERR_SUCCESS && lines < 1)
        rv = EXR_ERR_INVALID_ARGUMENT;
    float *buf = NULL;
    if (rv == EXR_ERR_SUCCESS) {
        int rows = lines < img->height ? lines : img->height;
        buf = gmem_alloc((size_t)rows * img->width * img->channels * sizeof(float));
        rv = buf ? write_chunks(api, ctx, img, opt && opt->full_width > 0 ? opt->y : 0, scale, lines, buf)
                 : EXR_ERR_OUT_OF_MEMORY;
    }
    gmem_free(buf);
    exr_result_t rf = ctx ? api->finish(&ctx) : EXR_ERR_SUCCESS; /* writes the chunks' offsets */
    current_sink = NULL;
    if (rv == EXR_ERR_SUCCESS)
        rv = rf;
    if (rv == EXR_ERR_OUT_OF_MEMORY)
        return gerror_set(err, G_ERR_NOMEM, "%s: out of memory encoding a %dx%d image", path, img->width,
                          img->height);
    if (rv != EXR_ERR_SUCCESS)
        return gerror_set(err, G_ERR_IO, "%s: cannot write image: %s", path,
                          sink->error ? strerror(sink->error)
                                      : sink->message[0] ? sink->message : api->get_default_error_message(rv));
    return G_OK;
}

int gimage_exr_write(const char *path, const GImage *img, const GImageWriteOptions *opt, double scale, GError *err)
{
    if (opt && (opt->spectra || opt->display))
        return gerror_set(err, G_ERR_INVALID, "%s: spectra and display transforms are written through OpenImageIO",
                          path);
    const ExrCoreLib *api = exr_core_lib(path, err);
    if (!api)
        return G_ERR_IO;
    GImageSink sink;
    int rc = gimage_sink_begin(&sink, path, err);
    if (rc != G_OK)
        return rc;
    rc = encode_exr(api, &sink, path, img, opt, scale, err);
    return gimage_sink_end(&sink, rc, path, err);
}
