"""Survey coordinates (Core/include/sltk/cloud/LocalFrame.h): a cloud far from the origin gives the
surface of the same cloud near the origin, moved, in every front end and output.

The cloud's coordinates are multiples of 2^-29, so that the shift (1e7, 1e7, 2.5e5) is exact in
double: the two reconstructions see the same local cloud, and the outputs may differ only by the
precision of their files. Usage: TestSurveyCoordinates.py SLTK_EXE (with the sltk Python module on
PYTHONPATH)."""
import json
import math
import os
import re
import struct
import shutil
import subprocess
import sys
import tempfile

from vtkmodules.vtkCommonCore import vtkLogger, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLHyperTreeGridReader

import sltk as sltk_filters

vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
sltk = sys.argv[1]
tmp = tempfile.mkdtemp(prefix="sltk-survey-")
failures = []
SHIFT = (1e7, 1e7, 2.5e5)
EXTENT = 2.4  # the ellipsoid's largest extent
TOLERANCE = 1e-6 * EXTENT  # the bound on the deviation


def expect(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures.append(what)


def ellipsoid(n=1500):
    """Golden-angle points on an ellipsoid with semi-axes 1.2, 1.0, 0.7, as multiples of 2^-29."""
    q = 2.0 ** 29
    points = []
    for k in range(n):
        z = -1 + 2 * (k + 0.5) / n
        r = math.sqrt(1 - z * z)
        p = (1.2 * r * math.cos(2.4 * k), r * math.sin(2.4 * k), 0.7 * z)
        points.append(tuple(round(v * q) / q for v in p))
    return points


def moved(points, by):
    return [tuple(p[a] + by[a] for a in range(3)) for p in points]


def write_xyz(path, points):
    with open(path, "w") as f:
        for p in points:
            f.write("%r %r %r\n" % p)


def read_ply_vertices(path):
    """The vertices of a binary little-endian PLY whose vertex element is x, y, z (float or double)."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    first = next(k for k, line in enumerate(header) if line.startswith("element vertex"))
    count = int(header[first].split()[2])
    properties = [line.split()[1] for line in header[first + 1:] if line.startswith("property")]
    properties = properties[:next((k for k, line in enumerate(header[first + 1:]) if line.startswith("element")),
                                  len(properties))]
    fmt = "<" + "".join({"double": "d", "float": "f"}[kind] for kind in properties)
    size = struct.calcsize(fmt)
    return properties[0], [struct.unpack_from(fmt, data, end + i * size)[:3] for i in range(count)]


def largest_deviation(near, far, by):
    return max(max(abs(f[a] - n[a] - by[a]) for a in range(3)) for n, f in zip(near, far))


def vti_origin(path):
    with open(path, "rb") as f:
        head = f.read(4096).decode(errors="replace")
    start = head.index('Origin="') + len('Origin="')
    return [float(v) for v in head[start:head.index('"', start)].split()]


# The CLI: the same surface moved, in a double PLY; the same image moved; the same summary.
near, far = ellipsoid(), None
far = moved(near, SHIFT)
outputs = {}
for name, points in (("near", near), ("far", far)):
    cloud = os.path.join(tmp, name + ".xyz")
    write_xyz(cloud, points)
    files = {k: os.path.join(tmp, name + "." + k) for k in ("vti", "ply", "json")}
    p = subprocess.run([sltk, "reconstruct", cloud, "--runs", "2", "--interpolator", "q1", "--quiet", "-o",
                        files["vti"], "--surface", files["ply"], "--json", files["json"]],
                       capture_output=True, text=True, timeout=300)
    expect(p.returncode == 0, "sltk reconstruct of the %s cloud exits 0 (%s)" % (name, p.stderr.strip()))
    outputs[name] = files
near_json, far_json = (json.load(open(outputs[k]["json"])) for k in ("near", "far"))
for key in ("surface_points", "surface_pieces", "euler_characteristic", "cdx", "kp"):
    expect(near_json[key] == far_json[key], "%s the same far from the origin (%s, %s)" %
           (key, near_json[key], far_json[key]))
near_kind, near_vertices = read_ply_vertices(outputs["near"]["ply"])
far_kind, far_vertices = read_ply_vertices(outputs["far"]["ply"])
expect(far_kind == "double", "the far surface's PLY has double vertices (it has %s)" % far_kind)
expect(len(near_vertices) == len(far_vertices) == near_json["surface_points"], "the PLYs hold every vertex")
deviation = largest_deviation(near_vertices, far_vertices, SHIFT)
expect(deviation <= TOLERANCE, "the far PLY is the near one moved, to %g (%g)" % (TOLERANCE, deviation))
origin_near, origin_far = vti_origin(outputs["near"]["vti"]), vti_origin(outputs["far"]["vti"])
expect(all(abs(origin_far[a] - origin_near[a] - SHIFT[a]) <= TOLERANCE for a in range(3)),
       "the image's origin is moved by the shift (%s, %s)" % (origin_near, origin_far))

# The CLI with --octree: the same surface moved and the octree's grid moved (its .htg coordinates).
octree = {}
for name in ("near", "far"):
    files = {k: os.path.join(tmp, name + "-octree." + k) for k in ("htg", "ply", "json")}
    p = subprocess.run([sltk, "reconstruct", os.path.join(tmp, name + ".xyz"), "--octree", "--runs", "2",
                        "--interpolator", "q1", "--quiet", "-o", files["htg"], "--surface", files["ply"], "--json",
                        files["json"]], capture_output=True, text=True, timeout=300)
    expect(p.returncode == 0, "sltk reconstruct --octree of the %s cloud exits 0 (%s)" % (name, p.stderr.strip()))
    octree[name] = files
near_json, far_json = (json.load(open(octree[k]["json"])) for k in ("near", "far"))
for key in ("surface_points", "surface_pieces", "euler_characteristic"):
    expect(near_json[key] == far_json[key], "--octree: %s the same far from the origin (%s, %s)" %
           (key, near_json[key], far_json[key]))
near_kind, near_vertices = read_ply_vertices(octree["near"]["ply"])
far_kind, far_vertices = read_ply_vertices(octree["far"]["ply"])
expect(far_kind == "double" and len(near_vertices) == len(far_vertices) == near_json["surface_points"],
       "--octree: the far PLY holds every vertex in double (%s, %d)" % (far_kind, len(far_vertices)))
deviation = largest_deviation(near_vertices, far_vertices, SHIFT)
expect(deviation <= TOLERANCE, "--octree: the far PLY is the near one moved, to %g (%g)" % (TOLERANCE, deviation))
def htg_coordinates(path):
    reader = vtkXMLHyperTreeGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    return [getattr(grid, get)() for get in ("GetXCoordinates", "GetYCoordinates", "GetZCoordinates")]


for axis, (a, b) in enumerate(zip(htg_coordinates(octree["near"]["htg"]), htg_coordinates(octree["far"]["htg"]))):
    expect(a.GetNumberOfTuples() == b.GetNumberOfTuples() > 0 and
           all(abs(b.GetTuple1(i) - a.GetTuple1(i) - SHIFT[axis]) <= TOLERANCE for i in range(a.GetNumberOfTuples())),
           "--octree: the .htg's %s coordinates moved" % "xyz"[axis])

# Where a result that does not fit misses its cloud (MissedPlaces.h) is said in the user's coordinates with
# their detail: a needle beside the ellipsoid, thinner than run 1's cells of C_dx = 4, is missed, and the
# far cloud's statement names the near one's places moved by the shift (not the local frame's, not 1e+07).
PLACE = re.compile(r"(\d+) point\(s\) \(of the \d+ there\) around \(([^)]*)\) from \(([^)]*)\) to \(([^)]*)\)")
needle = [(round((1.2 + 1.5 * (k + 1) / 200) * 2 ** 29) / 2 ** 29, 0.0, 0.0) for k in range(200)]
places = {}
for name, points in (("near", near + needle), ("far", moved(near + needle, SHIFT))):
    cloud = os.path.join(tmp, name + "-needle.xyz")
    write_xyz(cloud, points)
    summary = os.path.join(tmp, name + "-needle.json")
    p = subprocess.run([sltk, "reconstruct", cloud, "--cdx", "4", "--runs", "1", "--quiet", "--json", summary],
                       capture_output=True, text=True, timeout=300)
    statement = next((line for line in p.stderr.splitlines() if "does not fit the cloud" in line), "")
    places[name] = [[int(m.group(1))] + [[float(v) for v in m.group(g).split(",")] for g in (2, 3, 4)]
                    for m in PLACE.finditer(statement)]
    expect(p.returncode == 3 and places[name], "the %s needle is missed, exit 3, with its places (%d: %s)" %
           (name, p.returncode, statement or p.stderr.strip()))
    # --json's missed_places are the statement's, in full precision.
    listed = json.load(open(summary)).get("missed_places", []) if os.path.exists(summary) else []
    expect(len(listed) == len(places[name]) and
           all(j["points"] == t[0] and all(abs(j[key][k] - t[g][k]) <= 1e-5 * max(1.0, abs(t[g][k]))
                                           for g, key in ((1, "centre"), (2, "lower"), (3, "upper")) for k in range(3))
               for j, t in zip(listed, places[name])),
           "--json's missed_places of the %s needle are the statement's (%s, %s)" % (name, listed, places[name]))
    places[name + " json"] = listed
near_places, far_places = places["near"], places["far"]
NEEDLE_EXTENT = 2.7 + 1.2  # the cloud's largest extent, x from -1.2 to 2.7
expect(len(near_places) == len(far_places) and
       all(a[0] == b[0] and all(abs(q[k] - p[k] - SHIFT[k]) <= 1e-4 * NEEDLE_EXTENT for p, q in zip(a[1:], b[1:])
                                for k in range(3)) for a, b in zip(near_places, far_places)),
       "the far needle's places are the near one's moved, to 1e-4 of the extent (%s, %s)" % (near_places, far_places))
expect(len(places["near json"]) == len(places["far json"]) > 0 and
       all(a["points"] == b["points"] and a["nearby"] == b["nearby"] and
           all(abs(b[key][k] - a[key][k] - SHIFT[k]) <= TOLERANCE for key in ("centre", "lower", "upper")
               for k in range(3)) for a, b in zip(places["near json"], places["far json"])),
       "--json: the far needle's missed_places are the near one's moved, to %g" % TOLERANCE)

# STL holds 32-bit floats: refused before any work, with the formats that hold the surface.
p = subprocess.run([sltk, "reconstruct", os.path.join(tmp, "far.xyz"), "--surface", os.path.join(tmp, "far.stl")],
                   capture_output=True, text=True, timeout=60)
expect(p.returncode == 2 and "STL stores 32-bit floats" in p.stderr and ".vtp or .ply" in p.stderr,
       "an STL surface far from the origin is refused with exit 2 and the fix (%d: %s)" % (p.returncode, p.stderr))
expect(not os.path.exists(os.path.join(tmp, "far.stl")), "no STL file is left")

# A PLY that stores double is read in double (vtkPLYReader stores float, which resolves 1 at 1e7):
# the far surface is the reference of the same reconstruction at Chamfer 0, and as a cloud it has
# the near surface's spacing h_P.
ref_json = os.path.join(tmp, "reference.json")
p = subprocess.run([sltk, "reconstruct", os.path.join(tmp, "far.xyz"), "--runs", "2", "--interpolator", "q1",
                    "--quiet", "--reference", outputs["far"]["ply"], "--json", ref_json],
                   capture_output=True, text=True, timeout=300)
chamfer = json.load(open(ref_json))["chamfer"] if p.returncode == 0 else None
expect(chamfer is not None and chamfer <= TOLERANCE,
       "a double PLY reference far from the origin is read in double (Chamfer %s, %s)" % (chamfer, p.stderr.strip()))


def spacing(cloud):
    p = subprocess.run([sltk, "info", cloud], capture_output=True, text=True, timeout=120)
    line = next((l for l in p.stdout.splitlines() if l.startswith("h_P")), None)
    return float(line.split()[1]) if p.returncode == 0 and line else None


near_h, far_h = spacing(outputs["near"]["ply"]), spacing(outputs["far"]["ply"])
expect(near_h is not None and far_h is not None and abs(far_h - near_h) <= 1e-6 * near_h,
       "a double PLY cloud far from the origin is read in double (h_P %s near, %s far)" % (near_h, far_h))

# An OBJ cloud is text: read in double (VTK's OBJ reader keeps double points), the same h_P moved.
for name, points in (("near", near), ("far", far)):
    with open(os.path.join(tmp, name + ".obj"), "w") as f:
        for p in points:
            f.write("v %r %r %r\n" % p)
near_h, far_h = spacing(os.path.join(tmp, "near.obj")), spacing(os.path.join(tmp, "far.obj"))
expect(near_h is not None and far_h is not None and abs(far_h - near_h) <= 1e-6 * near_h,
       "an OBJ cloud far from the origin is read in double (h_P %s near, %s far)" % (near_h, far_h))


def point_set(points):
    vtk_points = vtkPoints()
    vtk_points.SetDataTypeToDouble()
    for p in points:
        vtk_points.InsertNextPoint(p)
    data = vtkPolyData()
    data.SetPoints(vtk_points)
    return data


def reconstruct(filter_class, points):
    f = filter_class()
    f.SetNumberOfRuns(2)
    f.SetInterpolator(sltk_filters.vtkSLLevelSetReconstruct.Q1)
    f.SetInputData(point_set(points))
    f.Update()
    return f.GetOutputDataObject(0), f.GetOutputDataObject(1)


def surface_points(surface):
    return [surface.GetPoint(i) for i in range(surface.GetNumberOfPoints())]


def triangles(surface):
    legacy = surface.GetPolys().GetData()  # built on each call: once
    ids = [int(legacy.GetValue(k)) for k in range(legacy.GetNumberOfValues())]
    found, k = [], 0
    while k < len(ids):  # the legacy layout: n, then n point ids
        found.append(tuple(ids[k + 1:k + 1 + ids[k]]))
        k += 1 + ids[k]
    return found


def pieces_and_euler(surface):
    """The connected pieces of the surface's triangles and its Euler characteristic V - E + F."""
    cells = triangles(surface)
    parent = list(range(surface.GetNumberOfPoints()))

    def root(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    edges = set()
    for cell in cells:
        for a, b in zip(cell, cell[1:] + cell[:1]):
            edges.add((min(a, b), max(a, b)))
            parent[root(a)] = root(b)
    used = {i for cell in cells for i in cell}
    return len({root(i) for i in used}), len(used) - len(edges) + len(cells)


def same_surface(name, near_surface, far_surface):
    """The issue's acceptance: the same points moved, the same triangles, pieces and Euler characteristic."""
    expect(far_surface.GetNumberOfPoints() == near_surface.GetNumberOfPoints() > 0,
           "%s: the same surface points far from the origin" % name)
    deviation = largest_deviation(surface_points(near_surface), surface_points(far_surface), SHIFT)
    expect(deviation <= TOLERANCE, "%s: the surface moved, to %g (%g)" % (name, TOLERANCE, deviation))
    expect(triangles(near_surface) == triangles(far_surface), "%s: the same triangles" % name)
    near_topology, far_topology = pieces_and_euler(near_surface), pieces_and_euler(far_surface)
    expect(near_topology == far_topology == (1, 2), "%s: one piece of Euler characteristic 2 near and far (%s, %s)" %
           (name, near_topology, far_topology))


# The filters: the image (or the octree's grid) and the surface moved, the surface in double.
near_image, near_surface = reconstruct(sltk_filters.vtkSLLevelSetReconstruct, near)
far_image, far_surface = reconstruct(sltk_filters.vtkSLLevelSetReconstruct, far)
same_surface("vtkSLLevelSetReconstruct", near_surface, far_surface)
expect(far_surface.GetPoints().GetDataType() == 11, "vtkSLLevelSetReconstruct: the far surface's points are doubles")
expect(all(abs(far_image.GetOrigin()[a] - near_image.GetOrigin()[a] - SHIFT[a]) <= TOLERANCE for a in range(3)),
       "vtkSLLevelSetReconstruct: the image's origin moved")

near_grid, near_surface = reconstruct(sltk_filters.vtkOctreeSDF, near)
far_grid, far_surface = reconstruct(sltk_filters.vtkOctreeSDF, far)
same_surface("vtkOctreeSDF", near_surface, far_surface)
expect(far_grid.GetNumberOfCells() == near_grid.GetNumberOfCells() > 0, "vtkOctreeSDF: the same cells")
for axis, get in enumerate(("GetXCoordinates", "GetYCoordinates", "GetZCoordinates")):
    a, b = getattr(near_grid, get)(), getattr(far_grid, get)()
    expect(a.GetNumberOfTuples() == b.GetNumberOfTuples() and
           all(abs(b.GetTuple1(i) - a.GetTuple1(i) - SHIFT[axis]) <= TOLERANCE for i in range(a.GetNumberOfTuples())),
           "vtkOctreeSDF: the grid's %s moved" % get[3])

if failures:
    sys.exit("%d failure(s); the files: %s" % (len(failures), tmp))
shutil.rmtree(tmp, ignore_errors=True)
