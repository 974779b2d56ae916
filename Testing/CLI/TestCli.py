"""The sltk command line: exit codes, messages, JSON summaries, no partial files."""
import json
import math
import os
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
    ran = [r["grid"] for r in json.load(open(rec_kp))["runs"]] if rc2 == 0 else []
    expect(planned == ran and len(ran) == 3, "info and reconstruct give the same grids with --kp %s --initial %s: %s vs %s"
           % (kp, initial, planned, ran))
flat = os.path.join(tmp, "circle.xyz")
with open(flat, "w") as f:
    for k in range(400):
        f.write("%.9f %.9f 0.5\n" % (math.cos(2 * math.pi * k / 400), math.sin(2 * math.pi * k / 400)))
rc, out, err = run("info", flat, "--json", summary)
expect(rc == 0 and json.load(open(summary))["dimension"] == 2 and "2D" in out,
       "info plans a cloud with no z extent in 2D, as reconstruct runs it: " + err.strip())

bad = os.path.join(tmp, "nan.xyz")
write_sphere(bad, 100, bad_line=17)
rc, _, err = run("info", bad)
expect(rc == 1 and "point 17" in err and "non-finite" in err, "NaN coordinates are named: " + err.strip())

rc, _, err = run("info", os.path.join(tmp, "missing.ply"))
expect(rc == 1 and "cannot open" in err, "a missing file is reported: " + err.strip())
rc, _, err = run("info", sphere, "--cdx", "zero")
expect(rc == 2 and "expects a number" in err, "a malformed option value is usage error 2")
rc, _, err = run("info", sphere, "--cdx", "0.05", "--memory-budget", "16")
expect(rc == 1 and "use C_dx >=" in err and "--thin" not in err, "a grid beyond memory is refused with a C_dx: " + err.strip())
big = os.path.join(tmp, "big.xyz")
write_sphere(big, 120000)
rc, _, err = run("info", big, "--cdx", "0.05", "--memory-budget", "16")
expect(rc == 1 and "use C_dx >=" in err and "--thin 2.5" in err, "a large refused cloud gets the merged-scan hint: " + err.strip())
# Outputs that would destroy an input, collide, or cannot be written: refused before any work.
before = open(sphere).read()
for option in ("-o", "--json", "--csv"):
    rc, _, err = run("reconstruct", sphere, option, sphere)
    expect(rc == 2 and "would be overwritten" in err and open(sphere).read() == before,
           "%s naming the input cloud is refused, the cloud untouched: %s" % (option, err.strip()))
points = [line for line in open(sphere).read().splitlines() if line.strip() and not line.startswith("#")]
ply = os.path.join(tmp, "sphere.ply")
with open(ply, "w") as f:
    f.write("ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\nend_header\n" % len(points))
    f.write("\n".join(points) + "\n")
ply_before = open(ply).read()
rc, _, err = run("reconstruct", ply, "--surface", ply)
expect(rc == 2 and "would be overwritten" in err and open(ply).read() == ply_before,
       "--surface naming the input cloud is refused, the cloud untouched: " + err.strip())
rc, _, err = run("info", sphere, "--json", sphere)
expect(rc == 2 and "would be overwritten" in err and open(sphere).read() == before, "info --json naming the cloud is refused")
rc, _, err = run("reconstruct", sphere, "-o", os.path.join(tmp, "no-such-folder", "sdf.vti"))
expect(rc == 2 and "does not exist" in err, "a missing output folder is found before the run: " + err.strip())
rc, _, err = run("reconstruct", sphere, "-o", os.path.join(tmp, "sdf.xyz"))
expect(rc == 2 and ".vti" in err and not os.path.exists(os.path.join(tmp, "sdf.xyz")),
       "-o with an extension that is not the format written is refused: " + err.strip())
