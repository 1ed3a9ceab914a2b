#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The README's dependency list (between <!-- deps:begin --> and <!-- deps:end -->) is exactly what
# scripts/install-deps.sh installs, each group with its reason (install-deps.sh --markdown).
#   check-readme-deps.sh SOURCE_DIR
set -euo pipefail
src="$1"
expected="$("$src/scripts/install-deps.sh" --markdown)"
actual="$(sed -n '/<!-- deps:begin -->/,/<!-- deps:end -->/p' "$src/README.md" | sed '1d;$d')"
if [ "$expected" != "$actual" ]; then
  echo "check-readme-deps: README.md's dependency list differs from scripts/install-deps.sh:" >&2
  diff <(echo "$expected") <(echo "$actual") >&2 || true
  echo "check-readme-deps: paste the output of scripts/install-deps.sh --markdown between the markers" >&2
  exit 1
fi
echo "check-readme-deps: $(grep -c '^- ' <<<"$expected") package groups, README and script agree"
