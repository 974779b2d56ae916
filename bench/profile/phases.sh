#!/usr/bin/env bash
# Where the time of a reconstruction goes, as a user runs it: `sltk reconstruct CLOUD` (with the
# options given) REPEAT times, each under /usr/bin/time -v with its outputs written, and per run
# the medians of its set-up (distance and initial data, or the tiled transfer), of the iterations'
# phases (band, energy, SL step, reinitialisation and cut, metrics: the run's log line,
# Core/include/sltk/recon/RunIterations.h), the band nodes per iteration and the cost per band
# node and iteration; then planning (reading, cleaning, the automatic choices), output
# (contour, files) and the whole wall time and peak memory.
#   bench/profile/phases.sh BUILD_DIR CLOUD [sltk reconstruct options...]
#   REPEAT=3 (default)
set -euo pipefail
out=$(mktemp -d) repeat=${REPEAT:-3}
sltk="$1/bin/sltk" cloud=$2
shift 2
for r in $(seq "$repeat"); do
  /usr/bin/time -v "$sltk" reconstruct "$cloud" --verbose --quiet -o "$out/sdf.$r.vti" \
    --surface "$out/surface.$r.vtp" --csv "$out/history.$r.csv" "$@" >"$out/stdout.$r.txt" 2>"$out/log.$r.txt" ||
    { cat "$out/log.$r.txt"; exit 1; }
  case " $* " in *" --octree "*) rm -f "$out/sdf.$r.vti" ;; esac
done
/usr/bin/python3 - "$out" "$repeat" <<'PY'
import csv, re, statistics, sys
out, repeat = sys.argv[1], int(sys.argv[2])
PHASES = ["band", "energy", "SL step", "reinitialisation", "metrics"]
stamp = re.compile(r"\(\s*([\d.]+)s\)")
runs = {}  # run -> list (per repeat) of dicts
totals = []
for r in range(1, repeat + 1):
    text = open(f"{out}/log.{r}.txt").read()
    first = None
    last = 0.0
    per = {}
    for line in text.splitlines():
        t = stamp.search(line)
        m = re.search(r"run (\d+): grid (\d+) nodes, distance ([\d.e+-]+) s, initial data ([\d.e+-]+) s", line)
        if m:
            run = int(m.group(1))
            per.setdefault(run, {})["setup"] = float(m.group(3)) + float(m.group(4))
            per[run]["nodes"] = int(m.group(2))
            if first is None and t:
                first = float(t.group(1)) - per[run]["setup"]
        m = re.search(r"run (\d+) \(tiled\): (\d+) tiles of \d+ .* set up in ([\d.e+-]+) s", line)
        if m:
            per.setdefault(int(m.group(1)), {})["setup"] = float(m.group(3))
        m = re.search(r"run (\d+): (\d+) iterations, .* ([\d.e+-]+) s \((.*?)\)", line)
        if m:
            run = int(m.group(1))
            d = per.setdefault(run, {})
            d["iterations"] = int(m.group(2))
            d["seconds"] = float(m.group(3))
            for name in PHASES:
                p = re.search(name + r" ([\d.e+-]+) s", m.group(4))
                d[name] = float(p.group(1)) if p else 0.0
            if t:
                last = float(t.group(1))
    with open(f"{out}/history.{r}.csv") as f:
        rows = list(csv.DictReader(f))
    band_key = next(k for k in rows[0] if k.lower().startswith("band"))
    run_key = next(k for k in rows[0] if k.lower().startswith("run"))
    for row in rows:
        d = per.setdefault(int(float(row[run_key])), {})
        d["band nodes"] = d.get("band nodes", 0.0) + float(row[band_key])
    for run, d in per.items():
        runs.setdefault(run, []).append(d)
    tt = open(f"{out}/log.{r}.txt").read()
    m, s = re.search(r"Elapsed \(wall clock\) time.*: (\d+):([\d.]+)", tt).groups()
    wall = 60 * int(m) + float(s)
    rss = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", tt).group(1)) / 1024.0
    totals.append({"plan": first or 0.0, "output": wall - last, "wall": wall, "rss": rss})
med = lambda xs: statistics.median(xs) if xs else float("nan")
print(f"medians of {repeat} runs of sltk reconstruct (seconds; ns per band node and iteration)")
print(f"{'run':>3} {'setup':>7} {'iters':>5} " + " ".join(f"{p:>10}" for p in PHASES) +
      f" {'run s':>7} {'band/it':>9} {'ns/node':>8}")
for run in sorted(runs):
    ds = runs[run]
    get = lambda k: med([d.get(k, 0.0) for d in ds])
    iters = get("iterations")
    band = get("band nodes")
    loop = sum(get(p) for p in PHASES)
    per_node = 1e9 * loop / band if band else float("nan")
    print(f"{run:>3} {get('setup'):>7.2f} {iters:>5.0f} " + " ".join(f"{get(p):>10.2f}" for p in PHASES) +
          f" {get('seconds'):>7.2f} {band / max(iters, 1):>9.0f} {per_node:>8.0f}")
print(f"planning (read, clean, automatic choices) {med([t['plan'] for t in totals]):.2f} s, "
      f"output (contour, files) {med([t['output'] for t in totals]):.2f} s, "
      f"wall {med([t['wall'] for t in totals]):.2f} s, peak RSS {med([t['rss'] for t in totals]):.0f} MB")
PY
rm -rf "$out"
