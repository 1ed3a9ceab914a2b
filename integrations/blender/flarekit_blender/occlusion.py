# SPDX-License-Identifier: Apache-2.0
"""How much of each light the camera sees: from the render's depth pass (the pixels of its
projected disc that are not nearer than it), or from Blender's own ray cast against the scene
(rays from the camera to points spread over the light's disc), where translucent surfaces pass
the share their alpha leaves."""
import math

import numpy as np
from mathutils import Vector

#: Rays per light for the ray-cast coverage: 64 points over the disc resolve a partly hidden
#: light to about 1/64 (0.016), finer than the flare's smallest visible change.
RAYS = 64
#: A depth within this fraction of the light's own is the light itself, not in front of it.
DEPTH_TOLERANCE = 1e-4


def depth_visibility(depth, light):
    """The share of the light's projected disc whose depth pass lies at or behind it. Only the
    part inside the frame counts; a disc wholly outside the frame is visible (1), as flarekit's
    disc visibility has it (nothing in the render can hide it)."""
    if not light.in_front:
        return 0.0
    height, width = depth.shape
    x, y = light.position
    r = max(light.radius_px, 0.5)
    x0, x1 = int(math.floor(x - r)), int(math.ceil(x + r))
    y0, y1 = int(math.floor(y - r)), int(math.ceil(y + r))
    xs = np.arange(max(x0, 0), min(x1, width))
    ys = np.arange(max(y0, 0), min(y1, height))
    if xs.size == 0 or ys.size == 0:
        return 1.0
    gx, gy = np.meshgrid(xs + 0.5, ys + 0.5)
    inside = (gx - x) ** 2 + (gy - y) ** 2 <= r * r
    if not inside.any():
        # Smaller than a pixel: the pixel under its centre.
        px, py = int(math.floor(x)), int(math.floor(y))
        if not (0 <= px < width and 0 <= py < height):
            return 1.0
        return float(depth[py, px] >= light.depth * (1 - DEPTH_TOLERANCE))
    patch = depth[ys[0]:ys[-1] + 1, xs[0]:xs[-1] + 1]
    seen = patch >= light.depth * (1 - DEPTH_TOLERANCE)
    return float(seen[inside].mean())


def _surface_alpha(obj, face_index):
    """The opacity of a hit surface: its material's alpha when the material blends (Alpha
    Blend, Hashed or Clip with a Principled BSDF's Alpha below 1), else 1."""
    if obj is None or not obj.material_slots:
        return 1.0
    try:
        poly = obj.data.polygons[face_index]
        material = obj.material_slots[poly.material_index].material
    except (AttributeError, IndexError):
        material = obj.material_slots[0].material
    if material is None or material.blend_method == 'OPAQUE':
        return 1.0
    alpha = 1.0
    if material.use_nodes:
        for node in material.node_tree.nodes:
            if node.type == 'BSDF_PRINCIPLED' and not node.inputs['Alpha'].is_linked:
                alpha = float(node.inputs['Alpha'].default_value)
    else:
        alpha = float(material.diffuse_color[3])
    return min(max(alpha, 0.0), 1.0)


def _transmission(scene, depsgraph, origin, target, is_sun):
    direction = (target - origin)
    distance = direction.length
    direction.normalize()
    passed = 1.0
    start = origin.copy()
    for _ in range(16):  # at most 16 translucent layers along one ray
        limit = math.inf if is_sun else distance - (start - origin).length - 1e-4
        if limit <= 0:
            break
        hit, location, _normal, index, obj, _matrix = scene.ray_cast(
            depsgraph, start, direction, distance=limit if math.isfinite(limit) else 1.0e9)
        if not hit:
            break
        alpha = _surface_alpha(obj, index)
        passed *= 1.0 - alpha
        if passed <= 0.0:
            return 0.0
        start = location + direction * 1e-4
    return passed


def raycast_visibility(scene, depsgraph, camera, light):
    """The mean transmission of RAYS rays from the camera to points on the light's disc (a
    Fibonacci spiral over the disc facing the camera)."""
    if not light.in_front:
        return 0.0
    origin = camera.evaluated_get(depsgraph).matrix_world.translation.copy()
    centre = Vector(light.world)
    axis = (centre - origin).normalized()
    u = axis.orthogonal().normalized()
    v = axis.cross(u).normalized()
    golden = math.pi * (3.0 - math.sqrt(5.0))
    total = 0.0
    for i in range(RAYS):
        rho = light.world_radius * math.sqrt((i + 0.5) / RAYS)
        theta = i * golden
        point = centre + u * (rho * math.cos(theta)) + v * (rho * math.sin(theta))
        total += _transmission(scene, depsgraph, origin, point, light.kind == 'SUN')
    return total / RAYS
