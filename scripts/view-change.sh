#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# How much a flare changed a picture, in the two figures the budgets are stated in:
#   moved:   share of pixels whose display view moved by more than 30 levels (of 255) in any
#            channel;
#   clipped: share of pixels with a channel at white in the result that had none in the input.
# The display view is the file's own codes for 8/16-bit images and a plain clipped sRGB view
# (linear clamped to [0, 1], then the sRGB curve) for float images, so an EXR before and after
# is judged as a viewer showing it unmodified would. Prints "moved 3.21% clipped 0.40%".
# Usage: scripts/view-change.sh BEFORE AFTER   (needs oiiotool from openimageio-tools)
set -eu
[ $# -eq 2 ] || { echo "usage: $0 BEFORE AFTER" >&2; exit 2; }
view=$(mktemp -d)
trap 'rm -rf "$view"' EXIT
for side in before after; do
    [ "$side" = before ] && src=$1 || src=$2
    # The pixel type and channel count from the summary line only ("W x H, N channel, half
    # openexr"): metadata such as a Software tag can name any type. Grey files are promoted to
    # RGB, as flarekit reads them.
    summary=$(oiiotool --info "$src" | head -1)
    channels=$(echo "$summary" | sed -n 's/.*, \([0-9]*\) channel.*/\1/p')
    rgb="--ch R,G,B"
    [ "${channels:-3}" -ge 3 ] || rgb="--ch 0,0,0 --chnames R,G,B"
    # shellcheck disable=SC2086
    case $(echo "$summary" | sed -n 's/.*channel, \(float\|half\).*/float/p') in
        float) oiiotool "$src" $rgb --clamp:min=0:max=1 --colorconvert linear sRGB \
                   -d uint8 -o "$view/$side.png" ;;
        *) oiiotool "$src" $rgb -d uint8 -o "$view/$side.png" ;;
    esac
done
# A level of 255 reads as 1.0; "at white" is a code above 254.5, "moved" a step above 30.5.
share() { oiiotool "$@" --printstats | awk '/Stats Avg/ {print $3 * 100; exit}'; }
white() { echo "$1 --maxchan --subc 0.998 --mulc 1e6 --clamp:min=0:max=1"; }
# shellcheck disable=SC2046
moved=$(share "$view/before.png" "$view/after.png" --absdiff --maxchan --subc 0.1196 \
    --mulc 1e6 --clamp:min=0:max=1)
# shellcheck disable=SC2046
clipped=$(share $(white "$view/after.png") $(white "$view/before.png") --sub --clamp:min=0)
printf 'moved %.2f%% clipped %.2f%%\n' "$moved" "$clipped"
