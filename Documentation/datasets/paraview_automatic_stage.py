"""VTK's combustor (43,008 curvilinear hexahedra) through ParaView's path as
PPIRay Volume with the default March Stage (Automatic): renders the view
twelve times, turning the camera 3 degrees each time as a user's drag does,
and prints per frame the stage the mapper ran, the stage its probe chose
(-1 while probing) and the probe's best frames (ms); then the same view in
the fragment stage, and the automatic stage's last image against it (max
difference in 1/255, pixels off by more than 1/255). Writes both
screenshots into the folder named on the command line.

Run: Module/run pvbatch Documentation/datasets/paraview_automatic_stage.py OUTDIR
"""
import os
import sys

import numpy as np
from paraview.simple import Render

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Plugin",
                                "Testing", "Python"))
from ppiray_pvtest import combustor_view, mapper_of, read_rgb, screenshot  # noqa: E402

view, display = combustor_view()
mapper = mapper_of(display)
print("March Stage property:", display.MarchStage)
camera = view.GetActiveCamera()
for frame in range(12):
    camera.Azimuth(3.0)
    Render(view)
    s = mapper.GetStatistics()
    print("frame %2d: ran %d, chosen %2d, probe fragment %.1f ms, compute %.1f ms"
          % (frame, s.GetMarchStage(), s.GetChosenMarchStage(), s.GetMarchStageProbeTime(0),
             s.GetMarchStageProbeTime(1)))
folder = sys.argv[1]
automatic = screenshot(view, os.path.join(folder, "combustor_automatic.png"))
print("the screenshot's frame ran in stage", mapper.GetStatistics().GetMarchStage())
display.MarchStage = "Fragment"
fragment = screenshot(view, os.path.join(folder, "combustor_fragment.png"))
a = read_rgb(automatic).astype(int)
f = read_rgb(fragment).astype(int)
d = np.abs(a - f)
print("automatic against fragment: max %d/255, %d pixels off by more than 1/255, %d lit pixels"
      % (d.max(), int((d.max(axis=2) > 1).sum()), int((f.max(axis=2) > 0).sum())))
