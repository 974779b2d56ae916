"""`mpirun -np 2 sltk reconstruct` reads the cloud in parallel
(Apps/sltk/ReadCloudShares.h, Documentation/Distributed.md "Reading the cloud"):
each rank parses its share of a text cloud (byte ranges cut at line ends) or of a
binary PLY of points (vertex records) and keeps it; the plan's cloud steps run on
the shares (vtkSLLevelSetReconstruct CloudPiecesAreShares) and only the cleaned cloud
is gathered. The surface is then the one of the same points read whole (a .vtp, which
every rank reads through VTK), for a text file with CRLF ends, a header, comments,
blank lines and no final newline, and for a binary PLY (a file repeating itself, whose shares are
the same points, is gathered instead); --json says points_total,
points_read_max (about half on two ranks), read_traffic (no point moved by the read),
plan_traffic (the plan's on the shares, the cleaned cloud's gather included) and each run's traffic, points_held_max (every point: the cleaned cloud, here the whole one,
is gathered for the runs) and run_points_held_max (the most a rank's
runs read: the points reconstructed on one rank, at most that on two). A bad line in rank 1's share ends both
ranks with the one-rank message.
Run by pvpython (VTK writes the .vtp): TestCloudReadRanks.py SLTK MPIEXEC OUTDIR"""
import json
import math
import os
import struct
import subprocess
import sys

from vtkmodules.vtkCommonCore import vtkPoints, VTK_DOUBLE
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

sltk, mpiexec, outdir = sys.argv[1:4]
os.makedirs(outdir, exist_ok=True)
MPI = [mpiexec, "--allow-run-as-root", "--oversubscribe"]
# pvpython started MPI as a singleton: its OMPI_*/PMIX_* variables would make mpirun's children join it.
CLEAN_ENV = {k: v for k, v in os.environ.items() if not k.startswith(("OMPI_", "PMIX_"))}
failures = []


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


def path(name):
    return os.path.join(outdir, "read_ranks_" + name)


def reconstruct(ranks, cloud, tag):
    surface, summary = path(tag + ".ply"), path(tag + ".json")
    for f in (surface, summary):
        if os.path.exists(f):
            os.remove(f)
    r = subprocess.run(MPI + ["-n", str(ranks), sltk, "reconstruct", cloud, "--quiet", "--threads", "1", "--runs", "1",
                              "--surface", surface, "--json", summary], capture_output=True, text=True,
                       timeout=120, env=CLEAN_ENV)
    check(r.returncode == 0, "%s on %d rank(s): exit 0 (%s)" % (tag, ranks, r.stderr.strip()[-300:]))
    data = open(surface, "rb").read() if os.path.exists(surface) else b""
    return data, (json.load(open(summary)) if os.path.exists(summary) else {})


def write_vtp(name, points):
    p = vtkPoints()
    p.SetDataType(VTK_DOUBLE)
    for x in points:
        p.InsertNextPoint(*x)
    cloud = vtkPolyData()
    cloud.SetPoints(p)
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(cloud)
    writer.SetFileName(path(name))
    check(writer.Write() == 1, "wrote " + name)
    return path(name)


# An ellipsoid, 3000 points on a Fibonacci spiral, with 17 significant digits.
N = 3000
points = []
for i in range(N):
    z = 1.0 - (2.0 * i + 1.0) / N
    r, a = math.sqrt(1.0 - z * z), i * math.pi * (3.0 - math.sqrt(5.0))
    points.append((1.5 * r * math.cos(a), r * math.sin(a), 0.8 * z))

# Text: a header, comments and blank lines among CRLF lines, commas, and no newline after the last point.
lines = ["x,y,z", "# an ellipsoid", ""]
for i, x in enumerate(points):
    lines.append(("%.17g,%.17g,%.17g" if i % 2 else "%.17g %.17g %.17g 0 0 1") % x)
    if i % 500 == 7:
        lines += ["", "// a comment"]
text = path("cloud.xyz")
with open(text, "wb") as f:
    f.write("\r\n".join(lines).encode())
# Binary PLY of the points alone (big endian, double x and z, float y): the serial reader keeps double
# coordinates in double (Apps/sltk/ReadVtkFile.h), y is the file's float.
ply = path("cloud.ply")
with open(ply, "wb") as f:
    f.write(b"ply\nformat binary_big_endian 1.0\nelement vertex %d\nproperty double x\nproperty float y\n"
            b"property double z\nend_header\n" % N)
    for x in points:
        f.write(struct.pack(">dfd", *x))
mixed = [(x, struct.unpack("<f", struct.pack("<f", y))[0], z) for x, y, z in points]

