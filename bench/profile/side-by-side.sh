#!/usr/bin/env bash
# Two builds of sltk on one cloud, side by side: `sltk reconstruct CLOUD --verbose` (with the
# options given, outputs written) alternately with build A and build B, REPEAT times each, so
# that both see the same machine (noise on a shared 2-core machine is 10-40%). Prints per build
# the medians of the SL step over all runs, of the reinitialisation, of the band bookkeeping, of the wall time and of the
# peak memory (/usr/bin/time -v), of each run's set-up (its distance and initial data), of the planning (the log's
# clock at run 1's set-up, less that set-up) and of the output (the wall time after the last run's iterations), and
# whether the two surfaces are byte-identical (an exact change must keep them so). Each build's own libraries are used (LD_LIBRARY_PATH=BUILD/lib), so a copy
# of an old build dir can be compared with the current one.
#   bench/profile/side-by-side.sh BUILD_A BUILD_B CLOUD [sltk reconstruct options...]
#   REPEAT=3 (default)
set -euo pipefail
a=$1 b=$2 cloud=$3
shift 3
out=$(mktemp -d) repeat=${REPEAT:-3}
for r in $(seq "$repeat"); do
  for side in a b; do
    build=$a
    [ "$side" = b ] && build=$b
    LD_LIBRARY_PATH="$build/lib" /usr/bin/time -v "$build/bin/sltk" reconstruct "$cloud" --verbose --quiet \
      --surface "$out/surface.$side.ply" --json "$out/summary.$side.$r.json" "$@" >"$out/stdout.$side.$r.txt" \
      2>"$out/log.$side.$r.txt" || { cat "$out/log.$side.$r.txt"; exit 1; }
  done
done
identical=no
cmp -s "$out/surface.a.ply" "$out/surface.b.ply" && identical=yes
/usr/bin/python3 - "$out" "$repeat" "$a" "$b" "$identical" <<'PY'
import re, statistics, sys
out, repeat, builds, identical = sys.argv[1], int(sys.argv[2]), sys.argv[3:5], sys.argv[5]
def clock(text, what):
    return [float(x) for x in re.findall(r"\(\s*([\d.]+)s\)[^\n]*" + what, text)]
def phase(text, name):
    return sum(float(x) for x in re.findall(r"run \d+: \d+ iterations, .*?" + name + r" ([\d.e+-]+) s", text))
for side, build in zip("ab", builds):
    step, reinit, band, wall, rss, setup, plan, output = [], [], [], [], [], [], [], []
    for r in range(1, repeat + 1):
        text = open(f"{out}/log.{side}.{r}.txt").read()
        step.append(phase(text, "SL step"))
        reinit.append(phase(text, "reinitialisation"))
        band.append(phase(text, "band"))
        m, s = re.search(r"Elapsed \(wall clock\) time.*: (\d+):([\d.]+)", text).groups()
        wall.append(60 * int(m) + float(s))
        rss.append(int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", text).group(1)) / 1024.0)
        setup.append([float(d) + float(i) for d, i in
                      re.findall(r"run \d+: grid \d+ nodes, distance ([\d.e+-]+) s, initial data ([\d.e+-]+) s", text)])
        plan.append(clock(text, r"run 1: grid")[0] - setup[-1][0])
        output.append(wall[-1] - clock(text, r"run \d+: \d+ iterations")[-1])
    med = statistics.median
    print(f"{side} {build}: SL step {med(step):.2f} s, reinitialisation {med(reinit):.2f} s, band {med(band):.2f} s, wall {med(wall):.2f} s"
          f" (runs {', '.join(f'{w:.1f}' for w in wall)}), peak {med(rss):.0f} MB")
    runs = min(len(x) for x in setup)
    print(f"  set-up per run {' / '.join(f'{med(x[j] for x in setup):.2f}' for j in range(runs))} s,"
          f" planning {med(plan):.2f} s, output {med(output):.2f} s")
print(f"surfaces byte-identical: {identical}")
PY
rm -rf "$out"
