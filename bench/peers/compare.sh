#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Whole-process comparison with the peers a user would otherwise run, side by side on this
# machine: `flarekit postfx` against Blender's compositor Glare node (Ghosts) on an HDR EXR,
# `flarekit apply` against GIMP's Lens Flare on a PNG, each at 1920x1080 and 3840x2160. Every
# run is a whole process (start-up, read, effect, write), as a user or a script meets it.
# Runs alternate flarekit / peer; the figure is the median of the pairwise time ratios.
#   bench/peers/compare.sh [FLAREKIT] [OUT_DIR] [PAIRS]
# With --builds, two flarekit builds instead, the same commands on the same inputs (a change's
# cost in whole-process time, paired so the VM's drift cancels); the peer is OLD:
#   bench/peers/compare.sh --builds OLD_FLAREKIT NEW_FLAREKIT [OUT_DIR] [PAIRS]
# Installs Blender and GIMP with apt-get when they are missing (Debian 12: Blender 3.4, GIMP
# 2.10). Not part of the test suite. Prints every run and a Markdown table (OUT_DIR/table.md).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
old=""
if [ "${1:-}" = "--builds" ]; then
  old="$(realpath "$2")"
  shift 2
fi
flarekit="$(realpath "${1:-$here/../../build/flarekit}")"
out="${2:-$(mktemp -d)}"
pairs="${3:-5}"
mkdir -p "$out"
need=()
if [ -z "$old" ]; then
  command -v blender >/dev/null || need+=(blender)
  command -v gimp-console >/dev/null || need+=(gimp)
fi
command -v oiiotool >/dev/null || need+=(openimageio-tools)
if [ ${#need[@]} -gt 0 ]; then
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${need[@]}"
fi
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
if [ -n "$old" ]; then
  echo "flarekit: $flarekit ($("$flarekit" --version)); peer: $old ($("$old" --version))"
else
  echo "flarekit: $("$flarekit" --version); $(blender --version 2>/dev/null | head -1); GIMP $(gimp-console --version | awk '{print $NF}')"
fi

seconds() {  # runs "$@" quietly, prints its wall time in seconds
  local t0 t1
  t0=$(date +%s%N)
  "$@" >/dev/null 2>&1 || { echo "compare: failed: $*" >&2; exit 1; }
  t1=$(date +%s%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN {printf "%.4f", (b - a) / 1e9}'
}
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

# One row: label, then the flarekit command and the peer command (as arrays via eval).
table="$out/table.md"
printf '| job | size | flarekit s (median) | peer s (median) | peer / flarekit (median of pairs) |\n|---|---|---|---|---|\n' > "$table"
row() {
  local job="$1" size="$2" ours="$3" theirs="$4" ratios="" fk="" pe=""
  for i in $(seq "$pairs"); do
    local a b
    a=$(eval "seconds $ours")
    b=$(eval "seconds $theirs")
    echo "$job $size pair $i: flarekit $a s, peer $b s"
    fk="$fk$a"$'\n'
    pe="$pe$b"$'\n'
    ratios="$ratios$(awk -v a="$a" -v b="$b" 'BEGIN {printf "%.3f", b / a}')"$'\n'
  done
  # Between two builds the ratio is near 1, so it gets three decimals.
  local places=1
  [ -n "$old" ] && places=3
  printf "| %s | %s | %.3f | %.3f | %.${places}fx |\n" "$job" "$size" \
    "$(printf '%s' "$fk" | median)" "$(printf '%s' "$pe" | median)" \
    "$(printf '%s' "$ratios" | median)" >> "$table"
}

for size in 1920x1080 3840x2160; do
  exr="$out/sky-$size.exr"
  png="$out/photo-$size.png"
  oiiotool "$here/../../samples/sunset-hdr.exr" --resize "$size" -d half -o "$exr"
  oiiotool "$here/../../samples/sunset.png" --resize "$size" -o "$png"
  if [ -n "$old" ]; then
    row "postfx, new vs old build" "$size" "\"$flarekit\" postfx \"$exr\" -o \"$out/fk-$size.exr\"" \
      "\"$old\" postfx \"$exr\" -o \"$out/old-$size.exr\""
    row "apply, new vs old build" "$size" "\"$flarekit\" apply \"$png\" -o \"$out/fk-$size.png\"" \
      "\"$old\" apply \"$png\" -o \"$out/old-$size.png\""
    continue
  fi
  # GIMP's flare needs its centre: the light flarekit finds in the same picture.
  centre=$("$flarekit" apply "$png" -o "$out/probe.png" -v | awk '/^flare at/ {split($3, p, ","); printf "%d %d", p[1], p[2]}')
  row "postfx vs Blender Glare (Ghosts)" "$size" \
    "\"$flarekit\" postfx \"$exr\" -o \"$out/fk-$size.exr\"" \
    "blender -b --factory-startup -noaudio --python \"$here/blender_glare_ghosts.py\" -- \"$exr\" \"$out/blender-$size.exr\" 1"
  row "apply vs GIMP Lens Flare" "$size" \
    "\"$flarekit\" apply \"$png\" -o \"$out/fk-$size.png\"" \
    "gimp-console -i -d -f -b '(begin (load \"$here/gimp_lens_flare.scm\") (flarekit-gimp-flare \"$png\" \"$out/gimp-$size.png\" ${centre% *} ${centre#* }))' -b '(gimp-quit 0)'"
done
cat "$table"
