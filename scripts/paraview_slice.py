# The fluid's velocity in a plane with the bodies' surface markers, rendered by ParaView
# from a run's XDMF sidecar (the picture scripts/plot --slice draws with matplotlib, here
# through ParaView's XDMF reader, as a user opening the sidecar sees it):
#
#   pvbatch scripts/paraview_slice.py run.xmf y=0.125 1.0 slice.png
#   xvfb-run -a pvbatch scripts/paraview_slice.py ...      (on a machine without a display)
#
# The plane is AXIS=VALUE; the time picks the field write nearest it. The slice is coloured
# by the speed with arrows of the velocity; the markers within half a cell of the plane
# are drawn as black points. Needs ParaView (Debian paraview, python3-paraview).
import sys

from paraview.simple import (Clip, ColorBy, CreateView, GetColorTransferFunction, Glyph, ProgrammableFilter, Render,
                             SaveScreenshot, Show, Slice, Transform, XDMFReader)

AXES = "xyz"

# A ProgrammableFilter's script: the points of every block that is not the grid of cells
# (the point sets), as one vtkPolyData of vertices.
GATHER_POINTS = """
import vtk
points, vertices = vtk.vtkPoints(), vtk.vtkCellArray()
blocks = self.GetInputDataObject(0, 0).NewIterator()
blocks.InitTraversal()
while not blocks.IsDoneWithTraversal():
    block = blocks.GetCurrentDataObject()
    if not block.IsA("vtkRectilinearGrid"):
        for i in range(block.GetNumberOfPoints()):
            vertices.InsertNextCell(1)
            vertices.InsertCellPoint(points.InsertNextPoint(block.GetPoint(i)))
    blocks.GoToNextItem()
output = self.GetPolyDataOutput()
output.SetPoints(points)
output.SetVerts(vertices)
"""


def cells_bounds(reader):
    """The bounds and extent of the reader's grid of cells."""
    from paraview import servermanager
    blocks = servermanager.Fetch(reader).NewIterator()
    blocks.InitTraversal()
    while not blocks.IsDoneWithTraversal():
        block = blocks.GetCurrentDataObject()
        if block.IsA("vtkRectilinearGrid"):
            return block.GetBounds(), block.GetExtent()
        blocks.GoToNextItem()
    fail(f"{reader.FileNames[0]}: no grid of cells (a run with fields writes one)")


def fail(message):
    print(f"paraview_slice.py: {message}", file=sys.stderr)
    sys.exit(2)


def main(xmf, plane, at, png):
    axis_name, _, value = plane.partition("=")
    try:
        axis, value, at = AXES.index(axis_name), float(value), float(at)
    except ValueError:
        fail(f"'{plane}' is not AXIS=VALUE with AXIS x, y or z (e.g. y=0.125), or '{at}' is not a time")
    normal = [0.0, 0.0, 0.0]
    normal[axis] = 1.0

    # The reader gives per field write a block of cells (a rectilinear grid) and a block of
    # points per point set; the slice cuts the cells, and the points are gathered apart.
    fluid = XDMFReader(FileNames=[xmf])
    times = list(fluid.TimestepValues) or [0.0]
    time = min(times, key=lambda t: abs(t - at))
    fluid.UpdatePipeline(time)
    bounds, extent = cells_bounds(fluid)
    lo, hi = bounds[2 * axis], bounds[2 * axis + 1]
    if not lo <= value <= hi:
        fail(f"{axis_name}={value} is outside the grid's [{lo:g}, {hi:g}]")
    half_cell = 0.5 * (hi - lo) / max(extent[2 * axis + 1] - extent[2 * axis], 1)

    view = CreateView("RenderView")
    view.ViewSize = [1200, 900]
    view.ViewTime = time
    view.OrientationAxesVisibility = 0

    cut = Slice(Input=fluid)
    cut.SliceType.Origin = [value if a == axis else 0.5 * (bounds[2 * a] + bounds[2 * a + 1]) for a in range(3)]
    cut.SliceType.Normal = normal
    shown = Show(cut, view)
    ColorBy(shown, ("CELLS", "velocity", "Magnitude"))
    shown.SetScalarBarVisibility(view, True)
    GetColorTransferFunction("velocity").RescaleTransferFunction(*cut.CellData["velocity"].GetRange(-1))

    arrows = Glyph(Input=cut, GlyphType="Arrow")
    arrows.OrientationArray = ["CELLS", "velocity"]
    arrows.ScaleArray = ["CELLS", "velocity"]
    arrows.GlyphMode = "Uniform Spatial Distribution (Bounds Based)"
    arrows.MaximumNumberOfSamplePoints = 800
    speed = max(cut.CellData["velocity"].GetRange(-1)[1], 1e-30)
    arrows.ScaleFactor = 0.06 * max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]) / speed
    glyphs = Show(arrows, view)
    glyphs.ColorArrayName = [None, ""]
    glyphs.AmbientColor = glyphs.DiffuseColor = [1, 1, 1]

    markers = ProgrammableFilter(Input=fluid, OutputDataSetType="vtkPolyData", Script=GATHER_POINTS)
    markers.UpdatePipeline(time)
    if markers.GetDataInformation().GetNumberOfPoints() > 0:
        above = Clip(Input=markers)
        above.ClipType.Origin = [value - half_cell if a == axis else 0 for a in range(3)]
        above.ClipType.Normal = normal
        above.Invert = 0  # keeps the side the normal points to
        slab = Clip(Input=above)
        slab.ClipType.Origin = [value + half_cell if a == axis else 0 for a in range(3)]
        slab.ClipType.Normal = normal
        slab.Invert = 1  # keeps the other side
        # Moved a cell towards the camera, so that the slice hides none of them.
        lifted = Transform(Input=slab)
        lifted.Transform.Translate = [2 * half_cell * n for n in normal]
        dots = Show(lifted, view)
        dots.ColorArrayName = [None, ""]
        dots.SetRepresentationType("Points")
        dots.PointSize = 4
        dots.AmbientColor = dots.DiffuseColor = [0, 0, 0]

    view.CameraPosition = [c + (2 * (hi - lo) + 1) * n for c, n in zip(cut.SliceType.Origin, normal)]
    view.CameraFocalPoint = cut.SliceType.Origin
    view.CameraViewUp = [0, 0, 1] if axis != 2 else [0, 1, 0]
    view.ResetCamera()
    Render(view)
    SaveScreenshot(png, view)
    print(png)


if __name__ == "__main__":
    if len(sys.argv) != 5:
        fail("usage: pvbatch scripts/paraview_slice.py run.xmf AXIS=VALUE TIME out.png")
    main(*sys.argv[1:])
