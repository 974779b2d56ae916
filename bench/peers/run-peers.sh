#!/usr/bin/env bash
# SLTK with no options against the reconstructions from unoriented points a user can install from
# Debian (CGAL Poisson with jet normals + MST orientation, Open3D screened Poisson), on the shared
# clouds that have a true mesh; optionally the accuracy anchors iPSR and WNNC + SSDRecon from the
# user's own builds. Every run under /usr/bin/time -v (wall, peak RSS); every output scored by the
# one scorer score.py. A benchmark: a table (OUTDIR/summary.md, summary.json), never pass/fail.
#
# usage: bench/peers/run-peers.sh SLTK_BINARY OUTDIR
# environment: DATA     shared clouds (default /work/shared/data/clouds)
#              CASES    space-separated subset of case names (default: all found)
#              TOOLS    space-separated subset of sltk cgal open3d ipsr wnnc_ssd (default: all)
#              MODELS=1 add the synthetic models of bench/unseen/make_models.py
#              TIMEOUT  seconds per run (default 900); MEM_LIMIT_MB as in bench/unseen (0 = none)
#              PYTHON   a Python with vtkmodules, numpy, scipy, open3d (default /usr/bin/python3)
#              CGAL_POISSON  a built cgal_poisson (default: built into OUTDIR/cgal-build)
#              SAMPLES  add the area-sampled Chamfer with this many samples per surface (default 0)
#              IPSR     an iPSR binary (authors' defaults); unset = skipped
#              SSD_RECON + WNNC_DIR  PoissonRecon's SSDRecon binary and a WNNC checkout (its
#                       main_wnnc.py, run with WNNC_PYTHON, --width_config WNNC_WIDTH, default l1,
#                       on the CPU); unset = skipped
set -uo pipefail

{ # one compound command: bash parses it whole, so editing this file during a run is harmless
[ $# -ge 2 ] || { sed -n 2,23p "$0"; exit 2; }
sltk="$(realpath "$1")"; out="$2"
[ -x "$sltk" ] || { echo "not an executable: $sltk" >&2; exit 2; }
here="$(cd "$(dirname "$0")" && pwd)"
data="${DATA:-/work/shared/data/clouds}"
python="${PYTHON:-/usr/bin/python3}"
timeout="${TIMEOUT:-900}"
samples="${SAMPLES:-0}"
tools="${TOOLS:-sltk cgal open3d ipsr wnnc_ssd}"
mem_mb="${MEM_LIMIT_MB:-$(awk '/MemTotal/ {print int($2 * 0.8 / 1024)}' /proc/meminfo)}"
mkdir -p "$out"
out="$(realpath "$out")"
: > "$out/skipped.txt"
note() { echo "$*" | tee -a "$out/skipped.txt" >&2; }

# The CGAL peer is compiled here, out of the source tree, unless the caller gives one.
cgal="${CGAL_POISSON:-$out/cgal-build/cgal_poisson}"
if [[ " $tools " == *" cgal "* ]] && [ ! -x "$cgal" ]; then
  { cmake -S "$here/cgal" -B "$out/cgal-build" -DCMAKE_BUILD_TYPE=Release && cmake --build "$out/cgal-build"; } \
    > "$out/cgal-build.log" 2>&1 || note "skipped cgal: build failed (libcgal-dev installed? see $out/cgal-build.log)"
fi

# name|cloud|reference
cases=()
real() { # name cloud reference
  if [ -f "$data/$2" ] && [ -f "$3" ]; then cases+=("$1|$data/$2|$3")
  else note "skipped $1: no $data/$2 or no $3"; fi
}
if [ -f "$data/dragon/dragon_vrip_res2.ply.gz" ] && [ ! -f "$out/dragon_vrip_res2.ply" ]; then
  gunzip -c "$data/dragon/dragon_vrip_res2.ply.gz" > "$out/dragon_vrip_res2.ply"
fi
real bunny bunny/bunny.xyz "$data/bunny/bun_zipper.ply"
real bunny_scans bunny/scans/bunny_scans_registered.xyz "$data/bunny/bun_zipper.ply"
real dragon dragon/dragon_res2.xyz "$out/dragon_vrip_res2.ply"
real teapot teapot/teapot.xyz "$data/teapot/teapot.obj"
real fandisk fandisk/fandisk.xyz "$data/fandisk/fandisk.ply"
real knot1 knot/knot1.xyz "$data/knot/knot1.off"
real knot2 knot/knot2.xyz "$data/knot/knot2.off"
if [ "${MODELS:-0}" = 1 ]; then
  [ -f "$out/models/models.json" ] || "$python" "$here/../unseen/make_models.py" "$out/models" || exit 1
  while read -r name; do cases+=("$name|$out/models/$name.xyz|$out/models/$name.ply")
  done < <("$python" -c 'import json, sys
for m in json.load(open(sys.argv[1])): print(m["name"])' "$out/models/models.json")
fi

# The optional anchors run only where the user points at their builds: they need public sources
# that are not Debian packages, and this script does not build them.
[ -n "${IPSR:-}" ] || { [[ " $tools " == *" ipsr "* ]] && note "skipped ipsr: set IPSR to an iPSR binary"; }
[ -n "${SSD_RECON:-}" ] && [ -n "${WNNC_DIR:-}" ] || {
  [[ " $tools " == *" wnnc_ssd "* ]] && note "skipped wnnc_ssd: set SSD_RECON (PoissonRecon's SSDRecon) and WNNC_DIR"; }

# tool NAME CLOUD SURFACE WORKDIR: the command line of one tool, as a user would type it.
command_of() {
  case "$1" in
    sltk) echo "$sltk reconstruct $2 --surface $3" ;;
    cgal) [ -x "$cgal" ] && echo "$cgal $2 $3" ;;
    open3d) echo "$python $here/open3d_poisson.py $2 $3" ;;
    # iPSR reads a PLY of points: the cloud is converted first (outside the timed command).
    ipsr) [ -n "${IPSR:-}" ] && echo "$IPSR --in $4/cloud.ply --out $3" ;;
    wnnc_ssd) [ -n "${SSD_RECON:-}" ] && [ -n "${WNNC_DIR:-}" ] && echo "cd $WNNC_DIR && ${WNNC_PYTHON:-python3} \
main_wnnc.py $2 --width_config ${WNNC_WIDTH:-l1} --cpu --out_dir $4 && $SSD_RECON --in $4/$(basename "${2%.*}").xyz --out $3" ;;
  esac
}

