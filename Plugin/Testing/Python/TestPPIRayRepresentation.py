"""pvbatch: the plugin's "PPIRay Volume" representation on a generated dataset.

Wavelet -> Tetrahedralize (40,000 tetrahedra) shown as PPIRay Volume:
 1. the image matches its baseline; the mapper uploaded geometry, field and
    transfer function once each;
 2. a new opacity function and a mapper property (IntegrationMode) between two
    renders: the image matches the second baseline, the transfer function was
    uploaded again, geometry and field were not;
 3. a mapper property alone (PsiTableSize): nothing re-uploaded;
 4. interactive renders below and above the LOD threshold, then a still
    render: below it the mapper's image sample distance follows its rule from
    the allocated time ParaView lowers; the still image is the full-quality
    one of step 2, at distance 1;
 5. an opaque slice and outline in the same view: matches the third baseline;
 6. PPIRay Blend Mode "Isosurfaces" with two Isosurface Values, shaded:
    matches the fourth baseline; the mapper is in ISOSURFACE_BLEND and no cell
    data was re-uploaded;
 7. a vector array (RTData, 0, 0) coloured by Magnitude and by component X
    renders as RTData, by component Y does not; the lookup table's vector
    mode reaches the mapper.

Usage: pvbatch TestPPIRayRepresentation.py PLUGIN BASELINE_DIR TEMPORARY_DIR
"""
import math
import os
import sys

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ppiray_pvtest as pt  # noqa: E402

from paraview.simple import (  # noqa: E402
    Calculator,
    GetColorTransferFunction,
    Hide,
    Outline,
    Render,
    Show,
    Slice,
    Tetrahedralize,
    Wavelet,
)


def counts(mapper):
    return (mapper.GetStatistics().GetGeometryUploadCount(), mapper.GetStatistics().GetFieldUploadCount(),
            mapper.GetStatistics().GetTransferFunctionUploadCount())


