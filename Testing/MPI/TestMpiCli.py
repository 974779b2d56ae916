"""`mpirun -np 2 sltk hjb` (Apps/sltk/MpiSession.h): the custom problem is
split over the ranks and rank 0 writes one set of outputs, bitwise the
one-rank solve; a failure on one rank's slab ends the run with one message and
no output; `sltk reconstruct` on several ranks is refused (not distributed
yet). Run by pvpython (VTK reads the images): TestMpiCli.py SLTK MPIEXEC OUTDIR"""
import json
import os
import subprocess
import sys

from vtkmodules.vtkIOXML import vtkXMLImageDataReader

sltk, mpiexec, outdir = sys.argv[1:4]
os.makedirs(outdir, exist_ok=True)
MPI = [mpiexec, "--allow-run-as-root", "--oversubscribe"]
TEST4 = ["hjb", "--fx=-a1", "--fy=-a2", "--cost", "(a1^2+a2^2)/2", "--v0", "max(1-x^2-y^2,0)",
         "--exact", "x^2+y^2 <= 1 ? (sqrt(x^2+y^2)-1)^2/(2*t) : 0", "--nodes", "41,41", "--domain", "-2,2,-2,2",
         "--controls", "ball", "--control-dim", "2", "--control-radius", "2.2", "--rk", "1", "--courant", "1.25",
         "--final-time", "0.5", "--quiet", "--threads", "1"]
failures = []


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


# pvpython started MPI as a singleton: its OMPI_*/PMIX_* variables would make mpirun's children join it.
CLEAN_ENV = {k: v for k, v in os.environ.items() if not k.startswith(("OMPI_", "PMIX_"))}


def run(command):
    return subprocess.run(command, capture_output=True, text=True, timeout=120, env=CLEAN_ENV)


def values(path):
    reader = vtkXMLImageDataReader()
    reader.SetFileName(path)
    reader.Update()
    array = reader.GetOutput().GetPointData().GetArray("ValueFunction")
    return [array.GetValue(k) for k in range(array.GetNumberOfTuples())]


outputs = {}
for ranks in (1, 2):
    image, summary = [os.path.join(outdir, "cli_test4_%d.%s" % (ranks, e)) for e in ("vti", "json")]
    for f in (image, summary):
        if os.path.exists(f):
            os.remove(f)
    r = run(MPI + ["-n", str(ranks), sltk] + TEST4 + ["-o", image, "--json", summary])
    check(r.returncode == 0, "%d rank(s): exit 0 (%s)" % (ranks, r.stderr.strip()[-300:]))
    check(r.stdout.count("custom, 41 x 41") == 1, "%d rank(s): one summary printed, by rank 0" % ranks)
    outputs[ranks] = (values(image), json.load(open(summary)))
(v1, s1), (v2, s2) = outputs[1], outputs[2]
check(s2["ranks"] == 2 and s1["ranks"] == 1, "--json carries the rank count")
check(v1 == v2, "the 2-rank value function is bitwise the 1-rank one")
check(s1["l1_error"] == s2["l1_error"] and s1["linf_error"] == s2["linf_error"], "the same error norms")
check(set(s1) == set(s2), "the same --json keys")

# A running cost that is not finite on the upper rank's slab only.
image = os.path.join(outdir, "cli_broken.vti")
if os.path.exists(image):
    os.remove(image)
broken = list(TEST4)
broken[broken.index("--cost") + 1] = "y > 1.9 ? log(-1) : (a1^2+a2^2)/2"
r = run(MPI + ["-n", "2", sltk] + broken + ["-o", image])
check(r.returncode != 0, "a failure on one slab fails the run")
check(r.stderr.count("sltk: error:") == 1 and "the running cost f_C" in r.stderr and "rank 1 of 2" in r.stderr,
      "one message, naming the formula and the rank (%s)" % r.stderr.strip()[:300])
check(not os.path.exists(image), "no output written")

# Too many ranks for the rows: refused with the fix, by every rank alike (no hang).
r = run(MPI + ["-n", "4", sltk] + TEST4[:TEST4.index("--nodes") + 1] + ["21,21"] + TEST4[TEST4.index("--nodes") + 2:])
check(r.returncode != 0 and "use fewer ranks" in r.stderr, "too many ranks for the grid refused (%s)" %
      r.stderr.strip()[:200])

r = run(MPI + ["-n", "2", sltk, "reconstruct", "cloud.xyz", "-o", os.path.join(outdir, "never.vti")])
check(r.returncode == 2 and "runs on one rank today" in r.stderr, "sltk reconstruct on 2 ranks refused")

sys.exit(1 if failures else 0)
