"""pvpython: the SLTK plugin loads, its proxies run, bad input errors without a crash."""
import math
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

plugin = sys.argv[1]
LoadPlugin(plugin, ns=globals())

# The HJB solver through the proxy pipeline (initial datum of Test 1, then a Test 2 solve).
solver = CWENOHamiltonJacobiBellmanSolver(NumberOfNodes=41, FinalTime=0.0)
solver.UpdatePipeline()
image = servermanager.Fetch(solver)
assert image.GetDimensions() == (41, 41, 1), image.GetDimensions()
values = image.GetPointData().GetArray("ValueFunction")
for node in (0, 41 * 28 + 12, 41 * 30 + 14):  # a corner, the bump's centre (0.3, 0.7), a flank
    x = image.GetPoint(node)
    r = math.hypot(x[0] - 0.3, x[1] - 0.7) / 0.15
    s = r - 1.0
    exact = 0.15 * (1.0 + r**3 * (-1.0 + 3.0 * s * (1.0 - 2.0 * s))) if r < 1.0 else 0.0
    assert abs(values.GetValue(node) - exact) < 1e-14, (node, values.GetValue(node), exact)
info = solver.GetDataInformation()
assert info.GetNumberOfPoints() == 41 * 41
solver.Preset = "Test 2: semi-concave data (1D)"
solver.NumberOfNodes = 81
solver.FinalTime = -1.0
solver.UpdatePipeline()
l1 = servermanager.Fetch(solver).GetFieldData().GetArray("L1Error").GetValue(0)
assert abs(l1 / 1.78e-6 - 1.0) < 0.05, l1  # Table 3.3, CWENOZ, N = 81

# A custom problem by formulas (rigid rotation of a cone, one revolution), animated: its time steps
# are advertised and served; at t = 1 the cone is back (L1 5.4e-3 at 41 x 41 nodes, the apex smoothed).
custom = CWENOHamiltonJacobiBellmanSolver(Preset="Custom (formulas below)", Dimensions=[41, 41, 1],
                                          DomainBounds=[-1, 1, -1, 1, 0, 0], DynamicsX="-2*pi*y",
                                          DynamicsY="2*pi*x", InitialValue="max(0.25 - hypot(x - 0.5, y), 0)",
                                          ExactSolution="max(0.25 - hypot(x - 0.5*cos(2*pi*t), y + 0.5*sin(2*pi*t)), 0)",
                                          FinalTime=1.0, CourantNumber=2.0)
steps = list(custom.TimestepValues)
assert len(steps) == 11 and steps[0] == 0.0 and abs(steps[-1] - 1.0) < 1e-12, steps
custom.UpdatePipeline(steps[5])  # the data information describes the output at that time
assert abs(custom.FieldData["Time"].GetRange()[0] - steps[5]) < 1e-12, custom.FieldData["Time"].GetRange()
assert custom.FieldData["Steps"].GetRange()[0] == 5
custom.UpdatePipeline(1.0)
l1 = custom.FieldData["L1Error"].GetRange()[0]
assert l1 < 1e-2, l1
custom.DynamicsY = "2*pi*x +"  # malformed: an error, no crash, no output
custom.UpdatePipeline(1.0)
assert custom.GetDataInformation().GetNumberOfPoints() == 0

# Bad input: an empty point set and a degenerate one must fail with an error, not crash.
empty = servermanager.sources.PointSource(NumberOfPoints=1, Radius=0.0)
recon = SemiLagrangianLevelSetReconstruction(Input=empty)
recon.UpdatePipeline()
assert recon.GetDataInformation().GetNumberOfPoints() == 0

# A real reconstruction: points on a sphere (a sphere source's vertices, cells ignored).
cloud = Sphere(Radius=1.0, ThetaResolution=40, PhiResolution=40)
recon.Input = cloud
recon.Interpolator = "WENO3"
recon.NumberOfRuns = 2
recon.UpdatePipeline()
sdf = servermanager.Fetch(recon)
assert sdf.GetPointData().GetArray("SignedDistance") is not None
surface = servermanager.Fetch(recon, idx=1)
bounds = surface.GetBounds()
assert surface.GetNumberOfPolys() > 100 and abs(bounds[1] - 1.0) < 0.05, (surface.GetNumberOfPolys(), bounds)
history = servermanager.Fetch(recon, idx=2)
assert history.GetNumberOfRows() >= 2 and history.GetColumnByName("CloudError") is not None
# The per-run (p, eta) schedule is a repeatable property: rows reach the filter, a bad row is an error.
energies = history.GetColumnByName("Energy")
recon.RunParameters = [1, 0, 2, 0, 2, 1]
recon.UpdatePipeline()
assert list(recon.RunParameters) == [1, 0, 2, 0, 2, 1], list(recon.RunParameters)
assert servermanager.Fetch(recon, idx=1).GetNumberOfPolys() > 100
scheduled = servermanager.Fetch(recon, idx=2).GetColumnByName("Energy")
assert scheduled.GetValue(scheduled.GetNumberOfTuples() - 1) != energies.GetValue(energies.GetNumberOfTuples() - 1), \
    "eta = 0 in runs 1-2 changes the reconstruction"
