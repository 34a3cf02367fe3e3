# blender -b --python blender_check.py -- F2 SCENE FILE.glb FRAME...
#
# Blender (Debian's, headless) imports FILE.glb with its own glTF importer and
# plays the animation to each FRAME (`last`: the scene's last frame); the world
# transform of every shape's object (the node's extras.f2Shape, in node
# order; those hidden at scale 0 left out) and the camera's must match what
# `F2 export SCENE --prims --frame FRAME` writes: positions within 1e-3 of the
# scene's size (the diagonal of its primitives' bounds), rotations within half
# a degree. Also the camera's vertical field of view (from /camera's d and
# size), the fps and the frame range of the imported actions.
#
# Frames: F2's (x, y, z) is glTF's (x, y, -z) (docs/output.md), which
# Blender's importer turns Z-up: (x, -z_gltf, y_gltf) = (x, z, y). So a
# world matrix M of F2 is P M P in Blender, P the swap of y and z.
import json
import math
import struct
import subprocess
import sys

import numpy

# Debian 12's Blender 3.4 importer still calls numpy.bool, which its numpy
# (1.24) removed: every mesh import fails with "module 'numpy' has no
# attribute 'bool'". The alias it meant is the builtin bool.
if "bool" not in numpy.__dict__:
    numpy.bool = bool

import bpy  # noqa: E402
from mathutils import Matrix, Vector  # noqa: E402

args = sys.argv[sys.argv.index("--") + 1:]
f2, scene_path, glb, frames = args[0], args[1], args[2], args[3:]


def glb_json(path):
    """The JSON chunk of a .glb (header 12 bytes, then length and type)."""
    with open(path, "rb") as f:
        data = f.read()
    length, kind = struct.unpack_from("<II", data, 12)
    assert kind == 0x4E4F534A, "the first chunk of a .glb is its JSON"
    return json.loads(data[20:20 + length])


gltf = glb_json(glb)
f2_extras = gltf["scenes"][0]["extras"]["f2"]
fps, last_frame = f2_extras["fps"], f2_extras["lastFrame"]
shape_order = [n["extras"]["f2Shape"] for n in gltf["nodes"] if "f2Shape" in n.get("extras", {})]

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
# The importer turns seconds into frames at the scene's fps: F2's, as a user sets it.
scene.render.fps = fps
bpy.ops.import_scene.gltf(filepath=glb)

failures = 0


def fail(message):
    global failures
    failures += 1
    if failures <= 10:
        print("FAIL " + message)


by_label = {o["f2Shape"]: o for o in bpy.data.objects if "f2Shape" in o.keys()}
if sorted(by_label) != sorted(shape_order):
    fail(f"{glb}: Blender made {len(by_label)} shape objects, the file has {len(shape_order)} shape nodes")
cameras = [o for o in bpy.data.objects if o.type == "CAMERA"]
if len(cameras) != 1:
    fail(f"{glb}: {len(cameras)} cameras imported")

# The actions span the scene's frames (a scene with motion has actions).
if bpy.data.actions:
    end = max(a.frame_range[1] for a in bpy.data.actions)
    start = min(a.frame_range[0] for a in bpy.data.actions)
    if start != 0 or abs(end - last_frame) > 1e-3:
        fail(f"{glb}: the actions span frames {start}-{end}, the scene 0-{last_frame}")

P = Matrix(((1, 0, 0), (0, 0, 1), (0, 1, 0)))


def f2_world(values):
    """A 3x4 matrix of --prims in Blender's frame, as a 4x4."""
    m = Matrix((values[0:3], values[4:7], values[8:11]))
    t = Vector((values[3], values[7], values[11]))
    w = (P @ m @ P).to_4x4()
    w.translation = P @ t
    return w


def turn_between(a, b):
    """The angle in degrees between two rotations (scale removed)."""
    qa = a.to_3x3().normalized().to_quaternion()
    qb = b.to_3x3().normalized().to_quaternion()
    return math.degrees(qa.rotation_difference(qb).angle)


