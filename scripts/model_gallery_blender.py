"""The reference render of scripts/model_gallery.sh: a model file imported by Blender's own
importers and rendered by Cycles from the camera rayo used, lit like rayo's automatic framing
(docs/models.md, "Gallery"). A comparison tool, not part of rayo: Blender is not a dependency.

    blender -b --factory-startup -P scripts/model_gallery_blender.py -- \
        --model FILE --out PNG --size 512 --samples 32 \
        --eye X,Y,Z --look-at X,Y,Z --up X,Y,Z --vfov DEGREES \
        [--sun DX,DY,DZ,INTENSITY ...] [--ambient L] [--background R,G,B] [--no-ground]
        [--max-bounces N] [--match-path] [--obj-lambert] [--no-clearcoat]

An --out ending in .exr is written as linear float OpenEXR (scene-referred, no view transform),
anything else as 8-bit PNG through the 'Standard' view. scripts/cycles_compare.sh uses the last
four options (docs/path-tracing.md, "Against Cycles").

Positions, directions and the up vector are in rayo's (the file's) frame, +y up; the glTF and
OBJ importers turn +y up into Blender's +z up, (x, y, z) -> (x, -z, y), and the PLY importer
does not, so PLY objects are given that rotation here. A rayo directional light of intensity I
(a Lambertian surface sends kd*I*cos) is a Cycles sun of strength pi*I (kd*E*cos/pi).
"""

import argparse
import math
import os
import sys

