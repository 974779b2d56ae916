"""The Zermelo swimmer's backward reachable sets (thesis Test 5, Fig. 3.9) in ParaView.

    xvfb-run -a pvpython --force-offscreen-rendering zermelo_reachable_set.py \
        [--plugin SLTKPlugin.so] [--nodes 101] [--interpolator CWENO] [--reference 301] [--png zermelo.png]

A swimmer with unit speed in any direction must reach the island |(x1 - 1, x2)| <= 0.25
against a current 2 - x2^2/2 flowing along x1, avoiding two square rocks (3.39). The
solver's ReachTime field is the first time each node can reach the island (3.40); its
level sets ReachTime = t are the boundaries of the reachable sets R[0, t]. We draw them
for t = 0.25, 0.5, ..., 3 (coloured by t), the island and the rocks in red and, with
--reference N, the same sets on a finer N-node grid in black, as in Fig. 3.9. The script
prints, for each t, the area of R[0, t] (nodes times cell area) and, with a reference whose
grid contains the coarse nodes ((N_ref - 1) a multiple of (N - 1)), the area of the symmetric
difference of the two sets at the coarse nodes, relative to the reference's area.
"""
import argparse
import os

import numpy
from vtkmodules.util import numpy_support

from paraview import servermanager
from paraview.simple import (Calculator, ColorBy, Contour, GetAnimationScene,
                             GetColorTransferFunction, GetScalarBar, LoadDistributedPlugin, LoadPlugin, Render, ResetCamera, SaveScreenshot, Show)
from sltk_view import white_view

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--plugin", help="path of SLTKPlugin.so (default: found on PV_PLUGIN_PATH)")
parser.add_argument("--nodes", type=int, default=101, help="nodes along x1 (x2 gets 4/5 of them); Fig. 3.9: 101")
parser.add_argument("--interpolator", default="CWENO", choices=["Q1", "WENO3", "CWENO", "CWENOZ"])
parser.add_argument("--reference", type=int, default=0, help="nodes of a finer reference solution (0: none)")
parser.add_argument("--final-time", type=float, default=3.0)
parser.add_argument("--png", default="zermelo.png")
args = parser.parse_args()

if args.plugin:
    LoadPlugin(args.plugin, ns=globals())
else:
    LoadDistributedPlugin("SLTKPlugin", ns=globals())

times = [0.25 * k for k in range(1, int(round(args.final_time / 0.25)) + 1)]


def reach_time(nodes):
    """Test 5 on `nodes` x (4 (nodes - 1) / 5 + 1) nodes; never-reached nodes (-1) become +1e3."""
    solver = CWENOHamiltonJacobiBellmanSolver(Preset="Test 5: Zermelo swimmer with obstacles (2D)",  # noqa: F821
                                              NumberOfNodes=nodes, FinalTime=args.final_time,
                                              Interpolator=args.interpolator)
    solver.UpdatePipeline(args.final_time)
    return solver, Calculator(Input=solver, ResultArrayName="Arrival", Function="ReachTime < 0 ? 1000 : ReachTime")


def arrival_times(source):
    """ReachTime at the nodes (never reached: +inf), as an (ny, nx) numpy array, and the cell area."""
    image = servermanager.Fetch(source)
    nx, ny, _ = image.GetDimensions()
    values = numpy_support.vtk_to_numpy(image.GetPointData().GetArray("ReachTime")).reshape(ny, nx)
    dx, dy, _ = image.GetSpacing()
    return numpy.where(values < 0, numpy.inf, values), dx * dy


def shape(formula):
    """The zero level set of a formula on a fine grid of the domain (island, rocks)."""
    field = CWENOHamiltonJacobiBellmanSolver(Preset="Custom (formulas below)", InitialValue=formula,  # noqa: F821
                                             DynamicsX="0", DynamicsY="0", Dimensions=[501, 401, 1],
                                             DomainBounds=[-3, 2, -2, 2, 0, 0], FinalTime=0.0)
    return Contour(Input=field, ContourBy=["POINTS", "ValueFunction"], Isosurfaces=[0.0])


view = white_view(1000, 800)

if args.reference and (args.reference - 1) % (args.nodes - 1) != 0:
    parser.error("--reference N needs N - 1 to be a multiple of --nodes - 1 (the grids then share the coarse nodes)")
solver, arrival = reach_time(args.nodes)
# The solver's output is animated over its time steps t_k; show (and fetch) the final time.
scene = GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
scene.AnimationTime = args.final_time
view.ViewTime = args.final_time
fronts = Contour(Input=arrival, ContourBy=["POINTS", "Arrival"], Isosurfaces=times, ComputeScalars=1)
display = Show(fronts, view)
ColorBy(display, ("POINTS", "Arrival"))
lut = GetColorTransferFunction("Arrival")
lut.ApplyPreset("Viridis (matplotlib)", True)
lut.RescaleTransferFunction(0.0, args.final_time)
display.LineWidth = 2.0
display.SetScalarBarVisibility(view, True)
bar = GetScalarBar(lut, view)
bar.Title = "reach time t"
bar.ComponentTitle = ""
bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]

reference_solver, reference = reach_time(args.reference) if args.reference else (None, None)
if reference:
    black = Show(Contour(Input=reference, ContourBy=["POINTS", "Arrival"], Isosurfaces=times), view)
    black.ColorArrayName = ["POINTS", ""]
    black.AmbientColor = black.DiffuseColor = [0.0, 0.0, 0.0]
    black.LineWidth = 1.0

island = "hypot(x - 1, y) - 0.25"
rocks = "max(0.2 - max(abs(x - 0.3), abs(y - 0.4)), 0.2 - max(abs(x + 1), abs(y + 1.5)))"
for formula in (island, rocks):
    red = Show(shape(formula), view)
    red.ColorArrayName = ["POINTS", ""]
    red.AmbientColor = red.DiffuseColor = [0.85, 0.0, 0.0]
    red.LineWidth = 3.0

coarse, cell = arrival_times(solver)
if reference:
    fine, _ = arrival_times(reference_solver)
    stride = (args.reference - 1) // (args.nodes - 1)
    fine = fine[::stride, ::stride]  # the reference at the coarse nodes
print("    t   area of R[0,t]" + ("   reference   |symmetric difference| / |reference|" if reference else ""))
for t in times:
    inside = coarse <= t + 1e-12
    line = "%5.2f   %12.4f" % (t, inside.sum() * cell)
    if reference:
        exact = fine <= t + 1e-12
        line += "   %9.4f   %.4f" % (exact.sum() * cell, (inside != exact).sum() / max(exact.sum(), 1))
    print(line)

ResetCamera(view)
view.CameraPosition = [-0.5, 0.0, 10.0]
view.CameraFocalPoint = [-0.5, 0.0, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.CameraParallelProjection = 1
view.CameraParallelScale = 2.1
Render(view)
SaveScreenshot(args.png, view, ImageResolution=[1000, 800])
print("wrote", os.path.abspath(args.png))
