#!/usr/bin/python3
"""Synthetic models of known genus for the unseen-cloud benchmark.

usage: /usr/bin/python3 bench/unseen/make_models.py OUTDIR

VTK from Python: ParaView 5.11's VTK is the system one (/usr/lib/python3/dist-packages/vtkmodules).
`/usr/bin/python3` imports it directly (`import vtkmodules...`, `from paraview import vtk` works too);
`pvpython` runs this script as well. A pyenv `python3` first on PATH does NOT see it, hence the
explicit /usr/bin/python3.

Each model is a signed distance function sampled on a regular grid, contoured at 0
(vtkFlyingEdges3D) and cleaned. Written to OUTDIR: NAME.ply (the closed reference mesh), NAME.xyz
(the cloud: the mesh's vertices) and models.json (name, genus, parts, points, reference).
The *_cad models are decimated (vtkDecimatePro, topology kept): flat faces keep few, large
triangles, curved ones many small ones; their reference is the fine mesh. Their cloud is the
vertices of the decimated mesh after splitting its edges longer than a maximum edge length, as a
CAD exporter's "maximum edge length" setting does (vtkAdaptiveSubdivisionFilter), or, with no
maximum (part3_cad_vertices), the decimated vertices alone. The latter is beyond what any
reconstruction from points alone can decide: the largest empty disc on its flat faces (radius
0.34) is wider than the plate is half thick (0.3), so the points do not say whether the faces
are there (bench/unseen/README.md, "Sampling condition"). Every reference mesh is checked: no boundary or non-manifold edges,
the expected number of parts and V - E + F = 2 parts - 2 genus. For the *_cad models it also
prints the largest empty disc (the largest distance from a reference vertex to the cloud) on the
whole surface and on each thin part of SAMPLING, with its ratio to the part's local feature size.
bone_cad, chain_cad and animal_cad are the issue's thin handles and limbs sampled that way.
"""
import json
import os
import sys

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersCore import (vtkCleanPolyData, vtkDecimatePro, vtkFeatureEdges,
                                       vtkFlyingEdges3D, vtkPolyDataConnectivityFilter,
                                       vtkTriangleFilter)
from vtkmodules.vtkFiltersModeling import vtkAdaptiveSubdivisionFilter
from vtkmodules.vtkIOPLY import vtkPLYWriter


# Signed distance functions (negative inside) on arrays of coordinates.
def sphere(x, y, z, c=(0.0, 0.0, 0.0), r=1.0):
    return np.sqrt((x - c[0]) ** 2 + (y - c[1]) ** 2 + (z - c[2]) ** 2) - r


def torus(x, y, z, cx=0.0, R=1.0, r=0.35):
    return np.sqrt((np.sqrt((x - cx) ** 2 + y ** 2) - R) ** 2 + z ** 2) - r


def smooth_min(a, b, k):
    h = np.clip(0.5 + 0.5 * (b - a) / k, 0.0, 1.0)
    return b + (a - b) * h - k * h * (1.0 - h)


def double_torus(x, y, z):
    # two tori (R = 1, r = 0.35) side by side, overlapping at the origin, smoothly joined
    return smooth_min(torus(x, y, z, -1.0), torus(x, y, z, 1.0), 0.15)


def rounded_box(x, y, z, half=(2.0, 0.8, 0.3), rounding=0.1):
    qx, qy, qz = (np.abs(v) - (h - rounding) for v, h in zip((x, y, z), half))
    outside = np.sqrt(np.maximum(qx, 0) ** 2 + np.maximum(qy, 0) ** 2 + np.maximum(qz, 0) ** 2)
    return outside + np.minimum(np.maximum(qx, np.maximum(qy, qz)), 0.0) - rounding


def part3(x, y, z):
    # a 4 x 1.6 x 0.6 plate with rounded edges and 3 through-holes of radius 0.3 along z
    d = rounded_box(x, y, z)
    for cx in (-1.2, 0.0, 1.2):
        d = np.maximum(d, 0.3 - np.sqrt((x - cx) ** 2 + y ** 2))
    return d


def two_spheres(x, y, z):
    # radius 1, gap 0.3 between the surfaces
    return np.minimum(sphere(x, y, z, (-1.15, 0, 0)), sphere(x, y, z, (1.15, 0, 0)))