def check(frame):
    prims = subprocess.run([f2, "export", scene_path, "--prims", "--frame", str(frame)],
                           check=True, capture_output=True, text=True).stdout
    rows = [line.split() for line in prims.splitlines()]
    records = [[float(x) for x in r[1:]] for r in rows if r and r[0] in ("sphere", "cylinder", "box")]
    lo, hi = [math.inf] * 3, [-math.inf] * 3
    for r in records:
        reach = math.hypot(r[0], r[1] / 2) + math.hypot(r[2], r[3], r[4]) / 2  # unused sizes are 0
        for axis, c in enumerate((r[8], r[12], r[16])):
            lo[axis], hi[axis] = min(lo[axis], c - reach), max(hi[axis], c + reach)
    size = math.dist(lo, hi) if records else 1.0

    scene.frame_set(int(frame), subframe=frame - int(frame))
    bpy.context.view_layer.update()
    visible = [by_label[label] for label in shape_order
               if label in by_label and abs(by_label[label].matrix_world.determinant()) > 1e-6]
    if len(visible) != len(records):
        fail(f"{glb} at frame {frame}: {len(visible)} visible shape objects, {len(records)} primitives")
        return
    worst = [0.0, 0.0]

    def compare(name, got, want):
        apart = (got.translation - want.translation).length
        turn = turn_between(got, want)
        worst[0], worst[1] = max(worst[0], apart), max(worst[1], turn)
        if apart > 1e-3 * size or turn > 0.5:
            fail(f"{glb} at frame {frame}, {name}: {apart} apart, turned {turn} degrees")

    for obj, r in zip(visible, records):
        compare(obj["f2Shape"], obj.matrix_world, f2_world(r[5:17]))

    # A camera looks down its local -Z in glTF and in Blender, F2's down +z:
    # compare where it is, where it looks and which way is up.
    row = next(r for r in rows if r and r[0] == "camera")
    width, height, d = (float(x) for x in row[1:4])
    want = f2_world([float(x) for x in row[4:16]])
    got = cameras[0].matrix_world
    forward_got = (got.to_3x3() @ Vector((0, 0, -1))).normalized()
    up_got = (got.to_3x3() @ Vector((0, 1, 0))).normalized()
    # want is P M P: F2's local +z and +y are P (0, 0, 1) = +y and P (0, 1, 0) = +z.
    forward_want = (want.to_3x3() @ Vector((0, 1, 0))).normalized()
    up_want = (want.to_3x3() @ Vector((0, 0, 1))).normalized()
    apart = (got.translation - want.translation).length
    turn = max(math.degrees(forward_got.angle(forward_want, 0)), math.degrees(up_got.angle(up_want, 0)))
    worst[0], worst[1] = max(worst[0], apart), max(worst[1], turn)
    if apart > 1e-3 * size or turn > 0.5:
        fail(f"{glb} at frame {frame}, camera: {apart} apart, looks {turn} degrees off")
    camera = cameras[0].data
    yfov = 2 * math.atan(height / (2 * width * d))
    if camera.sensor_fit != "VERTICAL" or abs(camera.angle_y - yfov) > 1e-4:
        fail(f"{glb} at frame {frame}: the camera's vertical field of view is {camera.angle_y} "
             f"({camera.sensor_fit}), F2's {yfov}")
    print(f"{glb} at frame {frame}: {len(visible)} shapes and the camera, worst {worst[0]:.3g} apart "
          f"(size {size:.4g}), {worst[1]:.3g} degrees")


print(f"{glb}: {fps} fps (Blender {scene.render.fps}), frames 0-{last_frame}")
for frame in frames:
    check(last_frame if frame == "last" else min(float(frame), last_frame))
sys.stdout.flush()
# Blender's exit code is its own unless the script leaves it.
sys.exit(1 if failures else 0)
