"""mpirun -np 2 pvbatch --symmetric: vtkSLLevelSetReconstruct asked for ghost
levels (UpdatePiece with ghost levels, as a VTK application or a filter that
needs them asks) gives each rank its block plus that many rows of the
neighbour's on each inner side, flagged in vtkGhostType (DUPLICATEPOINT and
DUPLICATECELL beyond the block), holding the one-rank values; the surface is
contoured without them (the same piece at every ghost level)
(Documentation/Distributed.md). Each rank runs the threads of the one thread
rule (sltk::threadsPerRank): by default the cores this process may use shared
by the ranks on its machine, at most VTK_SMP_MAX_THREADS; on a 2-core node,
one a rank."""
import os

from vtkmodules.vtkCommonDataModel import vtkDataSetAttributes
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkParallelCore import vtkDummyController, vtkMultiProcessController

import sltk

controller = vtkMultiProcessController.GetGlobalController()
rank, ranks = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
assert ranks == 2, "run me under mpirun -np 2 pvbatch --symmetric (got %d ranks)" % ranks

cloud = vtkSphereSource()
cloud.SetThetaResolution(40)
cloud.SetPhiResolution(40)
cloud.Update()


threads_used = []


def reconstruct(ghost_levels, controller=None):
    recon = sltk.vtkSLLevelSetReconstruct()
    recon.SetInputData(cloud.GetOutput())
    recon.SetNumberOfRuns(2)
    if controller is not None:
        recon.SetController(controller)
        recon.Update()
    else:
        recon.UpdatePiece(rank, ranks, ghost_levels)
        threads_used.append(recon.GetThreadsUsed())
    return recon.GetOutputDataObject(0), recon.GetOutputDataObject(1)


block, piece = reconstruct(0)
local_ranks = int(os.environ.get("OMPI_COMM_WORLD_LOCAL_SIZE", ranks))
expected = max(1, len(os.sched_getaffinity(0)) // local_ranks)
cap = int(os.environ.get("VTK_SMP_MAX_THREADS", "0") or 0)
expected = min(expected, cap) if cap > 0 else expected
assert threads_used == [expected], "rank %d runs %s thread(s), not %d" % (rank, threads_used, expected)
assert block.GetPointData().GetArray(vtkDataSetAttributes.GhostArrayName()) is None, "no ghost level asked, none given"
whole, _ = reconstruct(0, vtkDummyController())  # the one-rank image, on every rank
levels = 2
ghosted, ghosted_piece = reconstruct(levels)
low, high = block.GetExtent()[4:6]
glow, ghigh = ghosted.GetExtent()[4:6]
inner_low, inner_high = low > whole.GetExtent()[4], high < whole.GetExtent()[5]
assert (glow, ghigh) == (low - levels * inner_low, high + levels * inner_high), \
    "rank %d: block %s, with %d ghost levels %s" % (rank, (low, high), levels, (glow, ghigh))
ghosts = ghosted.GetPointData().GetArray(vtkDataSetAttributes.GhostArrayName())
cell_ghosts = ghosted.GetCellData().GetArray(vtkDataSetAttributes.GhostArrayName())
assert ghosts is not None and cell_ghosts is not None, "ghost rows are flagged in vtkGhostType"
nx, ny = ghosted.GetDimensions()[0:2]
phi, reference = ghosted.GetPointData().GetArray("SignedDistance"), whole.GetPointData().GetArray("SignedDistance")
wnx, wny = whole.GetDimensions()[0:2]
worst = 0.0
for k in range(glow, ghigh + 1):
    flagged = ghosts.GetValue((k - glow) * nx * ny) & vtkDataSetAttributes.DUPLICATEPOINT
    assert bool(flagged) == (k < low or k > high), "rank %d row %d: flagged %s" % (rank, k, flagged)
    for j in range(0, ny, 7):
        for i in range(0, nx, 7):
            mine = phi.GetValue((k - glow) * nx * ny + j * nx + i)
            worst = max(worst, abs(mine - reference.GetValue(k * wnx * wny + j * wnx + i)))
dx = whole.GetSpacing()[0]
assert worst < 1e-12 * dx, "rank %d: ghost rows and block differ from one rank by %g dx" % (rank, worst / dx)
first_cell_layer = cell_ghosts.GetValue(0) & vtkDataSetAttributes.DUPLICATECELL
assert bool(first_cell_layer) == inner_low, "rank %d: the cells of the lower ghost rows are flagged" % rank
assert (ghosted_piece.GetNumberOfPoints(), ghosted_piece.GetNumberOfCells()) == \
    (piece.GetNumberOfPoints(), piece.GetNumberOfCells()), "rank %d: the surface leaves the ghost rows out" % rank
print("rank %d: block rows %d..%d, with %d ghost levels %d..%d, within %.1e dx of one rank"
      % (rank, low, high, levels, glow, ghigh, worst / dx))
