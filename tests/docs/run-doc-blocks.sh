#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Documentation that runs: every ```sh block of README.md and docs/*.md, in order, one temporary
# folder per Markdown file (so a page's blocks build on each other as a reader's would), with
# `flarekit` on PATH, the repository's samples/, presets/, examples/, integrations/ and build/
# beside, and the small inputs the pages name (photo.exr, plate/sh010.####.exr, sun.csv, ...)
# made from the shipped samples. A block fails the test when it exits non-zero, when a file it names with -o
# is missing, or when an image it wrote does not decode. A block that cannot run here is marked
# in the Markdown on the line before it, and is listed by name as skipped:
#   <!-- docs-test: skip: the reason -->
#   run-doc-blocks.sh SOURCE_DIR BUILD_DIR CLI [PAGE.md ...]
set -uo pipefail
# shellcheck source=tests/support/undecodable-images.sh
source "$(dirname "$0")/../support/undecodable-images.sh"
src="$(cd "$1" && pwd)"
build="$(cd "$2" && pwd)"
cli="$(readlink -f "$3")"
shift 3
pages=("$@")
[ ${#pages[@]} -gt 0 ] || pages=("$src/README.md" "$src"/docs/*.md)
work="$(mktemp -d "${TMPDIR:-/tmp}/flarekit-docs.XXXXXX")"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/bin"
ln -s "$cli" "$work/bin/flarekit"
export PATH="$work/bin:$PATH"
unset OCIO FLAREKIT_PRESET_PATH FLAREKIT_DATA_DIR DISPLAY

# --- the inputs the pages name, made from the shipped samples (small, so blocks are fast). ctest
# runs each page as its own test: its DocFixtures test (FIXTURES=make) makes them once in the
# build folder, and the pages' tests take them from there (FLAREKIT_DOC_FIXTURES); run by hand,
# the script makes them itself, the 240-frame plate only when a page names it.
make_fixtures() {  # folder with-plate(0/1)
  mkdir -p "$1/plate" "$1/fg"
  (
    set -e
    cd "$1"
    oiiotool "$src/samples/sunset-hdr.exr" --resize 320x180 -o photo.exr
    cp photo.exr sky.exr
    oiiotool "$src/samples/sunset.png" --resize 320x180 -o photo.jpg
    # the PSP's 480x272 screen with an occluder box
    oiiotool --pattern constant:color=1,1,1 480x272 3 --box:color=0,0,0:fill=1 200,60,300,200 \
      -d uint8 -o MASK.png
    oiiotool --pattern noise:type=uniform:min=0.6:max=1 64x64 1 -d uint8 -o my-dust.png
    cp "$src/presets/subtle.json" my.json
    cp "$src/presets/postfx/killzone2.json" my-postfx.json
    cp "$src/tests/package/c_api_check.c" app.c
    # a 240-frame plate (1001-1240), its foreground matte and a track of its sun
    printf 'frame,x,y\n1001,116.5,31\n1240,120,33.5\n' > sun.csv
    [ "$2" = 1 ] || exit 0
    oiiotool "$src/samples/sunset-hdr.exr" --resize 160x90 -o plate/sh010.1001.exr
    oiiotool --pattern constant:color=0 160x90 1 --box:color=1:fill=1 0,60,40,89 -d half -o fg/fg.1001.exr
    for f in $(seq 1002 1240); do
      cp plate/sh010.1001.exr "plate/sh010.$f.exr"
      cp fg/fg.1001.exr "fg/fg.$f.exr"
    done
  ) > "$work/fixtures.log" 2>&1 || { echo "docs: making the inputs failed:"; cat "$work/fixtures.log"; exit 1; }
}
if [ "${FIXTURES:-}" = make ]; then
  rm -rf "$build/doc-fixtures"
  make_fixtures "$build/doc-fixtures" 1
  echo "docs: the pages' inputs are in $build/doc-fixtures"
  exit 0
fi
if ! grep -q -E '^ *```sh *$' "${pages[@]}"; then
  echo "docs: no command blocks in ${pages[*]##*/}"
  exit 0
fi
if [ -n "${FLAREKIT_DOC_FIXTURES:-}" ]; then
  fixtures="$FLAREKIT_DOC_FIXTURES"
  [ -f "$fixtures/sun.csv" ] || { echo "docs: $fixtures holds no inputs (the DocFixtures test makes them)"; exit 1; }
else
  fixtures="$work/fixtures"
  plate=0
  if grep -q -E '(plate|fg)/' "${pages[@]}"; then plate=1; fi
  make_fixtures "$fixtures" "$plate"
fi

# --- the blocks: FILE:LINE, its skip reason if marked, its text with the fence's indent removed
extract() {  # page outdir -> outdir/NNN.sh and outdir/NNN.meta ("LINE<TAB>skip reason")
  awk -v out="$2" '
    function flush() { close(file) }
    /^ *```sh *$/ && !inblock {
      inblock = 1; n++; indent = match($0, /[^ ]/) - 1
      file = sprintf("%s/%03d.sh", out, n)
      meta = sprintf("%s/%03d.meta", out, n)
      reason = ""
      if (prev ~ /<!-- docs-test: skip: .* -->/) {
        reason = prev; sub(/.*<!-- docs-test: skip: /, "", reason); sub(/ *-->.*/, "", reason)
      }
      printf "%d\t%s\n", NR, reason > meta; close(meta)
      printf "" > file
      next
    }
    /^ *``` *$/ && inblock { inblock = 0; flush(); next }
    inblock { print substr($0, indent + 1) >> file; next }
    NF { prev = $0 }
  ' "$1"
}

status=0 ran=0 skipped=0
for page in "${pages[@]}"; do
  name="$(basename "$page" .md)"
  dir="$work/run-$name"
  blocks="$work/blocks-$name"
  mkdir -p "$dir" "$blocks"
  cp -r "$fixtures/." "$dir/"
  for shared in samples presets examples integrations; do ln -s "$src/$shared" "$dir/$shared"; done
  ln -s "$build" "$dir/build"
  extract "$page" "$blocks"
  for block in "$blocks"/*.sh; do
    [ -e "$block" ] || continue
    IFS=$'\t' read -r line reason < "${block%.sh}.meta"
    where="${page#"$src"/}:$line"
    if [ -n "$reason" ]; then
      echo "docs: SKIP $where: $reason"
      skipped=$((skipped + 1))
      continue
    fi
    touch "$work/stamp"
    sleep 0.01
    start=$(date +%s)
    if ! (cd "$dir" && bash -euo pipefail "$block") > "$work/log" 2>&1; then
      echo "docs: FAIL $where: the block exited non-zero:"
      sed 's/^/    /' "$block"
      tail -n 20 "$work/log" | sed 's/^/  | /'
      status=1
      continue
    fi
    problems=""
    # Every -o target exists (a frame pattern: at least one frame of it).
    for target in $(grep -o -- '-o [^ ]*' "$block" | cut -d' ' -f2); do
      pattern="$(sed -e 's/#\+/*/g' -e 's/%0[0-9]d/*/g' <<<"$target")"
      # shellcheck disable=SC2086
      ( cd "$dir" && compgen -G "$pattern" > /dev/null ) || problems+=" no $target;"
    done
    # Every image it wrote decodes completely.
    mapfile -d '' written < <(find "$dir" -newer "$work/stamp" -type f \( -name '*.png' -o \
      -name '*.exr' -o -name '*.jpg' -o -name '*.tif' -o -name '*.ppm' \) -print0)
    bad="$(undecodable_images "${written[@]}")"
    [ -z "$bad" ] || problems+=" an image it wrote does not decode: $bad;"
    if [ -n "$problems" ]; then
      echo "docs: FAIL $where:$problems"
      status=1
    else
      echo "docs: ok   $where ($(( $(date +%s) - start )) s)"
      ran=$((ran + 1))
    fi
  done
done
echo "docs: $ran blocks ran, $skipped skipped by their mark"
exit $status
