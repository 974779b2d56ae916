#!/usr/bin/env bash
# Distributed reconstruction (Documentation/Distributed.md): a cloud (default
# the Stanford bunny of ../shared, with the thesis's --cdx 2 --kp 10), 1 rank x
# 1 thread against 2 ranks x 1 thread, alternated REPEAT times in one run so
# both see the same machine. Each rank runs under /usr/bin/time -v (its own
# peak RSS). Prints the median reconstruction time (--json seconds), the
# median wall time of the whole mpirun, the speed-up, the largest rank's peak
# RSS against the one-rank run's, the traffic (bytes the busiest rank sent,
# collective calls, ghost rows and far feet per run), and checks that both give the same
# iterations per run and the same Err_P.
#   bench/mpi/recon-ranks.sh BUILD_DIR [CLOUD] [REPEAT=3] [extra sltk options...]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$1 cloud=${2:-$here/../../../shared/data/clouds/bunny/bunny.xyz} repeat=${3:-3}
shift $(( $# < 3 ? $# : 3 ))
extra=("$@")
[ ${#extra[@]} -eq 0 ] && extra=(--cdx 2 --kp 10)
out=$(mktemp -d)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
for r in $(seq "$repeat"); do
  for ranks in 1 2; do
    start=$(date +%s.%N)
    mpirun --oversubscribe -np "$ranks" "$here/rank-rss.sh" "$out/time.$ranks.$r" \
      "$build/bin/sltk" reconstruct "$cloud" "${extra[@]}" --threads 1 --quiet --json "$out/$ranks.$r.json" \
      >"$out/$ranks.$r.txt"
    python3 -c "print($(date +%s.%N) - $start)" >"$out/wall.$ranks.$r"
    [ "$r" = 1 ] && cat "$out/$ranks.$r.txt"
  done
done
PYTHONPATH="$here${PYTHONPATH:+:$PYTHONPATH}" /usr/bin/python3 - "$out" "$repeat" <<'PY'
import json, sys
from rank_medians import print_medians
out, repeat = sys.argv[1], int(sys.argv[2])
print_medians(out, repeat, "reconstruction")
s1, s2 = (json.load(open(f"{out}/{k}.1.json")) for k in (1, 2))
its1, its2 = [x["iterations"] for x in s1["runs"]], [x["iterations"] for x in s2["runs"]]
gap = max(abs(a["err_cloud"] - b["err_cloud"]) / a["err_cloud"] for a, b in zip(s1["runs"], s2["runs"]))
print(f"iterations per run {its1} (1 rank) {its2} (2 ranks): {'the same' if its1 == its2 else 'DIFFERENT'}; "
      f"Err_P relative gap {gap:.2g}; surface {s1['surface_pieces']} / {s2['surface_pieces']} piece(s), "
      f"Euler {s1['euler_characteristic']} / {s2['euler_characteristic']}")
grids = [x["grid"] for x in s2["runs"]]
print(f"traffic on 2 ranks: {s2['bytes_sent_max'] / 1e6:.1f} MB sent by the busiest rank over {sum(its2)} "
      f"iterations, {s2['collectives']:.0f} collective calls; ghost rows per run {[x.get('ghost_rows') for x in s2['runs']]}"
      f" on grids {grids}; far feet per run {[x.get('far_feet') for x in s2['runs']]}")
PY
rm -rf "$out"
