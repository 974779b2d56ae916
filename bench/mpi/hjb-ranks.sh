#!/usr/bin/env bash
# Distributed HJB (Documentation/Distributed.md): the thesis's Test 4 (the
# compiled preset, or the same problem as formulas: PROBLEM=formulas) on
# N x N nodes, 1 rank x 1 thread against
# 2 ranks x 1 thread, alternated REPEAT times in one run so both see the same
# machine. Each rank runs under /usr/bin/time -v (its own peak RSS). Prints the
# median solve time (--json seconds: the filter's update, without MPI start-up),
# the median wall time of the whole mpirun, the speed-up, the largest rank's
# peak RSS against the one-rank run's, and the ghost bytes each rank sends per
# step. The values are checked bitwise equal (the same answer on every count).
#   bench/mpi/hjb-ranks.sh BUILD_DIR [N=321] [REPEAT=3] [PROBLEM=preset|formulas]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$1 n=${2:-321} repeat=${3:-3} problem=${4:-preset}
out=$(mktemp -d)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
test4=(hjb --fx=-a1 --fy=-a2 --cost "(a1^2+a2^2)/2" --v0 "max(1-x^2-y^2,0)"
  --exact "x^2+y^2 <= 1 ? (sqrt(x^2+y^2)-1)^2/(2*t) : 0" --nodes "$n,$n" --domain -2,2,-2,2 --controls ball
  --control-dim 2 --control-radius 2.2 --rk 1 --courant 1.25 --final-time 0.5 --quiet --threads 1)
[ "$problem" = preset ] && test4=(hjb --preset test4 --n "$n" --quiet --threads 1)
for r in $(seq "$repeat"); do
  for ranks in 1 2; do
    start=$(date +%s.%N)
    mpirun --oversubscribe -np "$ranks" "$(dirname "$0")/rank-rss.sh" "$out/time.$ranks.$r" \
      "$build/bin/sltk" "${test4[@]}" --json "$out/$ranks.$r.json" -o "$out/$ranks.$r.vti" >"$out/$ranks.$r.txt"
    python3 -c "print($(date +%s.%N) - $start)" >"$out/wall.$ranks.$r"
    [ "$r" = 1 ] && cat "$out/$ranks.$r.txt"
  done
done
PYTHONPATH="$here${PYTHONPATH:+:$PYTHONPATH}" /usr/bin/python3 - "$out" "$repeat" "$n" <<'PY'
import json, math, sys
from rank_medians import print_medians
out, repeat, n = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
print_medians(out, repeat, "solve")
s1, s2 = (json.load(open(f"{out}/{k}.1.json")) for k in (1, 2))
print(f"L1 error {s1['l1_error']:.6g} (1 rank) {s2['l1_error']:.6g} (2 ranks), steps {s1['steps']}")
# Ghost rows per side: G = ceil(1.25 max|f_D| dt/dx) + 3 with max|f_D| = 2.2, dt = 1.25 dx.
ghost = math.ceil(1.25 * 2.2 * 1.25) + 3
print(f"ghost rows G = {ghost}: each inner rank boundary exchanges 2 x {ghost} x {n} x 8 = "
      f"{2 * ghost * n * 8 / 1024:.1f} KiB per step each way ({s1['steps']} steps)")
PY
pvpython - "$out" "$repeat" <<'PY' 2>/dev/null
import sys
from vtkmodules.vtkIOXML import vtkXMLImageDataReader
out, repeat = sys.argv[1], int(sys.argv[2])
def values(path):
    r = vtkXMLImageDataReader(); r.SetFileName(path); r.Update()
    a = r.GetOutput().GetPointData().GetArray("ValueFunction")
    return [a.GetValue(k) for k in range(a.GetNumberOfTuples())]
same = values(f"{out}/1.1.vti") == values(f"{out}/2.1.vti")
print("value function, 2 ranks against 1:", "bitwise equal" if same else "DIFFERENT")
PY
rm -rf "$out"
