#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Checks the licences of what flarekit's built artefacts link: each NEEDED entry (readelf -d) of
# every file given is mapped to the Debian package that ships it (dpkg -S) and looked up in the
# allow-list (first argument; "package<TAB>licence<TAB>why" lines). Prints one line per library,
# and fails on a package that is not on the list.
#   tests/package/licence-check.sh tests/package/licence-allowlist.tsv FILE...
set -euo pipefail
allowlist="$1"
shift
status=0
cache="$(ldconfig -p)"
declare -A package_of path_of
for file in "$@"; do
  mapfile -t needed < <(readelf -d "$file" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
  [ ${#needed[@]} -gt 0 ] || { echo "licence-check: $file: no NEEDED entries (not a dynamic ELF file?)" >&2; status=1; }
  for soname in "${needed[@]}"; do
    # Each soname is looked up once (dpkg -S reads the whole package database: 0.6 s a call).
    if [ -n "${package_of[$soname]+set}" ]; then
      package="${package_of[$soname]}" path="${path_of[$soname]}"
    else
      path="$(awk -v s="$soname" '$1 == s && /x86-64|64bit/ {print $NF; exit}' <<<"$cache")"
      [ -n "$path" ] || path="$(awk -v s="$soname" '$1 == s {print $NF; exit}' <<<"$cache")"
      package=""
      for candidate in "$path" "$(readlink -f "$path")" "${path/#\/usr\/lib/\/lib}" "${path/#\/lib/\/usr\/lib}"; do
        [ -n "$candidate" ] || continue
        package="$( (dpkg -S "$candidate" 2>/dev/null || true) | sed -n '1s/:.*//p')"
        [ -n "$package" ] && break
      done
      package_of[$soname]="$package" path_of[$soname]="$path"
    fi
    if [ -z "$package" ]; then
      echo "licence-check: $file: $soname: no Debian package ships it (${path:-not found by ldconfig})" >&2
      status=1
      continue
    fi
    licence="$(awk -F '\t' -v p="$package" '!/^#/ && $1 == p {print $2; exit}' "$allowlist")"
    if [ -z "$licence" ]; then
      echo "licence-check: $file: $soname: package $package is not on the allow-list $allowlist" >&2
      status=1
      continue
    fi
    echo "$(basename "$file"): $soname  $package  $licence"
  done
done
exit $status
