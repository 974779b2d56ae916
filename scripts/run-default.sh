#!/usr/bin/env bash
# README command 1: sets SLTK up and runs the main job on the bundled default.
# Today the most complete working pipeline is: fetch the public-domain Stanford
# bunny, check it and plan the reconstruction grids of its three runs (thesis
# (4.36)), then run the HJB solver on the thesis's Test 1. The level-set
# reconstruction itself is not built yet (see README, "Status").
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${SLTK_BUILD_DIR:-$repo/build}
"$repo/scripts/setup.sh"
out="$build/default-run"
mkdir -p "$out"
"$repo/Data/fetch-bunny.sh" "$build/data"

echo
echo "== sltk info: the Stanford bunny (npm bunny@1.0.1) =="
"$build/bin/sltk" info "$build/data/bunny.ply" --json "$out/bunny-info.json"
echo
echo "== sltk hjb: thesis Test 1 (3.5.1) =="
"$build/bin/sltk" hjb --preset test1 --n 81 -o "$out/test1.vti" --json "$out/test1.json"
echo
echo "outputs in $out"
