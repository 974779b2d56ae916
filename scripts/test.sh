#!/usr/bin/env bash
# Sets SLTK up (scripts/setup.sh) and runs every test: the default ctest suite
# (Core, filters, pvpython plugin, 2-rank MPI, install + embedding example, CLI)
# under one virtual X server, then the Core tests again under ASan + UBSan.
#   SLTK_SKIP_SANITIZE=1   skip the sanitizer build
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${SLTK_BUILD_DIR:-$repo/build}
"$repo/scripts/setup.sh"

export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
status=0
# A failed test runs once more (--repeat until-pass:2): the virtual X server now and then refuses
# a client's connection ("bad X server connection", about one run in ten here since the plugin
# test renders a PNG; the same test then passes). A real failure fails twice; the first
# attempt's output stays in the log.
(cd "$build" && xvfb-run -a -s "-screen 0 1024x768x24" ctest --output-on-failure -j 2 -LE long --repeat until-pass:2) ||
  status=1

if [ "${SLTK_SKIP_SANITIZE:-0}" != 1 ]; then
  asan="$build-asan"
  cmake -S "$repo" -B "$asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSLTK_ENABLE_VTK=OFF -DSLTK_ENABLE_P4EST=OFF -DSLTK_SANITIZE=ON \
    -DSLTK_BUILD_BENCHMARKS=OFF >"$asan.configure.log" 2>&1 || { cat "$asan.configure.log"; exit 1; }
  cmake --build "$asan" -j "${SLTK_JOBS:-$(nproc)}"
  (cd "$asan" && ctest --output-on-failure -j 2 -LE long) || status=1
fi
exit $status
