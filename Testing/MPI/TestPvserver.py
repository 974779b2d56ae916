"""The ParaView client against `mpirun -np 2 pvserver` (Documentation/Distributed.md):
a pvpython client starts a 2-rank pvserver on a free port, connects, loads the
plugin on the server, solves the thesis's Test 4 as formulas and gets the
partitioned result: two partitions, each rank's piece (1722 points = 2 x 41 x 21,
the pieces share a row), the whole extent, Ranks = 2, the serial solve's errors
(file of MPI.DistributedHjb.Serial) and, fetched, rank 0's piece bitwise the
serial values. A formula that is not finite on one rank's slab fails the
update on both ranks and leaves the server answering. A reconstruction on the
same server is split into one block per rank whose surface pieces join into
one region (ParaView's parallel Connectivity).
Run by pvpython: TestPvserver.py PLUGIN MPIEXEC OUTDIR"""
import os
import socket
import subprocess
import sys
import time

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.vtkIOXML import vtkXMLImageDataReader

plugin, mpiexec, outdir = sys.argv[1:4]
with socket.socket() as s:  # a free port (another test may hold the default 11111)
    s.bind(("localhost", 0))
    port = s.getsockname()[1]
# pvpython started MPI as a singleton: its OMPI_*/PMIX_* variables would make mpirun's children join it.
env = {k: v for k, v in os.environ.items() if not k.startswith(("OMPI_", "PMIX_"))}
server = subprocess.Popen(["timeout", "110", mpiexec, "--allow-run-as-root", "--oversubscribe", "-n", "2", "pvserver",
                           "--server-port=%d" % port, "--force-offscreen-rendering"],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
TEST4 = dict(Preset="Custom (formulas below)", DynamicsX="-a1", DynamicsY="-a2", RunningCost="(a1^2+a2^2)/2",
             InitialValue="max(1-x^2-y^2,0)", ExactSolution="x^2+y^2 <= 1 ? (sqrt(x^2+y^2)-1)^2/(2*t) : 0",
             Dimensions=[41, 41, 1], DomainBounds=[-2, 2, -2, 2, -1, 1], ControlSet="Ball",
             ControlDimension=2, ControlRadius=2.2, RKOrder=1, CourantNumber=1.25, FinalTime=0.5,
             NumberOfThreads=1)
try:
    for attempt in range(100):
        try:
            Connect("localhost", port)
            break
        except Exception:  # noqa: BLE001 - the server is not listening yet
            assert server.poll() is None, "pvserver ended: " + server.stdout.read()
            time.sleep(0.3)
    partitions = servermanager.ActiveConnection.GetNumberOfDataPartitions()
    assert partitions == 2, "connected to %d partitions, expected 2" % partitions
    LoadPlugin(plugin, remote=True, ns=globals())

    solver = CWENOHamiltonJacobiBellmanSolver(**TEST4)
    solver.UpdatePipeline()
    info = solver.GetDataInformation()
    assert info.GetNumberOfPoints() == 2 * 41 * 21, "one piece per rank: %d points" % info.GetNumberOfPoints()
    assert tuple(info.GetExtent()) == (0, 40, 0, 40, 0, 0), info.GetExtent()
    assert solver.FieldData["Ranks"].GetRange() == (2.0, 2.0), "the solve was split over both server ranks"

    reader = vtkXMLImageDataReader()
    reader.SetFileName(os.path.join(outdir, "distributed_hjb_serial.vti"))
    reader.Update()
    serial = reader.GetOutput()
    for name, tolerance in (("L1Error", 1e-13), ("LinfError", 0.0)):
        got, want = solver.FieldData[name].GetRange()[0], serial.GetFieldData().GetArray(name).GetValue(0)
        assert abs(got - want) <= tolerance * want, "%s: %r, serial %r" % (name, got, want)
    piece = servermanager.Fetch(solver)  # rank 0's piece
    e = piece.GetExtent()
    assert piece.GetNumberOfPoints() < 41 * 41, "rank 0's piece is a block: %s" % (e,)
    got, want = piece.GetPointData().GetArray("ValueFunction"), serial.GetPointData().GetArray("ValueFunction")
    n = 0
    for j in range(e[2], e[3] + 1):
        for i in range(e[0], e[1] + 1):
            assert got.GetValue(n) == want.GetValue(i + 41 * j), "node (%d, %d) differs from the serial solve" % (i, j)
            n += 1

    broken = CWENOHamiltonJacobiBellmanSolver(**dict(TEST4, RunningCost="y > 1.9 ? log(-1) : (a1^2+a2^2)/2"))
    broken.UpdatePipeline()
    assert broken.GetDataInformation().GetNumberOfPoints() == 0, "a failed solve has no result on any rank"
    again = CWENOHamiltonJacobiBellmanSolver(**dict(TEST4, Dimensions=[21, 41, 1]))
    again.UpdatePipeline()
    assert again.GetDataInformation().GetNumberOfPoints() == 2 * 21 * 21, "the server still answers after a failure"
    # The reconstruction on the same server: every rank reconstructs its slab from the whole cloud.
    cloud = Sphere(Radius=1.0, ThetaResolution=30, PhiResolution=30)
    recon = SemiLagrangianLevelSetReconstruction(Input=cloud, NumberOfRuns=2, NumberOfThreads=1)
    recon.UpdatePipeline()
    image = recon.GetDataInformation()
    assert image.GetNumberOfPoints() > 0, "the reconstruction produced an image"
    assert recon.FieldData["Ranks"].GetRange() == (2.0, 2.0), "the reconstruction was split over both server ranks"
    mine = servermanager.Fetch(recon)  # rank 0's block
    whole = image.GetExtent()
    assert mine.GetExtent()[5] < whole[5], "rank 0's block %s is not the whole extent %s" % (mine.GetExtent(), whole)
    surface_regions = Connectivity(Input=OutputPort(recon, 1))
    surface_regions.UpdatePipeline()
    assert surface_regions.CellData["RegionId"].GetRange() == (0.0, 0.0), "the surface pieces join into one region"
    # The octree on the same server: each rank its own trees; its surface pieces join too.
    octree = OctreeSignedDistancefromPoints(Input=cloud, NumberOfRuns=2, NumberOfThreads=1)
    octree.UpdatePipeline()
    assert octree.GetDataInformation().GetDataClassName() == "vtkHyperTreeGrid"
    assert octree.CellData["Rank"].GetRange() == (0.0, 1.0), "the trees of both server ranks"
    octree_regions = Connectivity(Input=OutputPort(octree, 1))
    octree_regions.UpdatePipeline()
    assert octree_regions.CellData["RegionId"].GetRange() == (0.0, 0.0), "the octree's surface is one region"
    Disconnect()
    print("pvserver on 2 ranks: partitioned result, serial values and errors; a failure on one slab, no hang; "
          "the reconstruction split into blocks and the octree into trees, each surface one region")
finally:
    server.terminate()
    try:
        server.wait(timeout=20)
    except subprocess.TimeoutExpired:
        server.kill()
