"""The white render view of the tutorials' pvbatch images, shared by
common/renderPhases.py and the render.py of damBreakSpheres and
periodicChannel."""
from paraview.simple import CreateView


def white_view(size, axes=False):
    """A render view of SIZE pixels on white, orientation axes if AXES."""
    view = CreateView("RenderView")
    view.ViewSize = size
    view.OrientationAxesVisibility = 1 if axes else 0
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    return view
