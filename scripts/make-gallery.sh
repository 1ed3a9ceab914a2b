#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Regenerates docs/images/gallery/ from the CC0 HDR environment photographs of Debian's
# blender-data package (studiolights/world: 1024x512 equirectangular EXRs): 640x360 crops with
# the sun off centre, every sprite and postfx preset on them at the defaults, 8-bit JPEGs.
# Usage: scripts/make-gallery.sh [build dir]   (needs blender-data and oiiotool)
set -eu
build=${1:-build}
world=/usr/share/blender/datafiles/studiolights/world
out=docs/images/gallery
crops=$(mktemp -d)
trap 'rm -rf "$crops"' EXIT
mkdir -p "$out"
# name x y: the crop's top-left corner in the HDRI
for c in "sunrise 194 113" "city 180 20" "night 40 80" "forest 380 60"; do
    set -- $c
    oiiotool "$world/$1.exr" --cut "640x360+$2+$3" --origin +0+0 --fullpixels -d half \
        -o "$crops/$1.exr"
    oiiotool "$crops/$1.exr" --colorconvert linear sRGB -d uint8 -o "$out/$1-input.jpg"
done
for p in $("$build/flarekit" presets | awk '{print $1}'); do
    "$build/flarekit" apply "$crops/sunrise.exr" -o "$out/sunrise-apply-$p.jpg" --preset "$p"
done
for p in anamorphic killzone2 modern photo subtle; do
    "$build/flarekit" postfx "$crops/sunrise.exr" -o "$out/sunrise-postfx-$p.jpg" --preset "$p"
done
# The 8-bit path: sunrise as a camera JPEG would store it (clipped sRGB), flared as a photo.
oiiotool "$crops/sunrise.exr" --colorconvert linear sRGB -d uint8 -o "$crops/sunrise-8bit.png"
"$build/flarekit" apply "$crops/sunrise-8bit.png" -o "$out/sunrise-8bit-apply.jpg"
"$build/flarekit" postfx "$crops/sunrise-8bit.png" -o "$out/sunrise-8bit-postfx.jpg"
"$build/flarekit" postfx "$crops/sunrise-8bit.png" -o "$out/sunrise-8bit-expanded.jpg" \
    --expand-highlights
for s in city night forest; do
    "$build/flarekit" apply "$crops/$s.exr" -o "$out/$s-apply.jpg" --max-lights 4
    "$build/flarekit" postfx "$crops/$s.exr" -o "$out/$s-postfx.jpg"
done
# Every shipped lens at the `lens render` defaults (ghosts at the flux level, spectral
# starburst) on the sunrise crop.
for l in $("$build/flarekit" lens list | awk 'NR > 1 {print $1}'); do
    "$build/flarekit" lens render "$l" "$crops/sunrise.exr" -o "$out/sunrise-lens-$l.jpg"
done
# An HDR interior with bright windows: every postfx preset at its defaults.
oiiotool "$world/interior.exr" --cut 640x360+300+60 --origin +0+0 --fullpixels -d half \
    -o "$crops/interior.exr"
oiiotool "$crops/interior.exr" --colorconvert linear sRGB -d uint8 -o "$out/interior-input.jpg"
for p in anamorphic killzone2 modern photo subtle; do
    "$build/flarekit" postfx "$crops/interior.exr" -o "$out/interior-postfx-$p.jpg" --preset "$p"
done
# A studio with a fluorescent strip light and globe lamps: each light one flare.
oiiotool "$world/studio.exr" --cut 640x360+384+60 --origin +0+0 --fullpixels -d half \
    -o "$crops/studio.exr"
oiiotool "$crops/studio.exr" --colorconvert linear sRGB -d uint8 -o "$out/studio-input.jpg"
"$build/flarekit" apply "$crops/studio.exr" -o "$out/studio-apply.jpg" --max-lights 4
"$build/flarekit" postfx "$crops/studio.exr" -o "$out/studio-postfx.jpg"
# A sunlit yard seen from a dark arcade (no sun in view): the whole frame, postfx's defaults
# and killzone2, with the bright yard's bloom and ghosts capped (area_reference).
oiiotool "$world/courtyard.exr" --colorconvert linear sRGB -d uint8 -o "$out/courtyard-input.jpg"
for p in photo killzone2; do
    "$build/flarekit" postfx "$world/courtyard.exr" -o "$out/courtyard-postfx-$p.jpg" --preset "$p"
done
# An 8-bit photograph with no light in it (MATE's GreenMeadow, from mate-backgrounds when
# installed): apply and postfx --expand-highlights leave it as it is.
meadow=/usr/share/backgrounds/mate/nature/GreenMeadow.jpg
if [ -f "$meadow" ]; then
    oiiotool "$meadow" --resize 640x0 -o "$crops/meadow.png"
    oiiotool "$crops/meadow.png" -o "$out/meadow-input.jpg"
    "$build/flarekit" apply "$crops/meadow.png" -o "$out/meadow-apply.jpg" 2>/dev/null
    "$build/flarekit" postfx "$crops/meadow.png" -o "$out/meadow-postfx.jpg" \
        --preset killzone2 --expand-highlights 2>/dev/null
fi
