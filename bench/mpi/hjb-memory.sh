#!/usr/bin/env bash
# Peak memory of a distributed HJB solve (Documentation/Distributed.md): the
# thesis's Test 1 (a rotation, no control: one evaluation per node and step,
# so memory, not the minimisation, is what is measured) as formulas on N x N
# nodes, 1 rank writing one .vti against 2 ranks each writing its own block of
# a .pvti. Prints every rank's peak RSS (/usr/bin/time -v), the process
# baseline (the same run on 41 x 41 nodes) and the ratios of the largest rank
# to the one-rank run, whole and above the baseline, and checks that the two
# value functions are bitwise equal.
#   bench/mpi/hjb-memory.sh BUILD_DIR [N=4097] [STEPS=5]
set -euo pipefail
build=$1 n=${2:-4097} steps=${3:-5}
here=$(dirname "$0")
out=$(mktemp -d)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
rotation() { # nodes per axis; dt = 2 dx, `steps` steps
  echo hjb --fx "-2*pi*(y-0.5)" --fy "2*pi*(x-0.5)" --v0 "max(0.15-hypot(x-0.3,y-0.7),0)" --nodes "$1,$1" \
    --domain 0,1,0,1 --courant 2 --final-time "$(python3 -c "print($steps * 2 / ($1 - 1))")" --quiet --threads 1
}
run() { # label ranks nodes output
  local IFS=$'\n'
  mpirun --oversubscribe -np "$2" "$here/rank-rss.sh" "$out/$1" "$build/bin/sltk" \
    $(rotation "$3" | python3 -c "import shlex,sys; print('\n'.join(shlex.split(sys.stdin.read())))") \
    -o "$out/$4" >"$out/$1.txt"
}
run base1 1 41 base1.vti
run base2 2 41 base2.pvti
run one 1 "$n" one.vti
run two 2 "$n" two.pvti
head -1 "$out/one.txt"
python3 - "$out" <<'PY'
import glob, re, sys
out = sys.argv[1]
def rss(label):
    return [int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", open(f).read()).group(1)) / 1024
            for f in sorted(glob.glob(f"{out}/{label}.[0-9]*"))]
b1, b2, one, two = max(rss("base1")), max(rss("base2")), max(rss("one")), max(rss("two"))
print(f"baseline (41 x 41): 1 rank {b1:.0f} MB, 2 ranks {b2:.0f} MB per rank")
print(f"1 rank: {one:.0f} MB; 2 ranks: {', '.join(f'{m:.0f}' for m in rss('two'))} MB")
print(f"largest rank / 1-rank run: {two / one:.2f} whole, {(two - b2) / (one - b1):.2f} above the baseline")
PY
pvpython - "$out" <<'PY' 2>/dev/null
import sys
from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLPImageDataReader
out = sys.argv[1]
def values(reader, path):
    reader.SetFileName(path); reader.Update()
    a = reader.GetOutput().GetPointData().GetArray("ValueFunction")
    return [a.GetValue(k) for k in range(a.GetNumberOfTuples())]
same = values(vtkXMLImageDataReader(), f"{out}/one.vti") == values(vtkXMLPImageDataReader(), f"{out}/two.pvti")
print("value function, 2 ranks (.pvti) against 1 (.vti):", "bitwise equal" if same else "DIFFERENT")
PY
rm -rf "$out"
