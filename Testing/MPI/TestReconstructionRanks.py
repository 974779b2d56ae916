"""mpirun -np 2 pvbatch: a cloud that the pipeline splits over the ranks (a
piece-aware source, as a partitioned reader would give) is reconstructed from
the whole cloud on every rank, each rank computing its slab of the grid: the
image is split into one block per rank, each rank contours its block, and the
pieces join into one closed surface (ParaView's parallel Connectivity finds
one region), with the whole convergence history; one execution serves the
three ports; a filter that needs a ghost level (Gradient) gets one flagged
row of the neighbour's. With OctreeStorage the ranks share the tiles out
(the uniform grids' iterations: as many history rows), each rank contours
its own tiles (one closed surface across the pieces) and rank 0 outputs the
whole hyper tree grid."""
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

plugin = sys.argv[1]
LoadPlugin(plugin, ns=globals())
ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
assert ranks == 2, "run me under mpirun -np 2 pvbatch (got %d ranks)" % ranks

cloud = Sphere(Radius=1.0, ThetaResolution=40, PhiResolution=40)
ids = ProcessIdScalars(Input=cloud)
ids.UpdatePipeline()
owners = ids.PointData["ProcessId"].GetRange()
assert owners == (0.0, 1.0), "the cloud should be split over both ranks: %s" % (owners,)

recon = SemiLagrangianLevelSetReconstruction(Input=cloud, NumberOfRuns=2)
executions = []
recon.GetClientSideObject().AddObserver("StartEvent", lambda *args: executions.append(1))  # rank 0's filter
recon.UpdatePipeline()
blocks = ProcessIdScalars(Input=recon)
blocks.UpdatePipeline()
assert blocks.PointData["ProcessId"].GetRange() == (0.0, 1.0), "each rank holds a block of the image"
whole = recon.GetDataInformation().GetExtent()
mine = recon.GetClientSideObject().GetOutputDataObject(0).GetExtent()
assert mine[5] < whole[5], "rank 0's block %s is not the whole extent %s" % (mine, whole)

surface = OutputPort(recon, 1)
bounds = recon.GetDataInformation(1).GetBounds()
assert all(abs(abs(b) - 1.0) < 0.05 for b in bounds), "the surface spans the whole sphere: %s" % (bounds,)
regions = Connectivity(Input=surface)
regions.UpdatePipeline()
region_ids = regions.CellData["RegionId"].GetRange()
assert region_ids == (0.0, 0.0), "one surface across the ranks' pieces, not one per rank: %s" % (region_ids,)
pieces = ProcessIdScalars(Input=surface)
pieces.UpdatePipeline()
assert pieces.PointData["ProcessId"].GetRange() == (0.0, 1.0), "each rank contours its block"
history = servermanager.Fetch(recon, idx=2)
assert history.GetNumberOfRows() >= 2, "the convergence history"
# Port 1 is asked with a ghost level under MPI; one execution must serve all three ports.
assert len(executions) == 1, "the reconstruction ran %d times for one set of outputs" % len(executions)
mine = recon.GetClientSideObject().GetOutputDataObject(0)
assert mine.GetPointData().GetArray("vtkGhostType") is None, "no ghost level was asked of the image"
block = mine.GetExtent()
# A filter that needs a ghost level gets one: rank 0's block and the first row
# of rank 1's, flagged (the reconstruction runs again for it).
gradient = Gradient(Input=recon)
gradient.UpdatePipeline()
mine = recon.GetClientSideObject().GetOutputDataObject(0)
assert mine.GetPointData().GetArray("vtkGhostType") is not None, "the image's ghost row is flagged"
assert mine.GetExtent() == block[:5] + (block[5] + 1,), \
    "rank 0's block %s grew by one row of rank 1's: %s" % (block, mine.GetExtent())
assert len(executions) == 2, "one more run for the ghost level (%d runs)" % len(executions)
print("split cloud reconstructed on 2 slabs: bounds %s, one region" % (bounds,))

# OctreeStorage: the tiles of run 2 shared out over the ranks; each outputs its own trees.
tiled = SemiLagrangianLevelSetReconstruction(Input=cloud, NumberOfRuns=2, OctreeStorage=1)
tiled.UpdatePipeline()
single = servermanager.Fetch(recon, idx=2)
tiled_history = servermanager.Fetch(tiled, idx=2)
assert tiled_history.GetNumberOfRows() == single.GetNumberOfRows(), \
    "the same iterations as the uniform grids (%d, %d)" % (tiled_history.GetNumberOfRows(), single.GetNumberOfRows())
tree = tiled.GetDataInformation(0)
assert tree.GetNumberOfCells() > 0, "the hyper tree grid has leaves"
tiled_regions = Connectivity(Input=OutputPort(tiled, 1))
tiled_regions.UpdatePipeline()
assert tiled_regions.CellData["RegionId"].GetRange() == (0.0, 0.0), "one closed surface from the shared tiles"
tiled_bounds = tiled.GetDataInformation(1).GetBounds()
assert all(abs(a - b) < 1e-6 for a, b in zip(tiled_bounds, bounds)), \
    "the tiled surface spans the uniform one: %s, %s" % (tiled_bounds, bounds)
print("OctreeStorage on 2 ranks: %d rows of history, %d leaves, one region" %
      (tiled_history.GetNumberOfRows(), tree.GetNumberOfCells()))
