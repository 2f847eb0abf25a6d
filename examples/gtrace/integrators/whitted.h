/* whitted.h - the Whitted integrator (whitted.c): tracing a ray and shading what it hits, the paper's Fig. 4;
 * `gtrace --integrator whitted`, the default. */
#ifndef GTRACE_WHITTED_H
#define GTRACE_WHITTED_H

#include "trace/trace.h"

#include <generic/color.h>

/** Radiance arriving along r (Fig. 4: closest hit, then shade) at recursion depth `depth` (0: a camera ray). out
 * must have storage. */
int whitted_trace(TraceCtx *c, const Ray *r, const Media *media, int depth, GColor *out);

#endif