import bpy
from mathutils import Matrix, Vector


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="model_gallery_blender.py")
    p.add_argument("--model", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--size", type=int, default=512)
    p.add_argument("--samples", type=int, default=32)
    p.add_argument("--threads", type=int, default=0)
    p.add_argument("--eye", required=True)
    p.add_argument("--look-at", required=True)
    p.add_argument("--up", required=True)
    p.add_argument("--vfov", type=float, required=True)
    p.add_argument("--sun", action="append", default=[],
                   help="DX,DY,DZ,INTENSITY: a rayo directional light (direction of travel)")
    p.add_argument("--ambient", type=float, default=0.1,
                   help="radiance of the uniform environment that lights the model")
    p.add_argument("--background", default="0.18,0.2,0.24",
                   help="what camera rays that miss see (rayo's model background)")
    p.add_argument("--no-ground", action="store_true")
    p.add_argument("--max-bounces", type=int, default=4,
                   help="Cycles' bounces of every kind (rayo's path --max-depth minus 1)")
    p.add_argument("--match-path", action="store_true",
                   help="sample like rayo's path integrator: no adaptive sampling, a 1-pixel "
                   "box filter, no clamping, no light threshold, no glossy blur, caustics on")
    p.add_argument("--obj-lambert", action="store_true",
                   help="OBJ materials as rayo reads an MTL without Ks: Kd a Lambertian "
                   "Diffuse BSDF, Ke an emission (the importer makes a Principled BSDF)")
    p.add_argument("--no-clearcoat", action="store_true",
                   help="Principled Clearcoat 0 (rayo does not read KHR_materials_clearcoat)")
    p.add_argument("--check-import", action="store_true",
                   help="only import the model and report whether that worked")
    return p.parse_args(argv)


def vec(text):
    return Vector([float(x) for x in text.split(",")])


def to_blender(v):
    """rayo's frame (+y up) to Blender's (+z up), as the glTF and OBJ importers convert."""
    return Vector((v.x, -v.z, v.y))


def import_model(path):
    ext = os.path.splitext(path)[1].lower()
    # Blender 3.4's glTF importer uses numpy's `np.bool`, which Debian 12's numpy 1.24 no
    # longer has (gltf2_blender_mesh.py): give it back the builtin it aliased.
    import numpy
    if "bool" not in numpy.__dict__:
        numpy.bool = bool
    before = set(bpy.data.objects)
    if ext in (".gltf", ".glb"):
        bpy.ops.import_scene.gltf(filepath=path)
    elif ext == ".obj":
        bpy.ops.import_scene.obj(filepath=path)
    elif ext == ".ply":
        bpy.ops.import_mesh.ply(filepath=path)
    else:
        raise SystemExit("model_gallery_blender.py: no importer for " + ext)
    new = [o for o in bpy.data.objects if o not in before]
    if ext == ".ply":  # the PLY importer keeps the file's axes: make +y up +z up
        for o in new:
            if o.parent is None:
                o.matrix_world = Matrix.Rotation(math.pi / 2, 4, "X") @ o.matrix_world
    return new


def fix_image_paths(model_dir):
    """MTL files written on Windows name maps like `.\\tex.jpg`; rayo reads backslashes as
    slashes (docs/textures.md), Blender's OBJ importer does not: do as rayo does."""
    for image in bpy.data.images:
        if image.source != "FILE" or not image.filepath:
            continue
        if os.path.exists(bpy.path.abspath(image.filepath)):
            continue
        candidate = os.path.join(model_dir, image.filepath.replace("\\", "/"))
        candidate = os.path.normpath(candidate)
        if os.path.exists(candidate):
            image.filepath = candidate
            image.reload()
            print("model_gallery_blender.py: image path", repr(image.name), "->", candidate)


def world_bounds(objects):
    lo = Vector((math.inf,) * 3)
    hi = Vector((-math.inf,) * 3)
    bpy.context.view_layer.update()
    for o in objects:
        if o.type != "MESH":
            continue
        for corner in o.bound_box:
            p = o.matrix_world @ Vector(corner)
            lo = Vector(map(min, lo, p))
            hi = Vector(map(max, hi, p))
    return lo, hi


def look_rotation(forward, up):
    """The rotation that points an object's -Z along `forward` with +Y toward `up`."""
    f = forward.normalized()
    right = f.cross(up).normalized()
    true_up = right.cross(f)
    m = Matrix((right, true_up, -f)).transposed()
    return m.to_quaternion()


def add_camera(args):
    eye, look_at, up = (to_blender(vec(t)) for t in (args.eye, args.look_at, args.up))
    data = bpy.data.cameras.new("rayo view")
    data.sensor_fit = "VERTICAL"
    data.angle_y = math.radians(args.vfov)
    data.clip_start = 1e-3 * (look_at - eye).length
    data.clip_end = 1e3 * (look_at - eye).length
    cam = bpy.data.objects.new("rayo view", data)
    bpy.context.scene.collection.objects.link(cam)
    cam.location = eye
    cam.rotation_mode = "QUATERNION"
    cam.rotation_quaternion = look_rotation(look_at - eye, up)
    bpy.context.scene.camera = cam


def add_sun(text, index):
    dx, dy, dz, intensity = (float(x) for x in text.split(","))
    data = bpy.data.lights.new("rayo light %d" % index, type="SUN")
    data.energy = math.pi * intensity
    data.angle = 0.0  # rayo's directional lights cast hard shadows
    sun = bpy.data.objects.new(data.name, data)
    bpy.context.scene.collection.objects.link(sun)
    sun.rotation_mode = "QUATERNION"
    direction = to_blender(Vector((dx, dy, dz)))
    sun.rotation_quaternion = direction.to_track_quat("-Z", "Y")


def add_ground(model_objects):
    """rayo's ground: a grey (kd 0.4) square at the model's lowest point, +-50 bounding radii."""
    lo, hi = world_bounds(model_objects)
    centre = 0.5 * (lo + hi)
    half = 50.0 * 0.5 * (hi - lo).length
    bpy.ops.mesh.primitive_plane_add(size=2.0 * half, location=(centre.x, centre.y, lo.z))
    plane = bpy.context.active_object
    mat = bpy.data.materials.new("rayo ground")
    mat.use_nodes = True
    nodes = mat.node_tree.nodes
    nodes.clear()
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (0.4, 0.4, 0.4, 1.0)
    out = nodes.new("ShaderNodeOutputMaterial")
    mat.node_tree.links.new(diffuse.outputs["BSDF"], out.inputs["Surface"])
    plane.data.materials.append(mat)


def set_world(ambient, background):
    """Camera rays see rayo's background colour; every other ray sees a uniform environment of
    radiance `ambient` (rayo's ambient term ka*Ia, unoccluded there, occluded here)."""
    world = bpy.data.worlds.new("rayo world")
    bpy.context.scene.world = world
    world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    nodes.clear()
    light_path = nodes.new("ShaderNodeLightPath")
    lighting = nodes.new("ShaderNodeBackground")
    lighting.inputs["Color"].default_value = (ambient, ambient, ambient, 1.0)
    seen = nodes.new("ShaderNodeBackground")
    seen.inputs["Color"].default_value = tuple(background) + (1.0,)
    mix = nodes.new("ShaderNodeMixShader")
    out = nodes.new("ShaderNodeOutputWorld")
    links.new(light_path.outputs["Is Camera Ray"], mix.inputs["Fac"])
    links.new(lighting.outputs["Background"], mix.inputs[1])
    links.new(seen.outputs["Background"], mix.inputs[2])
    links.new(mix.outputs["Shader"], out.inputs["Surface"])


def obj_materials_as_lambert():
    """The OBJ importer's Principled BSDF (Specular 0, Roughness 1: Burley's diffuse, brighter
    toward grazing angles) replaced by what rayo makes of an MTL with Kd and Ke only: a
    Lambertian Diffuse BSDF of colour Kd plus an emission of radiance Ke (strength 1)."""
    for mat in bpy.data.materials:
        if not mat.use_nodes:
            continue
        nodes, links = mat.node_tree.nodes, mat.node_tree.links
        principled = [n for n in nodes if n.bl_idname == "ShaderNodeBsdfPrincipled"]
        if len(principled) != 1:
            continue
        p = principled[0]
        if (p.inputs["Specular"].default_value != 0.0 or p.inputs["Metallic"].default_value != 0.0
                or any(i.is_linked for i in p.inputs)):
            continue  # a specular or textured MTL material stays as the importer made it
        colour = tuple(p.inputs["Base Color"].default_value)
        emission = tuple(p.inputs["Emission"].default_value)[:3]
        strength = p.inputs["Emission Strength"].default_value
        nodes.clear()
        diffuse = nodes.new("ShaderNodeBsdfDiffuse")
        diffuse.inputs["Color"].default_value = colour
        diffuse.inputs["Roughness"].default_value = 0.0  # Oren-Nayar with sigma 0: Lambert
        out = nodes.new("ShaderNodeOutputMaterial")
        if max(emission) * strength > 0.0:
            emit = nodes.new("ShaderNodeEmission")
            emit.inputs["Color"].default_value = emission + (1.0,)
            emit.inputs["Strength"].default_value = strength
            add = nodes.new("ShaderNodeAddShader")
            links.new(diffuse.outputs["BSDF"], add.inputs[0])
            links.new(emit.outputs["Emission"], add.inputs[1])
            links.new(add.outputs["Shader"], out.inputs["Surface"])
        else:
            links.new(diffuse.outputs["BSDF"], out.inputs["Surface"])
        print("model_gallery_blender.py: %r as Lambert kd %s, emission %s x %g"
              % (mat.name, colour[:3], emission, strength))


COLOUR_INPUTS = ("Base Color", "Emission")


def feeds_colour(node, seen=None):
    """Whether `node`'s output reaches a Principled BSDF's Base Color or Emission input, directly
    or through the importer's mix nodes (factors, vertex colours)."""
    seen = seen if seen is not None else set()
    if node.name in seen:
        return False
    seen.add(node.name)
    for output in node.outputs:
        for link in output.links:
            target = link.to_node
            if target.bl_idname == "ShaderNodeBsdfPrincipled":
                if link.to_socket.name in COLOUR_INPUTS:
                    return True
            elif target.bl_idname not in ("ShaderNodeSeparateColor", "ShaderNodeSeparateRGB",
                                          "ShaderNodeNormalMap"):
                if feeds_colour(target, seen):
                    return True
    return False


def separate_colour_images():
    """glTF decodes base colour and emissive textures as sRGB and the others as linear data.
    Blender 3.4's glTF importer makes one image per glTF image and sets it to Non-Color when any
    material reads data from it, so an image that is both (boxTexcoords.gltf: base colour and
    metallic-roughness) is read as linear in its colour role too: such uses get an sRGB copy."""
    copies = {}
    for mat in bpy.data.materials:
        if not mat.use_nodes:
            continue
        for node in mat.node_tree.nodes:
            if node.bl_idname != "ShaderNodeTexImage" or node.image is None:
                continue
            image = node.image
            if image.colorspace_settings.name != "Non-Color" or not feeds_colour(node):
                continue
            if image.name not in copies:
                copy = image.copy()
                copy.colorspace_settings.name = "sRGB"
                copies[image.name] = copy
                print("model_gallery_blender.py: image %r is data and colour: an sRGB copy for "
                      "its colour uses" % image.name)
            node.image = copies[image.name]


def remove_clearcoat():
    for mat in bpy.data.materials:
        if not mat.use_nodes:
            continue
        for n in mat.node_tree.nodes:
            if n.bl_idname == "ShaderNodeBsdfPrincipled" and (
                    n.inputs["Clearcoat"].is_linked or n.inputs["Clearcoat"].default_value > 0):
                for link in list(n.inputs["Clearcoat"].links):
                    mat.node_tree.links.remove(link)
                n.inputs["Clearcoat"].default_value = 0.0
                print("model_gallery_blender.py: %r: clearcoat removed" % mat.name)


def configure_render(args):
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = args.samples
    scene.cycles.use_adaptive_sampling = True
    scene.cycles.max_bounces = args.max_bounces
    scene.cycles.use_denoising = False
    if args.match_path:
        # rayo's path integrator: every pixel gets its samples, jittered over the pixel (a box
        # of one pixel), no path's value clamped, every light sampled, every bounce kind up to
        # the same depth, caustics kept.
        scene.cycles.use_adaptive_sampling = False
        scene.cycles.pixel_filter_type = "BOX"
        scene.cycles.filter_width = 1.0
        scene.cycles.sample_clamp_direct = 0.0
        scene.cycles.sample_clamp_indirect = 0.0
        scene.cycles.light_sampling_threshold = 0.0
        scene.cycles.blur_glossy = 0.0
        scene.cycles.caustics_reflective = True
        scene.cycles.caustics_refractive = True
        for kind in ("diffuse", "glossy", "transmission", "volume", "transparent_max"):
            setattr(scene.cycles, kind + "_bounces", args.max_bounces)
        scene.cycles.seed = 0
    if args.threads > 0:
        scene.render.threads_mode = "FIXED"
        scene.render.threads = args.threads
    scene.render.resolution_x = args.size
    scene.render.resolution_y = args.size
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    # rayo writes display-referred sRGB without a tone curve: no Filmic.
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    if args.out.lower().endswith(".exr"):  # linear, as rendered: the view transform is not applied
        scene.render.image_settings.file_format = "OPEN_EXR"
        scene.render.image_settings.color_mode = "RGB"
        scene.render.image_settings.color_depth = "32"
        scene.render.image_settings.exr_codec = "ZIP"
    else:
        scene.render.image_settings.file_format = "PNG"
        scene.render.image_settings.color_mode = "RGB"
        scene.render.image_settings.color_depth = "8"
    scene.render.filepath = os.path.abspath(args.out)


def main():
    args = parse_args()
    bpy.ops.wm.read_factory_settings(use_empty=True)
    try:
        model_objects = import_model(os.path.abspath(args.model))
    except Exception as error:  # an importer's failure, e.g. Draco without its library
        print("model_gallery_blender.py: import failed:", error)
        sys.exit(2)
    meshes = [o for o in model_objects if o.type == "MESH"]
    if not meshes:
        print("model_gallery_blender.py: import failed: no mesh objects")
        sys.exit(2)
    lo, hi = world_bounds(meshes)
    print("model_gallery_blender.py: imported %d mesh object(s), bounds (Blender frame) %s %s"
          % (len(meshes), tuple(round(x, 4) for x in lo), tuple(round(x, 4) for x in hi)))
    if args.check_import:
        return
    fix_image_paths(os.path.dirname(os.path.abspath(args.model)))
    separate_colour_images()
    if args.obj_lambert and args.model.lower().endswith(".obj"):
        obj_materials_as_lambert()
    if args.no_clearcoat:
        remove_clearcoat()
    # The file's own lights (glTF KHR_lights_punctual) stay; its cameras are not used.
    add_camera(args)
    for i, text in enumerate(args.sun):
        add_sun(text, i)
    if not args.no_ground:
        add_ground(meshes)
    set_world(args.ambient, vec(args.background))
    configure_render(args)
    bpy.ops.render.render(write_still=True)


main()
