/* node_blend.h - sampling a blend node whose reflection and refraction are different blends (interpolate-one of
 * reflection or refraction), shared by lib/kit/node_blend.c and lib/kit/node_kit.c. Internal. */
#ifndef GENERIC_KIT_NODE_BLEND_H
#define GENERIC_KIT_NODE_BLEND_H

#include "generic/kit/node_kit.h"

/** The blend a node's sampling draws from, given the blends its reflection (refl) and refraction (refr) are: refl
 * when the two are one blend (returns 0); else every child of either once, with weight |w_refl| + |w_refr|
 * (returns 1), so that each of the two is drawn wherever it has a lobe. refl alone (0) when that union has more
 * than GNODE_BLEND_MAX children. */
int gnode_blend_sampled(const GNodeBlend *refl, const GNodeBlend *refr, GNodeBlend *sel);

/** gnode_blend_sample over gnode_blend_sampled's blend: a reflected sample weighs refl's value of white light, a
 * transmitted one refr's (a delta lobe of child m: its weight in that blend over its selection probability), so
 * the estimate is the node's own reflection and refraction even where they blend other children. */
int gnode_blend_sample_split(const GNodeBlend *refl, const GNodeBlend *refr, GSurfPoint *sp, GVec3 out,
                           const GColor *rel_index, double u1, double u2, GMaterialSample *s, GColor *weight);

#endif
