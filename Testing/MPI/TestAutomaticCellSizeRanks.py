"""`mpirun -np 2 sltk reconstruct` with an automatic C_dx plans for the ranks it
runs on (Documentation/Distributed.md, "Memory check"): under a memory budget
that one rank runs with, the windows of two ranks on this machine, ghost rows
included, do not fit at one rank's C_dx; the two ranks take the smallest
coarser C_dx whose windows fit, say so, and run, instead of refusing what one
rank runs. An explicit --cdx that does not fit is still refused with the C_dx
that would. Run by python3: TestAutomaticCellSizeRanks.py SLTK MPIEXEC OUTDIR"""
import json
import math
import os
import subprocess
import sys

sltk, mpiexec, outdir = sys.argv[1:4]
os.makedirs(outdir, exist_ok=True)
MPI = [mpiexec, "--allow-run-as-root", "--oversubscribe"]
BUDGET = ["--memory-budget", "16"]  # the smallest budget allowed; it binds on this cloud (C_dx about 2)
failures = []


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


def run(ranks, arguments):
    env = {k: v for k, v in os.environ.items() if not k.startswith(("OMPI_", "PMIX_"))}
    return subprocess.run(MPI + ["-n", str(ranks), sltk, "reconstruct", cloud] + arguments, capture_output=True,
                          text=True, timeout=110, env=env)


# A unit sphere, 3000 points on a Fibonacci spiral.
cloud = os.path.join(outdir, "auto_cdx_sphere.xyz")
with open(cloud, "w") as f:
    n = 3000
    for i in range(n):
        z = 1.0 - (2.0 * i + 1.0) / n
        r, a = math.sqrt(1.0 - z * z), i * math.pi * (3.0 - math.sqrt(5.0))
        f.write("%.9f %.9f %.9f\n" % (r * math.cos(a), r * math.sin(a), z))

summaries = {}
for ranks in (1, 2):
    summary = os.path.join(outdir, "auto_cdx_%d.json" % ranks)
    if os.path.exists(summary):
        os.remove(summary)
    r = run(ranks, BUDGET + ["--json", summary, "--quiet"])
    check(r.returncode == 0, "%d rank(s) under the budget: exit 0 (%s)" % (ranks, r.stderr.strip()[-400:]))
    summaries[ranks] = json.load(open(summary)) if os.path.exists(summary) else {}
one, two = summaries[1], summaries[2]
if one and two:
    check(one["cdx"] > 1.0, "the budget binds on one rank (C_dx %.3g)" % one["cdx"])
    check(two["cdx"] > one["cdx"], "two ranks on this machine take a coarser C_dx (%.3g > %.3g)" % (two["cdx"],
                                                                                                   one["cdx"]))
    check(two["cdx"] < 1.5 * one["cdx"], "no coarser than the windows need (%.3g)" % two["cdx"])
    check(any("differ from one rank's" in c for c in two["automatic_choices"]),
          "the choice says the grids differ from one rank's: %s" % two["automatic_choices"])
    check(two["pieces"] == 1 and two["fits_cloud"], "two ranks: one piece that fits the cloud")

    # The same C_dx as one rank's, given explicitly: refused, with the C_dx that fits.
    r = run(2, BUDGET + ["--cdx", repr(one["cdx"]), "--quiet"])
    check(r.returncode != 0 and "C_dx >=" in r.stderr and "on this machine" in r.stderr,
          "an explicit --cdx whose windows do not fit is refused with advice (%s)" % r.stderr.strip()[-300:])

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
