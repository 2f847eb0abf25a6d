/* sppm.h - stochastic progressive photon mapping (sppm.c): `gtrace --integrator sppm`. */
#ifndef GTRACE_SPPM_H
#define GTRACE_SPPM_H

#include "photons.h"
#include "render/render.h"

/** Bounds of the options (checked by sppm_check). */
#define SPPM_MAX_PASSES 1000000
#define SPPM_MAX_PHOTONS 100000000
#define SPPM_DEFAULT_PASSES 64
#define SPPM_DEFAULT_PHOTONS 100000
#define SPPM_DEFAULT_ALPHA (2.0 / 3.0)
/** Most bytes a batch of stored photons may take (a pass's photons are traced and gathered in batches). */
#define SPPM_BATCH_BYTES (64u << 20)

/** Checks rs's photon options: passes 1..SPPM_MAX_PASSES, photons 1..SPPM_MAX_PHOTONS, radius > 0 and finite (0:
 * the default), alpha in (0, 1] (0: the default); G_ERR_INVALID naming the bound. */
int sppm_check(const RenderSettings *rs, GError *err);

/** Renders s (accel_build must have run) by SPPM (Hachisuka and Jensen 2009): per pass, one camera ray a pixel
 * followed through ideal (delta) surfaces to a visible point, where emission and direct light (light samples,
 * shadowed by every surface) are added; then rs->photons particle paths (photons.h) whose non-ideal hits after the
 * first surface are gathered at the visible points within their radius, and each point's radius and light updated
 * with rs->alpha. Every random number is seeded by the pixel and the pass or by the particle's index, and each
 * point sums its photons in an order fixed by the particles' indices: the image does not depend on the thread
 * count or the crop. fb as render_image; progress by passes. With share (not NULL: a distributed job), this
 * process renders only its band of rows (photon_share_range of fb's height; the other rows of fb stay black) and
 * traces only its range of each batch's paths, share->batch completing every batch before it is gathered: the
 * band's pixels equal a single process's, bit for bit, whatever the number of processes. */
int sppm_render(const Scene *s, const RenderSettings *rs, Framebuffer *fb, RenderStats *st, const PhotonShare *share,
                GError *err);

#endif