def capsule(x, y, z, a, b, r):
    """Distance to the segment a-b minus r: a limb of radius r."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    ab = b - a
    t = np.clip(((x - a[0]) * ab[0] + (y - a[1]) * ab[1] + (z - a[2]) * ab[2]) / ab.dot(ab), 0.0, 1.0)
    return np.sqrt((x - a[0] - t * ab[0]) ** 2 + (y - a[1] - t * ab[1]) ** 2 + (z - a[2] - t * ab[2]) ** 2) - r


# The animal's limbs, (end, end, radius) of each capsule: legs 0.04 thick and 0.7 long, two horns
# 0.03 thick (the animal below, and its parts in SAMPLING).
ANIMAL_LEGS = [((lx, -0.3, lz), (lx, -1.0, lz), 0.02) for lx in (-0.8, 0.8) for lz in (-0.25, 0.25)]
ANIMAL_HORNS = [((1.35, 0.2, 0.2 + hz), (1.6, 0.75, 0.2 + 2.5 * hz), 0.015) for hz in (-0.12, 0.12)]


def animal(x, y, z):
    # a four-legged body (an ellipsoid 2.4 x 1 x 1) with a head, legs 0.04 thick and 0.7
    # long, and two horns 0.03 thick: on the 0.02 grid (h_P about 0.01) 4 and 3 point
    # spacings, the thin limbs of issue "Real-world clouds"; genus 0
    body = (np.sqrt((x / 1.2) ** 2 + (y / 0.5) ** 2 + (z / 0.5) ** 2) - 1.0) * 0.5
    d = smooth_min(body, sphere(x, y, z, (1.3, 0.0, 0.2), 0.32), 0.1)
    for a, b, r in ANIMAL_LEGS:
        d = smooth_min(d, capsule(x, y, z, a, b, r), 0.03)
    for a, b, r in ANIMAL_HORNS:
        d = smooth_min(d, capsule(x, y, z, a, b, r), 0.02)
    return d


def ring(x, y, z, c, axis, R, r):
    """A torus of tube radius r around the circle of radius R about `axis` (0, 1 or 2) through c."""
    p = [x - c[0], y - c[1], z - c[2]]
    along = p.pop(axis)
    return np.sqrt((np.sqrt(p[0] ** 2 + p[1] ** 2) - R) ** 2 + along ** 2) - r


def arch(x, y, z, cx, r):
    """The bone's arch at x = cx, its tube radius r: half of a torus standing on the shaft."""
    return ring(x, y, z, (cx, 0.0, 0.42), 1, 0.3, r)


def bone(x, y, z, radii=(0.015, 0.02)):
    # a shaft with two knobs (genus 0) and two arches standing on it, 0.03 and 0.04 thick: on the
    # 0.02 grid (h_P about 0.01) 3 and 4 point spacings, the thin handles of issue "Real-world
    # clouds"; genus 2
    d = smooth_min(capsule(x, y, z, (-1.0, 0, 0), (1.0, 0, 0), 0.2),
                   np.minimum(sphere(x, y, z, (-1.1, 0, 0), 0.32), sphere(x, y, z, (1.1, 0, 0), 0.32)), 0.1)
    for cx, r in zip((-0.45, 0.45), radii):
        d = smooth_min(d, arch(x, y, z, cx, r), 0.02)
    return d


def bone_thin(x, y, z):
    # the bone with arches 0.02 and 0.03 thick: 2 and 3 point spacings of its cloud (spacing 0.01)
    return bone(x, y, z, (0.01, 0.015))


def chain(x, y, z):
    # three linked tori (R = 0.6, tube radius 0.06: 12 point spacings) 0.8 apart, each through
    # the next's hole, their tubes 0.28 apart where they pass: 3 parts of genus 1
    return np.minimum(np.minimum(ring(x, y, z, (0.0, 0, 0), 2, 0.6, 0.06), ring(x, y, z, (0.8, 0, 0), 1, 0.6, 0.06)),
                      ring(x, y, z, (1.6, 0, 0), 2, 0.6, 0.06))


def contour(f, lo, hi, h):
    """Zero level set of f sampled with spacing h on the box [lo, hi] (shifted by h/pi so that
    no node lies exactly on the surface)."""
    lo = np.asarray(lo, float) - h / np.pi
    n = np.ceil((np.asarray(hi, float) - lo) / h).astype(int) + 1
    axes = [lo[a] + h * np.arange(n[a]) for a in range(3)]
    z, y, x = np.meshgrid(axes[2], axes[1], axes[0], indexing="ij")  # x fastest, as VTK
    image = vtkImageData()
    image.SetDimensions(*n)
    image.SetOrigin(*lo)
    image.SetSpacing(h, h, h)
    image.GetPointData().SetScalars(numpy_support.numpy_to_vtk(f(x, y, z).ravel(), deep=True))
    fe = vtkFlyingEdges3D()
    fe.SetInputData(image)
    fe.SetValue(0, 0.0)
    fe.ComputeNormalsOff()
    fe.ComputeGradientsOff()
    clean = vtkCleanPolyData()
    clean.SetInputConnection(fe.GetOutputPort())
    tri = vtkTriangleFilter()  # also drops the lines/vertices clean may leave from degenerate cells
    tri.PassLinesOff()
    tri.PassVertsOff()
    tri.SetInputConnection(clean.GetOutputPort())
    tri.Update()
    return tri.GetOutput()


