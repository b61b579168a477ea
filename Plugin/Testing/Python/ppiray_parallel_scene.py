"""pvbatch [--mpi --symmetric]: the scenes of TestPPIRayParallel, rendered by
however many ranks run it. Each rank prints what its mapper rendered:
    PPIRAY rank <r> of <n> scene <name> tetrahedra <count> hexahedra <count> peels <count>

Scenes: "wavelet" (a distributed source: each rank generates a piece, then
Tetrahedralize), "voxels" (the same pieces appended as they are: voxels, passed to
the mapper unsplit and rendered natively), "clipped" (the pieces cut by a
plane: voxels, wedges, pyramids and tetrahedra, split by the mapper) and "hole"
(Data/wavelet_hole.vtu, non-convex, read on rank 0 only). Either way the
view redistributes the cells for ordered compositing.

Usage: pvbatch [--mpi --symmetric] ppiray_parallel_scene.py PLUGIN OUTPUT_DIR DATA_DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ppiray_pvtest as pt  # noqa: E402

from paraview import servermanager  # noqa: E402
from paraview.simple import (AppendDatasets, Clip, Delete, Hide, Tetrahedralize,  # noqa: E402
                             Wavelet, XMLUnstructuredGridReader)


def render_scene(name, source, view, output):
    display = pt.show_volume(source, view, "RTData")
    pt.set_camera(view, (30.0, 20.0, 40.0))
    process = servermanager.vtkProcessModule.GetProcessModule()
    rank, ranks = process.GetPartitionId(), process.GetNumberOfLocalPartitions()
    # Every rank takes part in the screenshot (a collective render).
    pt.screenshot(view, os.path.join(output, "%s%s.png" % (name, "-rank%d" % rank if rank else "")))
    mapper = pt.mapper_of(display)
    print("PPIRAY rank %d of %d scene %s tetrahedra %d hexahedra %d peels %d"
          % (rank, ranks, name, mapper.GetStatistics().GetNumberOfTetrahedra(), mapper.GetStatistics().GetNumberOfHexahedra(),
             mapper.GetStatistics().GetNumberOfPeels()), flush=True)
    Hide(source, view)


def main(plugin, output, data):
    pt.load_plugin(plugin)
    view = pt.render_view()
    wavelet = Wavelet(WholeExtent=[-10, 10, -10, 10, -10, 10])
    render_scene("wavelet", Tetrahedralize(Input=wavelet), view, output)
    render_scene("voxels", AppendDatasets(Input=wavelet), view, output)
    clip = Clip(Input=wavelet, ClipType="Plane", Crinkleclip=0)
    clip.ClipType.Origin = [2.0, 1.0, 0.0]
    clip.ClipType.Normal = [1.0, 0.6, 0.3]
    render_scene("clipped", clip, view, output)
    hole = XMLUnstructuredGridReader(FileName=[os.path.join(data, "wavelet_hole.vtu")])
    render_scene("hole", hole, view, output)
    Delete(view)


if __name__ == "__main__":
    if len(sys.argv) != 4:
        pt.fail("usage: " + __doc__.strip().splitlines()[-1])
    main(*sys.argv[1:])
