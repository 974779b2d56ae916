#!/usr/bin/env bash
# Sets SLTK up on Debian 12: installs the Debian packages that are missing
# (non-interactive, idempotent), then configures and builds in ./build.
#   SLTK_BUILD_DIR   build directory (default: <repo>/build)
#   SLTK_JOBS        parallel build jobs (default: nproc)
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${SLTK_BUILD_DIR:-$repo/build}
jobs=${SLTK_JOBS:-$(nproc)}

# Build and test dependencies (Documentation/Toolchain.md). ParaView brings its own VTK.
packages=(cmake make g++ paraview paraview-dev python3-paraview libp4est-dev libopenmpi-dev openmpi-bin
  libeigen3-dev libgtest-dev libx11-dev libglew-dev xvfb xauth nlohmann-json3-dev libcli11-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=Release >"$build.configure.log" 2>&1 || {
  cat "$build.configure.log"; exit 1; }
cmake --build "$build" -j "$jobs"
