"""Open a run's fields in ParaView's own Python, as a user's File > Open would, and take a picture.

    xvfb-run -a -s "-noreset -screen 0 1280x1024x24" pvpython scripts/paraview_open.py RUN_DIR/fields.xdmf picture.png [scale]

``-noreset``: pvpython connects to the X server twice, and a server that resets when the first
connection closes refuses the second now and then ("bad X server connection", SIGABRT).

Opens the file with ParaView's default reader for .xdmf, prints one JSON line (the reader, the time
steps, the point and cell arrays, the cell count, the cells of the first body after a Threshold on
``body``, the von Mises range at the last time), and saves a picture at the last time of the mesh
warped by ``displacement`` (times ``scale``, 1 by default; ``final_shape.xdmf`` is deformed already) coloured by ``von_mises``, with its colour
bar.  ``tests/sim/test_paraview.py`` runs it on runs of every kinematics.
"""
import json
import sys

from paraview import simple

path, picture = sys.argv[1], sys.argv[2]
scale = float(sys.argv[3]) if len(sys.argv) > 3 else 1.0
reader = simple.OpenDataFile(path)
reader.UpdatePipelineInformation()
times = reader.TimestepValues
times = list(times) if isinstance(times, (list, tuple)) or hasattr(times, "__len__") else [times]
last = times[-1] if times else 0.0
reader.UpdatePipeline(last)
data = reader.GetDataInformation()
# final_shape.xdmf is deformed already and carries no displacement
warped = (simple.WarpByVector(Input=reader, Vectors=["POINTS", "displacement"], ScaleFactor=scale)
          if "displacement" in reader.PointData.keys() else reader)
first = simple.Threshold(Input=reader, Scalars=["CELLS", "body"])
if hasattr(first, "LowerThreshold"):       # ParaView 5.10 and later
    first.LowerThreshold, first.UpperThreshold = 1, 1
else:
    first.ThresholdRange = [1, 1]
first.UpdatePipeline(last)
view = simple.CreateRenderView()
view.ViewSize = [900, 700]
view.ViewTime = last
shown = simple.Show(warped, view)
simple.ColorBy(shown, ("CELLS", "von_mises"))
shown.RescaleTransferFunctionToDataRange(True, False)
shown.SetScalarBarVisibility(view, True)
bounds = data.GetBounds()
if bounds[5] > bounds[4]:      # 3D: from above one side, z up
    centre = [0.5 * (bounds[2 * i] + bounds[2 * i + 1]) for i in range(3)]
    view.CameraFocalPoint = centre
    view.CameraPosition = [c + d for c, d in zip(centre, (1.0, -1.6, 0.9))]
    view.CameraViewUp = [0.0, 0.0, 1.0]
simple.ResetCamera(view)
simple.SaveScreenshot(picture, view)
print(json.dumps({
    "reader": reader.GetXMLName(), "times": times, "cells": data.GetNumberOfCells(),
    "points": data.GetNumberOfPoints(), "dataset": data.GetDataSetTypeAsString(),
    "point_arrays": [a.Name for a in reader.PointData], "cell_arrays": [a.Name for a in reader.CellData],
    "first_body_cells": first.GetDataInformation().GetNumberOfCells(),
    "von_mises_range": list(reader.CellData["von_mises"].GetRange()),
}))