recon.RunParameters = [0.5, 1]
recon.UpdatePipeline()
assert recon.GetDataInformation().GetNumberOfPoints() == 0, "p < 1 is refused"
recon.RunParameters = []
# OctreeStorage switches the SignedDistance output to a hyper tree grid (and back); ParaView's
# Contour of its dual grid at 0 is the Surface output.
recon.OctreeStorage = 1
recon.UpdatePipeline()
assert recon.GetDataInformation().GetDataClassName() == "vtkHyperTreeGrid", recon.GetDataInformation().GetDataClassName()
assert {"SignedDistance", "DistanceToCloud", "Level"} <= set(recon.CellData.keys()), recon.CellData.keys()
tree_surface = Contour(Input=HyperTreeGridToDualGrid(Input=recon), ContourBy=["POINTS", "SignedDistance"], Isosurfaces=[0.0])
tree_surface.UpdatePipeline()
tiled_surface = servermanager.Fetch(recon, idx=1)
bounds = tree_surface.GetDataInformation().GetBounds()
assert tree_surface.GetDataInformation().GetNumberOfCells() == tiled_surface.GetNumberOfPolys() and \
    abs(bounds[1] - 1.0) < 0.05, (tree_surface.GetDataInformation().GetNumberOfCells(), tiled_surface.GetNumberOfPolys())
recon.OctreeStorage = 0
recon.UpdatePipeline()
assert recon.GetDataInformation().GetDataClassName() == "vtkImageData"

# The octree reconstruction: a hyper tree grid with the signed distance, the zero level set and
# the leaves per iteration. VTK's own hyper tree grid filters take it (Contour is
# vtkHyperTreeGridContour on it, the axis-aligned Slice vtkHyperTreeGridAxisCut), rendered to a PNG.
import os, tempfile
octree = OctreeSignedDistancefromPoints(Input=cloud, NumberOfRuns=2)
octree.UpdatePipeline()
assert octree.GetDataInformation().GetDataClassName() == "vtkHyperTreeGrid", \
    octree.GetDataInformation().GetDataClassName()
assert {"SignedDistance", "DistanceToCloud", "Level", "Rank"} <= set(octree.CellData.keys()), octree.CellData.keys()
assert octree.CellData["Level"].GetRange() == (0.0, 3.0), octree.CellData["Level"].GetRange()
octree_history = servermanager.Fetch(octree, idx=2)
leaves, uniform = (octree_history.GetColumnByName(name) for name in ("Leaves", "UniformNodes"))
last = octree_history.GetNumberOfRows() - 1
assert octree_history.GetColumnByName("LargestRankLeaves") is not None and \
    0 < leaves.GetValue(last) < uniform.GetValue(last), "run 2 holds fewer leaves than its uniform grid"
octree_surface = servermanager.Fetch(octree, idx=1)
zero = Contour(Input=octree, ContourBy=["CELLS", "SignedDistance"], Isosurfaces=[0.0])
zero.UpdatePipeline()
bounds = zero.GetDataInformation().GetBounds()
assert zero.GetDataInformation().GetNumberOfCells() == octree_surface.GetNumberOfPolys() > 1000 and \
    abs(bounds[1] - 1.0) < 0.05, (zero.GetDataInformation().GetNumberOfCells(), octree_surface.GetNumberOfPolys())
