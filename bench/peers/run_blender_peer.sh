#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Peer benchmark: flarekit postfx (CPU chain) against Blender's compositor Glare
# node (type Ghosts), headless, on the same HDR image at 1920x1080 and 3840x2160, same machine.
#   usage: bench/peers/run_blender_peer.sh [FLAREKIT] [OUT_DIR]
# Installs Blender with apt-get when it is missing (Debian 12: Blender 3.4). Prints each run and
# a table: Blender's warm run time, flarekit's mean warm chain time, and their ratio. Both
# times leave file reading and writing out (Blender's first run, which loads the image, is
# dropped; flarekit's --repeat times the chain alone).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
flarekit="${1:-$here/../../build/flarekit}"
out="${2:-$(mktemp -d)}"
mkdir -p "$out"
if ! command -v blender >/dev/null; then
  apt-get update && apt-get install -y --no-install-recommends blender
fi
blender --version | head -1
printf '| size | Blender Glare (Ghosts) s | flarekit preset | flarekit CPU s | ratio |\n|---|---|---|---|---|\n' > "$out/table.md"
for size in 1920x1080 3840x2160; do
  input="$out/sky-$size.exr"
  oiiotool "$here/../../samples/sunset-hdr.exr" --resize "$size" -d half -o "$input"
  blender_log="$out/blender-$size.log"
  blender -b --factory-startup -noaudio --python "$here/blender_glare_ghosts.py" -- "$input" "$out/blender-$size.exr" 3 \
    | grep '^blender-glare-ghosts' | tee "$blender_log"
  blender_s=$(awk '$4 > 0 {sum += $5; n++} END {printf "%.4f", sum / n}' "$blender_log")  # warm runs
  for preset in killzone2 modern; do
    line=$("$flarekit" postfx "$input" -o "$out/flarekit-$size-$preset.exr" --preset "$preset" --repeat 6)
    echo "$line"
    flarekit_s=$(echo "$line" | awk '{print $5}')
    ratio=$(awk -v b="$blender_s" -v f="$flarekit_s" 'BEGIN {printf "%.1f", b / f}')
    printf '| %s | %s | %s | %s | %sx |\n' "$size" "$blender_s" "$preset" "$flarekit_s" "$ratio" >> "$out/table.md"
  done
done
cat "$out/table.md"
