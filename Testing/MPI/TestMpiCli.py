"""`mpirun -np 2 sltk hjb` (Apps/sltk/MpiSession.h): the custom problem is
split over the ranks and rank 0 writes one set of outputs, bitwise the
one-rank solve (one .vti collected on rank 0, or a .pvti with one piece per
rank); a failure on one rank's slab ends the run with one message and
no output; `mpirun -np 2 sltk reconstruct` reconstructs slabs and gives the
one-rank iterations, Err_P, signed distance (.pvti) and one closed surface;
an empty cloud, a NaN and a grid beyond the memory budget end both ranks with
one message and no output.
Run by pvpython (VTK reads the images): TestMpiCli.py SLTK MPIEXEC OUTDIR"""
import json
import math
import os
import subprocess
import sys

import shutil

from vtkmodules.vtkIOXML import vtkXMLHyperTreeGridReader, vtkXMLImageDataReader, vtkXMLPImageDataReader

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


def values(path, name="ValueFunction"):
    reader = vtkXMLPImageDataReader() if path.endswith(".pvti") else vtkXMLImageDataReader()
    reader.SetFileName(path)
    reader.Update()
    array = reader.GetOutput().GetPointData().GetArray(name)
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
check(abs(s1["l1_error"] - s2["l1_error"]) <= 1e-13 * s1["l1_error"] and s1["linf_error"] == s2["linf_error"],
      "the same error norms (L1 reduced over the ranks: its last bits may differ)")
check(set(s1) == set(s2), "the same --json keys")

# -o FILE.pvti: every rank writes its own block (FILE/FILE_<rank>.vti); 3 ranks and one .vti: rank 0 collects.
pvti, pieces = os.path.join(outdir, "cli_pieces.pvti"), os.path.join(outdir, "cli_pieces")
three = os.path.join(outdir, "cli_test4_3.vti")
for old in (pvti, pieces, three):
    shutil.rmtree(old) if os.path.isdir(old) else (os.remove(old) if os.path.exists(old) else None)
for attempt in (1, 2):  # the second run replaces the first one's pieces
    r = run(MPI + ["-n", "2", sltk] + TEST4 + ["-o", pvti])
    check(r.returncode == 0, "-o FILE.pvti on 2 ranks, run %d (%s)" % (attempt, r.stderr.strip()[-300:]))
written = sorted(os.listdir(pieces)) if os.path.isdir(pieces) else []
check(written == ["cli_pieces_0.vti", "cli_pieces_1.vti"], "one piece per rank in %s: %s" % (pieces, written))
check(all(len(values(os.path.join(pieces, f))) < 41 * 41 for f in written), "each piece is a block, not the grid")
check(os.path.exists(pvti) and values(pvti) == v1, "the pieces read back as the 1-rank value function, bitwise")
check(not [f for f in os.listdir(outdir) if ".part" in f], "no temporary file or folder left")
r = run(MPI + ["-n", "3", sltk] + TEST4 + ["-o", three])
check(r.returncode == 0 and values(three) == v1, "3 ranks, one .vti collected by rank 0: bitwise the 1-rank one")
clash = os.path.join(outdir, "cli_clash")
os.makedirs(clash, exist_ok=True)
open(os.path.join(clash, "keep.txt"), "w").write("mine")
r = run(MPI + ["-n", "2", sltk] + TEST4 + ["-o", clash + ".pvti"])
check(r.returncode == 2 and "holds other files" in r.stderr and os.path.exists(os.path.join(clash, "keep.txt")),
      "a folder named like the pieces' that holds other files is refused and kept (%s)" % r.stderr.strip()[:200])

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

# sltk reconstruct: each rank reconstructs its slab of every run; rank 0 joins the surface pieces.
cloud = os.path.join(outdir, "cli_sphere.xyz")
with open(cloud, "w") as f:
    n = 900
    for k in range(n):  # a Fibonacci sphere, squashed: an ellipsoid of radii 1, 0.8, 0.6
        z = 1.0 - 2.0 * (k + 0.5) / n
        r, t = math.sqrt(1.0 - z * z), k * math.pi * (3.0 - math.sqrt(5.0))
        f.write("%.9f %.9f %.9f\n" % (r * math.cos(t), 0.8 * r * math.sin(t), 0.6 * z))
