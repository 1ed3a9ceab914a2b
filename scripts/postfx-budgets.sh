#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# The post-process budgets on real pictures: every shipped postfx preset at its defaults on
# each IMAGE (8/16-bit files with --expand-highlights, as a photographer flares a JPEG; float
# files as they are), measured by scripts/view-change.sh. Prints one Markdown row per image and
# preset (moved: share of the frame whose view moved by more than 30 levels; clipped: share
# newly at white), then each preset's worst figures and whether it keeps the budgets (moved at
# most 15%, clipped at most 2%). Exits 1 when a preset is over budget.
# Usage: scripts/postfx-budgets.sh FLAREKIT IMAGE...   (needs oiiotool)
set -eu
[ $# -ge 2 ] || { echo "usage: $0 FLAREKIT IMAGE..." >&2; exit 2; }
flarekit=$1
shift
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
presets=$("$flarekit" presets --postfx | awk '{print $1}')
echo "| image | preset | moved | clipped |"
echo "|---|---|---|---|"
for image in "$@"; do
    case $image in
        *.exr|*.EXR|*.hdr) expand= ; out=$work/out.exr ;;
        *) expand=--expand-highlights ; out=$work/out.png ;;
    esac
    for p in $presets; do
        # shellcheck disable=SC2086
        "$flarekit" postfx "$image" -o "$out" --preset "$p" $expand 2>/dev/null
        set -- $("$here/view-change.sh" "$image" "$out")
        echo "| $(basename "$image") | $p | $2 | $4 |"
        echo "$p ${2%\%} ${4%\%}" >> "$work/figures"
    done
done
echo
echo "| preset | worst moved | worst clipped | within 15% / 2% |"
echo "|---|---|---|---|"
status=0
for p in $presets; do
    line=$(awk -v p="$p" '$1 == p { if ($2 > m) m = $2; if ($3 > c) c = $3 }
        END { printf "%.2f %.2f %s", m, c, (m <= 15 && c <= 2) ? "yes" : "no" }' "$work/figures")
    set -- $line
    echo "| $p | $1% | $2% | $3 |"
    [ "$3" = yes ] || status=1
done
exit $status
