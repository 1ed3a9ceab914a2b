#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs every Debian 12 package flarekit needs to build, test and benchmark.
# Idempotent: packages already present are skipped, apt-get runs only when needed.
set -euo pipefail

packages=(
  # the compiler, CMake, Ninja, pkg-config and git that build flarekit
  build-essential cmake ninja-build pkg-config git
  # the formatting check of ./setup.sh test (.clang-format)
  clang-format
  # a compiler cache: setup.sh builds through it, so a fresh clone reuses what an earlier build
  # on this machine compiled
  ccache
  # image I/O: EXR, PNG, JPEG and TIFF through their own libraries (fast start-up)
  libopenexr-dev libimath-dev libpng-dev libjpeg62-turbo-dev libtiff-dev
  # OpenEXR's ZIP chunks deflated and inflated by libdeflate instead of zlib (3x faster)
  libdeflate-dev zlib1g-dev
  # OpenEXR's ZIP level 1, the default, deflated by ISA-L's igzip (3-5x faster than libdeflate's)
  libisal-dev
  # every other image format through OpenImageIO, loaded only when needed; oiiotool and iinfo
  # for the tests and benches
  libopenimageio-dev openimageio-tools
  # JSON presets and scenes, CLI parsing, threads
  nlohmann-json3-dev libcli11-dev libtbb-dev
  # the lens starburst: Fraunhofer diffraction of the aperture through KissFFT's C++ template
  # (header-only, BSD-3-Clause; FFTW is GPL and would bind every program linking libflarekit)
  libkissfft-dev
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev
  # contact-sheet labels are rendered by OIIO with this font
  fonts-dejavu-core
  # headless OpenGL 4.5 through EGL (Mesa llvmpipe gives GL without a GPU)
  libepoxy-dev libegl-dev libegl-mesa0 libgl1-mesa-dri
  # the demo's and shots' MP4 (run as a program, not linked)
  ffmpeg
  # the any-renderer shaders compiled at build time: GLSL to SPIR-V (glslc), SPIR-V to HLSL and
  # MSL (SPIRV-Cross), and their tests' checks (spirv-val, glslang's HLSL front end)
  glslc spirv-cross spirv-tools glslang-tools
  # the engine API's Vulkan backend: Vulkan headers (the library loads libvulkan.so.1 only when
  # a Vulkan engine is made), and for its tests Mesa's lavapipe and the Khronos validation layer
  libvulkan-dev libvulkan1 mesa-vulkan-drivers vulkan-validationlayers
  # the embedding example opens a window with GLFW when there is a display
  libglfw3-dev
  # the embedding example's window test and the studio's tests run on a private X server (Xvfb,
  # local socket only; xauth for xvfb-run in the docs)
  xvfb xauth
  # flarekit convert: Unity's lens-flare assets are YAML (yaml-cpp, MIT)
  libyaml-cpp-dev
  # flarekit studio, the live designer: Dear ImGui 1.86 panels in a GLFW window
  libimgui-dev
  # shots on a farm: the Slurm test runs a one-node cluster (its own munged, slurmctld, slurmd)
  slurmctld slurmd slurm-client munge
  # shots: colour spaces through OpenColorIO
  libopencolorio-dev
  # the Python module (`import flarekit`): pybind11 and numpy for Debian's python3, pytest for
  # its tests
  pybind11-dev python3-dev python3-numpy python3-pytest
  # the flare-data generator's PyTorch dataset and its Dask cluster runs (and their tests)
  python3-torch python3-dask python3-distributed
  # the frei0r filter for ffmpeg, melt, Kdenlive and Shotcut: frei0r.h (the plug-in only; see
  # NOTICE), and melt for its test in the real host (ffmpeg is above)
  frei0r-plugins-dev melt
  # the GIMP 2.10 plug-in: libgimp (LGPL-3.0-or-later, linked by the plug-in only) and GIMP for
  # its test in batch mode
  libgimp2.0-dev gimp
  # the Blender add-on's test: Blender 3.4 on the system's Python, rendering in the background
  blender
  # the fuzz targets: clang with libFuzzer and the sanitizer runtimes
  clang libclang-rt-14-dev
)

# --markdown: the list above as Markdown bullets (each group's packages and its comment), which
# the README's dependency paragraph is (tests/docs/check-readme-deps.sh compares them).
if [ "${1:-}" = "--markdown" ]; then
  awk '
    /^packages=\(/ { inlist = 1; next }
    inlist && /^\)/ { if (pkgs != "") print "- " pkgs ": " why; exit }
    inlist && /^ *#/ {
      if (pkgs != "") { print "- " pkgs ": " why; pkgs = ""; why = "" }
      line = $0; sub(/^ *# */, "", line); why = (why == "" ? line : why " " line); next
    }
    inlist && NF { for (i = 1; i <= NF; i++) pkgs = pkgs (pkgs == "" ? "" : ", ") "`" $i "`" }
  ' "$0"
  exit 0
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: run as root or install sudo" >&2; exit 1; }
  SUDO=sudo
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