RECON = ["reconstruct", cloud, "--runs", "2", "--quiet", "--threads", "1"]
recon = {}
for ranks in (1, 2):
    image = os.path.join(outdir, "cli_recon_%d.%s" % (ranks, "vti" if ranks == 1 else "pvti"))
    summary, surface = [os.path.join(outdir, "cli_recon_%d.%s" % (ranks, e)) for e in ("json", "vtp")]
    for f in (summary, surface):
        if os.path.exists(f):
            os.remove(f)
    r = run(MPI + ["-n", str(ranks), sltk] + RECON + ["-o", image, "--json", summary, "--surface", surface])
    check(r.returncode == 0, "reconstruct on %d rank(s): exit 0 (%s)" % (ranks, r.stderr.strip()[-300:]))
    recon[ranks] = (values(image, "SignedDistance"), json.load(open(summary)) if r.returncode == 0 else {})
(p1, j1), (p2, j2) = recon[1], recon[2]
check(j2.get("ranks") == 2 and j1.get("ranks") == 1, "reconstruct --json carries the rank count")
check([x["iterations"] for x in j1.get("runs", [])] == [x["iterations"] for x in j2.get("runs", [])],
      "the same iterations per run on 1 and 2 ranks")
check(all(abs(a["err_cloud"] - b["err_cloud"]) <= 1e-12 * a["err_cloud"] for a, b in zip(j1["runs"], j2["runs"])),
      "the same Err_P on 1 and 2 ranks")
check(len(p1) == len(p2) and max(abs(a - b) for a, b in zip(p1, p2)) < 1e-12,
      "the 2-rank blocks (.pvti) hold the 1-rank signed distance")
check(j2.get("surface_pieces") == 1 and j2.get("euler_characteristic") == 2 == j1.get("euler_characteristic"),
      "the joined surface is one closed piece of genus 0, as on one rank")
check(j2.get("surface_points") == j1.get("surface_points"), "the joined surface has the 1-rank vertices (%s, %s)" %
      (j1.get("surface_points"), j2.get("surface_points")))
r = run(MPI + ["-n", "2", sltk] + RECON + ["-o", os.path.join(outdir, "never.vti")])
check(r.returncode == 2 and "write -o as .pvti" in r.stderr, "reconstruct -o FILE.vti on 2 ranks refused with the fix")
# --octree: the ranks share the tiles of run 2 out; each writes its own trees (.phtg) and surface piece.
octree, trees = {}, {}
for ranks in (1, 2):
    tree, summary = [os.path.join(outdir, "cli_octree_%d.%s" % (ranks, e)) for e in ("htg" if ranks == 1 else "phtg",
                                                                                    "json")]
    for f in (tree, summary):
        if os.path.exists(f):
            os.remove(f)
    r = run(MPI + ["-n", str(ranks), sltk] + RECON + ["--octree", "-o", tree, "--json", summary])
    check(r.returncode == 0 and os.path.exists(tree), "reconstruct --octree -o %s on %d rank(s): exit 0 and the "
          "trees written (%s)" % (os.path.basename(tree), ranks, r.stderr.strip()[-300:]))
    octree[ranks] = json.load(open(summary)) if r.returncode == 0 else {}
    # Each piece with the serial reader (as MPI.OctreeRanks: VTK 9.2's parallel reader is not relied on).
    pieces = [tree] if ranks == 1 else [os.path.join(outdir, "cli_octree_2", "cli_octree_2_%d.htg" % k)
                                        for k in range(ranks)]
    cells, owners = 0, []
    for piece in pieces:
        reader = vtkXMLHyperTreeGridReader()
        reader.SetFileName(piece)
        reader.Update()
        grid = reader.GetOutput() if os.path.exists(piece) else None
        cells += grid.GetNumberOfCells() if grid else 0
        owners.append(grid.GetCellData().GetArray("Rank").GetRange() if grid and grid.GetNumberOfCells() else None)
    trees[ranks] = (cells, owners)
