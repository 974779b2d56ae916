#!/usr/bin/env bash
# `sltk reconstruct` with its DEFAULT options on clouds it was never tuned on: the shared real clouds
# and the synthetic models of known genus of make_models.py. Per cloud: exit status, wall time,
# peak RSS, grids, pieces, Euler characteristic, genus, boundary edges, Chamfer/Hausdorff.
# A benchmark: it prints a Markdown table (OUTDIR/summary.md, summary.json), never pass/fail.
#
# usage: bench/unseen/run-defaults.sh SLTK_BINARY OUTDIR [extra sltk options...]
# environment: DATA     shared clouds (default /work/shared/data/clouds; missing = synthetic only)
#              PYTHON   a Python that imports vtkmodules (default /usr/bin/python3)
#              TIMEOUT  seconds per cloud (default 900)
#              MEM_LIMIT_MB  address-space cap (ulimit -v) per run, default 80% of RAM, 0 = none
#              CASES    space-separated subset of case names (default: all)
set -uo pipefail

{ # one compound command: bash parses it whole, so editing this file during a run is harmless
[ $# -ge 2 ] || { sed -n 2,14p "$0"; exit 2; }
sltk="$(realpath "$1")"; out="$2"; shift 2
[ -x "$sltk" ] || { echo "not an executable: $sltk" >&2; exit 2; }
here="$(cd "$(dirname "$0")" && pwd)"
data="${DATA:-/work/shared/data/clouds}"
python="${PYTHON:-/usr/bin/python3}"
timeout="${TIMEOUT:-900}"
mem_mb="${MEM_LIMIT_MB:-$(awk '/MemTotal/ {print int($2 * 0.8 / 1024)}' /proc/meminfo)}"
mkdir -p "$out"
out="$(realpath "$out")"

# Synthetic models (regenerated only if missing).
[ -f "$out/models/models.json" ] || "$python" "$here/make_models.py" "$out/models" || exit 1

# name|cloud|reference|expected genus (summed over the parts)|expected parts ("" = unknown)
cases=()
: > "$out/skipped.txt"
real() { # name cloud reference genus parts
  if [ -f "$data/$2" ]; then cases+=("$1|$data/$2|$3|$4|$5")
  else echo "skipped $1: no $data/$2" | tee -a "$out/skipped.txt" >&2; fi
}
real bunny bunny/bunny.xyz "$data/bunny/bun_zipper.ply" 0 1
real bunny_scans bunny/scans/bunny_scans_registered.xyz "$data/bunny/bun_zipper.ply" 0 1
if [ -f "$data/dragon/dragon_vrip_res2.ply.gz" ] && [ ! -f "$out/dragon_vrip_res2.ply" ]; then
  gunzip -c "$data/dragon/dragon_vrip_res2.ply.gz" > "$out/dragon_vrip_res2.ply"
fi
real dragon dragon/dragon_res2.xyz "$out/dragon_vrip_res2.ply" "" 1
real teapot teapot/teapot.xyz "$data/teapot/teapot.obj" "" 1
real fandisk fandisk/fandisk.xyz "$data/fandisk/fandisk.ply" 0 1
real knot1 knot/knot1.xyz "$data/knot/knot1.off" 1 1
real knot2 knot/knot2.xyz "$data/knot/knot2.off" 2 2 # a link: two knotted tori
real kitten kitten/kitten.xyz "" 1 1
real frog frog/frog.xyz "" "" 1
while read -r name genus parts; do
  cases+=("$name|$out/models/$name.xyz|$out/models/$name.ply|$genus|$parts")
done < <("$python" -c 'import json, sys
for m in json.load(open(sys.argv[1])): print(m["name"], m["genus"], m["parts"])' "$out/models/models.json")

: > "$out/cases.txt"
for c in "${cases[@]}"; do
  IFS='|' read -r name cloud ref genus parts <<< "$c"
  if [ -n "${CASES:-}" ] && [[ " $CASES " != *" $name "* ]]; then continue; fi
  echo "$c" >> "$out/cases.txt"
  args=(reconstruct "$cloud" --surface "$out/$name.ply" --json "$out/$name.json")
  [ -n "$ref" ] && args+=(--reference "$ref")
  rm -f "$out/$name.ply" "$out/$name.json"
  echo "== $name: sltk ${args[*]} $*" >&2
  (
    [ "$mem_mb" -gt 0 ] && ulimit -v $((mem_mb * 1024))
    /usr/bin/time -v -o "$out/$name.time" timeout "$timeout" "$sltk" "${args[@]}" "$@" \
      > "$out/$name.log" 2> "$out/$name.err"
  )
  echo $? > "$out/$name.rc"
  tail -n 3 "$out/$name.log" "$out/$name.err" 2>/dev/null | grep -v '^$' >&2
done
"$python" "$here/summarize.py" "$out" "$timeout" "$sltk $*"
exit $?
}
