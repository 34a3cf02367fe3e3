# blender -b --python scripts/blender-render.py -- FILE.glb FRAME OUT.png [WIDTH HEIGHT]
#
# Renders frame FRAME of an `f2 export --gltf` file with Blender's own
# renderer (Cycles on the CPU: no GPU or display needed), through the
# camera F2 exported, with F2's background and ambient light (the scene's
# extras) as the world: the picture of docs/output.md, "Into other tools".
import json
import struct
import sys

import numpy

if "bool" not in numpy.__dict__:  # Debian 12's importer still calls numpy.bool (tests/gltf/blender_check.py)
    numpy.bool = bool

import bpy  # noqa: E402

args = sys.argv[sys.argv.index("--") + 1:]
glb, frame, out = args[0], float(args[1]), args[2]
width, height = (int(args[3]), int(args[4])) if len(args) >= 5 else (800, 600)

with open(glb, "rb") as f:
    data = f.read()
length = struct.unpack_from("<I", data, 12)[0]
extras = json.loads(data[20:20 + length])["scenes"][0]["extras"]["f2"]

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.fps = extras["fps"]
bpy.ops.import_scene.gltf(filepath=glb)
scene.camera = next(o for o in bpy.data.objects if o.type == "CAMERA")
scene.frame_set(int(frame), subframe=frame - int(frame))

# F2's ambient term lights every surface evenly: a world of the background's
# colour at the ambient's strength does the same in Cycles.
world = bpy.data.worlds.new("f2")
world.use_nodes = True
background = world.node_tree.nodes["Background"]
r, g, b = (c / 255.0 for c in extras["background"])
background.inputs["Color"].default_value = (r, g, b, 1.0)
background.inputs["Strength"].default_value = max(extras["ambient"], 0.05) * 4
scene.world = world

scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = 32
scene.cycles.use_denoising = False  # Debian builds Blender without OpenImageDenoise
scene.render.resolution_x, scene.render.resolution_y = width, height
scene.render.resolution_percentage = 100
scene.render.image_settings.file_format = "PNG"
scene.render.filepath = out
bpy.ops.render.render(write_still=True)