def cad_like(mesh, reduction, max_edge):
    """A CAD-like tessellation of mesh: decimated, then edges longer than max_edge split; or, with
    reduction "spacing", the mesh's vertices merged within max_edge (a cloud sampled at about
    that spacing from a finer reference)."""
    if reduction == "spacing":
        merge = vtkCleanPolyData()
        merge.SetInputData(mesh)
        merge.ToleranceIsAbsoluteOn()
        merge.SetAbsoluteTolerance(max_edge)
        merge.Update()
        return merge.GetOutput()
    coarse = decimate(mesh, reduction)
    if max_edge is None:
        return coarse
    split = vtkAdaptiveSubdivisionFilter()
    split.SetInputData(coarse)
    split.SetMaximumEdgeLength(max_edge)
    split.Update()
    return split.GetOutput()


def decimate(mesh, reduction):
    d = vtkDecimatePro()
    d.SetInputData(mesh)
    d.SetTargetReduction(reduction)
    d.PreserveTopologyOn()
    d.SplittingOff()
    d.BoundaryVertexDeletionOff()
    d.SetFeatureAngle(30)
    d.Update()
    return d.GetOutput()


def topology(mesh):
    """(parts, Euler characteristic, boundary edges, non-manifold edges) of a triangle mesh."""
    tris = numpy_support.vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    edges = np.sort(np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]]), axis=1)
    n_edges = len(np.unique(edges, axis=0))
    fe = vtkFeatureEdges()
    fe.SetInputData(mesh)
    fe.BoundaryEdgesOn()
    fe.NonManifoldEdgesOff()
    fe.FeatureEdgesOff()
    fe.ManifoldEdgesOff()
    fe.Update()
    boundary = fe.GetOutput().GetNumberOfLines()
    fe.BoundaryEdgesOff()
    fe.NonManifoldEdgesOn()
    fe.Update()
    nonmanifold = fe.GetOutput().GetNumberOfLines()
    conn = vtkPolyDataConnectivityFilter()
    conn.SetInputData(mesh)
    conn.SetExtractionModeToAllRegions()
    conn.Update()
    chi = mesh.GetNumberOfPoints() - n_edges + len(tris)
    return conn.GetNumberOfExtractedRegions(), chi, boundary, nonmanifold


# name: (function, box low, box high, grid spacing, genus, parts, CAD-like (decimation, maximum
# edge length or None) or None)
MODELS = {
    "sphere": (sphere, (-1.2,) * 3, (1.2,) * 3, 0.03, 0, 1, None),
    "torus": (torus, (-1.5, -1.5, -0.5), (1.5, 1.5, 0.5), 0.03, 1, 1, None),
    "double_torus": (double_torus, (-2.5, -1.5, -0.5), (2.5, 1.5, 0.5), 0.03, 2, 1, None),
    "part3": (part3, (-2.2, -1.0, -0.5), (2.2, 1.0, 0.5), 0.025, 3, 1, None),
    "two_spheres": (two_spheres, (-2.3, -1.2, -1.2), (2.3, 1.2, 1.2), 0.035, 0, 2, None),
    "animal": (animal, (-1.4, -1.1, -0.65), (1.8, 0.9, 0.65), 0.02, 0, 1, None),
    "bone": (bone, (-1.5, -0.4, -0.4), (1.5, 0.4, 0.8), 0.02, 2, 1, None),
    "bone_thin": (bone_thin, (-1.5, -0.4, -0.4), (1.5, 0.4, 0.8), 0.005, 2, 1, ("spacing", 0.01)),
    "chain": (chain, (-0.75, -0.75, -0.75), (2.35, 0.75, 0.75), 0.02, 3, 3, None),
    "torus_cad": (torus, (-1.5, -1.5, -0.5), (1.5, 1.5, 0.5), 0.01, 1, 1, (0.9, None)),
    "part3_cad": (part3, (-2.2, -1.0, -0.5), (2.2, 1.0, 0.5), 0.01, 3, 1, (0.95, 0.3)),
    "part3_cad_vertices": (part3, (-2.2, -1.0, -0.5), (2.2, 1.0, 0.5), 0.01, 3, 1, (0.95, None)),
    # the thin handles and limbs of issue "Real-world clouds", sampled non-uniformly: the arches and
    # limbs keep small triangles (curved), the shaft, body and knobs large ones (SAMPLING below)
    "bone_cad": (bone, (-1.5, -0.4, -0.4), (1.5, 0.4, 0.8), 0.005, 2, 1, (0.95, 0.05)),
    "chain_cad": (chain, (-0.75, -0.75, -0.75), (2.35, 0.75, 0.75), 0.01, 3, 3, (0.9, 0.05)),
    "animal_cad": (animal, (-1.4, -1.1, -0.65), (1.8, 0.9, 0.65), 0.0075, 0, 1, (0.9, 0.05)),
}


