"""mpirun -np 2 pvbatch: a cloud that the pipeline splits over the ranks (a
piece-aware source, as a partitioned reader would give) is reconstructed whole.
The filter asks its input for the whole cloud on every rank and piece 0
reconstructs: one closed surface through the whole unit sphere, not one blob
per rank."""
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager
from vtkmodules.vtkFiltersCore import vtkPolyDataConnectivityFilter

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
surface = servermanager.Fetch(recon, idx=1)
bounds = surface.GetBounds()
assert all(abs(abs(b) - 1.0) < 0.05 for b in bounds), "the surface spans the whole sphere: %s" % (bounds,)
pieces = vtkPolyDataConnectivityFilter()
pieces.SetInputData(surface)
pieces.SetExtractionModeToAllRegions()
pieces.Update()
assert pieces.GetNumberOfExtractedRegions() == 1, "one surface, not one per rank: %d" % \
    pieces.GetNumberOfExtractedRegions()
history = servermanager.Fetch(recon, idx=2)
assert history.GetNumberOfRows() >= 2, "the convergence history comes from rank 0"
image = servermanager.Fetch(recon)
assert image.GetFieldData().GetArray("CloudSpacing") is not None
# Port 1 is asked with a ghost level under MPI; one execution must serve all three ports.
assert len(executions) == 1, "the reconstruction ran %d times for one set of outputs" % len(executions)
print("split cloud reconstructed whole by piece 0: bounds %s" % (bounds,))