cut = Slice(Input=octree)
cut.HyperTreeGridSlicer = "Axis Aligned Plane"
cut.HyperTreeGridSlicer.Normal = [0, 0, 1]
cut.UpdatePipeline()
assert cut.GetDataInformation().GetDataClassName() == "vtkHyperTreeGrid", cut.GetDataInformation().GetDataClassName()
view = CreateView("RenderView")
view.ViewSize = [400, 300]
# Shown as a user applies it: the trees as their outline (the proxy's hint), the surface inside it;
# the uniform filter's 2D image of a planar cloud as ParaView's coloured slice (no hint there).
assert Show(octree, view).Representation == "Outline" and Show(OutputPort(octree, 1), view).Representation == "Surface"
Hide(octree, view)
Hide(OutputPort(octree, 1), view)
ring = Ellipse(Center=[0.0, 0.0, 0.5], MajorRadiusVector=[1.0, 0.0, 0.0], Ratio=1.0, Resolution=64, Close=1)
flat_image = SemiLagrangianLevelSetReconstruction(Input=ring, NumberOfRuns=1)
assert Show(flat_image, view).Representation == "Slice", Show(flat_image, view).Representation
Hide(flat_image, view)
cut_display = Show(cut, view)
ColorBy(cut_display, ("CELLS", "SignedDistance"))
cut_display.SetRepresentationType("Surface With Edges")
Show(zero, view).Opacity = 0.4
view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = [0, 0, 5], [0, 0, 0], [0, 1, 0]
view.ResetCamera()
with tempfile.TemporaryDirectory() as folder:
    picture = os.path.join(folder, "octree.png")
    SaveScreenshot(picture, view, ImageResolution=[400, 300])
    from vtkmodules.vtkIOImage import vtkPNGReader
    png = vtkPNGReader()
    png.SetFileName(picture)
    png.Update()
    pixels = png.GetOutput().GetPointData().GetScalars()
    colours = {tuple(int(pixels.GetComponent(i, k)) for k in range(3)) for i in range(0, pixels.GetNumberOfTuples(), 7)}
    assert png.GetOutput().GetDimensions()[:2] == (400, 300) and len(colours) > 100, \
        "the cut's colour map and the contour are drawn (%d colours)" % len(colours)
    # Saved as .htg and read back. DataMode Binary: ParaView 5.11's default (appended) writes an
    # unreadable header for hyper tree grids with several cell arrays (Documentation/Toolchain.md).
    saved = os.path.join(folder, "octree.htg")
    SaveData(saved, proxy=octree, DataMode="Binary")
    back = HyperTreeGridReader(FileNames=[saved])
    back.UpdatePipeline()
    assert back.GetDataInformation().GetNumberOfCells() == octree.GetDataInformation().GetNumberOfCells()
    assert back.CellData["SignedDistance"].GetRange() == octree.CellData["SignedDistance"].GetRange()
    Delete(back)

# The text clouds of the CLI open from their extension with the plugin's reader (.xyz .pts .txt
# offer it; .csv stays ParaView's CSV reader's) as points drawn without a Glyph, and reconstruct.
with tempfile.TemporaryDirectory() as folder:
    golden = math.pi * (3.0 - math.sqrt(5.0))
    rows = []
    for k in range(500):  # a Fibonacci sphere of radius 1
        z = 1.0 - 2.0 * (k + 0.5) / 500
        r = math.sqrt(1.0 - z * z)
        rows.append("%.17g,%.17g,%.17g,0,0,1" % (r * math.cos(golden * k), r * math.sin(golden * k), z))
    paths = {}
    for extension in ("xyz", "pts", "txt", "csv"):
        paths[extension] = os.path.join(folder, "cloud." + extension)
        with open(paths[extension], "w") as f:
            f.write("# a sphere\nx,y,z,nx,ny,nz\n" + "\n".join(rows) + "\n")
    session = servermanager.ActiveConnection.Session
    factory = servermanager.vtkSMProxyManager.GetProxyManager().GetReaderFactory()
    for extension, offered in (("xyz", True), ("pts", True), ("txt", True), ("csv", False)):
        listed = factory.GetReaders(paths[extension], session)
        names = [listed.GetString(i) for i in range(1, listed.GetNumberOfStrings(), 3)]
        assert ("CloudTextReader" in names) == offered, (extension, names)
    text_cloud = OpenDataFile(paths["xyz"])
    assert text_cloud.GetXMLName() == "CloudTextReader", text_cloud.GetXMLName()
    assert text_cloud.SMProxy.GetVTKClassName() == "vtkSLPointCloudReader"
    text_cloud.UpdatePipeline()
    read = servermanager.Fetch(text_cloud)
    assert read.GetNumberOfPoints() == 500 and read.GetNumberOfVerts() == 500, (read.GetNumberOfPoints(), read.GetNumberOfVerts())
    written = [tuple(float(c) for c in row.split(",")[:3]) for row in rows]
    assert all(read.GetPoint(k) == written[k] for k in range(500)), "the points as written, to the last bit"
    from_text = SemiLagrangianLevelSetReconstruction(Input=text_cloud, NumberOfRuns=1)
    from_text.UpdatePipeline()
    text_surface = servermanager.Fetch(from_text, idx=1)
    bounds = text_surface.GetBounds()
    assert text_surface.GetNumberOfPolys() > 100 and all(abs(abs(b) - 1.0) < 0.1 for b in bounds), \
        (text_surface.GetNumberOfPolys(), bounds)
    Delete(from_text)
    # A refused file: the CLI's message (vtkErrorMacro) and no points, never a part of the cloud.
    bad = os.path.join(folder, "bad.xyz")
    with open(bad, "w") as f:
        f.write("\n".join(rows) + "\n0 1 0.02abc\n")
    text_cloud.FileName = bad
    text_cloud.UpdatePipeline()
    assert text_cloud.GetDataInformation().GetNumberOfPoints() == 0
    Delete(text_cloud)
print("pvpython plugin pipeline ok")
