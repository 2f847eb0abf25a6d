# cycles_common.py - Blender's Python shared by the Cycles twins (cycles_cornell.py, cycles_probe.py): their
# arguments, gtrace's coordinates in Blender's, a Lambert material, and the render: CPU, 8 bounces of every kind,
# caustics on, no clamping, denoising or adaptive sampling, a one-pixel box filter, a linear 32-bit EXR, and the line
# "cycles-render-seconds WALL CPU" bench/cycles.sh reads.
import sys
import time

import bpy


def arguments():
    """OUT.exr SIZE SAMPLES THREADS SEED [VARIANT...] after Blender's "--"."""
    args = sys.argv[sys.argv.index("--") + 1:]
    return args[0], int(args[1]), int(args[2]), int(args[3]), int(args[4]), args[5:]


def blender(p):
    """gtrace's (x, y, z), y up, as Blender's z-up coordinates."""
    return (p[0], -p[2], p[1])


def diffuse(name, rgb):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nodes = m.node_tree.nodes
    nodes.clear()
    bsdf = nodes.new("ShaderNodeBsdfDiffuse")
    bsdf.inputs["Color"].default_value = (rgb[0], rgb[1], rgb[2], 1.0)
    bsdf.inputs["Roughness"].default_value = 0.0
    output = nodes.new("ShaderNodeOutputMaterial")
    m.node_tree.links.new(bsdf.outputs["BSDF"], output.inputs["Surface"])
    return m


def render(scene, out, size, samples, threads, seed):
    """Renders scene with Cycles as the twins are compared, writes out and prints its wall and CPU seconds."""
    scene.render.engine = "CYCLES"
    cy = scene.cycles
    cy.device = "CPU"
    cy.samples = samples
    cy.seed = seed
    cy.use_adaptive_sampling = False
    cy.use_denoising = False
    cy.max_bounces = 8
    cy.diffuse_bounces = 8
    cy.glossy_bounces = 8
    cy.transmission_bounces = 8
    cy.transparent_max_bounces = 8
    cy.caustics_reflective = True
    cy.caustics_refractive = True
    cy.blur_glossy = 0.0
    cy.sample_clamp_direct = 0.0
    cy.sample_clamp_indirect = 0.0
    cy.pixel_filter_type = "BOX"
    cy.filter_width = 1.0
    cy.use_auto_tile = False
    scene.render.threads_mode = "FIXED"
    scene.render.threads = threads
    scene.render.resolution_x = size
    scene.render.resolution_y = size
    scene.render.resolution_percentage = 100
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.image_settings.exr_codec = "ZIP"
    scene.view_settings.view_transform = "Standard"
    scene.render.filepath = out
    scene.render.use_file_extension = False
    wall, cpu = time.perf_counter(), time.process_time()
    bpy.ops.render.render(write_still=True)
    print("cycles-render-seconds %.4f %.4f" % (time.perf_counter() - wall, time.process_time() - cpu), flush=True)
