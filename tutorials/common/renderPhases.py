"""pvbatch: the phases of a vheFoam case at the given times.

Usage: pvbatch renderPhases.py CASE.foam OUTPREFIX FIELDS T1 [T2 ...]
  FIELDS  comma-separated volume fractions, e.g. alpha.water,alpha.oil,phis
Writes OUTPREFIX_t<T>.png for each time.
  2D case (one cell thick): the cells, coloured by phase (first field
  blue, second amber, third orange, fourth grey, the rest white), mixed
  cells in the mixed colour.
  3D case: the 0.5 surface of each field, the walls' outline, any patch
  named "obstacle", and the mesh on the mid-plane y = const (shows the
  refinement of a dynamicRefineFvMesh case).
"""
import os
import sys

from paraview.simple import (CellDatatoPointData, ColorBy, Contour,
                             OpenFOAMReader, Outline, PythonCalculator,
                             SaveScreenshot, Show,
                             Slice, Text)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from whiteView import white_view  # noqa: E402

foam, prefix, fields = sys.argv[1:4]
fields = fields.split(",")
times = [float(t) for t in sys.argv[4:]]
colours = [[0.2, 0.45, 0.85], [0.95, 0.75, 0.2], [0.9, 0.35, 0.1],
           [0.55, 0.55, 0.55]]

reader = OpenFOAMReader(FileName=foam)
reader.UpdatePipelineInformation()
patches = [p for p in reader.GetProperty("PatchArrayInfo")[::2]
           if p == "obstacle" or p == "patch/obstacle"]
reader.MeshRegions = ["internalMesh"] + patches
reader.CellArrays = fields
reader.UpdatePipeline(max(reader.TimestepValues))
available = list(reader.TimestepValues)
xmin, xmax, ymin, ymax, zmin, zmax = reader.GetDataInformation().GetBounds()
twoD = (zmax - zmin) < 0.05*(xmax - xmin)

view = white_view([1000, 800])

if twoD:
    # each cell's colour: its phases' colours mixed by volume fraction,
    # white for the rest (the last fluid, e.g. air)
    def channel(k):
        terms = ['%g*inputs[0].CellData["%s"]' % (colours[i][k] - 1, f)
                 for i, f in enumerate(fields[:len(colours)])]
        return "1+" + "+".join(terms)
    calc = PythonCalculator(Input=reader, ArrayAssociation="Cell Data",
                            ArrayName="colour",
                            Expression="make_vector(%s, %s, %s)"
                            % (channel(0), channel(1), channel(2)))
    s = Show(calc, view)
    ColorBy(s, ("CELLS", "colour"))
    s.MapScalars = 0
    view.CameraPosition = [0.5*(xmin + xmax), 0.5*(ymin + ymax), zmax + 3*(ymax - ymin)]
    view.CameraFocalPoint = [0.5*(xmin + xmax), 0.5*(ymin + ymax), 0.5*(zmin + zmax)]
    view.CameraViewUp = [0, 1, 0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = 0.55*max(ymax - ymin, xmax - xmin)
else:
    points = CellDatatoPointData(Input=reader)
    for i, f in enumerate(fields):
        c = Show(Contour(Input=points, ContourBy=["POINTS", f], Isosurfaces=[0.5]), view)
        c.ColorArrayName = ["POINTS", ""]
        c.DiffuseColor = colours[min(i, len(colours) - 1)]
        c.Opacity = 0.5 if i == 0 else 1.0
    mid = Slice(Input=reader)
    mid.SliceType.Normal = [0, 1, 0]
    mid.SliceType.Origin = [0.5*(xmin + xmax), 0.5*(ymin + ymax) + 1e-6, 0.5*(zmin + zmax)]
    m = Show(mid, view)
    m.SetRepresentationType("Wireframe")
    m.ColorArrayName = ["POINTS", ""]
    m.AmbientColor = m.DiffuseColor = [0.6, 0.6, 0.6]
    o = Show(Outline(Input=reader), view)
    o.ColorArrayName = ["POINTS", ""]
    o.AmbientColor = o.DiffuseColor = [0, 0, 0]
    cx, cy, cz = 0.5*(xmin + xmax), 0.5*(ymin + ymax), 0.5*(zmin + zmax)
    size = max(xmax - xmin, zmax - zmin)
    view.CameraPosition = [cx + 0.4*size, cy - 2.2*size, cz + 0.9*size]
    view.CameraFocalPoint = [cx, cy, cz]
    view.CameraViewUp = [0, 0, 1]

label = Text()
lshow = Show(label, view)
lshow.Color = [0, 0, 0]
lshow.WindowLocation = "Upper Center"
for t in times:
    tt = min(available, key=lambda x: abs(x - t))
    view.ViewTime = tt
    label.Text = "%s  t = %g" % (foam.split("/")[-1][:-5], tt)
    SaveScreenshot("%s_t%g.png" % (prefix, t), view, ImageResolution=[1000, 800])
