#!/usr/bin/env bash
# The main job: every shipped preset on the sample sunset, the HDR sample, and each preset's
# element sheet, written to OUT_DIR.   usage: scripts/demo.sh FLAREKIT OUT_DIR
set -euo pipefail
flarekit="$1"
out="$2"
here="$(cd "$(dirname "$0")/.." && pwd)"
mkdir -p "$out/sheets"
for preset in $("$flarekit" presets | awk '{print $1}'); do
  "$flarekit" apply "$here/samples/sunset.png" -o "$out/sunset-$preset.png" --preset "$preset" --light auto
  "$flarekit" elements --preset "$preset" -o "$out/sheets/$preset.png" --cell 192
  echo "demo: $out/sunset-$preset.png"
done
"$flarekit" apply "$here/samples/sunset-hdr.exr" -o "$out/sunset-hdr-sun-wide.exr" --preset sun-wide
"$flarekit" apply "$here/samples/sunset-hdr.exr" -o "$out/sunset-hdr-sun-wide.png" --preset sun-wide
echo "demo: done, images in $out/"
