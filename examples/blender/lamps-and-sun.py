# SPDX-License-Identifier: Apache-2.0
"""A small scene flared by the flarekit add-on, rendered in the background:

    blender -b --python examples/blender/lamps-and-sun.py -- OUT [DEPTH|RAYCAST] [SPRITE|POSTFX|LENS]

It builds a sun low in the sky, two point lamps (a wall hides one of them), a lamp beyond the
frame's right edge and a ground, enables the add-on (installed in Blender's add-ons folder),
renders frames 1-2 with Cycles on the CPU into OUT (render_0001.exr, ...) with the flares in
OUT/flares (flare_0001.exr and lights_0001.json per frame), and writes OUT/truth.json: each
light's projection by Blender's own world_to_camera_view, which the add-on's test compares
with the add-on's."""
import json
import math
import os
import sys

import addon_utils
import bpy
from bpy_extras.object_utils import world_to_camera_view
from mathutils import Vector

args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
if not args:
    sys.exit("usage: blender -b --python lamps-and-sun.py -- OUT [DEPTH|RAYCAST] [SPRITE|POSTFX|LENS]")
out = os.path.abspath(args[0])
occlusion = args[1] if len(args) > 1 else "DEPTH"
mode = args[2] if len(args) > 2 else "SPRITE"

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.engine = 'CYCLES'
scene.cycles.device = 'CPU'
scene.cycles.samples = 4
scene.cycles.use_denoising = False
scene.render.resolution_x, scene.render.resolution_y = 320, 180
scene.render.resolution_percentage = 100
scene.frame_start, scene.frame_end = 1, 2
scene.render.image_settings.file_format = 'OPEN_EXR'
scene.render.filepath = out + "/render_"

world = bpy.data.worlds.new("sky")
world.color = (0.05, 0.07, 0.1)
scene.world = world

camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
scene.collection.objects.link(camera)
scene.camera = camera
camera.rotation_euler = (math.radians(90), 0, 0)  # looking along +Y
camera.location = (0, -10, 2)
camera.keyframe_insert("location", frame=1)
camera.location = (0.3, -10, 2)  # a small pan between the two frames
camera.keyframe_insert("location", frame=2)


def add_light(name, kind, energy, location, color):
    light = bpy.data.lights.new(name, kind)
    light.energy = energy
    light.color = color
    obj = bpy.data.objects.new(name, light)
    obj.location = location
    scene.collection.objects.link(obj)
    return obj


sun = add_light("sun", 'SUN', 3.0, (0, 0, 10), (1.0, 0.9, 0.8))
sun.data.angle = math.radians(1.0)
toward = Vector((-0.35, 1.0, 0.12)).normalized()  # where the sun is, from the scene
sun.rotation_euler = toward.to_track_quat('Z', 'Y').to_euler()
add_light("lamp", 'POINT', 2000.0, (2.5, 6.0, 2.6), (0.6, 0.8, 1.0))
add_light("hidden lamp", 'POINT', 2000.0, (-1.5, 6.0, 1.5), (1.0, 0.5, 0.2))
add_light("rim", 'POINT', 500.0, (12.0, 4.0, 2.0), (1.0, 1.0, 1.0))  # outside the frame

bpy.ops.mesh.primitive_plane_add(size=60, location=(0, 10, 0))
bpy.ops.mesh.primitive_cube_add(location=(-1.5, 2.0, 1.5))  # the wall before the hidden lamp
bpy.context.active_object.scale = (1.2, 0.2, 1.5)

addon_utils.enable("flarekit_blender", default_set=True, handle_error=None)
settings = scene.flarekit
settings.enabled = True
settings.mode = mode
settings.occlusion = occlusion
settings.output_dir = out + "/flares/"

scene.frame_set(1)  # the objects as frame 1 has them (the keyframing left frame 2's)
bpy.ops.render.render(animation=True)

truth = {}
for frame in (1, 2):
    scene.frame_set(frame)
    lights = {}
    for obj in scene.objects:
        if obj.type != 'LIGHT':
            continue
        point = obj.matrix_world.translation
        if obj.data.type == 'SUN':
            axis = obj.matrix_world.to_quaternion() @ Vector((0, 0, 1))
            point = camera.matrix_world.translation + axis * 1.0e5
        ndc = world_to_camera_view(scene, camera, point)
        distance = (obj.matrix_world.translation - camera.matrix_world.translation).length
        lights[obj.name] = {"x": ndc.x * 320, "y": (1 - ndc.y) * 180, "front": ndc.z > 0,
                            "energy": obj.data.energy, "kind": obj.data.type,
                            "distance": distance, "color": list(obj.data.color)}
    truth[frame] = lights
with open(out + "/truth.json", "w") as f:
    json.dump(truth, f, indent=1)
