"""Renders a reconstructed surface (and optionally its point cloud) to a PNG.

    xvfb-run -a pvpython --force-offscreen-rendering render_surface.py SURFACE PNG [CLOUD]

SURFACE: .vtp / .ply / .stl; CLOUD: .ply / .vtp (points shown as small dots).
"""
import sys

from paraview.simple import OpenDataFile, Render, ResetCamera, SaveScreenshot, Show
from sltk_view import white_view

surface_file, png = sys.argv[1], sys.argv[2]
cloud_file = sys.argv[3] if len(sys.argv) > 3 else None

view = white_view(900, 700)

surface = OpenDataFile(surface_file)
display = Show(surface, view)
display.ColorArrayName = ["POINTS", ""]
display.DiffuseColor = [0.85, 0.72, 0.55]
display.Specular = 0.3
if cloud_file:
    cloud = OpenDataFile(cloud_file)
    dots = Show(cloud, view)
    dots.SetRepresentationType("Points")
    dots.ColorArrayName = ["POINTS", ""]
    dots.AmbientColor = dots.DiffuseColor = [0.1, 0.2, 0.7]
    dots.PointSize = 2.0
ResetCamera(view)
camera = view.GetActiveCamera()
camera.Azimuth(30)
camera.Elevation(15)
view.ResetCamera()
Render(view)
SaveScreenshot(png, view, ImageResolution=[900, 700])
print("wrote", png)
