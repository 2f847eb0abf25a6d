/* light.h - particle tracing to the camera (light.c): `gtrace --integrator light`. */
#ifndef GTRACE_LIGHT_TRACE_H
#define GTRACE_LIGHT_TRACE_H

#include "photons.h"
#include "render/render.h"

/** Renders s (accel_build must have run) by tracing particles from the lights (photons.h; rs->sppm_passes times
 * rs->sppm_photons paths, the defaults of sppm.h when 0) and connecting every non-ideal surface they meet, the
 * first included, to a pinhole camera: its power reflected towards the camera by the material, over the pixel's
 * area on the image plane, where no surface lies in between. The pixels sum their contributions in the particles'
 * order (the image does not depend on the thread count or the crop). Lights and surfaces seen directly or only
 * through ideal surfaces (mirrors, glass) are not drawn: their light reaches the camera along no connection.
 * G_ERR_UNSUPPORTED for a camera with a lens or an orthographic one (light_check). With share (not NULL: a
 * distributed job), this process traces only its range of each batch's paths and share->batch brings the batch to
 * rank 0, which sums it: rank 0's image equals a single process's, bit for bit; the other ranks' stays black. */
int light_render(const Scene *s, const RenderSettings *rs, Framebuffer *fb, RenderStats *st, const PhotonShare *share,
                 GError *err);

/** What light_render refuses before it starts: sppm_check's bounds, a camera that is not a pinhole. G_OK or the
 * status with its message. */
int light_check(const Scene *s, const RenderSettings *rs, GError *err);

#endif
