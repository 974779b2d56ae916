"""mpirun -np 2 pvbatch: each rank computes its own image block of the HJB
solver; the parallel writer writes one piece per rank. Checks the pieces
are distinct, each non-empty, together cover the whole extent, and carry the
exact initial datum."""
import math
import os
import sys
import xml.etree.ElementTree as ET

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

plugin, outdir = sys.argv[1], sys.argv[2]
LoadPlugin(plugin, ns=globals())
ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
assert ranks == 2, "run me under mpirun -np 2 pvbatch (got %d ranks)" % ranks

N = 33
solver = CWENOHamiltonJacobiBellmanSolver(NumberOfNodes=N, FinalTime=0.0)
target = os.path.join(outdir, "rank_extents.pvti")
writer = XMLPImageDataWriter(Input=solver, FileName=target)
writer.UpdatePipeline()

root = ET.parse(target).getroot()
pieces = root.findall("./PImageData/Piece")
assert len(pieces) == 2, "expected one piece per rank, got %d" % len(pieces)
extents = [tuple(int(v) for v in p.get("Extent").split()) for p in pieces]
assert extents[0] != extents[1], extents
covered = set()
for e in extents:
    block = {(i, j) for i in range(e[0], e[1] + 1) for j in range(e[2], e[3] + 1)}
    assert 0 < len(block) < N * N, "each rank holds a proper part of the grid: %s" % (e,)
    covered |= block
assert covered == {(i, j) for i in range(N) for j in range(N)}, "pieces do not cover the whole extent"

# Each piece file holds the exact initial datum on its own block.
from vtkmodules.vtkIOXML import vtkXMLImageDataReader
for p in pieces:
    reader = vtkXMLImageDataReader()
    reader.SetFileName(os.path.join(outdir, p.get("Source")))
    reader.Update()
    image = reader.GetOutput()
    values = image.GetPointData().GetArray("ValueFunction")
    worst = 0.0
    for n in range(image.GetNumberOfPoints()):
        x = image.GetPoint(n)
        r = math.hypot(x[0] - 0.3, x[1] - 0.7) / 0.15
        s = r - 1.0
        exact = 0.15 * (1.0 + r**3 * (-1.0 + 3.0 * s * (1.0 - 2.0 * s))) if r < 1.0 else 0.0
        worst = max(worst, abs(values.GetValue(n) - exact))
    assert worst < 1e-14, worst
print("rank extents:", extents, "ok")
