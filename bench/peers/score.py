#!/usr/bin/python3
"""Score one reconstructed surface against the true mesh: the one scorer of bench/peers, used for
every tool's output (SLTK's too), so that the tools are compared by the same numbers.

usage: /usr/bin/python3 score.py SURFACE REFERENCE [--samples N] [--seed S] [--json OUT.json]

Distances use the definition of `sltk reconstruct --reference` (Apps/sltk/SurfaceDistance.cxx):
both meshes are triangulated (vtkTriangleFilter); for every VERTEX of one mesh the exact distance
to the nearest TRIANGLE of the other (vtkStaticCellLocator::FindClosestPoint), both ways;
  Chamfer   = (mean over surface vertices + mean over reference vertices) / 2
  Hausdorff = the larger of the two maxima.
No sampling, so the numbers are deterministic and equal to what sltk's --reference prints.
--samples N adds an area-weighted variant (N uniform random points on each surface, fixed seed,
the same mean/max rule) that does not depend on how each tool spaces its vertices.

Topology of SURFACE, after merging exactly coincident points and dropping degenerate triangles:
pieces (triangles connected through shared vertices), Euler characteristic V - E + F, boundary
edges (one triangle) and non-manifold edges (three or more), closed = neither, and the genus
(2 pieces - chi) / 2, summed over the pieces, for closed surfaces only.
Prints one JSON object (and writes it to --json).
"""
import argparse
import json
import sys

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import reference, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkGenericCell, vtkPolyData, vtkStaticCellLocator
from vtkmodules.vtkFiltersCore import vtkTriangleFilter
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader
from vtkmodules.vtkIOLegacy import vtkPolyDataReader
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

READERS = {"ply": vtkPLYReader, "obj": vtkOBJReader, "stl": vtkSTLReader, "vtp": vtkXMLPolyDataReader,
           "vtk": vtkPolyDataReader}


def read_off(path):
    """OFF, the format of some ground-truth meshes (VTK 9.2 has no reader for it)."""
    tokens = open(path).read().split()
    if not tokens or tokens[0] != "OFF":
        sys.exit(f"{path} is not an OFF file")
    nv, nf = int(tokens[1]), int(tokens[2])
    at = 4
    points = vtkPoints()
    for i in range(nv):
        points.InsertNextPoint(*map(float, tokens[at:at + 3]))
        at += 3
    polys = vtkCellArray()
    for _ in range(nf):
        n = int(tokens[at])
        polys.InsertNextCell(n, [int(t) for t in tokens[at + 1:at + 1 + n]])
        at += 1 + n
    mesh = vtkPolyData()
    mesh.SetPoints(points)
    mesh.SetPolys(polys)
    return mesh


def read_triangles(path):
    """The mesh as sltk's readMesh sees it: read, then vtkTriangleFilter."""
    ext = path.rsplit(".", 1)[-1].lower()
    if ext == "off":
        mesh = read_off(path)
    elif ext in READERS:
        reader = READERS[ext]()
        reader.SetFileName(path)
        reader.Update()
        mesh = reader.GetOutput()
    else:
        sys.exit(f"unsupported mesh format: {path}")
    tri = vtkTriangleFilter()
    tri.SetInputData(mesh)
    tri.Update()
    out = tri.GetOutput()
    if out.GetNumberOfPolys() == 0:
        sys.exit(f"{path} has no triangles")
    return out


def arrays(mesh):
    """(points n x 3 float64, triangles m x 3 int64) of a triangulated vtkPolyData."""
    points = vtk_to_numpy(mesh.GetPoints().GetData()).astype(np.float64)
    conn = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).astype(np.int64)
    return points, conn.reshape(-1, 3)