check(trees[2][0] == trees[1][0] > 0 and trees[2][1] == [(0.0, 0.0), (1.0, 1.0)],
      "--octree: the 2 ranks' pieces (.phtg) hold the 1-rank trees' %s cells, each rank its own (%s)" %
      (trees[1][0], trees[2]))
# ParaView 5.11's .phtg reader crashes (Documentation/Toolchain.md): the 2-rank trees open through
# FILE.vtm, a multiblock of the pieces, with every rank's cells, and ParaView's Slice and Contour run on them.
from paraview import simple  # noqa: E402

vtm = os.path.join(outdir, "cli_octree_2.vtm")
opened = simple.OpenDataFile(vtm) if os.path.exists(vtm) else None
blocks = simple.servermanager.Fetch(opened) if opened else None
cells = sum(blocks.GetBlock(k).GetNumberOfCells() for k in range(blocks.GetNumberOfBlocks())) if blocks else 0
check(blocks is not None and blocks.GetNumberOfBlocks() == 2 and cells == trees[1][0] > 0 and
      opened.CellData["Rank"].GetRange() == (0.0, 1.0),
      "--octree on 2 ranks: FILE.vtm opens in pvpython with every rank's cells (%s of %s)" % (cells, trees[1][0]))
if opened:
    plane = simple.Slice(Input=opened)
    plane.SliceType.Normal = [0.0, 0.0, 1.0]
    cut = simple.servermanager.Fetch(plane)
    contour = simple.servermanager.Fetch(simple.Contour(Input=opened, ContourBy=["CELLS", "SignedDistance"],
                                                        Isosurfaces=[0.0]))
    count = [sum(d.GetBlock(k).GetNumberOfCells() for k in range(d.GetNumberOfBlocks())
                 if d.GetBlock(k)) for d in (cut, contour)]
    check(min(count) > 0, "Slice and Contour run on the 2-rank trees (%s and %s cells)" % tuple(count))
r = run(MPI + ["-n", "2", sltk] + RECON + ["--octree", "-o", os.path.join(outdir, "never.htg")])
check(r.returncode == 2 and "write -o as .phtg" in r.stderr, "reconstruct --octree -o FILE.htg on 2 ranks refused "
      "with the fix")
o1, o2 = octree[1], octree[2]
check([x["iterations"] for x in o1.get("runs", [])] == [x["iterations"] for x in o2.get("runs", [])] and
      len(o1.get("runs", [])) == 2, "--octree: the same iterations per run on 1 and 2 ranks")
check(all(abs(a["err_cloud"] - b["err_cloud"]) <= 1e-12 * a["err_cloud"] for a, b in zip(o1["runs"], o2["runs"])),
      "--octree: the same Err_P on 1 and 2 ranks")
check(o2.get("surface_points") == o1.get("surface_points") and o2.get("surface_pieces") == 1 and
      o2.get("euler_characteristic") == 2, "--octree: the 1-rank surface, one closed piece, on 2 ranks (%s, %s)" %
      (o1.get("surface_points"), o2.get("surface_points")))
# Bad input on 2 ranks: one clear message, a failing exit code, no output, no hang.
empty, nan = os.path.join(outdir, "cli_empty.xyz"), os.path.join(outdir, "cli_nan.xyz")
open(empty, "w").close()
with open(nan, "w") as f:
    f.write(open(cloud).read() + "0.1 nan 0.2\n")
never = os.path.join(outdir, "cli_never.pvti")
for what, args in (("an empty cloud", [empty]), ("a cloud with a NaN", [nan]),
                   ("a grid beyond the memory budget", [cloud, "--memory-budget", "16", "--cdx", "1", "--runs", "5"])):
    r = run(MPI + ["-n", "2", sltk, "reconstruct"] + args + ["--quiet", "-o", never])
    check(r.returncode != 0 and r.stderr.count("sltk: error:") == 1 and not os.path.exists(never),
          "%s on 2 ranks: one error, no output (%s)" % (what, r.stderr.strip()[:160]))

sys.exit(1 if failures else 0)
