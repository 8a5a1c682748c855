"""pvbatch: phi_s = 0.5 contours over vorticity at the final time.

Usage: pvbatch render.py CASE.foam OUT.png
"""
import os
import sys

from paraview.simple import (Calculator, CellDatatoPointData, ColorBy, Contour,
                             GetColorTransferFunction,
                             GetScalarBar, OpenFOAMReader, SaveScreenshot,
                             Show, Slice, Text)

sys.path.insert(0, os.path.join(os.environ["VHE_ROOT"], "tutorials", "common"))
from whiteView import white_view  # noqa: E402

foam, out = sys.argv[1:3]
reader = OpenFOAMReader(FileName=foam)
reader.MeshRegions = ["internalMesh"]
reader.CellArrays = ["vorticity", "phis", "alpha.liquid"]
reader.UpdatePipelineInformation()
t = reader.TimestepValues[-1]
reader.UpdatePipeline(t)
source = reader
if "phis" not in reader.CellData.keys():
    # a rigid material has no phis field: the solid is what the liquid
    # leaves
    source = Calculator(Input=reader, AttributeType="Cell Data",
                        ResultArrayName="phis", Function='1 - "alpha.liquid"')

bounds = reader.GetDataInformation().GetBounds()
zmid = 0.5 * (bounds[4] + bounds[5])
cut = Slice(Input=source)
cut.SliceType.Origin = [0, 0, zmid]
cut.SliceType.Normal = [0, 0, 1]
points = CellDatatoPointData(Input=cut)
edges = Contour(Input=points, ContourBy=["POINTS", "phis"], Isosurfaces=[0.5])

view = white_view([900, 900])
view.ViewTime = t

shown = Show(cut, view)
ColorBy(shown, ("CELLS", "vorticity", "Z"))
lut = GetColorTransferFunction("vorticity")
lut.ApplyPreset("Cool to Warm", True)
w = 0.06   # wall vorticity of the disk-free channel is f h / (2 nu) = 0.049
lut.RescaleTransferFunction(-w, w)
shown.SetScalarBarVisibility(view, True)
bar = GetScalarBar(lut, view)
bar.Title = "vorticity z [1/s]"
bar.ComponentTitle = ""
bar.TitleColor = [0, 0, 0]
bar.LabelColor = [0, 0, 0]
lines = Show(edges, view)
ColorBy(lines, None)
lines.AmbientColor = [0, 0, 0]
lines.DiffuseColor = [0, 0, 0]
lines.LineWidth = 3

title = Text(Text="vorticity (z) and phi_s = 0.5 at t = %g" % t)
tshow = Show(title, view)
tshow.Color = [0, 0, 0]
tshow.WindowLocation = "Upper Center"

view.InteractionMode = "2D"
view.ResetCamera()
view.CameraPosition = [0.5 * (bounds[0] + bounds[1]),
                       0.5 * (bounds[2] + bounds[3]), bounds[5] + 5]
view.CameraFocalPoint = [0.5 * (bounds[0] + bounds[1]),
                         0.5 * (bounds[2] + bounds[3]), zmid]
view.CameraViewUp = [0, 1, 0]
view.ResetCamera()
SaveScreenshot(out, view, ImageResolution=[900, 900])
