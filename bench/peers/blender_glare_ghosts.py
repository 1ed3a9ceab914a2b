# SPDX-License-Identifier: Apache-2.0
# Peer benchmark for flarekit postfx: the same image through Blender's compositor
# Glare node, type Ghosts, headless. Run by run_blender_peer.sh:
#   blender -b --factory-startup -noaudio --python blender_glare_ghosts.py -- IN.exr OUT.exr RUNS
# Prints one line per run: "blender-glare-ghosts <width>x<height> run <i> <seconds> s".
# The compositor has no Render Layers node, so Blender renders no scene: the time is the node
# tree (image in, Glare, composite out), the first run including the image load.
import sys
import time

import bpy

argv = sys.argv[sys.argv.index("--") + 1:]
src, dst, runs = argv[0], argv[1], int(argv[2])

scene = bpy.context.scene
image = bpy.data.images.load(src)
width, height = image.size
scene.render.resolution_x, scene.render.resolution_y = width, height
scene.render.resolution_percentage = 100
scene.render.use_compositing = True
scene.render.use_sequencer = False
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "16"
scene.render.filepath = dst
scene.use_nodes = True
tree = scene.node_tree
for node in list(tree.nodes):
    tree.nodes.remove(node)
source = tree.nodes.new("CompositorNodeImage")
source.image = image
glare = tree.nodes.new("CompositorNodeGlare")
glare.glare_type = "GHOSTS"
glare.quality = "HIGH"      # full resolution, as flarekit's chain reads the full image
glare.iterations = 3        # Blender's default
glare.threshold = 1.0       # the same threshold as flarekit's presets
glare.mix = 0.0             # image + glare, as flarekit composites
out = tree.nodes.new("CompositorNodeComposite")
tree.links.new(source.outputs["Image"], glare.inputs["Image"])
tree.links.new(glare.outputs["Image"], out.inputs["Image"])

for i in range(runs):
    start = time.perf_counter()
    bpy.ops.render.render(write_still=(i == runs - 1))
    print(f"blender-glare-ghosts {width}x{height} run {i} {time.perf_counter() - start:.4f} s", flush=True)
