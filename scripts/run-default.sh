#!/usr/bin/env bash
# README command 1: sets SLTK up and runs the main job on the bundled default:
# the public-domain Stanford bunny (npm bunny@1.0.1, 1,839 points) reconstructed
# by the semi-Lagrangian level-set method (thesis Algorithm 1), written as a
# signed distance (.vti), a surface (.ply) and a picture (.png).
# With the default (automatic) options: the least-squares Q1 interpolator (the
# cloud's noise is low), C_dx = 1, K_P = 2, three runs, one closed piece, about
# 2.6 s on 2 cores (2026-12-02). This bunny is sparse, its ears about one point
# spacing thick; WENO3 (--interpolator weno3) loses them in the first attempt and
# reconstructs again from C_dx = 0.5 with one run fewer (Documentation/Numerics.md,
# "Automatic parameters").
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${SLTK_BUILD_DIR:-$repo/build}
"$repo/scripts/setup.sh"
out="$build/default-run"
mkdir -p "$out"
"$repo/Data/fetch-bunny.sh" "$build/data"

echo
echo "== sltk reconstruct: the Stanford bunny (npm bunny@1.0.1), with a picture =="
# The picture renders through X: under a virtual X server, with one retry because one
# occasionally fails to start (Documentation/Toolchain.md, "Pitfalls").
for attempt in 1 2; do
  if xvfb-run -a -s "-screen 0 1024x768x24" "$build/bin/sltk" reconstruct "$build/data/bunny.ply" \
    -o "$out/bunny-sdf.vti" --surface "$out/bunny-surface.ply" --png "$out/bunny.png" \
    --csv "$out/bunny-convergence.csv" --json "$out/bunny-summary.json"; then
    break
  fi
  [ "$attempt" = 2 ] && { echo "run-default: the reconstruction failed" >&2; exit 1; }
done
echo
echo "outputs in $out: bunny-sdf.vti bunny-surface.ply bunny.png bunny-convergence.csv bunny-summary.json"
