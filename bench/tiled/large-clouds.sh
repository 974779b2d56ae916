#!/usr/bin/env bash
# The tiled reconstruction (sltk reconstruct --octree) on grids the uniform
# version cannot hold here (Documentation/Octree.md): the full Stanford dragon
# at the thesis's finest resolution (Table 4.8) and the merged raw bunny scans
# on a 700M-node grid (measured: Documentation/Octree.md). Each case runs once under /usr/bin/time -v and prints
# its run table, the surface's pieces and Euler characteristic, the wall time
# and the peak RSS. Without ../shared the script has nothing to measure.
# RANKS=N runs each case on N MPI ranks of one thread (the tiles shared out,
# Documentation/Octree.md "Distributing the tiled band") and prints every
# rank's peak RSS and their sum.
#   [RANKS=N] bench/tiled/large-clouds.sh BUILD_DIR [dragon|scans|scans-thin2.5 ...]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$1
shift
data=${SLTK_DATA:-$here/../../../shared/data/clouds}
[ -d "$data" ] || { echo "no data directory $data: nothing to measure" >&2; exit 0; }
cases=("$@")
[ ${#cases[@]} -eq 0 ] && cases=(dragon scans)
out=$(mktemp -d)
for name in "${cases[@]}"; do
  case "$name" in
    # 992x705x455 (318M nodes; the thesis's 966x687x444): the uniform version would need 12.7 GB.
    dragon) args=("$data/dragon/dragon.xyz" --cdx 3.86 --kp 10) ;;
    # 968x957x756 (700M nodes; the uniform version would ask 28 GB): thinned in voxels of 5
    # density spacings, so the grid's cells are finer than the thinned cloud's spacing but the
    # scans' scatter is averaged out: one closed piece.
    scans) args=("$data/bunny/scans/bunny_scans_registered.xyz" --remove-outliers --thin 5 --cdx 0.5 --kp 8
      --reference "$data/bunny/bun_zipper.ply") ;;
    # 929x923x728 (624M nodes) from a cloud thinned half as much: the grid resolves the scatter
    # (102 pieces; Documentation/Octree.md).
    scans-thin2.5) args=("$data/bunny/scans/bunny_scans_registered.xyz" --remove-outliers --thin 2.5 --cdx 1.0 --kp 16) ;;
    *) echo "unknown case $name (dragon, scans, scans-thin2.5)" >&2; exit 2 ;;
  esac
  echo "== $name"
  if [ "${RANKS:-1}" -gt 1 ]; then
    start=$(date +%s.%N)
    OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun --oversubscribe -np "$RANKS" \
      "$here/../mpi/rank-rss.sh" "$out/$name.time" "$build/bin/sltk" reconstruct "${args[@]}" --octree --threads 1 \
      --surface "$out/$name.vtp" --json "$out/$name.json" --quiet
    python3 - "$out/$name.time" "$start" <<'PY'
import glob, re, sys, time
peaks = [int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", open(f).read()).group(1))
         for f in sorted(glob.glob(sys.argv[1] + ".*"))]
print(f"wall {time.time() - float(sys.argv[2]):.1f} s; peak RSS per rank {peaks} kB, sum {sum(peaks)} kB")
PY
  else
    /usr/bin/time -v -o "$out/$name.time" "$build/bin/sltk" reconstruct "${args[@]}" --octree \
      --surface "$out/$name.vtp" --json "$out/$name.json" --quiet
    grep -E "Elapsed|Maximum resident" "$out/$name.time"
  fi
done
rm -rf "$out"
