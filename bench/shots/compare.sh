#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Whole-process throughput on a shot: N frames of 1920x1080 half-float EXR through `postfx` and
# `apply` in one process (frames in parallel, reading and writing beside rendering) against N
# one-frame processes, with the peak memory of each, and `lens render` per frame. Not part of
# the test suite: run it on a quiet machine.
#   bench/shots/compare.sh [build/flarekit] [frames, default 100]
set -euo pipefail
flarekit="$(realpath "${1:-build/flarekit}")"
frames="${2:-100}"
here="$(cd "$(dirname "$0")" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# The frames: the sample HDR sunset at 1080p as half floats (the same picture each frame: the
# cost of a frame does not depend on what it shows, within a few percent).
oiiotool "$here/../../samples/sunset-hdr.exr" --resize 1920x1080 -d half -o "$work/src.exr"
mkdir -p "$work/in" "$work/one" "$work/many"
for ((f = 1; f <= frames; f++)); do cp "$work/src.exr" "$(printf "$work/in/shot.%04d.exr" "$f")"; done

seconds() { /usr/bin/time -f "%e %M" -o "$work/time" "$@" >/dev/null 2>"$work/err" || {
  cat "$work/err" >&2; exit 1; }; cat "$work/time"; }

for job in postfx apply; do
  one=$(seconds "$flarekit" "$job" "$work/in/shot.####.exr" -o "$work/one/out.####.exr")
  summary=$(grep "frames in" "$work/err" || true)
  start=$(date +%s%N)
  peak=0
  for ((f = 1; f <= frames; f++)); do
    name=$(printf "shot.%04d.exr" "$f")
    r=$(seconds "$flarekit" "$job" "$work/in/$name" -o "$work/many/$name")
    kb=${r#* }
    ((kb > peak)) && peak=$kb
  done
  many=$(awk -v a="$(date +%s%N)" -v b="$start" 'BEGIN { printf "%.3f", (a - b) / 1e9 }')
  read -r oneS oneKb <<<"$one"
  awk -v job="$job" -v n="$frames" -v one="$oneS" -v kb="$oneKb" -v many="$many" -v peak="$peak" \
    'BEGIN { printf "%s, %d frames 1080p half EXR: one process %.2f s (%.2f frames/s, peak %d MiB); %d processes %.2f s (%.2f frames/s, peak %d MiB each); %.2fx\n", job, n, one, n / one, kb / 1024, n, many, n / many, peak / 1024, many / one }'
  echo "  $summary"
  cmp -s "$work/one/out.0001.exr" "$work/many/shot.0001.exr" && echo "  frame 1 bit-identical both ways"
done

r=$(seconds "$flarekit" lens render nikon-zoom-80-200 "$work/in/shot.0001.exr" -o "$work/lens.exr")
echo "lens render, nikon-zoom-80-200, one 1080p frame: ${r% *} s, peak $((${r#* } / 1024)) MiB"
