# SPDX-License-Identifier: Apache-2.0
"""flarekit for Blender: lens flares on every render, from the scene's own lights.

After each frame Cycles or Eevee renders, the add-on projects every sun, point, spot and area
lamp (and meshes marked ``flarekit_light``) through the active camera, measures how much of each
the camera sees (the render's depth pass, or Blender's ray cast), smooths that over an
animation's frames with flarekit's temporal filter, and draws the flare through flarekit's
Python module: a sprite preset per light (by its power and colour), the post-process chain on
the render, or the shipped lens nearest the camera's angle of view at its f-stop and blade
count. The flare alone is written as a linear EXR per frame (and loaded as the image
"flarekit flare" for the compositor), with a JSON of the lights beside it."""
import json
import os
import shutil
import sys

import bpy
import numpy as np
from bpy.props import (BoolProperty, EnumProperty, FloatProperty, PointerProperty,
                       StringProperty)

bl_info = {
    "name": "flarekit",
    "author": "flarekit contributors",
    "version": (1, 0, 0),
    "blender": (3, 4, 0),
    "location": "Properties > Render > flarekit",
    "description": "Lens flares from the scene's lights on every render (flarekit)",
    "category": "Render",
}


def _import_flarekit():
    """flarekit's Python module: on the path already, or installed beside this add-on
    (PREFIX/share/blender/scripts/addons/flarekit_blender -> PREFIX/lib/python3/dist-packages)."""
    try:
        import flarekit  # noqa: F401
        return
    except ImportError:
        pass
    here = os.path.dirname(os.path.realpath(__file__))
    candidate = os.path.normpath(os.path.join(here, "..", "..", "..", "..", "..", "lib",
                                              "python3", "dist-packages"))
    if os.path.isdir(os.path.join(candidate, "flarekit")):
        sys.path.append(candidate)


_import_flarekit()

from . import flares, occlusion, scene_lights  # noqa: E402
import flarekit  # noqa: E402

PASSES_NODE = "flarekit passes"
FLARE_IMAGE = "flarekit flare"


# The shipped presets and lenses, listed once (they do not change while Blender runs); each
# list's default is flarekit's own.
SPRITE_PRESETS = [(name, name, "") for name in flarekit.presets("sprite")]
POSTFX_PRESETS = [(name, name, "") for name in flarekit.presets("postfx")]
LENSES = [("AUTO", "From the camera", "The shipped lens nearest the camera's angle of view")] + \
    [(name, name, "") for name in flarekit.lenses()]


class FlarekitSettings(bpy.types.PropertyGroup):
    enabled: BoolProperty(name="Flares", default=False,
                          description="Draw flarekit's flares after each rendered frame")
    mode: EnumProperty(name="Mode", items=[
        ('SPRITE', "Sprite preset", "A preset's sprite flare on each light"),
        ('POSTFX', "Post-process", "The post-process chain on the whole render"),
        ('LENS', "Lens", "A lens prescription's traced ghosts on each light")], default='SPRITE')
    preset: EnumProperty(name="Preset", items=SPRITE_PRESETS, default="tanczos-classic")
    postfx_preset: EnumProperty(name="Post-process preset", items=POSTFX_PRESETS,
                                default="photo")
    lens: EnumProperty(name="Lens", items=LENSES, default="AUTO")
    gain: FloatProperty(name="Gain", default=1.0, min=0.0, max=1000.0,
                        description="Multiplies every flare (sprite: 1 draws the preset's own "
                                    "look for a light sending 3 W/m^2 into the lens)")
    occlusion: EnumProperty(name="Occlusion", items=[
        ('DEPTH', "Depth pass", "The pixels of the light's disc not nearer than it"),
        ('RAYCAST', "Ray cast", "Blender's ray cast to points over the light's disc; "
                                "translucent surfaces pass what their alpha leaves")],
        default='DEPTH')
    temporal: BoolProperty(name="Temporal filter", default=True,
                           description="Smooth each light's coverage over an animation's frames")
    include_emissive: BoolProperty(name="Marked meshes", default=True,
                                   description="Meshes with the custom property flarekit_light")
    output_dir: StringProperty(name="Output", subtype='DIR_PATH', default="//flarekit/",
                               description="Folder of flare_####.exr and lights_####.json")
    status: StringProperty(name="Status", default="",
                           description="The last frame's result, or why it has no flare")


