"""mpirun -np 2 pvbatch: vtkOctreeSDF on a sphere source that the pipeline splits over
the ranks (vtkSphereSource makes one piece per rank, so each rank holds part of the points). Each rank's hyper tree grid holds its
own leaves (Rank = its rank) and masks the other's; the parallel writer writes one piece
per rank; the ranks' leaves add up to the global leaf count, and every owned leaf's
DistanceToCloud is the distance from its centre to the whole sphere's points."""
import glob
import math
import os
import shutil
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager
from vtkmodules.vtkCommonDataModel import vtkHyperTreeGridNonOrientedGeometryCursor
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOXML import vtkXMLHyperTreeGridReader

plugin, outdir = sys.argv[1], sys.argv[2]
LoadPlugin(plugin, ns=globals())
ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
assert ranks == 2, "run me under mpirun -np 2 pvbatch (got %d ranks)" % ranks

sphere = Sphere(Radius=1.0, ThetaResolution=24, PhiResolution=24)
octree = OctreeSignedDistancefromPoints(Input=sphere, MinimumLevel=1, MaximumLevel=4, NumberOfThreads=1)
octree.UpdatePipeline()
global_leaves = octree.FieldData["GlobalLeaves"].GetRange()[0]
assert octree.CellData["Rank"].GetRange() == (-1.0, 1.0), octree.CellData["Rank"].GetRange()

target = os.path.join(outdir, "octree_ranks.phtg")
shutil.rmtree(os.path.join(outdir, "octree_ranks"), ignore_errors=True)
# Binary data mode: the default (appended) corrupts multi-array HTG pieces (Documentation/Toolchain.md).
SaveData(target, proxy=octree, DataMode="Binary")
pieces = sorted(glob.glob(os.path.join(outdir, "octree_ranks", "*.htg")))
assert len(pieces) == 2, "one piece per rank: %s" % pieces

source = vtkSphereSource()
source.SetRadius(1.0)
source.SetThetaResolution(24)
source.SetPhiResolution(24)
source.Update()
cloud = [source.GetOutput().GetPoint(i) for i in range(source.GetOutput().GetNumberOfPoints())]


def leaves(htg):
    """(owner, distance, centre) of every unmasked leaf, and the number of masked cells."""
    found, masked = [], 0
    rank, distance = htg.GetCellData().GetArray("Rank"), htg.GetCellData().GetArray("DistanceToCloud")
    cursor = vtkHyperTreeGridNonOrientedGeometryCursor()
    for tree in range(htg.GetMaxNumberOfTrees()):
        if htg.GetTree(tree) is None:
            continue
        htg.InitializeNonOrientedGeometryCursor(cursor, tree)
        stack = [()]
        while stack:
            path = stack.pop()
            cursor.ToRoot()
            for child in path:
                cursor.ToChild(child)
            if cursor.IsMasked():
                masked += 1
            elif cursor.IsLeaf():
                cell = cursor.GetGlobalNodeIndex()
                b = [0.0] * 6
                cursor.GetBounds(b)
                found.append((rank.GetValue(cell), distance.GetValue(cell), [0.5 * (b[2 * a] + b[2 * a + 1]) for a in range(3)]))
            else:
                stack.extend(path + (child,) for child in range(8))
    return found, masked


owned = 0
for piece in pieces:
    reader = vtkXMLHyperTreeGridReader()
    reader.SetFileName(piece)
    reader.Update()
    found, masked = leaves(reader.GetOutputDataObject(0))
    owners = {owner for owner, _, _ in found}
    assert len(owners) == 1 and -1 not in owners, "a piece's unmasked leaves belong to one rank: %s" % owners
    assert masked > 0, "the other rank's leaves are masked in %s" % piece
    worst = max(abs(d - min(math.dist(c, p) for p in cloud)) for _, d, c in found)
    assert worst < 1e-9, "DistanceToCloud is the distance to the whole cloud (error %g)" % worst
    owned += len(found)
assert owned == global_leaves, "the ranks' leaves add up to the forest: %d vs %d" % (owned, global_leaves)
print("octree ranks ok: %d leaves over %d ranks" % (owned, ranks))
