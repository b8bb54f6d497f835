# Run by tests/io/fields/test_paraview.cpp with pvbatch under a virtual X server:
#   xvfb-run -a pvbatch paraview_field.py FIELDS.xdmf FRAME SCREENSHOT.png
# Opens a ccm field output with ParaView's XDMF 3 reader, prints what it read as one JSON line
# (the frame times, the displacement of node 0 at FRAME, the largest von Mises stress at FRAME,
# the array names), and renders the bodies at the frame of largest von Mises stress, warped by
# their displacement, cut in half and coloured by von Mises, into SCREENSHOT.png.
import json
import sys

from paraview import servermanager
from paraview.simple import (Clip, ColorBy, ExtractBlock, GetActiveViewOrCreate,
                             GetColorTransferFunction, GetScalarBar, Render, SaveScreenshot,
                             Show, Text, WarpByVector, Xdmf3ReaderT)

xdmf, frame, png = sys.argv[1], int(sys.argv[2]), sys.argv[3]

reader = Xdmf3ReaderT(FileName=[xdmf])
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
bodies = ExtractBlock(Input=reader, Selectors=["/Root/*[1]"])  # the grid "bodies"


def bodies_at(t):
    bodies.UpdatePipeline(t)
    data = servermanager.Fetch(bodies)
    return data.GetBlock(0)


def von_mises_max(grid):
    return grid.GetCellData().GetArray("von_mises").GetRange()[1]


grid = bodies_at(times[frame])
answer = {
    "times": times,
    "u_node0": list(grid.GetPointData().GetArray("displacement").GetTuple3(0)),
    "von_mises_max": von_mises_max(grid),
    "point_arrays": sorted(reader.PointData.keys()),
    "cell_arrays": sorted(reader.CellData.keys()),
}
print("CCM_PARAVIEW " + json.dumps(answer), flush=True)

# The picture: the frame of largest stress.
peak = max(times, key=lambda t: von_mises_max(bodies_at(t)))
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [960, 600]
view.ViewTime = peak
view.OrientationAxesVisibility = 0
view.Background = [1.0, 1.0, 1.0]
try:  # ParaView >= 5.10 takes the background from the colour palette unless told otherwise
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
warped = WarpByVector(Input=bodies, Vectors=["POINTS", "displacement"])
half = Clip(Input=warped, ClipType="Plane", Crinkleclip=1)
bounds = servermanager.Fetch(bodies).GetBlock(0).GetBounds()
half.ClipType.Origin = [0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.0]
half.ClipType.Normal = [0.0, -1.0, 0.0]  # keeps y > mid: the camera looks at the cut
shown = Show(half, view)
shown.SetRepresentationType("Surface With Edges")
shown.EdgeColor = [0.25, 0.25, 0.25]
ColorBy(shown, ("CELLS", "von_mises"))
shown.RescaleTransferFunctionToDataRange(True, False)
lut = GetColorTransferFunction("von_mises")
lut.ApplyPreset("Viridis (matplotlib)", True)
bar = GetScalarBar(lut, view)
bar.Title = "von Mises stress [Pa]"
bar.ComponentTitle = ""
bar.TitleColor = bar.LabelColor = [0.1, 0.1, 0.1]
shown.SetScalarBarVisibility(view, True)
label = Text(Text="t = %.1f ms (warped by displacement, cut at the mid-plane)" % (1e3 * peak))
label_shown = Show(label, view)
label_shown.Color = [0.1, 0.1, 0.1]
label_shown.FontSize = 14
view.CameraPosition = [0.075, -0.09, 0.06]
view.CameraFocalPoint = [0.03, 0.03, 0.004]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.ResetCamera(False)
view.CameraParallelScale = 0.5 * view.CameraParallelScale
camera = view.GetActiveCamera()
camera.Zoom(1.6)
Render(view)
SaveScreenshot(png, view, ImageResolution=[960, 600])
print("CCM_PARAVIEW_SCREENSHOT " + png, flush=True)
