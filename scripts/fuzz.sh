#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds the libFuzzer targets (clang, ASan + UBSan, no GL) in build-fuzz and runs each for
# SECONDS (default 60) from its seed corpus under tests/fuzz/corpus/, as many at once as there are
# cores (FLAREKIT_FUZZ_JOBS). New inputs go to a scratch
# corpus; a crash, leak or timeout leaves its input in build-fuzz/artifacts/ and fails the run.
#   scripts/fuzz.sh [SECONDS] [TARGET...]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(FuzzPreset FuzzPostFxPreset FuzzScene FuzzImageRead FuzzPsp FuzzShotFiles FuzzConvert)

if [ "${FLAREKIT_FUZZ_NO_BUILD:-}" != 1 ]; then  # set by callers that run targets in parallel
# FLAREKIT_LAUNCHER: setup.sh's ccache flags (two words, split on purpose)
# shellcheck disable=SC2086
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ -DFLAREKIT_FUZZ=ON -DFLAREKIT_GL=OFF -DFLAREKIT_BUILD_TESTS=OFF \
  -DFLAREKIT_BUILD_BENCH=OFF -DFLAREKIT_WERROR="${FLAREKIT_WERROR:-OFF}" ${FLAREKIT_LAUNCHER:-} >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target "${targets[@]}"
fi

mkdir -p build-fuzz/artifacts
# Every seed once first (ctest label fuzz): a regression on a known input fails in seconds.
ctest --test-dir build-fuzz -L fuzz --output-on-failure -j"$(nproc)" -R "$(IFS='|'; echo "${targets[*]}")"
export ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=1"
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# One target per core at a time (each fuzzer is one process): 6 targets x 60 s take 3 minutes
# on 2 cores, not 6. Each writes its own log; the results are printed in the targets' order.
fuzz_one() {
  local t="$1" seeds="tests/fuzz/corpus/$1" scratch="build-fuzz/corpus/$1"
  local rc=0
  mkdir -p "$scratch"
  "build-fuzz/tests/fuzz/$t" "$scratch" "$seeds" -max_total_time="$seconds" -timeout=20 \
    -rss_limit_mb=3072 -max_len=262144 -print_final_stats=1 \
    -artifact_prefix="build-fuzz/artifacts/$t-" >"build-fuzz/$t.log" 2>&1 || rc=$?
  echo "$rc" >"build-fuzz/$t.status"
}
jobs_at_once="${FLAREKIT_FUZZ_JOBS:-$(nproc)}"
rm -f build-fuzz/*.status
running=0
for t in "${targets[@]}"; do
  echo "fuzz: $t for ${seconds}s (seeds: $(ls "tests/fuzz/corpus/$t" | wc -l))"
  fuzz_one "$t" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs_at_once" ]; then
    wait -n || true
    running=$((running - 1))
  fi
done
wait
failed=0
for t in "${targets[@]}"; do
  if [ "$(cat "build-fuzz/$t.status" 2>/dev/null)" != 0 ]; then
    echo "fuzz: $t FAILED (see build-fuzz/$t.log; the input is in build-fuzz/artifacts/):" >&2
    grep -E "ERROR|SUMMARY|Test unit written" "build-fuzz/$t.log" | head -5 >&2
    failed=1
  else
    echo "fuzz: $t: $(grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "build-fuzz/$t.log" | tr '\n' ' ')"
  fi
done
exit "$failed"
