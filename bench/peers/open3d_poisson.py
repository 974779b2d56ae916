#!/usr/bin/python3
"""The peer "Open3D Poisson": Open3D's screened Poisson (Kazhdan and Hoppe 2013, Open3D's copy of
PoissonRecon) on normals Open3D estimates and orients itself, with Open3D's documented defaults.

usage: /usr/bin/python3 open3d_poisson.py CLOUD.xyz OUT.ply [--depth 9] [--k 30] [--trim QUANTILE]

  normals  estimate_normals with KNN k = 30 (Open3D's default search parameter; a k-neighbourhood,
           not the tutorial's radius, because a radius depends on each cloud's scale)
  orient   orient_normals_consistent_tangent_plane(k), the same k (Hoppe's MST propagation)
  surface  create_from_point_cloud_poisson(depth = 9, as in Open3D's surface-reconstruction
           tutorial; Open3D's own default is 8), other parameters at Open3D's defaults
  trimming OFF by default: the tutorial's density trimming removes low-density vertices and so
           opens the surface; --trim 0.01 removes the vertices below that density quantile.
Prints one line of counts and timings; bench-only (see bench/peers/README.md).
"""
import argparse
import sys
import time

import numpy as np
import open3d as o3d


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("cloud")
    ap.add_argument("out")
    ap.add_argument("--depth", type=int, default=9)
    ap.add_argument("--k", type=int, default=30)
    ap.add_argument("--trim", type=float, default=0.0)
    a = ap.parse_args()

    # The shared clouds are "x y z" per line: read the first three columns ourselves so that extra
    # columns (given normals) never reach the tool; every tool gets the same unoriented points.
    xyz = np.loadtxt(a.cloud, usecols=(0, 1, 2), ndmin=2)
    pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(xyz))
    start = time.perf_counter()
    pcd.estimate_normals(o3d.geometry.KDTreeSearchParamKNN(knn=a.k))
    pcd.orient_normals_consistent_tangent_plane(a.k)
    normals_s = time.perf_counter() - start
    mesh, density = o3d.geometry.TriangleMesh.create_from_point_cloud_poisson(pcd, depth=a.depth)
    if a.trim > 0:
        density = np.asarray(density)
        mesh.remove_vertices_by_mask(density < np.quantile(density, a.trim))
    total_s = time.perf_counter() - start
    if not o3d.io.write_triangle_mesh(a.out, mesh, write_ascii=False, write_vertex_normals=False,
                                      write_vertex_colors=False):
        sys.exit(f"cannot write {a.out}")
    print(f"points {len(xyz)} k {a.k} depth {a.depth} trim {a.trim} normals_s {normals_s:.3f} "
          f"total_s {total_s:.3f} vertices {len(mesh.vertices)} faces {len(mesh.triangles)}")


if __name__ == "__main__":
    main()
