#!/usr/bin/env bash
# Builds the libFuzzer targets (CMakeLists.txt here, clang-14) and runs each for
# SECONDS (default 600), starting from the seeds of seeds.py plus whatever the
# corpus folders already hold. Crashes are written to OUT/crash-*; the exit code
# is non-zero when a target found one. Usage: bench/fuzz/run.sh [OUT] [SECONDS]
#   bench/fuzz/run.sh /tmp/sltk-fuzz 600
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
out=${1:-/tmp/sltk-fuzz}
seconds=${2:-600}
mkdir -p "$out"
cmake -S "$here" -B "$out/build" -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=RelWithDebInfo >"$out/configure.log"
cmake --build "$out/build" -j "$(nproc)" >"$out/build.log"
python3 "$here/seeds.py" "$out/corpus"
status=0
for target in Expression CloudReader; do
  name=$(echo "$target" | tr 'A-Z' 'a-z')
  corpus="$out/corpus/${name/cloudreader/cloud}"
  echo "fuzz: sltkFuzz$target for $seconds s (log $out/$target.log)"
  "$out/build/sltkFuzz$target" "$corpus" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -max_len=4096 -print_final_stats=1 -artifact_prefix="$out/$target-" >"$out/$target.log" 2>&1 || status=1
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb|ERROR|SUMMARY" "$out/$target.log" || true
done
exit $status
