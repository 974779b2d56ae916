#!/usr/bin/env bash
# The tiled against the uniform reconstruction on one cloud, each storage in
# its own process under /usr/bin/time -v (peak memory), alternated REPEAT times
# so that both see the same machine: iterations and Err_P per run, stored
# nodes, wall time and peak RSS, then the medians and their ratios.
#   bench/tiled/compare.sh BUILD_DIR CLOUD.xyz [sltkBenchTiled options...]
#   REPEAT=3 (default)
set -euo pipefail
build=$1 cloud=$2
shift 2
repeat=${REPEAT:-3}
out=$(mktemp -d)
for r in $(seq "$repeat"); do
  for storage in uniform tiled; do
    /usr/bin/time -v "$build/bin/sltkBenchTiled" --cloud "$cloud" --storage "$storage" "$@" \
      >"$out/$storage.$r.txt" 2>"$out/$storage.$r.time"
    [ "$r" = 1 ] && cat "$out/$storage.$r.txt"
  done
done
/usr/bin/python3 - "$out" "$repeat" <<'PY'
import re, statistics, sys
out, repeat = sys.argv[1], int(sys.argv[2])
def parse(storage, key):
    values = []
    for r in range(1, repeat + 1):
        text = open(f"{out}/{storage}.{r}.time").read()
        if key == "wall":
            m, s = re.search(r"Elapsed \(wall clock\) time.*: (\d+):([\d.]+)", text).groups()
            values.append(60 * int(m) + float(s))
        else:
            values.append(int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", text).group(1)) / 1024)
    return statistics.median(values)
for key, unit in (("wall", "s"), ("rss", "MB")):
    u, t = parse("uniform", key), parse("tiled", key)
    print(f"median {key}: uniform {u:.1f} {unit}, tiled {t:.1f} {unit}, tiled/uniform {t / u:.2f}")
PY
