#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The main job: the built-in drive (road, trees, buildings, tunnel, turn; 240 frames at
# 1280x720 with an occlusion-aware sun flare, PNG frames + MP4), then every shipped preset on
# the sample sunset, the HDR sample, each preset's element sheet, and the drive through the PSP
# GE emulator (Burnout Dominator's flare, correct and naive side by side), and every post-process
# preset on the HDR sample (CPU and GL) with its layers, all written to OUT_DIR.
#   usage: scripts/demo.sh FLAREKIT OUT_DIR
set -euo pipefail
flarekit="$1"
out="$2"
here="$(cd "$(dirname "$0")/.." && pwd)"
"$flarekit" demo -o "$out/drive"
mkdir -p "$out/sheets"
for preset in $("$flarekit" presets | awk '{print $1}'); do
  "$flarekit" apply "$here/samples/sunset.png" -o "$out/sunset-$preset.png" --preset "$preset" --light auto
  "$flarekit" apply "$here/samples/sunset-hdr.exr" -o "$out/sunset-hdr-$preset.png" --preset "$preset"
  "$flarekit" elements --preset "$preset" -o "$out/sheets/$preset.png" --cell 192
  echo "demo: $out/sunset-$preset.png"
done
"$flarekit" apply "$here/samples/sunset-hdr.exr" -o "$out/sunset-hdr-sun-wide.exr" --preset sun-wide
"$flarekit" apply "$here/samples/sunset-hdr.exr" -o "$out/sunset-hdr-sun-wide.png" --preset sun-wide
for scene in "$here"/samples/scenes/*.json; do
  "$flarekit" render "$scene" -o "$out/scene-$(basename "$scene" .json).png"
done
"$flarekit" psp demo -o "$out/psp" --frames 48
mkdir -p "$out/postfx"
for preset in $("$flarekit" presets --postfx | awk '{print $1}'); do
  "$flarekit" postfx "$here/samples/sunset-hdr.exr" -o "$out/postfx/sunset-hdr-$preset.png" --preset "$preset" --tonemap aces \
    --save-layers "$out/postfx/layers-$preset"
  "$flarekit" postfx "$here/samples/sunset-hdr.exr" -o "$out/postfx/sunset-hdr-$preset-gl.png" --preset "$preset" --tonemap aces --backend gl
  "$flarekit" postfx "$here/samples/sunset.png" -o "$out/postfx/sunset-$preset.png" --preset "$preset" --expand-highlights
  echo "demo: $out/postfx/sunset-hdr-$preset.png"
done
echo "demo: done: the drive is $out/drive/demo.mp4 (frames, coverage.csv and strip.png beside it); images in $out/, PSP frames in $out/psp/, post-process flares in $out/postfx/"
