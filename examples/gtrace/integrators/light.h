/* light.h - particle tracing to the camera (light.c): `gtrace --integrator light`. */
#ifndef GTRACE_LIGHT_TRACE_H
#define GTRACE_LIGHT_TRACE_H

#include "render/render.h"

/** Renders s (accel_build must have run) by tracing particles from the lights (photons.h; rs->sppm_passes times
 * rs->sppm_photons paths, the defaults of sppm.h when 0) and connecting every non-ideal surface they meet, the
 * first included, to a pinhole camera: its power reflected towards the camera by the material, over the pixel's
 * area on the image plane, where no surface lies in between. The pixels sum their contributions in the particles'
 * order (the image does not depend on the thread count or the crop). Lights and surfaces seen directly or only
 * through ideal surfaces (mirrors, glass) are not drawn: their light reaches the camera along no connection.
 * G_ERR_UNSUPPORTED for a camera with a lens or an orthographic one. */
int light_render(const Scene *s, const RenderSettings *rs, Framebuffer *fb, RenderStats *st, GError *err);

#endif
