#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs the Debian 12 packages litkit needs. Safe to run again: apt-get
# skips what is already there.
#
#   scripts/install-deps.sh          build, test and benchmark
#   scripts/install-deps.sh --fuzz   the same, plus clang and its sanitizer
#                                    and libFuzzer runtimes (a few hundred MB),
#                                    which only scripts/fuzz.sh needs
#   scripts/install-deps.sh --bench  the same, plus hyperfine and GNU time,
#                                    which only bench/compare.sh needs
#   scripts/install-deps.sh --web    the same, plus emscripten, Chromium and
#                                    node/npm, which only scripts/build-web.sh
#                                    and scripts/test-web.sh need
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config
  # .ci/run checks the sources' layout against .clang-format (scripts/check-format.sh).
  clang-format
  libglm-dev libtomlplusplus-dev libcli11-dev libpng-dev zlib1g-dev libdeflate-dev libtinyobjloader-dev
  # glTF mesh files (src/geometry/gltf.cpp): tinygltf, compiled in from its
  # header as tinyobjloader is, and the JSON parser it includes.
  libtinygltf-dev nlohmann-json3-dev
  # PNG's default level deflated by ISA-L (src/core/image.cpp; a shared
  # library: Debian has no archive of it).
  libisal-dev
  libgtest-dev libgmock-dev libbenchmark-dev libxsimd-dev
  # litkit compare's labels (FreeType, DejaVu Sans) and litkit turntable's GIFs.
  # The litkit executable links these, libpng and zlib statically: their -dev
  # packages ship the archives, and FreeType's need the brotli decoder's.
  libfreetype-dev fonts-dejavu-core libgif-dev libbrotli-dev
  # The OpenGL backend (litkit::gl) and the exported programs: EGL headless on
  # Mesa's llvmpipe where there is no GPU, GL loaded through libepoxy.
  libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri libepoxy-dev
  # Tests of the exports: glslangValidator checks the GLSL; the exported
  # program's --window is built with SDL2 and shown on a virtual X display.
  glslang-tools libsdl2-dev xvfb xauth
  # litkit view: Dear ImGui's panel; its tests drive a real window on Xvfb
  # with xdotool and read it back with xwd.
  libimgui-dev libstb-dev xdotool x11-apps
  # test_teach parses explain --json with Python's json module.
  python3
  # The Python module (python/, docs/python.md): pybind11 and NumPy for
  # Debian's python3, its headers; for its tests pytest, Pillow (which decodes
  # the CLI's PNGs independently) and IPython (whose display formatter shows
  # that pictures display inline in Jupyter).
  pybind11-dev python3-dev python3-numpy python3-pytest python3-pil python3-ipython
  # The package (pyproject.toml, setup.py): pip into a virtual environment
  # and `python3 -m build`, offline, with Debian's setuptools and wheel; the
  # notebook example run headlessly in its test (nbclient, an IPython kernel);
  # the sweep example on a Dask cluster of local worker processes.
  python3-venv python3-pip python3-setuptools python3-wheel python3-build
  python3-nbclient python3-nbformat python3-ipykernel python3-dask python3-distributed
  # The API reference (target docs; its test fails on any warning) and the
  # man page made from --help, rendered by groff in its test.
  doxygen help2man groff-base
)
# Debian 12's clang is clang-14; libFuzzer's runtime is in libclang-rt-14-dev.
fuzz_packages=(clang libclang-rt-14-dev)
# bench/compare.sh times whole runs with hyperfine and reads peak memory with
# GNU time; bench/glass.sh measures litkit's ray tree against Intel Embree.
bench_packages=(hyperfine time libembree-dev)
# The playground (docs/web.md): the library compiled to WebAssembly with
# Debian's emscripten (it brings clang, lld, binaryen, nodejs and node-acorn),
# and its test in Debian's headless Chromium, driven from node. npm comes
# with Debian's nodejs only as a package of its own; a node installed some
# other way usually has its npm, so it is asked for only when missing.
web_packages=(emscripten chromium)
command -v npm >/dev/null || web_packages+=(npm)

case "${1:-}" in
  "") ;;
  --fuzz) packages+=("${fuzz_packages[@]}") ;;
  --bench) packages+=("${bench_packages[@]}") ;;
  --web) packages+=("${web_packages[@]}") ;;
  *) echo "usage: $0 [--fuzz | --bench | --web]" >&2; exit 2 ;;
esac

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
