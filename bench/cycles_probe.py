# cycles_probe.py - Blender's Python: the twin of bench/scenes/cycles_probe.scene for Blender Cycles (a red sphere and
# a blue box on a grey ground under examples/scenes/sky.hdr), rendered on the CPU and written as an EXR (linear, no
# view transform); prints "cycles-render-seconds WALL CPU" as bench/cycles_cornell.py does.
#   blender -b --factory-startup -P bench/cycles_probe.py -- OUT.exr SIZE SAMPLES THREADS SEED
# gtrace's y-up coordinates (x, y, z) are Blender's (x, -z, y). The probe turned by -90 degrees about x in the scene
# file has its own z-up axes along Blender's, and gtrace maps a lat-long probe as Blender's Environment Texture does
# (include/generic/services/probe.h), so the world is that texture, unrotated, of strength 1, importance sampled
# (Cycles' automatic map; MIS against the surfaces' sampling, as gtrace's `technique reference`). The ground plane,
# infinite in gtrace, is a 2000-unit square. Lambert surfaces, 8 bounces, no clamping, denoising or adaptive
# sampling, a one-pixel box filter: as bench/cycles_cornell.py.
import math
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cycles_common import arguments, blender, diffuse, render  # noqa: E402

out, size, samples, threads, seed, rest = arguments()
here = os.path.dirname(os.path.abspath(__file__))

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene




bpy.ops.mesh.primitive_plane_add(size=2000.0, location=(0.0, 0.0, 0.0))
bpy.context.active_object.data.materials.append(diffuse("ground", (0.5, 0.5, 0.5)))

bpy.ops.mesh.primitive_uv_sphere_add(segments=128, ring_count=64, radius=0.6, location=blender((-0.9, 0.6, 0.0)))
bpy.ops.object.shade_smooth()
bpy.context.active_object.data.materials.append(diffuse("red", (0.7, 0.25, 0.2)))

lo, hi = (0.3, 0.0, -0.7), (1.1, 0.8, 0.1)
bpy.ops.mesh.primitive_cube_add(size=1.0, location=blender([(a + b) / 2 for a, b in zip(lo, hi)]))
o = bpy.context.active_object
o.scale = (hi[0] - lo[0], hi[2] - lo[2], hi[1] - lo[1])
o.data.materials.append(diffuse("blue", (0.25, 0.4, 0.7)))

# the camera: from <0.4, 1.7, 5.5> towards <0, 0.55, 0>, y up, vertical field of view 38 degrees
cam_data = bpy.data.cameras.new("camera")
cam_data.sensor_fit = "VERTICAL"
cam_data.angle = math.radians(38.0)
cam = bpy.data.objects.new("camera", cam_data)
eye, at = (0.4, 1.7, 5.5), (0.0, 0.55, 0.0)
cam.location = blender(eye)
d = [b - a for a, b in zip(blender(eye), blender(at))]
cam.rotation_euler = (math.atan2(math.hypot(d[0], d[1]), -d[2]), 0.0, math.atan2(d[1], d[0]) - math.pi / 2)
scene.collection.objects.link(cam)
scene.camera = cam

world = bpy.data.worlds.new("sky")
world.use_nodes = True
env = world.node_tree.nodes.new("ShaderNodeTexEnvironment")
env.image = bpy.data.images.load(os.path.join(here, "..", "examples", "scenes", "sky.hdr"))
env.interpolation = "Linear"
world.node_tree.links.new(env.outputs["Color"], world.node_tree.nodes["Background"].inputs["Color"])
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 1.0
world.cycles.sampling_method = "AUTOMATIC"
scene.world = world

render(scene, out, size, samples, threads, seed)