def last_frame_rgb(view):
    """(height, width, 3) uint8 of the view's last frame, not rendered again,
    in read_rgb's row order."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
    grab = vtkWindowToImageFilter()
    grab.SetInput(view.GetRenderWindow())
    grab.ReadFrontBufferOff()
    grab.ShouldRerenderOff()
    grab.Update()
    width, height, _ = grab.GetOutput().GetDimensions()
    rgba = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())
    return rgba.reshape(height, width, -1)[:, :, :3]


def lit_pixels(rgb, background=pt.BACKGROUND):
    """Pixels more than 2/255 from the background in some channel."""
    return numpy.abs(rgb.astype(float) - 255.0 * numpy.array(background)).max(axis=2) > 2.0


def main(plugin, baselines, temporary):
    pt.load_plugin(plugin)
    failures = []

    def check_image(view, name):
        image = pt.screenshot(view, os.path.join(temporary, name + ".png"))
        problem = pt.compare_with_baseline(image, os.path.join(baselines, name + ".png"), temporary)
        if problem:
            failures.append(problem)

    wavelet = Wavelet(WholeExtent=[-10, 10, -10, 10, -10, 10])
    tets = Tetrahedralize(Input=wavelet)
    view = pt.render_view()
    display = pt.show_volume(tets, view, "RTData")
    if pt.REPRESENTATION not in display.GetProperty("Representation").Available:
        pt.fail("'%s' is not offered for unstructured grids" % pt.REPRESENTATION)
    pt.set_camera(view, (30.0, 20.0, 40.0))

    # 1. First render; its pixels against the reference renderer given
    # ParaView's lookup table (Diverging colour space, as ParaView makes it).
    check_image(view, "TestPPIRayRepresentation")
    covered, p99, largest = pt.against_reference(
        view, display, os.path.join(temporary, "TestPPIRayRepresentation.png"), "RTData")
    print("against the reference with ParaView's lookup table: %d pixels, p99 %.2f, max %.2f /255"
          % (covered, p99, largest), flush=True)
    if covered < 10000 or p99 > 1.0 or largest > 2.0:
        failures.append("PPIRay Volume differs from VTK's evaluation of ParaView's lookup table: "
                        "%d pixels, p99 %.2f, max %.2f /255" % (covered, p99, largest))
    mapper = pt.mapper_of(display)
    if mapper.GetStatistics().GetNumberOfTetrahedra() != 5 * 20 ** 3:
        failures.append("expected 40000 tetrahedra, got %d" % mapper.GetStatistics().GetNumberOfTetrahedra())
    first = counts(mapper)
    if first != (1, 1, 1):
        failures.append("first render uploaded (geometry, field, TF) = %s, expected (1, 1, 1)"
                        % (first,))

    # 2. Transfer function and a mapper property change.
    display.ScalarOpacityFunction.Points = [40.0, 0.0, 0.5, 0.0, 150.0, 0.05, 0.5, 0.0,
                                            200.0, 0.8, 0.5, 0.0, 260.0, 0.8, 0.5, 0.0]
    display.IntegrationMode = "Average Color"
    check_image(view, "TestPPIRayRepresentationChanged")
    second = counts(mapper)
    if mapper.GetIntegrationMode() != 3:
        failures.append("IntegrationMode did not reach the mapper (%d)" % mapper.GetIntegrationMode())
    if second[:2] != first[:2]:
        failures.append("geometry/field re-uploaded after a transfer-function change: %s -> %s"
                        % (first, second))
    if second[2] != first[2] + 1:
        failures.append("transfer function uploaded %d times after one change"
                        % (second[2] - first[2]))

    # 3. A mapper property alone.
    display.PsiTableSize = 256
    Render(view)
    third = counts(mapper)
    if mapper.GetPsiTableSize() != 256:
        failures.append("PsiTableSize did not reach the mapper (%d)" % mapper.GetPsiTableSize())
    if third != second:
        failures.append("a mapper property re-uploaded cell data: %s -> %s" % (second, third))

    # 4. Interactive renders, then a still render at full quality. ParaView
    # raises the window's desired update rate for an interactive render
    # (vtkPVRenderView::InteractiveRender), so the volume's allocated time T
    # falls. Below the LOD threshold the mapper renders the interactive frame
    # itself, AutoAdjustSampleDistances setting the image sample distance
    # d <- clamp(d sqrt(t / T), 1, 10) from the last frame's time t; above it
    # ParaView shows its LOD geometry. A still render (T of minutes) brings d
    # back to 1.
    # The view at 600 x 600 for this step, so that on the CI machine a still
    # frame takes longer than the 1/15 s ParaView allocates while interacting
    # (at 300 x 300 it is close to it) and the interactive frame is coarser.
    view.LODThreshold = 1.0e6
    view.ViewSize = [600, 600]
    Render(view)
    still = last_frame_rgb(view).astype(float)
    volume = display.GetClientSideObject().GetActiveRepresentation().GetActor()
    d, t = mapper.GetImageSampleDistance(), mapper.GetTimeToDraw()
    view.SMProxy.InteractiveRender()
    allocated = volume.GetAllocatedRenderTime()
    rate = view.GetRenderWindow().GetDesiredUpdateRate()
    expected = min(max(d * math.sqrt(t / allocated), 1.0), 10.0)
    print("interactive render: desired update rate %g, allocated %.4f s, last frame %.4f s, "
          "image sample distance %.3f -> %.3f" % (rate, allocated, t, d,
                                                  mapper.GetImageSampleDistance()), flush=True)
    if d != 1.0 or not rate >= 1.0 or not allocated < 1.0:
        failures.append("an interactive render did not lower the allocated time: distance %g "
                        "before, rate %g, allocated %g s" % (d, rate, allocated))
    # The interactive frame against the still one just before it: the same
    # silhouette (1 %), colours within what sampling the rays d times coarser
    # and scaling up bilinearly changes, which grows with d (this scene at
    # 300 x 300, d = 2, 3, 4, 6, 10 set by hand, over the lit pixels: p99 2,
    # 3, 4, 7, 14 and max 4, 7, 10, 13, 26 /255): p99 <= max(2, 1.5 d),
    # max <= 4 d + 1.
    distance = mapper.GetImageSampleDistance()
    interactive = last_frame_rgb(view).astype(float)
    lit, lit_still = int(lit_pixels(interactive).sum()), int(lit_pixels(still).sum())
    # Over the pixels lit in either image (the background would dilute p99).
    difference = abs(interactive - still).max(axis=2)[lit_pixels(interactive) | lit_pixels(still)]
    p99, largest = numpy.percentile(difference, 99), difference.max()
    print("interactive frame against the still one: %d and %d lit pixels, p99 %.1f, max %.1f /255"
          % (lit, lit_still, p99, largest), flush=True)
    if (abs(lit - lit_still) > 0.01 * lit_still or p99 > max(2.0, 1.5 * distance)
            or largest > 4.0 * distance + 1.0):
        failures.append("interactive frame (distance %.2f) differs from the still one: %d and %d "
                        "lit pixels, p99 %.1f, max %.1f /255"
                        % (distance, lit, lit_still, p99, largest))
    # The distance is stored as a float: 1e-6 relative.
    if abs(mapper.GetImageSampleDistance() - expected) > 1.0e-6 * expected:
        failures.append("interactive image sample distance %g, expected %g"
                        % (mapper.GetImageSampleDistance(), expected))
    view.ViewSize = [300, 300]
    view.LODThreshold = 0.0
    view.SMProxy.InteractiveRender()
    check_image(view, "TestPPIRayRepresentationChanged")
    if mapper.GetImageSampleDistance() != 1.0:
        failures.append("a still render after interactive ones kept image sample distance %g"
                        % mapper.GetImageSampleDistance())
    if counts(mapper)[:2] != first[:2]:
        failures.append("an interactive render re-uploaded cell data: %s" % (counts(mapper),))

    # 5. Opaque geometry in the same view.
    display.IntegrationMode = "Partial Pre-Integration"
    slice_ = Slice(Input=wavelet)
    slice_.SliceType.Normal = [1.0, 0.0, 0.0]
    slice_display = Show(slice_, view)
    slice_display.SetRepresentationType("Surface")
    slice_display.ColorArrayName = ["POINTS", ""]
    slice_display.DiffuseColor = [0.85, 0.85, 0.85]
    outline = Outline(Input=wavelet)
    outline_display = Show(outline, view)
    outline_display.DiffuseColor = [1.0, 1.0, 1.0]
    check_image(view, "TestPPIRayRepresentationOpaque")
    Hide(slice_, view)

    # 6. Isosurfaces.
    before = counts(mapper)
    display.PPIRayBlendMode = "Isosurfaces"
    display.PPIRayIsosurfaceValues = [130.0, 210.0]
    display.Shade = 1
    check_image(view, "TestPPIRayRepresentationIso")
    if mapper.GetBlendMode() != 5 or mapper.GetEmbedIsoSurfaces():
        failures.append("Isosurfaces reached the mapper as blend mode %d, embed %d"
                        % (mapper.GetBlendMode(), mapper.GetEmbedIsoSurfaces()))
    if counts(mapper)[:2] != before[:2]:
        failures.append("isosurfaces re-uploaded cell data: %s -> %s" % (before, counts(mapper)))

    # 7. A vector array V = (RTData, 0, 0): by magnitude (ParaView's default)
    # and as component X it renders as RTData; as component Y (zero) it does
    # not. The lookup table's vector mode reaches the mapper.
    Hide(tets, view)
    Hide(outline, view)
    vectors = Calculator(Input=tets, ResultArrayName="V", Function="RTData*iHat")
    vdisplay = pt.show_volume(vectors, view, "V")
    lut = GetColorTransferFunction("V")
    images = {}
    for mode, component in (("Magnitude", 0), ("Component", 0), ("Component", 1)):
        lut.VectorMode = mode
        lut.VectorComponent = component
        name = "TestPPIRayRepresentationVector%s%d" % (mode, component)
        images[(mode, component)] = pt.read_rgb(
            pt.screenshot(view, os.path.join(temporary, name + ".png")))
        vmapper = pt.mapper_of(vdisplay)
        expected = (0 if mode == "Magnitude" else 1, component)
        if (vmapper.GetVectorMode(), vmapper.GetVectorComponent()) != expected:
            failures.append("%s %d reached the mapper as vector mode %d, component %d"
                            % (mode, component, vmapper.GetVectorMode(),
                               vmapper.GetVectorComponent()))
    # the first image: RTData with the same colour map and opacity
    scalar = pt.read_rgb(os.path.join(temporary, "TestPPIRayRepresentation.png"))
    for key, bound, same in ((("Magnitude", 0), 1, True), (("Component", 0), 1, True),
                             (("Component", 1), 10, False)):
        d = int(abs(images[key].astype(int) - scalar.astype(int)).max())
        print("vector %s %d against the scalar: max %d /255" % (key[0], key[1], d), flush=True)
        if (d <= bound) != same:
            failures.append("vector %s %d against the scalar image: max %d/255" % (key + (d,)))

    pt.finish(failures)


if __name__ == "__main__":
    if len(sys.argv) != 4:
        pt.fail("usage: " + __doc__.strip().splitlines()[-1])
    main(*sys.argv[1:])
