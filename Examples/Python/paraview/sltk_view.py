"""A render view with a white background and no orientation axes, shared by the examples."""
from paraview.simple import GetActiveViewOrCreate


def white_view(width, height):
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [width, height]
    view.OrientationAxesVisibility = 0
    view.Background = [1.0, 1.0, 1.0]
    try:  # ParaView >= 5.10 keeps the background in a palette unless told otherwise
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    return view
