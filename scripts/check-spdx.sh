#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Fails when a source file of the repository lacks its licence line, "SPDX-License-Identifier:
# Apache-2.0", in its first three lines (after a shebang or a GLSL #version, which must come
# first). `scripts/check-spdx.sh --fix` adds the line where it is missing.
set -euo pipefail
cd "$(dirname "$0")/.."
tag="SPDX-License-Identifier: Apache-2.0"
mapfile -t files < <(git ls-files '*.cpp' '*.h' '*.hpp' '*.c' '*.vert' '*.frag' '*.geom' '*.comp' \
  '*.glsl' '*.sh' '*.py' '*.cmake' '*.in' '*CMakeLists.txt' '*.yaml' '*.xml' '.ci/run')
comment_for() {
  case "$1" in
    *.sh|*.py|*.cmake|*.in|*CMakeLists.txt|*.yaml|.ci/run) echo "# $tag" ;;
    *.xml) echo "<!-- $tag -->" ;;
    *) echo "// $tag" ;;
  esac
}
missing=()
for f in "${files[@]}"; do
  [ -f "$f" ] || continue
  head -n 3 "$f" | grep -q "$tag" && continue
  missing+=("$f")
done
if [ "${1:-}" = "--fix" ]; then
  for f in "${missing[@]}"; do
    line="$(comment_for "$f")"
    first="$(head -n 1 "$f")"
    # A shebang, a GLSL #version and an XML declaration must stay the first line.
    if [[ "$first" == '#!'* || "$first" == '#version'* || "$first" == '<?xml'* ]]; then
      { echo "$first"; echo "$line"; tail -n +2 "$f"; } > "$f.spdx"
    else
      { echo "$line"; cat "$f"; } > "$f.spdx"
    fi
    chmod --reference="$f" "$f.spdx"
    mv "$f.spdx" "$f"
  done
  echo "check-spdx: added the licence line to ${#missing[@]} files"
  exit 0
fi
if [ ${#missing[@]} -gt 0 ]; then
  for f in "${missing[@]:0:20}"; do echo "check-spdx: $f: no \"$tag\" line in its first 3 lines" >&2; done
  echo "check-spdx: ${#missing[@]} of ${#files[@]} source files lack the licence line; run scripts/check-spdx.sh --fix" >&2
  exit 1
fi
echo "check-spdx: ${#files[@]} source files carry the licence line"