rc, _, err = run("hjb", "--preset", "test1", "--n", "21", "--json", os.path.join(tmp, "summary.txt"))
expect(rc == 2 and ".json" in err, "hjb --json with another extension is refused: " + err.strip())
rc, _, err = run("hjb", "--preset", "test1", "--n", "21", "-o", tmp)
expect(rc == 2 and "is a folder" in err, "a folder as the output is refused: " + err.strip())
# SIGINT while the output is written: the temporary is removed, nothing half-written stays.
import glob, signal, time
interrupted = os.path.join(tmp, "interrupted.vti")
writer = subprocess.Popen([sltk, "hjb", "--preset", "test1", "--n", "2001", "--final-time", "0.001", "-o", interrupted],
                          stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
seen = False
for _ in range(3000):
    if glob.glob(os.path.join(tmp, "interrupted.part*")):
        writer.send_signal(signal.SIGINT)
        seen = True
        break
    if writer.poll() is not None:
        break
    time.sleep(0.005)
writer.wait(timeout=120)
expect(seen and not glob.glob(os.path.join(tmp, "interrupted*")),
       "an interrupted write leaves no .part file and no output (caught the write: %s)" % seen)
rc, _, err = run("hjb", "--preset", "test1", "--n", "21", "--threads", "10000")
expect(rc == 2 and "--threads" in err and "1024" in err, "--threads 10000 is a usage error: " + err.strip())
flower = os.path.join(tmp, "flower.xyz")
with open(flower, "w") as f:
    for k in range(200):
        t = 2 * math.pi * k / 200
        f.write("%f %f 0\n" % ((1 + 0.3 * math.cos(3 * t)) * math.cos(t), math.sin(t)))
rc, _, err = run("reconstruct", flower, "--surface", os.path.join(tmp, "flower.ply"))
expect(rc == 2 and ".vtp" in err and not os.path.exists(os.path.join(tmp, "flower.ply")),
       "a 2D curve written as .ply is refused before the run: " + err.strip())
rc, out, err = run("reconstruct", flower, "--json", os.path.join(tmp, "flower.json"))
summary = json.load(open(os.path.join(tmp, "flower.json"))) if rc == 0 else {}
expect(rc == 0 and "1 closed curve(s)" in out and summary.get("euler_characteristic", 0) is None,
       "a 2D result reports closed curves, no Euler characteristic")
rc, _, err = run("info", tmp)
expect(rc == 1 and "is a folder" in err, "a folder given as the cloud is named: " + err.strip())
garbage = os.path.join(tmp, "garbage.xyz")
with open(garbage, "wb") as f:
    f.write(bytes((k * 37 + 11) % 256 for k in range(4000)))
rc, _, err = run("info", garbage)
expect(rc == 1 and ("binary data" in err or "expected three coordinates" in err), "binary garbage in a .xyz is named: " + err.strip())
token = os.path.join(tmp, "token.xyz")
with open(token, "w") as f:
    f.write("0 0 0\n1 0 0\n0 1 0.02abc\n0 0 1\n")
rc, _, err = run("info", token)
expect(rc == 1 and "0.02abc" in err and ":3:" in err, "a token like 0.02abc is refused with its line: " + err.strip())
# Damaged PLY files (vtkPLYReader asserts, crashes or pads on them): checked before VTK reads.
def ply_header(fmt, n, props="property float x\nproperty float y\nproperty float z\n", faces=0):
    face = "element face %d\nproperty list uchar int vertex_indices\n" % faces if faces else ""
    return "ply\nformat %s 1.0\nelement vertex %d\n%s%send_header\n" % (fmt, n, props, face)


import struct
corners = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)] * 25
ascii_rows = "".join("%g %g %g\n" % p for p in corners)
binary_rows = b"".join(struct.pack("<fff", *p) for p in corners)
tetra_faces = struct.pack("<Biii", 3, 0, 1, 2) * 4
damaged = {
    "truncated ASCII": (ply_header("ascii", 100) + ascii_rows[: len(ascii_rows) // 2]).encode(),
    "a short vertex line": (ply_header("ascii", 100) + "0 0\n" + ascii_rows.split("\n", 1)[1]).encode(),
    "faces but no x/y/z": (ply_header("ascii", 3, "property float a\nproperty float b\n", 1) + "0 0\n1 0\n0 1\n3 0 1 2\n").encode(),
    "only x": (ply_header("ascii", 3, "property float x\n", 1) + "0\n1\n2\n3 0 1 2\n").encode(),
    "truncated binary": ply_header("binary_little_endian", 100).encode() + binary_rows[:601],
    "truncated binary faces": ply_header("binary_little_endian", 100, faces=8).encode() + binary_rows + tetra_faces,
    "no ply magic": b"solid cube\n",
}
whats = {"truncated ASCII": "50 of the 100 vertex", "a short vertex line": "vertex 0 has 2 numbers",
         "faces but no x/y/z": "no scalar 'x'", "only x": "no scalar 'y'", "truncated binary": "50 of the 100 vertex",
         "truncated binary faces": "4 of the 8 face", "no ply magic": "does not start with the line 'ply'"}
for name, data in damaged.items():
    path = os.path.join(tmp, "damaged.ply")
    with open(path, "wb") as f:
        f.write(data)
    rc, _, err = run("info", path)
    expect(rc == 1 and "damaged PLY file" in err and whats[name] in err, "a cloud PLY with %s is named: %s" % (name, err.strip()))
    out_vti = os.path.join(tmp, "never.vti")
    rc, _, err = run("reconstruct", sphere, "--reference", path, "-o", out_vti)
    expect(rc == 1 and "damaged PLY file" in err and whats[name] in err and not os.path.exists(out_vti),
           "a --reference PLY with %s is refused before the run" % name)
good = os.path.join(tmp, "good.ply")
with open(good, "wb") as f:
    spread = [(math.cos(2.4 * k), math.sin(2.4 * k), -1 + 0.02 * k) for k in range(100)]
    f.write(ply_header("binary_little_endian", 100, faces=4).encode() +
            b"".join(struct.pack("<fff", *p) for p in spread) + tetra_faces)
rc, out, err = run("info", good)
expect(rc == 0 and "points       100" in out, "a whole binary PLY with faces is read: " + err.strip())
# Allocations the memory checks cannot foresee (here an address-space limit they do not see)
# end the command with an error, not an abort; and absurd step counts are refused up front.
import resource
limited = subprocess.run([sltk, "reconstruct", sphere, "--cdx", "0.5", "-o", os.path.join(tmp, "limited.vti")],
                         capture_output=True, text=True, timeout=300,
                         preexec_fn=lambda: resource.setrlimit(resource.RLIMIT_AS, (400 << 20, 400 << 20)))
expect(limited.returncode == 1 and "out of memory" in limited.stderr and not os.path.exists(os.path.join(tmp, "limited.vti")),
       "std::bad_alloc under a 400 MB address-space limit is an error, exit 1: " + limited.stderr.strip()[-160:])
rc, _, err = run("hjb", "--preset", "test1", "--n", "41", "--final-time", "1e7")
expect(rc == 1 and "more than 1e+06" in err and "final time" in err, "a final time of 1e7 steps is refused up front: " + err.strip())
rc, _, err = run("hjb", "--fx", "a1", "--fy", "a2", "--controls", "box", "--control-dim", "2", "--v0", "x",
                 "--nodes", "21,21", "--domain", "-1,1,-1,1", "--final-time", "1", "--courant", "1e-9")
expect(rc == 1 and "Courant" in err and "1e+10 steps" in err, "a Courant number of 1e-9 is refused up front: " + err.strip())
# Options for an axis or control the problem does not have, and an exact solution that is not a number.
custom2d = ["hjb", "--fx", "a1", "--fy", "a2", "--controls", "box", "--control-dim", "2", "--v0", "x",
            "--nodes", "21,21", "--final-time", "0.1"]
rc, _, err = run(*custom2d, "--fz", "1")
expect(rc == 2 and "--fz is given for a 2D problem" in err, "--fz in 2D is a usage error: " + err.strip())
rc, _, err = run(*custom2d, "--domain", "-1,1,-1,1,-1,1")
expect(rc == 2 and "--domain gives 3 axes for a 2D problem" in err, "a third --domain pair in 2D is a usage error: " + err.strip())
rc, _, err = run(*custom2d, "--argmin3", "1")
expect(rc == 2 and "--argmin3 is given for 2 control(s)" in err, "--argmin3 with 2 controls is a usage error: " + err.strip())
rc, _, err = run(*custom2d, "--exact", "0/0", "--json", os.path.join(tmp, "exact.json"))
expect(rc == 1 and "--exact" in err and "x = -1, y = -1" in err and not os.path.exists(os.path.join(tmp, "exact.json")),
       "--exact 0/0 is an error naming where, not vanishing norms: " + err.strip())
rc, _, err = run("frobnicate")
expect(rc == 2 and "frobnicate" in err, "an unknown command is usage error 2")
rc, out, _ = run()
expect(rc == 2 and "reconstruct" in out, "no command: the usage, usage error 2")
for command in ("info", "reconstruct", "hjb"):
    rc, out, _ = run(command, "--help")
    expect(rc == 0 and "--threads" in out and "--json" in out, "sltk %s --help lists its options" % command)
rc, out, _ = run("hjb", "--help")
expect("cwenoz" in out and "--control-radius" in out and "(3.1)" in out, "hjb --help: interpolators, custom problems")
rc, _, err = run("info", sphere, "--cdx", "0.02abc")
expect(rc == 2 and "--cdx" in err and "expects a number" in err, "trailing text after a number is refused: " + err.strip())
rc, _, err = run("info", sphere, "--cdx")
expect(rc == 2 and "--cdx" in err and "needs a value" in err, "a missing value is named: " + err.strip())
rc, _, err = run("info", sphere, "--frobnicate")
expect(rc == 2 and "--frobnicate" in err, "an unknown option is named: " + err.strip())
rc, _, err = run("reconstruct", sphere, "--runs", "7")
expect(rc == 2 and "--runs" in err and "[1, 6]" in err, "an out-of-range option names its range: " + err.strip())

bunny = os.path.join(shared, "bunny", "bun_zipper.ply")
if os.path.exists(bunny):
    rc, out, err = run("info", bunny)
    expect(rc == 0 and "35947" in out, "reads the Stanford bunny PLY from ../shared")
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
expect(os.path.getsize(out_vti) > 0 and open(out_ply, "rb").read(3) == b"ply", "signed distance and PLY surface written")
expect(open(out_csv).readline().startswith("Run,Iteration,Energy"), "convergence CSV written")
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
rc, _, err = run("reconstruct", sphere, "--thin", "-1")
expect(rc == 2 and "--thin" in err, "a negative --thin is a usage error")
rc, _, err = run("reconstruct", sphere, "--outlier-sigma", "2")
expect(rc == 2 and "--remove-outliers" in err, "--outlier-sigma alone is a usage error")
rc, _, err = run("reconstruct", sphere, "--thin", "100", "--quiet")
expect(rc == 1 and "after cleaning" in err, "thinning to a handful of points is a clear error: " + err.strip())
rc, _, err = run("reconstruct", sphere, "--reference", sphere)
expect(rc == 1 and "unsupported reference mesh" in err, "a point file is not a reference mesh: " + err.strip())

rc, _, err = run("reconstruct", sphere, "--surface", os.path.join(tmp, "x.obj"))
expect(rc == 2 and ".vtp, .ply or .stl" in err, "an unsupported surface format is refused before computing")
rc, _, err = run("reconstruct", bad, "-o", os.path.join(tmp, "bad.vti"))
expect(rc == 1 and "point 17" in err and not os.path.exists(os.path.join(tmp, "bad.vti")),
       "NaN input: error, no output file")
rc, _, err = run("reconstruct", sphere, "--schedule", "1:0,2", "-o", os.path.join(tmp, "never.vti"))
expect(rc == 2 and "p:eta pairs" in err, "a malformed --schedule is a usage error: " + err.strip())
rc, _, err = run("reconstruct", sphere, "--schedule", "1:0,2:200")
expect(rc == 2 and "pair 2" in err, "an out-of-range --schedule pair is named: " + err.strip())
rc, _, err = run("reconstruct", sphere, "--schedule", "1:0,2:0,2:1", "--eta", "2")
expect(rc == 2 and "either --eta or --schedule" in err, "--eta with --schedule is a usage error")
sched_json = os.path.join(tmp, "schedule.json")
rc, _, err = run("reconstruct", sphere, "--runs", "2", "--interpolator", "q1", "--schedule", "1:0,2:0", "--quiet",
                 "--json", sched_json)
sched = json.load(open(sched_json)) if rc == 0 else {"runs": [{}, {}]}
expect(rc == 0 and sched["runs"][1].get("err_cloud", 1) < 0.01 and
       sched["runs"][1].get("energy") != summary["runs"][1]["energy"],
       "--schedule 1:0,2:0 runs and changes the result (%s)" % err.strip())
rc, _, err = run("reconstruct", sphere, "--interpolator", "rbf")
expect(rc == 2 and "q1, weno3, cweno or cwenoz" in err, "an unknown interpolator is a usage error")

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
partial = os.path.join(tmp, "never.vti")
rc, _, err = run("hjb", "--preset", "test9", "-o", partial)
expect(rc == 2 and "test1, test2" in err and not os.path.exists(partial), "an unknown preset is a usage error, no file")
rc, _, err = run("hjb", "--n", "3")
expect(rc == 2 and "--n" in err, "too few nodes is a usage error")
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
bad = os.path.join(tmp, "bad-formula.vti")
rc, _, err = run(*custom[:-2], "--final-time", "0.5", "--cost", "(a1^2 + a2^2/2", "-o", bad)
expect(rc == 1 and "running cost f_C" in err and "column" in err and not os.path.exists(bad),
       "a malformed formula names the formula and the column, no file: " + err.strip())
rc, _, err = run("hjb", "--fx", "y", "--v0", "x", "--nodes", "21,21", "--controls", "cone")
expect(rc == 2 and "none, box, ball or sphere" in err, "an unknown control set is a usage error")
rc, _, err = run("hjb", "--preset", "test1", "--cost", "1")
expect(rc == 2 and "--fx" in err, "custom options without --fx are a usage error")
rc, _, err = run("hjb", "--fx", "y", "--v0", "x", "--nodes", "21,abc")
expect(rc == 2 and "--nodes" in err, "a malformed number list is a usage error")
expect(not [f for f in os.listdir(tmp) if ".part" in f], "no temporary files are left behind")

sys.exit(1 if failures else 0)