for cloud, whole in ((text, write_vtp("cloud.vtp", points)), (ply, write_vtp("mixed.vtp", mixed))):
    kind = os.path.basename(cloud)
    split, summary = reconstruct(2, cloud, kind + ".2")
    reference, whole_summary = reconstruct(2, whole, kind + ".whole.2")
    one, one_summary = reconstruct(1, cloud, kind + ".1")
    check(split != b"" and split == reference,
          "%s on 2 ranks: the surface of the same points read whole (%d bytes)" % (kind, len(split)))
    check(len(one) > 0 and len(split) > 0, "%s on 1 rank: a surface" % kind)
    check(summary.get("points_total") == N and summary.get("points_held_max") == N,
          "%s: points_total %s and points_held_max %s are the cloud's %d" % (
              kind, summary.get("points_total"), summary.get("points_held_max"), N))
    kept = one_summary.get("points_reconstructed", -1)
    check(one_summary.get("run_points_held_max") == kept and 0 < summary.get("run_points_held_max", 0) <= kept,
          "%s: run_points_held_max %s on 1 rank is the %d points reconstructed, %s on 2 ranks at most that" % (
              kind, one_summary.get("run_points_held_max"), kept, summary.get("run_points_held_max")))
    check(N // 2 - 60 <= summary.get("points_read_max", 0) <= N // 2 + 60,
          "%s: points_read_max %s is about half the cloud" % (kind, summary.get("points_read_max")))
    check(whole_summary.get("points_read_max") == N, "the .vtp is read whole by every rank (points_read_max %s)" %
          whole_summary.get("points_read_max"))
    # The traffic per phase: the read's agreements only (the shares stay where they were read); every run
    # exchanges ghost rows; the runs' busiest ranks together sent at least what the whole
    # reconstruction's busiest rank sent.
    read = summary.get("read_traffic", {})
    check(0 < read.get("collective_bytes_max", 0) < 24 * N // 8 and read.get("bytes_sent_max") == 0,
          "%s: the read moves no points, each rank keeps its share (%s)" % (kind, read))
    # The plan's traffic apart: it gathers the cleaned cloud (each rank's owned points, about half, reach
    # the other rank: 24 bytes a point), after the points' moves to their owners; none on one rank.
    plan = summary.get("plan_traffic", {})
    check("points_reconstructed" in summary and
          plan.get("collective_bytes_max", 0) >= 24 * (summary.get("points_reconstructed", 0) // 2) and
          plan.get("collectives_max", 0) > 0,
          "%s: the plan's traffic on 2 ranks carries the gather of the cleaned cloud (%s)" % (kind, plan))
    check(one_summary.get("plan_traffic") == {"bytes_sent_max": 0, "collective_bytes_max": 0, "collectives_max": 0},
          "%s on 1 rank: no plan traffic (%s)" % (kind, one_summary.get("plan_traffic")))
    runs = summary.get("runs", [])
    check(len(runs) > 0 and all(r.get("bytes_sent_max", 0) > 0 and r.get("collectives_max", 0) > 0 for r in runs),
          "%s: every run's traffic on 2 ranks (%s)" % (kind, [(r.get("bytes_sent_max"), r.get("collectives_max"))
                                                          for r in runs]))
    check(sum(r.get("bytes_sent_max", 0) for r in runs) >= summary.get("bytes_sent_max", -1) > 0,
          "%s: the runs' point-to-point bytes make up the reconstruction's (%s)" % (
              kind, summary.get("bytes_sent_max")))
    check("read_traffic" in one_summary and "bytes_sent_max" not in one_summary["runs"][0],
          "%s on 1 rank: no traffic per run" % kind)

# A file that repeats itself (the cloud twice), split at the repeat: the two shares are the same points,
# which the filter would take for the whole cloud on every rank; they are gathered instead, so the
# ranks give the one-rank verdict (every point has a duplicate: refused, with its message).
twice = path("twice.xyz")
with open(twice, "w") as f:
    for x in points[:1500] * 2:
        f.write("%.17g %.17g %.17g\n" % x)
verdicts = [subprocess.run(MPI + ["-n", str(n), sltk, "reconstruct", twice, "--quiet", "--runs", "1"],
                           capture_output=True, text=True, timeout=120, env=CLEAN_ENV) for n in (1, 2)]
said = [[line.replace("rank 0 of 2: ", "") for line in r.stderr.splitlines() if line.startswith("sltk")]
        for r in verdicts]
check(verdicts[1].returncode == verdicts[0].returncode and said[1] == said[0] and said[0],
      "a cloud repeated in two identical shares: the one-rank verdict on 2 ranks (%s)" % said[1])

# A bad line past the middle of the file (rank 1's share): both ranks stop with the one-rank message.
bad = path("bad.xyz")
with open(bad, "w") as f:
    for i, x in enumerate(points[:200]):
        f.write("%.9g %.9g %.9g\n" % x if i != 170 else "1 2 3abc\n")
results = [subprocess.run(MPI + ["-n", str(n), sltk, "reconstruct", bad, "--quiet"], capture_output=True, text=True,
                          timeout=120, env=CLEAN_ENV) for n in (1, 2)]
expected = "%s:171: '3abc' is not a number" % bad
check(results[0].returncode != 0 and expected in results[0].stderr, "1 rank: %s" % results[0].stderr.strip())
said = [[line for line in r.stderr.splitlines() if line.startswith("sltk")] for r in results]  # not mpirun's
check(results[1].returncode == results[0].returncode and said[1] == said[0],
      "2 ranks: the one-rank message and exit code (%s)" % said[1])

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
