"""The unit calibration of scripts/cycles_compare.sh (docs/path-tracing.md, "Against Cycles"):
what Cycles makes of its light settings, measured on a white Lambertian square (Diffuse BSDF,
colour 1, roughness 0) seen from above, direct light only, written as one line per light kind:

    emission  strength S, colour 1          -> radiance seen directly            (expect S)
    world     background colour C, strength 1 -> radiance of a camera ray that misses (C)
    sun       strength S, straight down      -> the square's radiance            (S/pi)
    point     power P W, radius 0, 1 m above -> the square's radiance below it   (P/(4 pi) / pi)

    blender -b --factory-startup -P scripts/cycles_units_blender.py -- OUT_DIR

A comparison tool, not part of rayo. rayo's side of each unit is in docs/path-tracing.md, "Units".
"""

import math
import os
import sys

import bpy


def white_lambert():
    mat = bpy.data.materials.new("white")
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
    diffuse.inputs["Roughness"].default_value = 0.0
    links.new(diffuse.outputs["BSDF"], nodes.new("ShaderNodeOutputMaterial").inputs["Surface"])
    return mat


def emitter(strength):
    mat = bpy.data.materials.new("emitter")
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    emission = nodes.new("ShaderNodeEmission")
    emission.inputs["Strength"].default_value = strength
    links.new(emission.outputs["Emission"], nodes.new("ShaderNodeOutputMaterial").inputs["Surface"])
    return mat


def centre_value(scene, path):
    """Renders the 9 x 9 image and returns its centre pixel's red channel."""
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True)
    image = bpy.data.images.load(path)
    w, h = image.size
    pixels = image.pixels[:]
    return pixels[4 * ((h // 2) * w + w // 2)]


def main():
    out = sys.argv[sys.argv.index("--") + 1] if "--" in sys.argv else "."
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.samples = 16
    scene.cycles.max_bounces = 0
    scene.cycles.use_denoising = False
    scene.cycles.pixel_filter_type = "BOX"
    scene.render.resolution_x = scene.render.resolution_y = 9
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    world = bpy.data.worlds.new("world")
    scene.world = world
    world.use_nodes = True
    background = world.node_tree.nodes["Background"]
    background.inputs["Color"].default_value = (0.0, 0.0, 0.0, 1.0)
    camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    camera.data.lens = 500.0  # a 4-degree view of the middle of the square
    camera.location = (0.0, 0.0, 3.0)
    scene.collection.objects.link(camera)
    scene.camera = camera
    bpy.ops.mesh.primitive_plane_add(size=2.0, location=(0.0, 0.0, 0.0))
    square = bpy.context.active_object

    results = []
    square.data.materials.append(emitter(2.5))
    results.append(("emission", "strength 2.5", centre_value(scene, os.path.join(out, "units_emission.exr")), 2.5))
    square.data.materials[0] = white_lambert()
    square.hide_render = True
    background.inputs["Color"].default_value = (0.75, 0.75, 0.75, 1.0)
    results.append(("world", "colour 0.75", centre_value(scene, os.path.join(out, "units_world.exr")), 0.75))
    background.inputs["Color"].default_value = (0.0, 0.0, 0.0, 1.0)
    square.hide_render = False
    for kind, setting, expected in (("SUN", 2.0, 2.0 / math.pi),
                                    ("POINT", 100.0, 100.0 / (4.0 * math.pi) / math.pi)):
        data = bpy.data.lights.new(kind.lower(), type=kind)
        data.energy = setting
        if kind == "SUN":
            data.angle = 0.0
        else:
            data.shadow_soft_size = 0.0
        light = bpy.data.objects.new(kind.lower(), data)
        light.location = (0.0, 0.0, 1.0)  # points straight down (-z) by default
        scene.collection.objects.link(light)
        label = "strength %g" % setting if kind == "SUN" else "power %g W at 1 m" % setting
        value = centre_value(scene, os.path.join(out, "units_%s.exr" % kind.lower()))
        results.append((kind.lower(), label, value, expected))
        bpy.data.objects.remove(light)
    for kind, label, value, expected in results:
        print("cycles_units: %-8s %-20s measured %.5f expected %.5f (%+.2f%%)"
              % (kind, label, value, expected, 100.0 * (value / expected - 1.0)))


main()
