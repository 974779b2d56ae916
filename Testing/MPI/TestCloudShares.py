"""mpirun -np 2 pvbatch: a source that gives each rank its own share of a cloud
(the pieces in rank order are the cloud's points in order, no point in two, as a
partitioned reader gives) reconstructed with CloudPiecesAreShares: the plan runs
on the shares (vtkSLLevelSetReconstruct.h, Documentation/Distributed.md "The plan
on the shares") and the result is the one of the whole cloud on every rank: the
same image extent, the same surface (points, cells, bounds) and the same
DistanceToCloud at every vertex, for a 3D cloud, a planar one (2D) and one at survey
coordinates (reconstructed in its local frame). The whole cloud on every rank with CloudPiecesAreShares on
is refused with a message (every point would count twice), without a hang."""
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

plugin = sys.argv[1]
LoadPlugin(plugin, ns=globals())
ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
assert ranks == 2, "run me under mpirun -np 2 pvbatch (got %d ranks)" % ranks

SCRIPT = """
import math
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
info = self.GetOutputInformation(0)
piece, pieces = info.Get(sddp.UPDATE_PIECE_NUMBER()), info.Get(sddp.UPDATE_NUMBER_OF_PIECES())
if %(whole)s:
    piece, pieces = 0, 1
n = 2400  # an ellipsoid with a bump, points along a spiral (deterministic)
first, last = n * piece // pieces, n * (piece + 1) // pieces
points = vtkPoints()
points.SetDataTypeToDouble()
for k in range(first, last):
    z = 1.0 - 2.0 * (k + 0.5) / n
    r = math.sqrt(1.0 - z * z)  # |z| < 1
    t = k * math.pi * (3.0 - math.sqrt(5.0))
    s = 1.0 + 0.2 * math.exp(-8.0 * ((r * math.cos(t) - 0.6) ** 2 + z * z))
    if %(planar)s:  # a closed curve in the plane z = 0.5 (a 2D reconstruction)
        x, y, w = 1.5 * math.cos(2.0 * math.pi * k / n), math.sin(2.0 * math.pi * k / n), 0.5
        x, y = x * (1.0 + 0.2 * math.cos(3.0 * math.pi * 2.0 * k / n)), y
    else:
        x, y, w = 1.5 * s * r * math.cos(t) + 3.0, s * r * math.sin(t) - 1.0, 0.8 * s * z
    points.InsertNextPoint(x + %(offset)s, y + %(offset)s, w)
self.GetPolyDataOutput().SetPoints(points)
"""


def cloud(whole, planar=False, offset=0.0):
    source = ProgrammableSource(OutputDataSetType="vtkPolyData")
    source.Script = SCRIPT % {"whole": whole, "planar": planar, "offset": repr(offset)}
    return source


def largestDifference(a, b):
    """The largest |DistanceToCloud| difference between two surfaces of the same vertices (each rank's piece)."""
    both = AppendAttributes(Input=[a, b])  # the second input's array as DistanceToCloud_input_1
    diff = PythonCalculator(Input=both, ArrayName="Difference",
                            Expression="abs(inputs[0].PointData['DistanceToCloud'] - "
                                       "inputs[0].PointData['DistanceToCloud_input_1'])")
    diff.UpdatePipeline()
    info = diff.GetDataInformation().GetPointDataInformation().GetArrayInformation("Difference")
    return info.GetComponentRange(0)[1] if info else None


def compare(kind, planar=False, offset=0.0, runs=2):
    shares = cloud(False, planar, offset)
    shares.UpdatePipeline()
    assert shares.GetDataInformation().GetNumberOfPoints() == 2400, "%s: the shares make the cloud" % kind
    byShares = SemiLagrangianLevelSetReconstruction(Input=shares, NumberOfRuns=runs, CloudPiecesAreShares=1)
    byShares.UpdatePipeline()
    byWhole = SemiLagrangianLevelSetReconstruction(Input=cloud(True, planar, offset), NumberOfRuns=runs)
    byWhole.UpdatePipeline()
    for port in (0, 1):
        a, b = byShares.GetDataInformation(port), byWhole.GetDataInformation(port)
        assert a.GetNumberOfPoints() == b.GetNumberOfPoints() > 0, "%s, port %d: %d points, whole cloud %d" % (
            kind, port, a.GetNumberOfPoints(), b.GetNumberOfPoints())
        assert a.GetNumberOfCells() == b.GetNumberOfCells(), "%s, port %d: cells" % (kind, port)
        assert a.GetBounds() == b.GetBounds(), "%s, port %d: bounds %s, whole cloud %s" % (
            kind, port, a.GetBounds(), b.GetBounds())
    assert byShares.GetDataInformation().GetExtent() == byWhole.GetDataInformation().GetExtent(), kind
    # Every vertex's distance to the cloud, from the shares' owners, is the whole cloud's.
    vertices = byShares.GetDataInformation(1).GetNumberOfPoints()
    near = byShares.GetDataInformation(1).GetPointDataInformation().GetArrayInformation("DistanceToCloud")
    assert near and near.GetComponentRange(0)[1] > 0.0, "%s: DistanceToCloud" % kind
    largest = largestDifference(OutputPort(byShares, 1), OutputPort(byWhole, 1))
    assert largest == 0.0, "%s: DistanceToCloud differs from the whole cloud's by up to %s" % (kind, largest)
    print("cloud shares, %s: the whole cloud's result, %d surface points" % (kind, vertices))


compare("3D", runs=3)  # more vertices a rank than a round of distanceToShares asks (16,384 on 2 ranks)
compare("planar", planar=True)
compare("survey coordinates", offset=4.0e6)

# The whole cloud on every rank is not a set of shares: refused on both ranks, no output.
wrong = SemiLagrangianLevelSetReconstruction(Input=cloud(True), NumberOfRuns=2, CloudPiecesAreShares=1)
wrong.UpdatePipeline()
assert wrong.GetDataInformation(1).GetNumberOfPoints() == 0, "identical pieces taken as shares"
