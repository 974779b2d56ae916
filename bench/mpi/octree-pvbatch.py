"""The octree filter in ParaView as a user runs it, on a cloud it was not tuned on:
`mpirun -np N pvbatch bench/mpi/octree-pvbatch.py PLUGIN CLOUD.xyz [PROPERTY=VALUE ...]`.
The .xyz is read with ParaView's own readers (CSV reader, Table To Points), which give
the points to rank 0 only: the filter takes the union of the ranks' pieces. Defaults
unless properties are given (e.g. MaximumLevel=9). Prints the wall time of the update,
the leaves (over every rank, and the most on one), and the gathered surface's points,
pieces, boundary edges and Euler characteristic (genus = 1 - chi / 2 for a closed one).
"""
import sys
import time

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager
from vtkmodules.vtkFiltersCore import vtkCleanPolyData, vtkFeatureEdges, vtkPolyDataConnectivityFilter
from vtkmodules.vtkCommonDataModel import vtkPolyData

plugin, cloud = sys.argv[1], sys.argv[2]
LoadPlugin(plugin, ns=globals())
properties = {}
for assignment in sys.argv[3:]:
    name, value = assignment.split("=", 1)
    properties[name] = float(value) if "." in value else int(value)
table = CSVReader(FileName=[cloud], HaveHeaders=0, FieldDelimiterCharacters=" ", MergeConsecutiveDelimiters=1)
points = TableToPoints(Input=table, XColumn="Field 0", YColumn="Field 1", ZColumn="Field 2")
octree = OctreeSignedDistancefromPoints(Input=points, **properties)
start = time.time()
octree.UpdatePipeline()
seconds = time.time() - start
history = servermanager.Fetch(octree, idx=2)
last = history.GetNumberOfRows() - 1
runs = history.GetColumnByName("Run")
per_run = {}
for row in range(history.GetNumberOfRows()):
    per_run[int(runs.GetValue(row))] = per_run.get(int(runs.GetValue(row)), 0) + 1
surface = servermanager.Fetch(octree, idx=1)
clean = vtkCleanPolyData()
clean.SetInputData(surface)
clean.Update()
merged = clean.GetOutput()
edges = vtkFeatureEdges()
edges.SetInputData(merged)
edges.BoundaryEdgesOn()
edges.NonManifoldEdgesOn()
edges.FeatureEdgesOff()
edges.ManifoldEdgesOff()
edges.Update()
pieces = vtkPolyDataConnectivityFilter()
pieces.SetInputData(merged)
pieces.SetExtractionModeToAllRegions()
pieces.Update()
edge_set = set()
for c in range(merged.GetNumberOfCells()):
    ids = merged.GetCell(c).GetPointIds()
    n = ids.GetNumberOfIds()
    for k in range(n):
        a, b = ids.GetId(k), ids.GetId((k + 1) % n)
        edge_set.add((min(a, b), max(a, b)))
chi = merged.GetNumberOfPoints() - len(edge_set) + merged.GetNumberOfCells()
print("%s: %d ranks, %.1f s, iterations %s, leaves %d (most on a rank %d, uniform %d), Err_P %.3g" % (
    cloud, servermanager.ActiveConnection.GetNumberOfDataPartitions(), seconds,
    "/".join(str(per_run[r]) for r in sorted(per_run)), history.GetColumnByName("Leaves").GetValue(last),
    history.GetColumnByName("LargestRankLeaves").GetValue(last), history.GetColumnByName("UniformNodes").GetValue(last),
    history.GetColumnByName("CloudError").GetValue(last)))
print("surface: %d points, %d triangles, %d piece(s), %d open edges, Euler characteristic %d" % (
    merged.GetNumberOfPoints(), merged.GetNumberOfCells(), pieces.GetNumberOfExtractedRegions(),
    edges.GetOutput().GetNumberOfCells(), chi))