def limbs(capsules):
    """The signed distance to the union of `capsules` (ANIMAL_LEGS, ANIMAL_HORNS)."""
    return lambda x, y, z: np.minimum.reduce([capsule(x, y, z, a, b, r) for a, b, r in capsules])


# The sampling condition of the CAD-like clouds (bench/unseen/README.md, "Sampling condition"): per
# part, (label, the part's signed distance or None for the whole surface, its local feature size:
# the distance to the medial axis, the half-thickness of a plate, the radius of a tube). The
# reference vertices within 1.5 grid spacings of the part's zero level set are that part's.
SAMPLING = {
    "torus_cad": [("tube", None, 0.35)],
    "part3_cad": [("plate", None, 0.3)],
    "part3_cad_vertices": [("plate", None, 0.3)],
    "bone_cad": [("arch 0.03 thick", lambda x, y, z: arch(x, y, z, -0.45, 0.015), 0.015),
                 ("arch 0.04 thick", lambda x, y, z: arch(x, y, z, 0.45, 0.02), 0.02)],
    "chain_cad": [("tubes", None, 0.06)],
    "animal_cad": [("legs", limbs(ANIMAL_LEGS), 0.02), ("horns", limbs(ANIMAL_HORNS), 0.015)],
}


def largest_empty_discs(mesh, cloud, h, parts):
    """Per part, the largest distance from a reference vertex of that part to the cloud, and its
    ratio to the part's local feature size (epsilon-sampling asks about 0.5 at most)."""
    from scipy.spatial import cKDTree
    ref = numpy_support.vtk_to_numpy(mesh.GetPoints().GetData()).astype(float)
    pts = numpy_support.vtk_to_numpy(cloud.GetPoints().GetData()).astype(float)
    dist, _ = cKDTree(pts).query(ref)
    out = [("whole surface", dist.max(), None)]
    for label, f, size in parts:
        on = np.ones(len(ref), bool) if f is None else np.abs(f(*ref.T)) < 1.5 * h
        out.append((label, dist[on].max(), size))
    return out


def main(out):
    os.makedirs(out, exist_ok=True)
    listing, ok = [], True
    for name, (f, lo, hi, h, genus, parts, cad) in MODELS.items():
        mesh = contour(f, lo, hi, h)
        cloud = cad_like(mesh, *cad) if cad else mesh
        writer = vtkPLYWriter()
        writer.SetFileName(os.path.join(out, name + ".ply"))
        writer.SetInputData(mesh)
        writer.SetFileTypeToBinary()
        writer.Write()
        pts = numpy_support.vtk_to_numpy(cloud.GetPoints().GetData())
        np.savetxt(os.path.join(out, name + ".xyz"), pts, fmt="%.7g")
        got_parts, chi, boundary, nonmanifold = topology(mesh)
        good = (boundary == 0 and nonmanifold == 0 and got_parts == parts
                and chi == 2 * parts - 2 * genus and 5000 <= len(pts) <= 40000)
        ok &= good
        print(f"{name:18s} points {len(pts):6d}  reference: {mesh.GetNumberOfPoints():7d} vertices, "
              f"{got_parts} part(s), chi {chi:3d}, boundary edges {boundary}, non-manifold "
              f"{nonmanifold}  {'ok' if good else 'WRONG (expected genus %d, %d parts)' % (genus, parts)}")
        listing.append({"name": name, "genus": genus, "parts": parts, "points": len(pts),
                        "reference_vertices": mesh.GetNumberOfPoints(), "cad": bool(cad)})
        if name in SAMPLING:
            print("    largest empty disc: " + ", ".join(
                f"{label} {disc:.4f}" + (f" = {disc / size:.2f} x {size:g}" if size else "")
                for label, disc, size in largest_empty_discs(mesh, cloud, h, SAMPLING[name])))
    with open(os.path.join(out, "models.json"), "w") as fp:
        json.dump(listing, fp, indent=2)
    return 0 if ok else 1


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
