"""pvbatch: free surface (alpha.gas = 0.5, blue) and bodies (phi_s = 0.5,
orange) of a dam-break case at the given times.

Usage: pvbatch render.py CASE.foam OUTPREFIX T1 [T2 ...]
Writes OUTPREFIX_t<T>.png for each time.
"""
import os
import sys

from paraview.simple import (CellDatatoPointData, Contour,
                             OpenFOAMReader, Outline,
                             SaveScreenshot, Show, Text)

sys.path.insert(0, os.path.join(os.environ["VHE_ROOT"], "tutorials", "common"))
from whiteView import white_view  # noqa: E402

foam, prefix = sys.argv[1:3]
times = [float(t) for t in sys.argv[3:]]
reader = OpenFOAMReader(FileName=foam)
reader.MeshRegions = ["internalMesh"]
reader.CellArrays = ["alpha.gas", "phis"]
reader.UpdatePipelineInformation()
available = list(reader.TimestepValues)

points = CellDatatoPointData(Input=reader)
surface = Contour(Input=points, ContourBy=["POINTS", "alpha.gas"],
                  Isosurfaces=[0.5])
bodies = Contour(Input=points, ContourBy=["POINTS", "phis"],
                 Isosurfaces=[0.5])
box = Outline(Input=reader)

view = white_view([1200, 700], axes=True)

s = Show(surface, view)
s.ColorArrayName = ["POINTS", ""]
s.DiffuseColor = [0.3, 0.55, 0.9]
s.Opacity = 0.45
b = Show(bodies, view)
b.ColorArrayName = ["POINTS", ""]
b.DiffuseColor = [0.95, 0.5, 0.1]
o = Show(box, view)
o.ColorArrayName = ["POINTS", ""]
o.DiffuseColor = [0, 0, 0]
o.AmbientColor = [0, 0, 0]
label = Text()
lshow = Show(label, view)
lshow.Color = [0, 0, 0]
lshow.WindowLocation = "Upper Center"

view.CameraPosition = [1.05 + 1.2, -2.6, 2.0]
view.CameraFocalPoint = [1.05, 0.5, 0.35]
view.CameraViewUp = [0, 0, 1]
for t in times:
    tt = min(available, key=lambda x: abs(x - t))
    view.ViewTime = tt
    label.Text = "%s  t = %g" % (foam.split("/")[-1][:-5], tt)
    SaveScreenshot("%s_t%g.png" % (prefix, t), view,
                   ImageResolution=[1200, 700])