def distances_to(queries, mesh):
    """Exact distance from each query point to the nearest triangle of mesh, the way
    SurfaceDistance.cxx's oneWay does it (same locator, same call)."""
    locator = vtkStaticCellLocator()
    locator.SetDataSet(mesh)
    locator.BuildLocator()
    cell, cell_id, sub_id, d2 = vtkGenericCell(), reference(0), reference(0), reference(0.0)
    closest = [0.0, 0.0, 0.0]
    out = np.empty(len(queries))
    for i, x in enumerate(queries.tolist()):
        locator.FindClosestPoint(x, closest, cell, cell_id, sub_id, d2)
        out[i] = float(d2)
    return np.sqrt(out)


def area_samples(points, triangles, n, rng):
    """n points uniformly distributed by area on the triangles."""
    a, b, c = (points[triangles[:, i]] for i in range(3))
    area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
    pick = rng.choice(len(triangles), size=n, p=area / area.sum())
    u, v = rng.random(n), rng.random(n)
    flip = u + v > 1  # fold the unit square onto the triangle
    u[flip], v[flip] = 1 - u[flip], 1 - v[flip]
    return a[pick] + u[:, None] * (b[pick] - a[pick]) + v[:, None] * (c[pick] - a[pick])


def two_way(to_ref, from_ref):
    return {"chamfer": 0.5 * (to_ref.mean() + from_ref.mean()), "hausdorff": max(to_ref.max(), from_ref.max()),
            "mean_to_reference": to_ref.mean(), "mean_from_reference": from_ref.mean()}


def topology(points, triangles):
    # Merge exactly coincident points: some writers duplicate vertices along seams, and a seam
    # must not count as a boundary or split a piece.
    _, merged = np.unique(points, axis=0, return_inverse=True)
    t = merged.reshape(-1)[triangles]
    degenerate = (t[:, 0] == t[:, 1]) | (t[:, 1] == t[:, 2]) | (t[:, 0] == t[:, 2])
    t = t[~degenerate]
    used = np.unique(t)
    edges = np.sort(np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]), axis=1)
    unique_edges, uses = np.unique(edges, axis=0, return_counts=True)
    n = int(merged.max()) + 1
    graph = coo_matrix((np.ones(len(unique_edges)), (unique_edges[:, 0], unique_edges[:, 1])), shape=(n, n))
    _, label = connected_components(graph, directed=False)
    pieces = len(np.unique(label[used]))
    chi = len(used) - len(unique_edges) + len(t)
    boundary, nonmanifold = int((uses == 1).sum()), int((uses > 2).sum())
    closed = boundary == 0 and nonmanifold == 0
    return {"vertices": int(len(used)), "triangles": int(len(t)), "degenerate_triangles": int(degenerate.sum()),
            "pieces": int(pieces), "euler_characteristic": int(chi), "boundary_edges": boundary,
            "nonmanifold_edges": nonmanifold, "closed": closed,
            "genus": (2 * pieces - chi) / 2 if closed else None}


def score(surface, ref_path, samples=0, seed=1):
    mesh = read_triangles(surface)
    points, triangles = arrays(mesh)
    result = {"surface": surface, "reference": ref_path}
    result.update(topology(points, triangles))
    if ref_path:
        ref = read_triangles(ref_path)
        ref_points, ref_triangles = arrays(ref)
        result.update(two_way(distances_to(points, ref), distances_to(ref_points, mesh)))
        if samples > 0:
            rng = np.random.default_rng(seed)
            on_surface = area_samples(points, triangles, samples, rng)
            on_ref = area_samples(ref_points, ref_triangles, samples, rng)
            sampled = two_way(distances_to(on_surface, ref), distances_to(on_ref, mesh))
            result.update({"sampled_" + k: v for k, v in sampled.items()})
            result["samples"], result["seed"] = samples, seed
    return {k: float(v) if isinstance(v, np.floating) else v for k, v in result.items()}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("surface")
    ap.add_argument("reference", nargs="?", default="")
    ap.add_argument("--samples", type=int, default=0)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--json")
    a = ap.parse_args()
    result = score(a.surface, a.reference, a.samples, a.seed)
    text = json.dumps(result, indent=2)
    if a.json:
        with open(a.json, "w") as fp:
            fp.write(text + "\n")
    print(text)


if __name__ == "__main__":
    main()
