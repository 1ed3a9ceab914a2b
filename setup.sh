#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# flarekit set-up on a fresh Debian 12 machine: installs the packages it needs, builds
# (Release), then runs one job.
#   ./setup.sh demo   renders the demo drive (out/drive: frames + MP4) and every shipped preset on
#                     the sample images into out/
#   ./setup.sh test   checks the formatting, runs the whole test suite, then builds the
#                     FLAREKIT_GL=OFF variant (core + CLI, no OpenGL) and runs its tests, then
#                     the ASan + UBSan variant and its tests (GL included, on llvmpipe), then
#                     each fuzz target for 60 s (CI runs this; with CI=true warnings are errors)
set -euo pipefail
cd "$(dirname "$0")"
job="${1:-}"
case "$job" in
  demo|test) ;;
  *) echo "usage: $0 demo|test" >&2; exit 2 ;;
esac

# Each stage's start on stdout, so a log tells where the time went.
start=$SECONDS
stage() { echo "== setup.sh: $* (at $((SECONDS - start)) s)"; }

stage "packages"
./scripts/install-deps.sh

werror=OFF
if [ "${CI:-}" = "true" ]; then werror=ON; fi
# Every build compiles through ccache (installed above): with the clone as the base directory
# and the working directory left out of the hash, a fresh clone on this machine reuses what any
# earlier clone compiled. 5 GB holds the four builds.
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=true CCACHE_MAXSIZE="${CCACHE_MAXSIZE:-5G}"
export FLAREKIT_LAUNCHER="-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache"
stage "main build"
# shellcheck disable=SC2086 # two flags, split on purpose
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DFLAREKIT_WERROR="$werror" $FLAREKIT_LAUNCHER
cmake --build build -j"$(nproc)"

case "$job" in
  demo) ./scripts/demo.sh build/flarekit out ;;
  test)
    stage "format check and main suite"
    ./scripts/check-format.sh
    ctest --test-dir build -j"$(nproc)" --output-on-failure
    stage "no-GL build and suite"
    # shellcheck disable=SC2086
    cmake -S . -B build-nogl -G Ninja -DCMAKE_BUILD_TYPE=Release -DFLAREKIT_GL=OFF -DFLAREKIT_BUILD_BENCH=OFF \
      -DFLAREKIT_WERROR="$werror" $FLAREKIT_LAUNCHER
    # What differs without GL: the CLI (its GL paths refuse with "built without OpenGL", the
    # rest must work) and the job layer against it. The unit and golden tests run the same core
    # objects as the main build's, so only the programs run here are built; the Slurm test
    # checks the farm, not the CLI.
    cmake --build build-nogl -j"$(nproc)" --target flarekit_cli flarekit_cli_tests \
      flarekit_cli_oiio_tests flarekit_job_tests
    ctest --test-dir build-nogl -j"$(nproc)" --output-on-failure -L 'cli|job' -LE 'slow|slurm'
    # AddressSanitizer + UndefinedBehaviorSanitizer, every error fatal: the core, codecs, jobs,
    # CLI (fault injection included), the C API and the GL plumbing and GPU paths (labels unit,
    # cli, job, gl). Left out: the package test and the documentation's blocks (they build
    # examples against the installed library with the system compiler's plain flags, which
    # cannot link an instrumented library); the GL accuracy sweeps, golden images and `slow`
    # sweeps (the same code the other tests run, over many cases for numbers: the main build
    # runs them); the Slurm farm (the CLI it runs is the one the cli tests run). Leak checking
    # is off here: Mesa unloads its driver at eglTerminate, so its one-time allocations are
    # reported against "<unknown module>" and cannot be suppressed by name, and libstdc++ and
    # OIIO have no frame pointers for the fast unwinder. The fuzz targets (no GL) check leaks.
    stage "ASan + UBSan build and suite"
    # Line tables only (-g1): the sanitizers' reports name function, file and line from them,
    # and full debug info made every instrumented unit 10-35% slower to compile. Only the
    # programs the suite below runs are built (not the accuracy, golden, slow or package tests).
    # shellcheck disable=SC2086
    cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
      -DFLAREKIT_SANITIZE=address,undefined -DFLAREKIT_BUILD_BENCH=OFF -DFLAREKIT_WERROR="$werror" \
      $FLAREKIT_LAUNCHER
    cmake --build build-asan -j"$(nproc)" --target flarekit_cli flarekit_unit_tests \
      flarekit_oiio_unit_tests flarekit_cli_tests flarekit_cli_oiio_tests flarekit_job_tests \
      flarekit_gl_tests
    ASAN_OPTIONS=detect_leaks=0:strict_string_checks=1 \
      UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
      ctest --test-dir build-asan -j"$(nproc)" --output-on-failure -L 'unit|cli|job|gl' \
      -LE 'slow|accuracy|golden|package|docs|slurm'
    stage "fuzz targets"
    FLAREKIT_WERROR="$werror" ./scripts/fuzz.sh 60
    stage "done"
    ccache -s
    ;;
esac
