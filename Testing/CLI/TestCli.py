"""The sltk command line: exit codes, messages, JSON summaries, no partial files.

Bad input (broken files, refused options and outputs) is in Testing/BadInput, one ctest case each."""
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

sltk = sys.argv[1]
shared = os.path.join(os.path.dirname(__file__), "..", "..", "..", "shared", "data", "clouds")
tmp = tempfile.mkdtemp(prefix="sltk-cli-")
failures = []


def run(*args, env=None):
    p = subprocess.run([sltk, *args], capture_output=True, text=True, timeout=300, env=env)
    return p.returncode, p.stdout, p.stderr


def expect(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures.append(what)


def write_sphere(path, n, bad_line=None):
    with open(path, "w") as f:
        f.write("# golden-angle sphere\n")
        for k in range(n):
            z = -1 + 2 * (k + 0.5) / n
            r = math.sqrt(1 - z * z)
            line = "%.9f %.9f %.9f\n" % (r * math.cos(2.4 * k), r * math.sin(2.4 * k), z)
            f.write("nan 0 0\n" if k == bad_line else line)


rc, out, _ = run("--version")
expect(rc == 0 and out.startswith("sltk "), "--version")

sphere = os.path.join(tmp, "sphere.xyz")
write_sphere(sphere, 2562)
summary = os.path.join(tmp, "info.json")
rc, out, err = run("info", sphere, "--json", summary)
expect(rc == 0, "info on a valid cloud exits 0 (%s)" % err.strip())
info = json.load(open(summary))
expect(info["points"] == 2562, "info JSON counts the points")
expect(0.05 < info["h_P"] < 0.09, "h_P of a 2562-point unit sphere is ~0.07 (got %g)" % info["h_P"])
expect(len(info["runs"]) == 3 and info["runs"][2]["dx"] * 4 == info["runs"][0]["dx"], "three runs halve dx (4.36)")

# One plan (ReconstructionPlan.h): info prints the grids reconstruct runs, run 1's padding for K_P included.
for kp, initial in (("10", "outside"), ("2", "ellipsoid")):
    info_kp, rec_kp = os.path.join(tmp, "info-kp.json"), os.path.join(tmp, "rec-kp.json")
    rc1, _, err1 = run("info", sphere, "--kp", kp, "--initial", initial, "--cdx", "2", "--json", info_kp)
    rc2, _, err2 = run("reconstruct", sphere, "--kp", kp, "--initial", initial, "--cdx", "2", "--max-iterations", "1",
                       "--quiet", "--json", rec_kp)
    planned = [r["grid"] for r in json.load(open(info_kp))["runs"]] if rc1 == 0 else None
    # One iteration a run leaves the surface short of the points: a result that does not fit (exit 3).
    ran = [r["grid"] for r in json.load(open(rec_kp))["runs"]] if rc2 in (0, 3) else []
    expect(planned == ran and len(ran) == 3, "info and reconstruct give the same grids with --kp %s --initial %s: %s vs %s"
           % (kp, initial, planned, ran))
flat = os.path.join(tmp, "circle.xyz")
with open(flat, "w") as f:
    for k in range(400):
        f.write("%.9f %.9f 0.5\n" % (math.cos(2 * math.pi * k / 400), math.sin(2 * math.pi * k / 400)))
rc, out, err = run("info", flat, "--json", summary)
expect(rc == 0 and json.load(open(summary))["dimension"] == 2 and "2D" in out,
       "info plans a cloud with no z extent in 2D, as reconstruct runs it: " + err.strip())

flower = os.path.join(tmp, "flower.xyz")
with open(flower, "w") as f:
    for k in range(200):
        t = 2 * math.pi * k / 200
        f.write("%f %f 0\n" % ((1 + 0.3 * math.cos(3 * t)) * math.cos(t), math.sin(t)))
rc, out, err = run("reconstruct", flower, "--json", os.path.join(tmp, "flower.json"))
summary = json.load(open(os.path.join(tmp, "flower.json"))) if rc == 0 else {}
expect(rc == 0 and "1 closed curve(s)" in out and summary.get("euler_characteristic", 0) is None,
       "a 2D result reports closed curves, no Euler characteristic")
flat_runs = summary.get("runs", [])
# --octree on a planar cloud: quadtrees in its plane (a 2D hyper tree grid) and the same curve.
flower_htg = os.path.join(tmp, "flower.htg")
rc, out, err = run("reconstruct", flower, "--octree", "-o", flower_htg, "--json", os.path.join(tmp, "flower-tree.json"),
                   "--quiet")
tree = json.load(open(os.path.join(tmp, "flower-tree.json"))) if rc == 0 else {}
head = open(flower_htg, "rb").read(600) if os.path.exists(flower_htg) else b""
expect(rc == 0 and "1 closed curve(s)" in out and re.search(rb'Dimensions="[0-9]+ [0-9]+ 1"', head)
       and [r["iterations"] for r in tree.get("runs", [])] == [r["iterations"] for r in flat_runs]
       and 0 < tree["runs"][-1]["leaves"] < tree["runs"][-1]["uniform_nodes"],
       "--octree on a planar cloud: a 2D hyper tree grid, the uniform run's iterations, fewer leaves than nodes (%s)"
       % err.strip())
# A whole binary PLY with faces is read (Testing/BadInput has the damaged ones).
import struct
good = os.path.join(tmp, "good.ply")
with open(good, "wb") as f:
    spread = [(math.cos(2.4 * k), math.sin(2.4 * k), -1 + 0.02 * k) for k in range(100)]
    f.write(("ply\nformat binary_little_endian 1.0\nelement vertex 100\nproperty float x\nproperty float y\n"
             "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n").encode() +
            b"".join(struct.pack("<fff", *p) for p in spread) + struct.pack("<Biii", 3, 0, 1, 2) * 4)
rc, out, err = run("info", good)
expect(rc == 0 and "points       100" in out, "a whole binary PLY with faces is read: " + err.strip())
rc, out, _ = run()
expect(rc == 2 and "reconstruct" in out, "no command: the usage, usage error 2")
for command in ("info", "reconstruct", "hjb"):
    rc, out, _ = run(command, "--help")
    expect(rc == 0 and "--threads" in out and "--json" in out, "sltk %s --help lists its options" % command)
rc, out, _ = run("hjb", "--help")
expect("cwenoz" in out and "--control-radius" in out and "(3.1)" in out, "hjb --help: interpolators, custom problems")

bunny = os.path.join(shared, "bunny", "bun_zipper.ply")
if os.path.exists(bunny):
    rc, out, err = run("info", bunny)
    expect(rc == 0 and "35947" in out, "reads the Stanford bunny PLY from ../shared")
else:
    print("skip ../shared/data not present")

# The same cloud gives the same file: the octree's surface twice, its normals included (VTK's
# threaded normals changed the last bits of some of the kitten's from run to run).
kitten = os.path.join(shared, "kitten", "kitten.xyz")
if os.path.exists(kitten):
    twice = [os.path.join(tmp, "kitten-octree-%d.ply" % k) for k in (1, 2)]
    codes = [run("reconstruct", kitten, "--octree", "--quiet", "--surface", path)[0] for path in twice]
    expect(codes == [0, 0] and open(twice[0], "rb").read() == open(twice[1], "rb").read(),
           "two --octree runs of the kitten write the same surface, byte for byte")
else:
    print("skip ../shared/data not present")

# Reconstruction: a 2562-point sphere in 2 runs (Q1 keeps it quick), outputs and JSON.
out_vti = os.path.join(tmp, "sphere.vti")
out_ply = os.path.join(tmp, "sphere.ply")
out_json = os.path.join(tmp, "recon.json")
out_csv = os.path.join(tmp, "recon.csv")
out_png = os.path.join(tmp, "sphere.png")
no_display = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
rc, _, err = run("reconstruct", sphere, "--png", out_png, "-o", out_vti, env=no_display)
expect(rc == 2 and "xvfb-run" in err and not os.path.exists(out_vti), "--png without a display: usage error first")
png_args = ["--png", out_png] if os.environ.get("DISPLAY") else []  # scripts/test.sh runs ctest under xvfb-run
rc, out, err = run("reconstruct", sphere, "--runs", "2", "--interpolator", "q1", "-o", out_vti, "--surface", out_ply,
                   "--json", out_json, "--csv", out_csv, "--quiet", *png_args)
if png_args:
    expect(rc == 0 and open(out_png, "rb").read(8) == b"\x89PNG\r\n\x1a\n" and os.path.getsize(out_png) > 10000,
           "--png writes a picture")
expect(rc == 0, "reconstruct a sphere exits 0 (%s)" % err.strip())
summary = json.load(open(out_json))
expect(summary["points"] == 2562 and len(summary["runs"]) == 2, "reconstruct JSON: points and runs")
expect(summary["runs"][1]["err_cloud"] < 0.01, "Err_P of the sphere below 0.01 (got %g)" % summary["runs"][1]["err_cloud"])
expect(all(k in summary for k in ("seconds", "peak_memory_mb")) and
       all(k in summary["runs"][0] for k in ("grid", "iterations", "energy", "err_cloud")), "reconstruct JSON fields")
expect(summary["fits_cloud"] is True and summary["runs"][1]["misfit_points"] < 0.05,
       "the sphere's result fits its cloud")
expect(os.path.getsize(out_vti) > 0 and open(out_ply, "rb").read(3) == b"ply", "signed distance and PLY surface written")
# A result that does not fit its cloud: a needle of points beside the sphere, thinner than run 1's cells
# of C_dx = 4, is lost; the files are written, and the exit status is 3.
needle = os.path.join(tmp, "needle.xyz")
write_sphere(needle, 2562)
with open(needle, "a") as f:
    f.writelines("%.9f 0.0 0.0\n" % (1.0 + 1.5 * (k + 1) / 400) for k in range(400))
needle_json, needle_vtp = os.path.join(tmp, "needle.json"), os.path.join(tmp, "needle.vtp")
rc, _, err = run("reconstruct", needle, "--cdx", "4", "--runs", "1", "--quiet", "--json", needle_json,
                 "--surface", needle_vtp)
needle_summary = json.load(open(needle_json)) if os.path.exists(needle_json) else {}
expect(rc == 3 and "the result does not fit the cloud" in err and "exit status 3" in err and
       needle_summary.get("fits_cloud") is False and os.path.exists(needle_vtp),
       "a result that does not fit: exit 3, the statement, fits_cloud false, files written (%d: %s)" % (rc, err))
expect(open(out_csv).readline().startswith("Run,Iteration,Energy"), "convergence CSV written")
# --octree: the tiled grid as a hyper tree grid (.htg), the surface and JSON as the uniform run's.
out_htg = os.path.join(tmp, "sphere.htg")
octree_json = os.path.join(tmp, "octree.json")
rc, out, err = run("reconstruct", sphere, "--runs", "2", "--interpolator", "q1", "--octree", "-o", out_htg,
                   "--json", octree_json, "--quiet")
expect(rc == 0, "reconstruct --octree -o FILE.htg exits 0 (%s)" % err.strip())
head = open(out_htg, "rb").read(400) if os.path.exists(out_htg) else b""
expect(b'type="HyperTreeGrid"' in head and b"SignedDistance" in open(out_htg, "rb").read(),
       "--octree -o writes a hyper tree grid with the signed distance")
tree_runs = json.load(open(octree_json))["runs"]
expect([r["iterations"] for r in tree_runs] == [r["iterations"] for r in summary["runs"]] and
       0 < tree_runs[1]["stored_nodes"] < tree_runs[1]["uniform_nodes"],
       "--octree: the uniform run's iterations, fewer nodes stored in run 2")
expect(0 < tree_runs[1]["leaves"] < tree_runs[1]["uniform_nodes"] and
       tree_runs[0]["leaves"] == tree_runs[0]["uniform_nodes"],
       "--octree JSON: the octree's leaves per run, fewer than its grid's nodes (run 1: its grid's nodes)")
# --octree -o FILE.vti: the uniform grid written from the trees, piece by piece; the signed distance is
# the uniform run's in its band (the same iterations) and +-gamma beyond it, as the uniform image holds it.
tree_vti = os.path.join(tmp, "sphere-trees.vti")
rc, out, err = run("reconstruct", sphere, "--runs", "2", "--interpolator", "q1", "--octree", "-o", tree_vti, "--quiet")
expect(rc == 0, "reconstruct --octree -o FILE.vti exits 0 (%s)" % err.strip())
try:
    from vtkmodules.vtkIOXML import vtkXMLImageDataReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    import numpy

    def read_image(path):
        reader = vtkXMLImageDataReader()
        reader.SetFileName(path)
        reader.Update()
        return reader.GetOutput()

    trees, uniform = read_image(tree_vti), read_image(out_vti)
    phi_t = vtk_to_numpy(trees.GetPointData().GetArray("SignedDistance"))
    phi_u = vtk_to_numpy(uniform.GetPointData().GetArray("SignedDistance"))
    gamma = numpy.abs(phi_u).max()
    band = numpy.abs(phi_u) < gamma
    same_grid = trees.GetDimensions() == uniform.GetDimensions() and numpy.allclose(
        trees.GetOrigin(), uniform.GetOrigin(), rtol=0, atol=1e-12) and numpy.allclose(
        trees.GetSpacing(), uniform.GetSpacing(), rtol=1e-12, atol=0)
    expect(same_grid and band.any() and numpy.abs(phi_t - phi_u)[band].max() < 1e-12 * gamma and
           (phi_t[~band] == phi_u[~band]).all() and
           trees.GetPointData().GetArray("DistanceToCloud") is not None and
           b'type="ImageData"' in open(tree_vti, "rb").read(400),
           "--octree -o FILE.vti: the uniform grid, its signed distance the uniform run's (%s, %s)" %
           (trees.GetDimensions(), uniform.GetDimensions()))
except ImportError as e:
    print("skip --octree -o FILE.vti's values: %s" % e)
# info --octree: the octree's plan, its stored nodes estimated from the cloud (an upper estimate).
plan_json, uniform_plan_json = os.path.join(tmp, "octree-plan.json"), os.path.join(tmp, "uniform-plan.json")
rc1, _, err1 = run("info", sphere, "--runs", "2", "--octree", "--json", plan_json)
rc2, _, _ = run("info", sphere, "--runs", "2", "--json", uniform_plan_json)
planned = json.load(open(plan_json))["runs"] if rc1 == 0 else []
uniform_planned = json.load(open(uniform_plan_json))["runs"] if rc2 == 0 else []
expect(len(planned) == 2 and len(uniform_planned) == 2 and
       tree_runs[1]["stored_nodes"] <= planned[1]["stored_nodes_estimate"] < planned[1]["nodes"] and
       planned[1]["memory_mb"] < uniform_planned[1]["memory_mb"] and planned[0]["grid"] == uniform_planned[0]["grid"],
       "info --octree: run 2's stored nodes estimated above the run's and below its grid's, less memory (%s)"
       % err1.strip())
# A grid the uniform storage refuses for memory: the refusal names --octree, whose plan fits.
rc1, _, err1 = run("info", sphere, "--cdx", "0.25", "--memory-budget", "1200")
rc2, out2, err2 = run("info", sphere, "--cdx", "0.25", "--memory-budget", "1200", "--octree")
expect(rc1 != 0 and "--octree" in err1 and rc2 == 0 and "stored (est.)" in out2,
       "info --octree plans what the uniform grids cannot hold (%s / %s)" % (err1.strip(), err2.strip()))
# --max-level L: the thesis's octree level (5.1) sets the finest cell, the cloud's extent / 2^L.
level_json = os.path.join(tmp, "level.json")
rc, out, err = run("info", sphere, "--runs", "2", "--max-level", "6", "--json", level_json)
points = [[float(v) for v in line.split()] for line in open(sphere) if not line.startswith("#")]
extent = max(max(p[a] for p in points) - min(p[a] for p in points) for a in range(3))
expect(rc == 0 and abs(json.load(open(level_json))["runs"][1]["dx"] * 64 - extent) < 1e-9 * extent,
       "--max-level 6: the finest cell is the cloud's extent / 64 (%s)" % err.strip())
# --interpolator lsq-q1: the thesis's chapter 5 least squares (5.5) instead of Q1, on the same grids.
lsq_json = os.path.join(tmp, "lsq.json")
rc, out, err = run("reconstruct", sphere, "--runs", "2", "--interpolator", "lsq-q1", "--json", lsq_json, "--quiet")
lsq_runs = json.load(open(lsq_json))["runs"] if rc == 0 else []
expect(rc == 0 and len(lsq_runs) == 2 and lsq_runs[1]["err_cloud"] < 0.01 and
       lsq_runs[1]["err_cloud"] != summary["runs"][1]["err_cloud"],
       "--interpolator lsq-q1 reconstructs the sphere, with its own Err_P (%s; q1 %g)" %
       (lsq_runs[1]["err_cloud"] if lsq_runs else err.strip(), summary["runs"][1]["err_cloud"]))
# --reference: Chamfer/Hausdorff against a UV sphere mesh (OFF), radius 1.
off = os.path.join(tmp, "sphere.off")
rings, sectors = 40, 80
verts = [(0.0, 0.0, 1.0)] + [
    (math.sin(math.pi * i / rings) * math.cos(2 * math.pi * j / sectors),
     math.sin(math.pi * i / rings) * math.sin(2 * math.pi * j / sectors), math.cos(math.pi * i / rings))
    for i in range(1, rings) for j in range(sectors)] + [(0.0, 0.0, -1.0)]
faces = [(0, 1 + j, 1 + (j + 1) % sectors) for j in range(sectors)]
for i in range(rings - 2):
    for j in range(sectors):
        a, b = 1 + i * sectors + j, 1 + i * sectors + (j + 1) % sectors
        faces += [(a, a + sectors, b), (b, a + sectors, b + sectors)]
last = len(verts) - 1
faces += [(last, 1 + (rings - 2) * sectors + (j + 1) % sectors, 1 + (rings - 2) * sectors + j) for j in range(sectors)]
with open(off, "w") as f:
    f.write("OFF\n%d %d 0\n" % (len(verts), len(faces)))
    f.writelines("%r %r %r\n" % v for v in verts)
    f.writelines("3 %d %d %d\n" % t for t in faces)
ref_json = os.path.join(tmp, "ref.json")
rc, out, err = run("reconstruct", sphere, "--runs", "2", "--interpolator", "q1", "--reference", off, "--json", ref_json,
                   "--quiet")
ref = json.load(open(ref_json)) if rc == 0 else {}
expect(rc == 0 and 0 < ref.get("chamfer", 1) < 0.005 and ref.get("hausdorff", 1) < 0.05,
       "Chamfer/Hausdorff to the exact sphere are small (%s)" % {k: ref.get(k) for k in ("chamfer", "hausdorff")})
expect(ref.get("surface_pieces") == 1 and ref.get("euler_characteristic") == 2 and ref.get("outliers_removed") == 0,
       "JSON: one closed piece (%s)" % {k: ref.get(k) for k in ("surface_pieces", "euler_characteristic")})
# Cleaning: a stray point far from the sphere is removed, thinning merges points.
stray = os.path.join(tmp, "stray.xyz")
with open(stray, "w") as f:
    f.write(open(sphere).read() + "3.0 0.5 -0.2\n")
clean_json = os.path.join(tmp, "clean.json")
rc, out, err = run("reconstruct", stray, "--runs", "1", "--interpolator", "q1", "--remove-outliers", "--thin", "1.5",
                   "--json", clean_json, "--quiet")
clean = json.load(open(clean_json)) if rc == 0 else {}
expect(rc == 0 and clean.get("outliers_removed") == 1 and 0 < clean.get("points_reconstructed", 0) < 2562 and
       clean.get("thinning_cell", 0) > 0 and clean.get("surface_pieces") == 1 and "outliers removed" in out,
       "--remove-outliers --thin: counts in the summary (%s)" % err.strip())
rc, out, err = run("info", stray, "--remove-outliers", "--thin", "1.5")
expect(rc == 0 and "1 outliers removed" in out and "density" in out, "info reports the cleaned cloud: " + err.strip())
sched_json = os.path.join(tmp, "schedule.json")
rc, _, err = run("reconstruct", sphere, "--runs", "2", "--interpolator", "q1", "--schedule", "1:0,2:0", "--quiet",
                 "--json", sched_json)
sched = json.load(open(sched_json)) if rc == 0 else {"runs": [{}, {}]}
expect(rc == 0 and sched["runs"][1].get("err_cloud", 1) < 0.01 and
       sched["runs"][1].get("energy") != summary["runs"][1]["energy"],
       "--schedule 1:0,2:0 runs and changes the result (%s)" % err.strip())
# Every option of the filter in the CLI too: --padding (Padding) and --tolerance (Tolerance), with
# Core's ranges (OptionRanges.h).
pad_json = os.path.join(tmp, "padding.json")
rc, _, err = run("info", sphere, "--runs", "2", "--padding", "6", "--json", pad_json)
padded = json.load(open(pad_json))["runs"] if rc == 0 else []
expect(len(padded) == 2 and all(a <= b for a, b in zip(padded[1]["grid"], uniform_planned[1]["grid"])) and
       padded[1]["grid"] != uniform_planned[1]["grid"],
       "--padding 6: run 2's grid narrower than with the default 10 (%s)" % err.strip())
rc, _, err = run("info", sphere, "--padding", "3")
expect(rc == 2 and "[4, 1000]" in err, "--padding 3 refused with Core's range: " + err.strip())
tol_json = os.path.join(tmp, "tolerance.json")
rc, _, err = run("reconstruct", sphere, "--runs", "2", "--interpolator", "q1", "--tolerance", "0.5", "--quiet",
                 "--json", tol_json)
loose = json.load(open(tol_json)) if rc == 0 else {"runs": []}
expect(rc == 0 and sum(r["iterations"] for r in loose["runs"]) < sum(r["iterations"] for r in summary["runs"]),
       "--tolerance 0.5 stops the runs sooner than the default 1e-4 (%s)" % err.strip())
rc, _, err = run("reconstruct", sphere, "--tolerance", "2")
expect(rc == 2 and "[0, 1]" in err, "--tolerance 2 refused with Core's range: " + err.strip())

vti = os.path.join(tmp, "v0.vti")
rc, out, err = run("hjb", "--n", "41", "--final-time", "0", "-o", vti, "--json", os.path.join(tmp, "hjb.json"))
expect(rc == 0 and os.path.getsize(vti) > 0, "hjb writes the value function")
hjb = json.load(open(os.path.join(tmp, "hjb.json")))
expect(abs(hjb["max"] - 0.15) < 1e-12 and hjb["min"] == 0.0 and hjb["steps"] == 0, "hjb at T = 0 is the initial datum")
# Test 2 at N = 81 against Table 3.3 (WENO 3.56e-6, CWENO 2.24e-6, CWENOZ 1.78e-6).
for name, thesis in (("weno3", 3.56e-6), ("cweno", 2.24e-6), ("cwenoz", 1.78e-6)):
    rc, out, err = run("hjb", "--preset", "test2", "--n", "81", "--interpolator", name, "--json",
                       os.path.join(tmp, "t2.json"))
    t2 = json.load(open(os.path.join(tmp, "t2.json"))) if rc == 0 else {}
    expect(rc == 0 and abs(t2.get("l1_error", 1) / thesis - 1) < 0.1 and t2.get("evaluations_per_node", 0) > 50,
           "test2 %s L1 within 10%% of Table 3.3 (%s)" % (name, t2.get("l1_error")))
# A custom problem by formulas: thesis Test 4 (3.37) equals the compiled preset.
rc, _, _ = run("hjb", "--preset", "test4", "--n", "21", "--json", os.path.join(tmp, "t4.json"))
t4 = json.load(open(os.path.join(tmp, "t4.json"))) if rc == 0 else {}
custom = ["hjb", "--fx=-a1", "--fy", "-a2", "--cost", "(a1^2 + a2^2)/2", "--v0", "max(1 - (x^2 + y^2), 0)",
          "--exact", "hypot(x, y) <= 1 ? (hypot(x, y) - 1)^2 / (2*t) : 0", "--nodes", "21,21", "--domain", "-2,2,-2,2",
          "--controls", "ball", "--control-dim", "2", "--control-radius", "2.2", "--rk", "1", "--courant", "1.25",
          "--warm-start", "5", "--final-time", "0.5"]
rc, out, err = run(*custom, "--json", os.path.join(tmp, "c4.json"))
c4 = json.load(open(os.path.join(tmp, "c4.json"))) if rc == 0 else {}
expect(rc == 0 and abs(c4.get("l1_error", 1) - t4.get("l1_error", 0)) < 1e-12 and c4.get("steps") == 2,
       "custom Test 4 formulas reproduce the preset (L1 %s vs %s) %s" % (c4.get("l1_error"), t4.get("l1_error"), err))
# A closed-form argmin replaces the search: v0 = |x|^2/2, f_D = -a, f_C = |a|^2/2 -> a* = x / (1 + t), one evaluation a node.
quadratic = ["hjb", "--fx=-a1", "--fy=-a2", "--cost", "(a1^2 + a2^2)/2", "--v0", "(x^2 + y^2)/2", "--exact",
          "(x^2 + y^2) / (2*(1 + t))", "--nodes", "21,21", "--controls", "ball",
          "--control-dim", "2", "--control-radius", "2", "--rk", "1", "--final-time", "0.5"]
rc, out, err = run(*quadratic, "--argmin1", "x/(1 + t)", "--argmin2", "y/(1 + t)", "--json", os.path.join(tmp, "argmin.json"))
am = json.load(open(os.path.join(tmp, "argmin.json"))) if rc == 0 else {}
expect(rc == 0 and am.get("evaluations_per_node") == 1 and am.get("l1_error", 1) < 1e-3,
       "--argmin1/--argmin2 replace the search (%s evaluations a node, L1 %s) %s"
       % (am.get("evaluations_per_node"), am.get("l1_error"), err))
rc, _, err = run(*quadratic, "--argmin1", "x", "-o", os.path.join(tmp, "argmin-bad.vti"))
expect(rc == 1 and "argmin component a2 is empty" in err and not os.path.exists(os.path.join(tmp, "argmin-bad.vti")),
       "a missing argmin component is named, no file: " + err.strip())
# --control-per-step (PerStageControls off): one control per time step instead of one per RK stage.
heun = [("2" if a == "1" and quadratic[k - 1] == "--rk" else a) for k, a in enumerate(quadratic)]
staged, stepped = os.path.join(tmp, "staged.json"), os.path.join(tmp, "stepped.json")
rc1, _, err1 = run(*heun, "--json", staged)
rc2, _, err2 = run(*heun, "--control-per-step", "--json", stepped)
st = json.load(open(staged)) if rc1 == 0 else {}
sp = json.load(open(stepped)) if rc2 == 0 else {}
expect(rc1 == 0 and rc2 == 0 and st.get("l1_error") is not None and sp.get("l1_error") is not None and
       st.get("l1_error") != sp.get("l1_error"),
       "--control-per-step reaches the solver (L1 %s per stage, %s per step) %s %s"
       % (st.get("l1_error"), sp.get("l1_error"), err1.strip(), err2.strip()))
expect(not [f for f in os.listdir(tmp) if ".part" in f], "no temporary files are left behind")

if failures:
    sys.exit("%d failure(s); the files: %s" % (len(failures), tmp))
shutil.rmtree(tmp, ignore_errors=True)