class FLAREKIT_PT_render(bpy.types.Panel):
    bl_label = "flarekit"
    bl_space_type = 'PROPERTIES'
    bl_region_type = 'WINDOW'
    bl_context = "render"

    def draw_header(self, context):
        self.layout.prop(context.scene.flarekit, "enabled", text="")

    def draw(self, context):
        s = context.scene.flarekit
        layout = self.layout
        layout.active = s.enabled
        layout.prop(s, "mode")
        if s.mode == 'SPRITE':
            layout.prop(s, "preset")
        elif s.mode == 'POSTFX':
            layout.prop(s, "postfx_preset")
        else:
            layout.prop(s, "lens")
        layout.prop(s, "gain")
        layout.prop(s, "occlusion")
        layout.prop(s, "temporal")
        layout.prop(s, "include_emissive")
        layout.prop(s, "output_dir")
        if s.status:
            layout.label(text=s.status, icon='ERROR' if s.status.startswith("failed") else 'INFO')


class _State:
    """What one render needs between frames: the passes' folder and each light's filter."""
    folder = None
    filters = {}
    last_frame = None
    frames = {}  # frame -> (lights, ray-cast coverage or None, (lens file, f-number) or None)


def _passes_node(scene):
    """A File Output node writing the render and its depth as float EXRs to a private folder
    each frame (the one way a handler gets a render's pixels and passes, in the background
    too)."""
    scene.use_nodes = True
    for layer in scene.view_layers:
        layer.use_pass_z = True
    tree = scene.node_tree
    layers = next((n for n in tree.nodes if n.type == 'R_LAYERS'), None)
    if layers is None:
        layers = tree.nodes.new("CompositorNodeRLayers")
    if not any(n.type == 'COMPOSITE' for n in tree.nodes):
        composite = tree.nodes.new("CompositorNodeComposite")
        tree.links.new(layers.outputs["Image"], composite.inputs["Image"])
    node = tree.nodes.get(PASSES_NODE)
    if node is None:
        node = tree.nodes.new("CompositorNodeOutputFile")
        node.name = node.label = PASSES_NODE
        node.file_slots.clear()
        node.file_slots.new("image_")
        node.file_slots.new("depth_")
    node.format.file_format = 'OPEN_EXR'
    node.format.color_depth = '32'
    node.format.color_mode = 'RGBA'
    node.base_path = _State.folder + os.sep
    tree.links.new(layers.outputs["Image"], node.inputs[0])
    tree.links.new(layers.outputs["Depth"], node.inputs[1])
    return node


def _remove_passes_node(scene):
    if scene.node_tree and scene.node_tree.nodes.get(PASSES_NODE):
        scene.node_tree.nodes.remove(scene.node_tree.nodes[PASSES_NODE])


@bpy.app.handlers.persistent
def _render_init(scene, *_):
    if not scene.flarekit.enabled:
        return
    _State.folder = flares.temp_folder()
    _State.filters = {}
    _State.last_frame = None
    _State.frames = {}
    _passes_node(scene)


@bpy.app.handlers.persistent
def _render_pre(scene, *_):
    """The lights as the frame about to render has them: by the time its pixels arrive the
    scene may already stand at the next frame of an animation."""
    if not scene.flarekit.enabled or not _State.folder:
        return
    try:
        settings = scene.flarekit
        camera = scene.camera
        # Evaluated at this frame: while an animation renders, the view layer's depsgraph still
        # holds the previous frame until it is updated.
        depsgraph = bpy.context.evaluated_depsgraph_get()
        depsgraph.update()
        lights = scene_lights.scene_lights(scene, camera, settings.include_emissive, depsgraph)
        rays = None
        if settings.occlusion == 'RAYCAST':
            rays = [occlusion.raycast_visibility(scene, depsgraph, camera, light)
                    for light in lights]
        lens = None
        if settings.mode == 'LENS':
            focal = scene_lights.focal_pixels(scene, camera)
            name = settings.lens
            if name == 'AUTO':
                name = flares.nearest_lens(flares.camera_hfov(scene, camera, focal))
            lens = (flares.lens_with_blades(name, camera.data.dof.aperture_blades,
                                            _State.folder), camera.data.dof.aperture_fstop)
        _State.frames[scene.frame_current] = (lights, rays, lens)
    except Exception as error:
        print(f"flarekit: frame {scene.frame_current}: {error}", file=sys.stderr)


