"""The wrapped SLTK filters import and run in plain VTK Python (ParaView's VTK)."""
import sys

from vtkmodules.vtkCommonCore import vtkLogger

import sltk

vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)

solver = sltk.vtkCWENOHJBSolver()
solver.SetNumberOfNodes(31)
solver.SetFinalTime(0.0)
solver.Update()
image = solver.GetOutput()
assert image.GetDimensions() == (31, 31, 1), image.GetDimensions()
lo, hi = image.GetPointData().GetArray("ValueFunction").GetRange()
assert lo == 0.0 and abs(hi - 0.15) < 0.01, (lo, hi)
from vtkmodules.vtkParallelCore import vtkDummyController
solver.SetController(vtkDummyController())  # Python may choose the ranks a custom problem is split over
assert solver.GetController() is not None

recon = sltk.vtkSLLevelSetReconstruct()
recon.SetInterpolator(sltk.vtkSLLevelSetReconstruct.CWENOZ)
assert recon.GetInterpolator() == 3
assert recon.GetCellSizeFactor() == 0.0 and recon.GetOutsideThresholdFactor() == 0.0, "automatic by default"
from vtkmodules.vtkCommonCore import vtkCommand, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
points = vtkPoints()
for k in range(200):
    points.InsertNextPoint(k % 7, (k // 7) % 5, k // 35)
cloud = vtkPolyData()
cloud.SetPoints(points)
errors = []
recon.AddObserver(vtkCommand.ErrorEvent, lambda caller, event: errors.append(event))
recon.SetInputData(cloud)
recon.SetCellSizeFactor(1e9)
assert recon.GetCellSizeFactor() == 1e9, "kept as given, not clamped"
recon.Update()
assert errors, "an out-of-range CellSizeFactor is refused when the filter runs"
for name, bad in (("NumberOfRuns", 100), ("Padding", 1), ("ThinningFactor", -1.0), ("NumberOfThreads", 100000)):
    recon.SetCellSizeFactor(0.0)
    getattr(recon, "Set" + name)(bad)
    assert getattr(recon, "Get" + name)() == bad, name + " is kept as given, not clamped"
    del errors[:]
    recon.Update()
    assert errors, name + " out of range is refused when the filter runs"
    getattr(recon, "Set" + name)({"NumberOfRuns": 3, "Padding": 10, "ThinningFactor": 0.0, "NumberOfThreads": 0}[name])
assert "NumberOfRuns: 3" in str(recon)

hjb_errors = []
solver.AddObserver(vtkCommand.ErrorEvent, lambda caller, event: hjb_errors.append(event))
for name, bad, good in (("NumberOfNodes", 3, 31), ("CourantNumber", -1.0, 0.0), ("TabulationPoints", 0, 33),
                        ("NumberOfThreads", 100000, 0), ("Preset", 9, 1), ("FinalTime", 1e9, 0.0)):
    getattr(solver, "Set" + name)(bad)
    assert getattr(solver, "Get" + name)() == bad, name + " is kept as given, not clamped"
    del hjb_errors[:]
    solver.Update()  # a refused property (or 1e9 / dt steps) is an error, not a clamp, a crash or hours of work
    assert hjb_errors, name + " out of range is refused when the HJB filter runs"
    getattr(solver, "Set" + name)(good)
del hjb_errors[:]
solver.Update()
assert not hjb_errors and solver.GetOutput().GetDimensions() == (31, 31, 1), "back in range, the filter runs"

octree = sltk.vtkOctreeSDF()
assert octree.GetOctreeStorage() and octree.IsA("vtkSLLevelSetReconstruct"), "the octree filter always stores the octree"
octree.SetAdaptiveStorage(0)  # the deprecated name still forwards, for one release
assert not octree.GetOctreeStorage() and not octree.GetAdaptiveStorage(), "SetAdaptiveStorage forwards to OctreeStorage"
octree.OctreeStorageOn()
assert octree.GetOutput().IsA("vtkHyperTreeGrid") and octree.GetOutput(2).IsA("vtkTable"), "GetOutput() is the octree, GetOutput(port) any port"
print("python wrapping ok")
sys.exit(0)
