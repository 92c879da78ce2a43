#!/usr/bin/env bash
# emb set-up on a fresh Debian (bookworm) machine: install what is missing, build, then
#   tools/setup.sh run    run the main job on its default model
#   tools/setup.sh test   run the whole test suite (this is what .ci/run calls)
# Idempotent: installs only missing Debian packages and re-uses the build directory.
set -euo pipefail

mode=${1:-run}
case "$mode" in run|test|build) ;; *) echo "usage: tools/setup.sh [run|test|build]" >&2; exit 2;; esac

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${EMB_BUILD_DIR:-$root/build}

packages=(
  g++ cmake ninja-build pkg-config
  libeigen3-dev libspectra-dev libsuitesparse-dev libmetis-dev libopenblas-dev
  libhdf5-dev libgmsh-dev gmsh libsundials-dev libyaml-cpp-dev libcli11-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3-h5py python3-matplotlib
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "emb setup: installing ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

jobs=$(nproc)
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j "$jobs"

case "$mode" in
  run)
    # Main job: mesh the default inline-4 crankshaft and compute its free-free modes.
    mkdir -p "$root/out"
    "$build/tools/emb/emb" modes "$root/meshes/crankshaft_i4.geo" --modes 20 -o "$root/out/crankshaft_i4_modes.h5"
    ;;
  test)
    cd "$build"
    ctest --output-on-failure -j "$jobs"
    ;;
esac
