/* textures.h - every texture header at once, for programs that build texture trees in C: the built-in nodes
 * (nodes.h) and generators (generators.h), their shape trees (shapes.h), affine maps (affine.h), noise
 * (noise.h) and texture systems (texsys.h). Writers of nodes and generators of their own include what they use:
 * node_kit.h, texture.h (ggenerator_new), noise.h, texture_parse.h. */
#ifndef GENERIC_TEXTURES_H
#define GENERIC_TEXTURES_H

#include "kit/affine.h"
#include "generators.h"
#include "nodes.h"
#include "kit/noise.h"
#include "kit/shapes.h"
#include "services/texsys.h"
#include "texture.h"

#endif
