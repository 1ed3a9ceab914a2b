# SPDX-License-Identifier: Apache-2.0
"""The scene's lights as the active camera sees them: where each projects in the render (pixels
from the top-left, pixel centres at +0.5, outside the frame allowed), how far it is along the
view axis, how large its disc looks, and how much light it sends into the lens."""
import math
from dataclasses import dataclass, field

from mathutils import Vector

#: A sun is this far along its direction when projected: far past any scene, finite for the
#: projection's arithmetic.
SUN_DISTANCE = 1.0e6


@dataclass
class SceneLight:
    name: str
    kind: str                  # SUN, POINT, SPOT, AREA or EMISSIVE
    position: tuple            # (x, y) render pixels from the top-left
    depth: float               # distance along the view axis (the sun: the far clip)
    in_front: bool             # in front of the camera
    radius_px: float           # the projected radius of its disc
    irradiance: float          # W/m^2 it sends to the lens (sun: its strength)
    power: float               # W (a lamp's; a sun's strength again)
    color: tuple               # linear RGB
    world: Vector = field(repr=False, default=None)        # its position (a sun: far along)
    world_radius: float = field(repr=False, default=0.0)   # its disc's radius in the world


def camera_frame(scene):
    """The render's size in pixels (resolution x percentage)."""
    r = scene.render
    scale = r.resolution_percentage / 100.0
    return int(r.resolution_x * scale), int(r.resolution_y * scale)


def focal_pixels(scene, camera):
    """The camera's focal length in pixels of the render (its sensor fit applied)."""
    width, height = camera_frame(scene)
    cam = camera.data
    aspect = (width * scene.render.pixel_aspect_x) / (height * scene.render.pixel_aspect_y)
    fit = cam.sensor_fit
    if fit == 'AUTO':
        fit = 'HORIZONTAL' if aspect >= 1 else 'VERTICAL'
    if fit == 'HORIZONTAL':
        return cam.lens / cam.sensor_width * width
    return cam.lens / cam.sensor_height * height


def project(scene, camera, point):
    """A world point to (x, y) render pixels, its view-axis depth and whether it is in front:
    the camera's own perspective (shift included), computed from its world matrix."""
    width, height = camera_frame(scene)
    local = camera.matrix_world.inverted() @ Vector(point)
    depth = -local.z  # Blender cameras look down their local -Z
    f = focal_pixels(scene, camera)
    cam = camera.data
    big = max(width, height)
    if abs(depth) < 1e-12:
        return (math.inf, math.inf), depth, False
    x = width / 2.0 + f * local.x / depth + cam.shift_x * big
    y = height / 2.0 - f * local.y / depth - cam.shift_y * big
    return (x, y), depth, depth > 0


def _marked_emitters(scene):
    for obj in scene.objects:
        if obj.type == 'MESH' and obj.get("flarekit_light") and obj.visible_get():
            yield obj


def scene_lights(scene, camera, include_emissive=True, depsgraph=None):
    """Every sun, point, spot and area lamp that renders, and the meshes marked with the custom
    property ``flarekit_light`` (their power in ``flarekit_power``, watts; default 100). With a
    depsgraph, the evaluated objects: animation and drivers at the current frame applied."""
    if depsgraph is not None:
        camera = camera.evaluated_get(depsgraph)
    lights = []
    f = focal_pixels(scene, camera)
    cam_pos = camera.matrix_world.translation
    for original in scene.objects:
        if original.type != 'LIGHT' or not original.visible_get() or original.hide_render:
            continue
        obj = original.evaluated_get(depsgraph) if depsgraph is not None else original
        light = obj.data
        color = tuple(light.color)
        if light.type == 'SUN':
            toward = (obj.matrix_world.to_quaternion() @ Vector((0.0, 0.0, 1.0))).normalized()
            world = cam_pos + toward * SUN_DISTANCE
            pos, depth, front = project(scene, camera, world)
            radius = max(0.5, math.tan(light.angle / 2.0) * f)
            # Behind everything: the depth pass holds the far clip or more (Cycles: 1e10) where
            # nothing is in front of the sky.
            far = camera.data.clip_end
            lights.append(SceneLight(original.name, 'SUN', pos, far if front else -far,
                                     front, radius, float(light.energy), float(light.energy),
                                     color, world,
                                     math.tan(light.angle / 2.0) * SUN_DISTANCE))
            continue
        world = obj.matrix_world.translation.copy()
        pos, depth, front = project(scene, camera, world)
        distance = max((world - cam_pos).length, 1e-6)
        size = light.shadow_soft_size if light.type != 'AREA' else light.size / 2.0
        irradiance = light.energy / (4.0 * math.pi * distance * distance)
        if light.type == 'SPOT':
            # Outside its cone the spot sends nothing toward the lens.
            axis = (obj.matrix_world.to_quaternion() @ Vector((0.0, 0.0, -1.0))).normalized()
            angle = axis.angle((cam_pos - world).normalized())
            if angle > light.spot_size / 2.0:
                irradiance = 0.0
        elif light.type == 'AREA':
            # One-sided: it emits along its -Z, with Lambert's cosine toward the lens.
            axis = (obj.matrix_world.to_quaternion() @ Vector((0.0, 0.0, -1.0))).normalized()
            irradiance *= max(0.0, axis.dot((cam_pos - world).normalized())) * 4.0
        radius = max(0.5, size / max(depth, 1e-6) * f) if front else 0.5
        lights.append(SceneLight(original.name, light.type, pos, depth, front, radius, irradiance,
                                 float(light.energy), color, world, size))
    if include_emissive:
        for original in _marked_emitters(scene):
            obj = original.evaluated_get(depsgraph) if depsgraph is not None else original
            world = obj.matrix_world.translation.copy()
            pos, depth, front = project(scene, camera, world)
            distance = max((world - cam_pos).length, 1e-6)
            power = float(obj.get("flarekit_power", 100.0))
            size = max(obj.dimensions) / 2.0
            radius = max(0.5, size / max(depth, 1e-6) * f) if front else 0.5
            lights.append(SceneLight(original.name, 'EMISSIVE', pos, depth, front, radius,
                                     power / (4.0 * math.pi * distance * distance), power,
                                     tuple(obj.get("flarekit_color", (1.0, 1.0, 1.0))), world,
                                     size))
    return lights
