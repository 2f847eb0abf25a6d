/* test_gtrace_pixel_stats.h - for the gtrace test programs that compare renders pixel by pixel within noise: the path
 * tracer's samples through each pixel's centre, with the mean and the variance of the mean per pixel and channel.
 * Include after test_gtrace_common.h. */
#ifndef TEST_GTRACE_PIXEL_STATS_H
#define TEST_GTRACE_PIXEL_STATS_H

/* Linear sRGB of a light colour, as the framebuffer stores a pixel. */
static inline void light_rgb(const GColor *c, double rgb[3])
{
    double xyz[3];
    assert_int_equal(gcolor_to_xyz(c, GCOLOR_LIGHT, xyz), G_OK);
    gcie_xyz_to_rgb(xyz, rgb);
}

/* Renders s (accel_build done) at width x height with the path tracer and its independent sampler, n samples (indices
 * first .. first + n - 1, so that disjoint ranges are independent renders) through each pixel's centre, on one
 * thread: mean[3 p + c] and var[3 p + c], the mean of pixel p's samples in channel c and the variance of that mean
 * (the sample variance over n), for p = y * width + x. Every sample must be finite. no_equiangular: the path tracer
 * without equiangular sampling in media (RenderSettings.no_equiangular). */
static inline void pixel_stats_opt(Scene *s, int width, int height, int first, int n, int no_equiangular, double *mean,
                                   double *var)
{
    GError err;
    gerror_clear(&err);
    RenderSettings rs = {.width = width, .height = height, .spp = 1, .depth = s->camera.depth, .threads = 1,
                         .quiet = 1, .integrator = RENDER_PATH, .sampler = SAMPLER_INDEPENDENT,
                         .no_equiangular = no_equiangular};
    Framebuffer fb;
    Renderer *r = NULL;
    if (renderer_create(&r, s, &rs, &fb, &err) != G_OK)
        fail_msg("renderer_create: %s", err.message);
    TraceCtx *c = renderer_thread_ctx(r, 0);
    const Camera *cam = renderer_camera(r);
    const Media *media = renderer_media(r);
    GColor sample = {0};
    assert_int_equal(gcolor_alloc(&sample, s->model), G_OK);
    for (int p = 0; p < width * height; p++) {
        Ray ray;
        camera_ray(cam, p % width + 0.5, p / width + 0.5, &ray);
        double first_rgb[3] = {0}, sum[3] = {0}, sum2[3] = {0}; /* sums of the differences to the first sample */
        for (int i = 0; i < n; i++) {
            GScratchMark mark = gscratch_mark(c->scratch);
            c->weight = 1.0;
            c->rays_left = RENDER_DEFAULT_MAX_RAYS;
            c->capped = 0;
            assert_int_equal(path_trace(c, &ray, media, (uint64_t)p, first + i, SAMPLER_INDEPENDENT, &sample), G_OK);
            gscratch_release(c->scratch, mark);
            assert_true(gcolor_is_finite(&sample));
            double rgb[3];
            light_rgb(&sample, rgb);
            for (int ch = 0; ch < 3; ch++) {
                if (i == 0)
                    first_rgb[ch] = rgb[ch];
                double dev = rgb[ch] - first_rgb[ch];
                sum[ch] += dev;
                sum2[ch] += dev * dev;
            }
        }
        for (int ch = 0; ch < 3; ch++) {
            double m = sum[ch] / n; /* exactly 0 where every sample is the same (a pixel of the sky alone) */
            mean[3 * p + ch] = first_rgb[ch] + m;
            var[3 * p + ch] = n > 1 ? fmax(0.0, sum2[ch] / n - m * m) / (n - 1) : 0.0;
        }
    }
    gcolor_free(&sample);
    renderer_destroy(r);
    framebuffer_free(&fb);
}

/* pixel_stats_opt with the path tracer's defaults. */
static inline void pixel_stats(Scene *s, int width, int height, int first, int n, double *mean, double *var)
{
    pixel_stats_opt(s, width, height, first, n, 0, mean, var);
}

#endif