@bpy.app.handlers.persistent
def _render_post(scene, *_):
    if not scene.flarekit.enabled or not _State.folder:
        return
    try:
        path = flare_frame(scene, scene.frame_current)
        scene.flarekit.status = f"frame {scene.frame_current}: {os.path.basename(path)}"
    except Exception as error:  # a failed flare never takes the render down
        print(f"flarekit: frame {scene.frame_current}: {error}", file=sys.stderr)
        scene.flarekit.status = f"failed at frame {scene.frame_current}: {error}"


@bpy.app.handlers.persistent
def _render_done(scene, *_):
    if _State.folder:
        shutil.rmtree(_State.folder, ignore_errors=True)
        _State.folder = None
        _remove_passes_node(scene)


def flare_frame(scene, frame):
    """The frame's flare from the passes the File Output node wrote; returns the flare path."""
    settings = scene.flarekit
    tag = f"{frame:04d}"
    image, _ = flarekit.read_image(os.path.join(_State.folder, f"image_{tag}.exr"))
    depth, _ = flarekit.read_image(os.path.join(_State.folder, f"depth_{tag}.exr"))
    depth = depth[..., 0]
    height, width = image.shape[:2]
    lights, rays, lens = _State.frames.pop(frame)
    raw = rays if rays is not None else [occlusion.depth_visibility(depth, light)
                                         for light in lights]
    # The temporal filter runs over consecutive frames; a jump starts it again.
    if _State.last_frame is None or frame != _State.last_frame + 1:
        _State.filters = {}
    _State.last_frame = frame
    fps = scene.render.fps / scene.render.fps_base
    weights = []
    for light, coverage in zip(lights, raw):
        if not settings.temporal:
            weights.append(coverage)
            continue
        f = _State.filters.setdefault(light.name, flarekit.TemporalFilter())
        state = f.update(min(max(coverage, 0.0), 1.0),
                         tuple(np.nan_to_num(light.position, posinf=1e6, neginf=-1e6)),
                         light.in_front, width, height, 1.0 / fps)
        weights.append(state["coverage"])  # not the edge fade: lights off-frame keep ghosts
    lens, f_number = lens if lens else (None, 0.0)
    flare = flares.draw(settings, image, lights, weights, lens, f_number)
    out_dir = bpy.path.abspath(settings.output_dir)
    os.makedirs(out_dir, exist_ok=True)
    path = os.path.join(out_dir, f"flare_{tag}.exr")
    flarekit.write_image(path, flare, depth="float")
    record = [{"name": l.name, "kind": l.kind, "x": l.position[0], "y": l.position[1],
               "in_front": l.in_front, "depth": l.depth,
               "radius_px": l.radius_px, "irradiance": l.irradiance, "color": list(l.color),
               "coverage": c, "filtered": w,
               "intensity": flares.light_intensity(l, w, settings.gain)}
              for l, c, w in zip(lights, raw, weights)]
    with open(os.path.join(out_dir, f"lights_{tag}.json"), "w") as out:
        json.dump({"frame": frame, "width": width, "height": height, "mode": settings.mode,
                   "lens": lens and os.path.basename(lens), "lights": record}, out, indent=1)
    shown = bpy.data.images.get(FLARE_IMAGE)
    if shown is None:
        shown = bpy.data.images.load(path)
        shown.name = FLARE_IMAGE
    else:
        shown.filepath = path
        shown.reload()
    return path


classes = (FlarekitSettings, FLAREKIT_PT_render)


def register():
    for cls in classes:
        bpy.utils.register_class(cls)
    bpy.types.Scene.flarekit = PointerProperty(type=FlarekitSettings)
    bpy.app.handlers.render_init.append(_render_init)
    bpy.app.handlers.render_pre.append(_render_pre)
    bpy.app.handlers.render_post.append(_render_post)
    bpy.app.handlers.render_complete.append(_render_done)
    bpy.app.handlers.render_cancel.append(_render_done)


def unregister():
    for handlers, fn in ((bpy.app.handlers.render_init, _render_init),
                         (bpy.app.handlers.render_pre, _render_pre),
                         (bpy.app.handlers.render_post, _render_post),
                         (bpy.app.handlers.render_complete, _render_done),
                         (bpy.app.handlers.render_cancel, _render_done)):
        if fn in handlers:
            handlers.remove(fn)
    del bpy.types.Scene.flarekit
    for cls in reversed(classes):
        bpy.utils.unregister_class(cls)
