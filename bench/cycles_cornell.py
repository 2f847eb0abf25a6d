# cycles_cornell.py - Blender's Python: the twin of examples/scenes/cornell.scene for Blender Cycles, rendered on the
# CPU and written as an EXR (linear, no view transform); prints "cycles-render-seconds WALL CPU" (the render call's
# wall time and the process's CPU time in it: scene sync, BVH build, path tracing, writing) for bench/cycles.sh.
#   blender -b --factory-startup -P bench/cycles_cornell.py -- OUT.exr SIZE SAMPLES THREADS SEED [VARIANT]
# VARIANT cornell (the default) or glossy: the twin of bench/scenes/cycles_glossy.scene, the box with a rough gold
# sphere and a glass sphere instead of the blocks. The gold is a Principled BSDF, metallic, of base colour gold's
# reflectance at normal incidence in linear sRGB (1.0, 0.766, 0.336: Cycles 3.4 fades it to white at grazing angles by
# Schlick's rule, where gtrace's `conductor { metal Au }` has gold's measured complex index); Cycles squares the
# Roughness input (alpha = roughness^2, Principled and Glossy alike) and gtrace's `roughness` is alpha itself, so
# gtrace's 0.25 is Cycles' 0.5 (Cycles 3.4's svm/closure.h: alpha = roughness * roughness). Cycles' GGX is the single
# scattering one: its Multiscatter GGX evaluates a random walk between the facets, noisier and slower than gtrace's
# deterministic compensation of that light (`compensate on`, a few per cent at alpha 0.25), so the twin favours
# Cycles. The glass is a sharp Glass BSDF of IOR 1.5, white (gtrace's `dielectric { index 1.5 }`); Cycles' caustics
# are on and its glossy filter off (no blur: both renderers estimate the same light).
# The twin: gtrace's y-up coordinates (x, y, z) are Blender's (x, -z, y); the boxes, the two rotated blocks and the
# camera (pinhole at <0, 1, 3.9> towards <0, 1, 0>, vertical field of view 38 degrees) are placed as in the scene
# file; lambert reflectances are Diffuse BSDFs (roughness 0, Lambert) of the same linear RGB; the one-sided square
# light (0.5 x 0.5 at height 1.99, radiance rgb 17 12 4) is an area light of power 4 * A * L (Cycles 3.4's area
# light has radiance power / (4 area): measured with the direct light alone, whose patch means then agree with
# gtrace's `--depth 0` within their noise). Path tracing as gtrace's: at most 8 bounces, no clamping, no denoising, no
# adaptive sampling, and a box pixel filter one pixel wide (gtrace averages a pixel's samples with equal weight;
# Cycles' default, a 1.5-pixel Blackman-Harris filter, would blur the noise over neighbouring pixels).
import math
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cycles_common import arguments, blender, diffuse, render  # noqa: E402

out, size, samples, threads, seed, rest = arguments()
variant = rest[0] if rest else "cornell"
if variant not in ("cornell", "glossy"):
    raise SystemExit("cycles_cornell.py: unknown variant " + variant)

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene




white = diffuse("white", (0.73, 0.73, 0.73))
red = diffuse("red", (0.63, 0.065, 0.05))
green = diffuse("green", (0.14, 0.45, 0.09))


def box(lo, hi, material, rotate_y=0.0, translate=(0.0, 0.0, 0.0)):
    """An axis-aligned box lo..hi (gtrace coordinates), rotated about gtrace's y (degrees) and moved."""
    centre = [(a + b) / 2 for a, b in zip(lo, hi)]
    dims = [b - a for a, b in zip(lo, hi)]
    bpy.ops.mesh.primitive_cube_add(size=1.0)
    o = bpy.context.active_object
    o.scale = (dims[0], dims[2], dims[1])
    # a rotation about gtrace's y by t is one about Blender's z by t (both right-handed)
    c, s = math.cos(math.radians(rotate_y)), math.sin(math.radians(rotate_y))
    rx, rz = c * centre[0] + s * centre[2], -s * centre[0] + c * centre[2]
    o.location = blender((rx + translate[0], centre[1] + translate[1], rz + translate[2]))
    o.rotation_euler = (0.0, 0.0, math.radians(rotate_y))
    o.data.materials.append(material)


box((-1.05, -0.05, -1.05), (1.05, 0, 1.05), white)  # floor
box((-1.05, 2, -1.05), (1.05, 2.05, 1.05), white)  # ceiling
box((-1.05, 0, -1.05), (1.05, 2, -1), white)  # back wall
box((-1.05, 0, -1), (-1, 2, 1.05), red)  # left wall
box((1, 0, -1), (1.05, 2, 1.05), green)  # right wall


def sphere(centre, radius, material):
    bpy.ops.mesh.primitive_uv_sphere_add(segments=128, ring_count=64, radius=radius, location=blender(centre))
    o = bpy.context.active_object
    bpy.ops.object.shade_smooth()
    o.data.materials.append(material)


def shader(name, kind, inputs, distribution):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nodes = m.node_tree.nodes
    nodes.clear()
    bsdf = nodes.new(kind)
    bsdf.distribution = distribution
    for key, value in inputs.items():
        bsdf.inputs[key].default_value = value
    output = nodes.new("ShaderNodeOutputMaterial")
    m.node_tree.links.new(bsdf.outputs[0], output.inputs["Surface"])
    return m


if variant == "cornell":
    box((-0.3, 0, -0.3), (0.3, 0.6, 0.3), white, -18, (0.33, 0, 0.35))
    box((-0.3, 0, -0.3), (0.3, 1.2, 0.3), white, 17, (-0.35, 0, -0.33))
else:
    gold = shader("gold", "ShaderNodeBsdfPrincipled", {"Base Color": (1.0, 0.766, 0.336, 1.0), "Metallic": 1.0,
                                                        "Roughness": math.sqrt(0.25)}, "GGX")
    glass = shader("glass", "ShaderNodeBsdfGlass", {"Color": (1.0, 1.0, 1.0, 1.0), "IOR": 1.5}, "SHARP")
    sphere((-0.45, 0.4, -0.35), 0.4, gold)
    sphere((0.45, 0.35, 0.2), 0.35, glass)

radiance, side = (17.0, 12.0, 4.0), 0.5
light = bpy.data.lights.new("lamp", type="AREA")
light.shape = "SQUARE"
light.size = side
light.color = tuple(c / radiance[0] for c in radiance)
light.energy = 4.0 * side * side * radiance[0]
lamp = bpy.data.objects.new("lamp", light)
lamp.location = blender((0.0, 1.99, 0.0))  # an area light emits along its -z: down
scene.collection.objects.link(lamp)

cam_data = bpy.data.cameras.new("camera")
cam_data.sensor_fit = "VERTICAL"
cam_data.angle = math.radians(38.0)
cam = bpy.data.objects.new("camera", cam_data)
cam.location = blender((0.0, 1.0, 3.9))
cam.rotation_euler = (math.pi / 2, 0.0, 0.0)  # looking along Blender's +y, gtrace's -z
scene.collection.objects.link(cam)
scene.camera = cam

world = bpy.data.worlds.new("black")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
scene.world = world

render(scene, out, size, samples, threads, seed)
