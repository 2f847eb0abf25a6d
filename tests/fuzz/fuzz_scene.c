/* fuzz_scene.c - libFuzzer target: gtrace's scene files (examples/gtrace/scenefile/ and everything a scene reaches:
 * objects, meshes, transforms, lights, IES and probe files, media, cameras, includes, the `colormodel` line),
 * loaded from memory inside the private directory (confined to it), built and rendered as a 4x3 crop at one sample
 * per pixel with the Whitted and the path integrator, in two colour models. The entry point, its promises and its
 * bounds on cost are in fuzz_scene_entry.h (shared with tests/test_gtrace_fuzz_regress.c); tests/fuzz/build.mk links
 * this target with gtrace's sources and Embree. `make fuzz` builds and runs it. */
#define GFUZZ_TARGET scene
#include "fuzz_scene_entry.h"

#include "fuzz_target.h"
