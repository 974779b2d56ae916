#!/usr/bin/env bash
# Real scans (thesis 4.5.4-4.5.5) reconstructed by the `sltk` command line and measured against
# their ground-truth meshes: grid and iterations per run, Err_P (4.35), the symmetric Chamfer and
# Hausdorff distances to the mesh (one-sided means are printed by sltk), pieces, Euler
# characteristic, wall time and peak memory. A benchmark: it prints a table, never pass/fail.
#
# usage: bench/scans-vs-ground-truth.sh [--build DIR] [--data DIR] [--out DIR] [--threads T]
#                                       [--interpolator NAME] [--with-dragon] [CASE ...]
#   cases (default: all but dragon): bunny teapot fandisk knot knotellipse knot2 frog kitten scans dragon
#   dragon (dragon_res2, 100,250 points, C_dx = 2; C_dx = 1 would need 37 GB) is the long one.
set -euo pipefail

here="$(cd "$(dirname "$0")/.." && pwd)"
build="$here/build"
data="$here/../shared/data/clouds"
out="${TMPDIR:-/tmp}/sltk-scans"
threads=2
interp=weno3
cases=()
with_dragon=0
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --data) data="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --threads) threads="$2"; shift 2 ;;
    --interpolator) interp="$2"; shift 2 ;;
    --with-dragon) with_dragon=1; shift ;;
    -h|--help) sed -n 2,10p "$0"; exit 0 ;;
    -*) echo "unknown option $1" >&2; exit 2 ;;
    *) cases+=("$1"); shift ;;
  esac
done
if [ ${#cases[@]} -eq 0 ]; then
  cases=(bunny teapot fandisk knot knotellipse knot2 frog kitten scans)
fi
[ "$with_dragon" = 1 ] && cases+=(dragon)
sltk="$build/bin/sltk"
[ -x "$sltk" ] || { echo "no $sltk: build first (scripts/setup.sh)" >&2; exit 2; }
[ -d "$data" ] || { echo "no data directory $data (../shared/data/clouds): nothing to measure" >&2; exit 0; }
mkdir -p "$out"

# name | cloud | reference mesh ("" = none) | options (thesis parameters, 4.5.4-4.5.5)
spec() {
  case "$1" in
    bunny) echo "bunny/bunny.xyz|bunny/bun_zipper.ply|--cdx 2 --kp 10" ;;
    teapot) echo "teapot/teapot.xyz|teapot/teapot.obj|--kp 10" ;;
    fandisk) echo "fandisk/fandisk.xyz|fandisk/fandisk.ply|" ;;
    knot) echo "knot/knot1.xyz|knot/knot1.off|--cdx 2 --kp 10" ;;
    knotellipse) echo "knot/knot1.xyz|knot/knot1.off|--cdx 2 --kp 10 --initial ellipsoid --max-iterations 200" ;;
    knot2) echo "knot/knot2.xyz|knot/knot2.off|--cdx 2 --kp 10" ;;
    frog) echo "frog/frog.xyz||--kp 10" ;;
    kitten) echo "kitten/kitten.xyz||--kp 10" ;;
    scans) echo "bunny/scans/bunny_scans_registered.xyz|bunny/bun_zipper.ply|--remove-outliers --thin 2.5 --cdx 3.3 --kp 16" ;;
    dragon) echo "dragon/dragon_res2.xyz|dragon/dragon_vrip.ply|--cdx 2 --kp 10" ;;
    *) return 1 ;;
  esac
}

for name in "${cases[@]}"; do
  line="$(spec "$name")" || { echo "unknown case $name" >&2; exit 2; }
  IFS='|' read -r cloud ref opts <<<"$line"
  if [ "$name" = dragon ] && [ ! -f "$data/$ref" ] && [ -f "$data/$ref.gz" ]; then
    gunzip -c "$data/$ref.gz" >"$out/dragon_vrip.ply"
    ref_path="$out/dragon_vrip.ply"
  else
    ref_path="${ref:+$data/$ref}"
  fi
  [ -f "$data/$cloud" ] || { echo "$name: no $data/$cloud, skipped"; continue; }
  args=("$data/$cloud" --interpolator "$interp" --threads "$threads" --quiet --json "$out/$name.json"
        --surface "$out/$name.ply")
  [ -n "$ref_path" ] && args+=(--reference "$ref_path")
  # shellcheck disable=SC2206
  args+=($opts)
  echo "== $name: sltk reconstruct ${args[*]}"
  /usr/bin/time -v "$sltk" reconstruct "${args[@]}" 2>"$out/$name.time" || echo "$name: sltk failed (see $out/$name.time)"
  grep -E "Maximum resident|Elapsed" "$out/$name.time" || true
done

python3 - "$out" "${cases[@]}" <<'EOF'
import json, os, sys
out, names = sys.argv[1], sys.argv[2:]
print(f"\n{'case':12} {'points':>8} {'final grid':>16} {'iterations':>12} {'Err_P final':>12} "
      f"{'Chamfer':>10} {'Hausdorff':>10} {'pieces':>6} {'Euler':>5} {'wall s':>7} {'peak MB':>8}")
for n in names:
    p = os.path.join(out, n + ".json")
    if not os.path.exists(p):
        print(f"{n:12} (no result)")
        continue
    j = json.load(open(p))
    runs = j["runs"]
    g = "x".join(str(v) for v in runs[-1]["grid"])
    it = "/".join(str(r["iterations"]) for r in runs)
    ch = j.get("chamfer"); hd = j.get("hausdorff")
    print(f"{n:12} {j['points_reconstructed']:>8} {g:>16} {it:>12} {runs[-1]['err_cloud']:>12.3e} "
          f"{(f'{ch:.3e}' if ch is not None else '-'):>10} {(f'{hd:.3e}' if hd is not None else '-'):>10} "
          f"{j['surface_pieces']:>6} {j['euler_characteristic']:>5} {j['seconds']:>7.1f} {j['peak_memory_mb']:>8.0f}")
EOF
