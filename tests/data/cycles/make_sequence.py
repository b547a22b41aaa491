# Makes the Cycles test sequence in this folder (Blender 3.4, Debian's `blender`):
#   blender -b --factory-startup -P tests/data/cycles/make_sequence.py -- OUT_DIR [WIDTH HEIGHT FRAMES REF_SPP]
# A room (white ceiling and floor, red and green side walls, the back wall half high so that the sky
# shows above it: Cycles writes depth 1e10 and a zero normal there) with a checker-textured box, a
# glossy sphere, and an area light under the ceiling that switches off at frame 5 (of 1..8); the
# camera pans, dollies and cranes up. Writes OUT_DIR/frame_NNNN.exr (1 spp, seed animated: multilayer EXR with
# Combined, Denoising Albedo, Normal, Depth and Vector) and OUT_DIR/reference_NNNN.exr (REF_SPP
# samples, Combined only). Motion blur off, Cycles' own denoising off, as the README tutorial says.
import math
import sys

import bpy

args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
out = args[0] if args else "/tmp/cycles_sequence"
width = int(args[1]) if len(args) > 1 else 64
height = int(args[2]) if len(args) > 2 else 36
frames = int(args[3]) if len(args) > 3 else 8
ref_spp = int(args[4]) if len(args) > 4 else 512

scene = bpy.context.scene
for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj, do_unlink=True)


def material(name, color, roughness=0.9, metallic=0.0, checker=False):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    bsdf = m.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (*color, 1.0)
    bsdf.inputs["Roughness"].default_value = roughness
    bsdf.inputs["Metallic"].default_value = metallic
    bsdf.inputs["Specular"].default_value = 0.5 if metallic > 0 else 0.0
    if checker:
        tex = m.node_tree.nodes.new("ShaderNodeTexChecker")
        tex.inputs["Scale"].default_value = 4.0
        tex.inputs["Color1"].default_value = (0.8, 0.8, 0.2, 1.0)
        tex.inputs["Color2"].default_value = (0.1, 0.1, 0.6, 1.0)
        m.node_tree.links.new(tex.outputs["Color"], bsdf.inputs["Base Color"])
    return m


def box(name, location, scale, mat):
    bpy.ops.mesh.primitive_cube_add(location=location)
    obj = bpy.context.object
    obj.name = name
    obj.scale = scale
    obj.data.materials.append(mat)
    return obj


white = material("white", (0.75, 0.75, 0.75))
red = material("red", (0.7, 0.1, 0.1))
green = material("green", (0.1, 0.6, 0.1))
box("floor", (0, 0, -1.05), (2, 2, 0.05), white)
box("ceiling", (0, 0, 1.05), (2, 2, 0.05), white)
box("back", (0, 2.05, -0.55), (2, 0.05, 0.55), white)  # half height: the sky shows above it
box("front", (0, -3.05, 0), (2, 0.05, 1.1), white)
box("left", (-2.05, 0, 0), (0.05, 2, 1.1), red)
box("right", (2.05, 0, 0), (0.05, 2, 1.1), green)
box("checker box", (-0.7, 0.6, -0.6), (0.4, 0.4, 0.4), material("checker", (1, 1, 1), checker=True))
bpy.ops.mesh.primitive_uv_sphere_add(location=(0.7, 0.3, -0.6), radius=0.4, segments=48, ring_count=24)
sphere = bpy.context.object
bpy.ops.object.shade_smooth()
sphere.data.materials.append(material("glossy", (0.9, 0.9, 0.9), roughness=0.15, metallic=1.0))

bpy.ops.object.light_add(type="AREA", location=(0, 0.3, 0.98))
light = bpy.context.object
light.data.size = 0.8
light.data.energy = 120.0
light.data.keyframe_insert("energy", frame=4)
light.data.energy = 0.0
light.data.keyframe_insert("energy", frame=5)
for fc in light.data.animation_data.action.fcurves:
    for k in fc.keyframe_points:
        k.interpolation = "CONSTANT"
scene.world = bpy.data.worlds.new("dark")
scene.world.color = (0.02, 0.02, 0.025)  # a dim sky

bpy.ops.object.camera_add(location=(0.0, -2.8, 0.1))
camera = bpy.context.object
scene.camera = camera
camera.data.lens = 22
# Pan, dolly and crane at once, so that the motion vectors have x and y components everywhere.
for frame, (x, z, pitch, yaw) in {1: (-0.3, -0.35, 84.0, -6.0), frames: (0.3, 0.35, 94.0, 6.0)}.items():
    camera.location = (x, -2.8 + 0.05 * frame, z)
    camera.rotation_euler = (math.radians(pitch), 0, math.radians(yaw))
    camera.keyframe_insert("location", frame=frame)
    camera.keyframe_insert("rotation_euler", frame=frame)

scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.use_denoising = False
scene.cycles.use_animated_seed = True
scene.cycles.max_bounces = 4
scene.render.use_motion_blur = False
scene.render.resolution_x, scene.render.resolution_y = width, height
scene.render.resolution_percentage = 100
scene.render.image_settings.file_format = "OPEN_EXR_MULTILAYER"
scene.render.image_settings.color_depth = "32"
scene.render.image_settings.exr_codec = "ZIP"
scene.frame_start, scene.frame_end = 1, frames
layer = scene.view_layers[0]


def render(prefix, spp, passes):
    scene.cycles.samples = spp
    layer.use_pass_normal = layer.use_pass_z = layer.use_pass_vector = passes
    layer.cycles.denoising_store_passes = passes
    scene.render.filepath = f"{out}/{prefix}_"
    bpy.ops.render.render(animation=True)


render("frame", 1, True)
render("reference", ref_spp, False)
