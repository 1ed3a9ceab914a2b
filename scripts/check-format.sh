#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Fails when a C++ file of the repository differs from what clang-format (.clang-format, Debian
# 12's clang-format 14) makes of it. `scripts/check-format.sh --fix` formats them in place.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files '*.cpp' '*.h' '*.hpp')
if [ "${1:-}" = "--fix" ]; then
  clang-format -i "${files[@]}"
  exit 0
fi
if ! clang-format --dry-run --Werror "${files[@]}" 2> format.log; then
  grep -m 20 -E "(error|warning):" format.log >&2 || true
  echo "check-format: $(grep -c -E '(error|warning):' format.log) places differ from clang-format; run scripts/check-format.sh --fix" >&2
  rm -f format.log
  exit 1
fi
rm -f format.log
echo "check-format: ${#files[@]} files formatted"
# Every source file also carries its licence line.
./scripts/check-spdx.sh