xyz_to_ply() { # iPSR's input: an ASCII PLY of the first three columns
  local n; n=$(awk 'NF >= 3' "$1" | wc -l)
  { printf 'ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\nend_header\n' "$n"
    awk 'NF >= 3 {print $1, $2, $3}' "$1"; } > "$2"
}

# Appended, not truncated: a long bench can be run in parts (CASES=...) into one OUTDIR, and the
# table covers every part; summarize.py keeps the last run of a (cloud, tool). Use a fresh OUTDIR
# for a new binary.
touch "$out/cases.txt" "$out/commands.txt"
for c in "${cases[@]}"; do
  IFS='|' read -r name cloud ref <<< "$c"
  if [ -n "${CASES:-}" ] && [[ " $CASES " != *" $name "* ]]; then continue; fi
  echo "$c" >> "$out/cases.txt"
  for tool in $tools; do
    cmd="$(command_of "$tool" "$cloud" "$out/$name.$tool.ply" "$out/$name.$tool.work")" || continue
    [ -n "$cmd" ] || continue
    base="$out/$name.$tool"
    rm -rf "$base.ply" "$base.score.json" "$base.work"; mkdir -p "$base.work"
    [ "$tool" = ipsr ] && xyz_to_ply "$cloud" "$base.work/cloud.ply"
    echo "$name|$tool|$cmd" >> "$out/commands.txt"
    echo "$name|$tool|$(date -u +%FT%TZ)|$(uptime)" >> "$out/load.txt"
    cut -d' ' -f1 /proc/loadavg > "$base.load" # the 1-minute load when the run starts: a shared machine
    echo "== $name $tool: $cmd" >&2
    (
      [ "$mem_mb" -gt 0 ] && ulimit -v $((mem_mb * 1024))
      /usr/bin/time -v -o "$base.time" timeout "$timeout" bash -c "$cmd" > "$base.log" 2> "$base.err"
    )
    echo $? > "$base.rc"
    if [ -s "$base.ply" ]; then
      score_args=("$base.ply" "$ref" --json "$base.score.json")
      [ "$samples" -gt 0 ] && score_args+=(--samples "$samples")
      "$python" "$here/score.py" "${score_args[@]}" > /dev/null 2> "$base.score.err" \
        || echo "   scoring failed: $(tail -n 1 "$base.score.err")" >&2
    fi
    grep -E 'Elapsed|Maximum resident' "$base.time" 2>/dev/null | sed 's/^\s*/   /' >&2
  done
done
"$python" "$here/summarize.py" "$out" "$timeout"
exit $?
}
