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


def run(*args):
    p = subprocess.run([sltk, *args], capture_output=True, text=True, timeout=300)
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

bad = os.path.join(tmp, "nan.xyz")
write_sphere(bad, 100, bad_line=17)
rc, _, err = run("info", bad)
expect(rc == 1 and "point 17" in err and "non-finite" in err, "NaN coordinates are named: " + err.strip())

rc, _, err = run("info", os.path.join(tmp, "missing.ply"))
expect(rc == 1 and "cannot open" in err, "a missing file is reported: " + err.strip())
rc, _, err = run("info", sphere, "--cdx", "zero")
expect(rc == 2 and "expects a number" in err, "a malformed option value is usage error 2")
rc, _, err = run("info", sphere, "--cdx", "1e-4")
expect(rc == 1 and "use C_dx >=" in err, "a grid beyond memory is refused with a C_dx: " + err.strip())
rc, _, err = run("frobnicate")
expect(rc == 2, "an unknown command is usage error 2")

bunny = os.path.join(shared, "bunny", "bun_zipper.ply")
if os.path.exists(bunny):
    rc, out, err = run("info", bunny)
    expect(rc == 0 and "35947" in out, "reads the Stanford bunny PLY from ../shared")
else:
    print("skip ../shared/data not present")

vti = os.path.join(tmp, "v0.vti")
rc, out, err = run("hjb", "--n", "41", "-o", vti, "--json", os.path.join(tmp, "hjb.json"))
expect(rc == 0 and os.path.getsize(vti) > 0, "hjb writes the value function")
hjb = json.load(open(os.path.join(tmp, "hjb.json")))
expect(abs(hjb["max"] - 0.15) < 1e-12 and hjb["min"] == 0.0, "hjb JSON has the range of v0")
partial = os.path.join(tmp, "never.vti")
rc, _, err = run("hjb", "--final-time", "1", "-o", partial)
expect(rc == 1 and not os.path.exists(partial), "a failed solve leaves no output file")
expect(not [f for f in os.listdir(tmp) if ".part" in f], "no temporary files are left behind")

sys.exit(1 if failures else 0)
