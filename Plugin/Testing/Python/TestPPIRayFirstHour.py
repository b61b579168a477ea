"""pvbatch: what a user does in the first hour, through ParaView's view:
Wavelet -> Tetrahedralize (40,000 tetrahedra) shown as "PPIRay Volume",
 1. the camera flown into the volume (ParaView's own clipping range: rays
    start at its near plane, inside the cells it cuts);
 2. each projection of "PPIRay Blend Mode" (Maximum, Minimum, Average
    Intensity, Additive) from outside, and Maximum Intensity from inside;
each screenshot against the CPU reference renderer in the same blend mode
with ParaView's lookup table, opacity function and camera, composited over
the view's background: p99 at most 1/255 and max at most 2/255 over the
covered pixels (8-bit rounding of the screenshot and of the background
blend, 0.5 each; float), at least a third of the view covered; and each
projection differs from the composite image (it is not silently composite).
Clipping planes are not a ParaView volume property (VTK's
vtkAbstractMapper::AddClippingPlane is checked by TestGPURayCastClipping).

Usage: pvbatch TestPPIRayFirstHour.py PLUGIN TEMPORARY_DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ppiray_pvtest as pt  # noqa: E402

from paraview.simple import Render, Tetrahedralize, Wavelet  # noqa: E402

SIZE = (240, 200)
# PPIRay Blend Mode entries and the reference's blend mode (vtkVolumeMapper's values).
BLENDS = (("Composite", 0), ("Maximum Intensity", 1), ("Minimum Intensity", 2),
          ("Average Intensity", 3), ("Additive", 4))


def main(plugin, temporary):
    pt.load_plugin(plugin)
    import numpy as np
    failures = []
    tets = Tetrahedralize(Input=Wavelet(WholeExtent=[-10, 10, -10, 10, -10, 10]))
    view = pt.render_view(SIZE)
    display = pt.show_volume(tets, view, "RTData", unit_distance=20.0)
    images = {}

    def check(name, blend):
        path = pt.screenshot(view, os.path.join(temporary, "TestPPIRayFirstHour%s.png" % name))
        covered, p99, largest = pt.against_reference(view, display, path, "RTData", blend=blend)
        print("%s: %d pixels covered, p99 %.2f, max %.2f /255 against the reference"
              % (name, covered, p99, largest))
        if covered < SIZE[0] * SIZE[1] // 3 or p99 > 1.0 or largest > 2.0:
            failures.append("%s: %d pixels covered, p99 %.2f, max %.2f" % (name, covered, p99,
                                                                          largest))
        images[name] = pt.read_rgb(path).astype(np.float64)

    for place, position in (("Outside", (30.0, -20.0, 25.0)), ("Inside", (2.0, -3.0, 1.5))):
        if place == "Outside":
            pt.set_camera(view, position)
        else:
            # Into the volume: ParaView's camera inside, its own clipping range.
            view.CameraPosition = list(position)
            view.CameraFocalPoint = [6.0, 5.0, 2.0]
            view.CameraViewUp = [0.0, 0.0, 1.0]
            view.CameraViewAngle = 60.0
        for text, blend in BLENDS:
            if place == "Inside" and blend not in (0, 1):
                continue
            display.PPIRayBlendMode = text
            Render(view)
            name = place + text.replace(" ", "")
            check(name, blend)
            if blend:
                apart = np.percentile(np.abs(images[name] - images[place + "Composite"]), 99)
                if apart <= 20.0:
                    failures.append("%s looks composite (p99 %.1f apart)" % (name, apart))
    pt.finish(failures)
    return 0


if __name__ == "__main__":
    pt.run(main, __doc__, 3)
