"""Where a fuzz case differs from the reference: its worst pixels, and what a
brute-force walk of each pixel's ray finds.

    Module/run python Testing/Python/ppiray_fuzz_pixels.py --seed 3 --case 1486 [--pixels 3]

Renders the case as the fuzz driver does (ppiray_fuzz.render_case), prints
the pixels that differ most from the CPU reference with their 3 x 3
neighbourhoods (max channel, mapper and reference), and samples each
pixel's ray from the near to the far plane (--samples points, then 200,000
around the extreme), locating each sample with vtkCellLocator and keeping
it only where its parametric coordinates lie in the cell (VTK's
EvaluatePosition accepts points 1e-3 outside) and on the kept side of the
case's clipping planes: the scalar's maximum and minimum along the ray, the
cell each is in, the transfer function's colour there (what a maximum or
minimum intensity projection shows, x 255, premultiplied by its opacity),
and the ray's length in the mesh. A third check: it shares no code with
the mapper or the reference.
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ppiray_fuzz as fuzz  # noqa: E402


def inside(cell, pcoords):
    """Whether parametric coordinates lie in the cell (tetrahedron: also
    their sum)."""
    if min(pcoords) < 0.0 or max(pcoords) > 1.0:
        return False
    return cell.GetCellType() != 10 or sum(pcoords) <= 1.0


def march(grid, locator, a, b, t0, t1, count, planes):
    """(t, s, cell) at `count` samples of a + t (b - a), t in [t0, t1], inside
    a cell and on the kept side of every plane (origin, normal)."""
    from vtkmodules.vtkCommonDataModel import vtkGenericCell
    point_scalars = grid.GetPointData().GetScalars()
    cell_scalars = grid.GetCellData().GetScalars()
    cell = vtkGenericCell()
    pcoords = [0.0, 0.0, 0.0]
    weights = [0.0] * 8
    found = []
    for t in np.linspace(t0, t1, count):
        p = a + (b - a) * t
        if any(np.dot(p - origin, normal) < 0.0 for origin, normal in planes):
            continue
        cid = locator.FindCell(p, 0.0, cell, pcoords, weights)
        if cid < 0 or not inside(cell, pcoords):
            continue
        ids = cell.GetPointIds()
        if point_scalars is not None:
            s = sum(weights[i] * point_scalars.GetTuple1(ids.GetId(i))
                    for i in range(ids.GetNumberOfIds()))
        else:
            s = cell_scalars.GetTuple1(cid)
        found.append((t, s, cid))
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seed", type=int, default=3)
    parser.add_argument("--case", type=int, required=True)
    parser.add_argument("--pixels", type=int, default=3, help="worst pixels (default 3)")
    parser.add_argument("--samples", type=int, default=20000,
                        help="samples along a ray (default 20,000)")
    args = parser.parse_args()

    from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
    from vtkmodules.vtkCommonDataModel import vtkCellLocator
    from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
    import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401
    messages = vtkStringOutputWindow()
    vtkOutputWindow.SetInstance(messages)
    window = vtkRenderWindow()
    window.SetMultiSamples(0)
    window.SetSize(fuzz.SIZE, fuzz.SIZE)
    renderer = vtkRenderer()
    renderer.GetCullers().RemoveAllItems()
    window.AddRenderer(renderer)

    case = fuzz.make_case(args.seed, args.case)
    images = {}
    result = fuzz.render_case(case, window, renderer, messages, images)
    print("case %d: %s, %s data, mapper %s, camera %s; reference %s" % (
        args.case, case["kind"], case["scalars"]["association"], case["mapper"],
        case["camera"]["where"], result.get("reference")))
    if "reference" not in images:
        print("not compared with the reference")
        return 0
    grid, prop = fuzz.build(case)
    fuzz.place_camera(renderer, case, grid)
    # The planes as render_case places them: through the bounds' centre.
    bounds = np.nan_to_num(np.array(grid.GetBounds(), float), nan=0.0, posinf=1.0, neginf=0.0)
    centre = 0.5 * (bounds[0::2] + bounds[1::2])
    planes = [(centre, np.array(case["camera"]["planes"][k], float))
              for k in range(case["mapper"]["planes"])]
    scalars = grid.GetPointData().GetScalars() or grid.GetCellData().GetScalars()
    scalar_range = scalars.GetRange() if scalars is not None else (0.0, 1.0)
    locator = vtkCellLocator()
    locator.SetDataSet(grid)
    locator.BuildLocator()
    size = fuzz.SIZE
    mapper = images["mapper"].reshape(size, size, 3)
    reference = images["reference"].reshape(size, size, 3)
    difference = np.abs(mapper - reference).max(axis=2)

    def world(x, y, z):
        renderer.SetDisplayPoint(x, y, z)
        renderer.DisplayToWorld()
        p = renderer.GetWorldPoint()
        return np.array(p[:3]) / p[3]

    for p in np.argsort(-difference.ravel())[:args.pixels]:
        y, x = divmod(int(p), size)
        rows = slice(max(y - 1, 0), y + 2)
        columns = slice(max(x - 1, 0), x + 2)
        print("pixel (%d, %d): %.0f/255 apart; mapper %s, reference %s" % (
            x, y, difference[y, x], mapper[y, x].round(), reference[y, x].round()))
        print("  3x3 max channel, mapper    %s" % mapper[rows, columns].max(axis=2).round().tolist())
        print("  3x3 max channel, reference %s" % reference[rows, columns].max(axis=2).round().tolist())
        a = world(x + 0.5, y + 0.5, 0.0)
        b = world(x + 0.5, y + 0.5, 1.0)
        found = march(grid, locator, a, b, 0.0, 1.0, args.samples, planes)
        if not found:
            print("  the ray meets no cell at %d samples (spacing %.2g)" % (
                args.samples, np.linalg.norm(b - a) / args.samples))
            continue
        length = np.linalg.norm(b - a)
        for name, pick in (("max", max), ("min", min)):
            t, s, cid = pick(found, key=lambda f: f[1])
            # Refine around the extreme: a short stretch can hide between samples.
            step = 1.0 / args.samples
            fine = march(grid, locator, a, b, max(t - 4 * step, 0.0), min(t + 4 * step, 1.0),
                         200000, planes)
            t, s, cid = pick(fine or found, key=lambda f: f[1])
            rgb = np.array(prop.GetRGBTransferFunction().GetColor(s))
            opacity = min(max(prop.GetScalarOpacity().GetValue(s), 0.0), 1.0)
            print("  %s %.6g in cell %d at %.6g from the near plane; colour %s" % (
                name, s, cid, t * length, (255 * opacity * rgb).round()))
        print("  in the mesh from %.6g to %.6g (%d of %d samples)" % (
            found[0][0] * length, found[-1][0] * length, len(found), args.samples))
        if case["mapper"]["blend"] in (3, 4):
            # vtkGPUVolumeRayCastMapper's average and additive, in the limit
            # of samples one unit distance apart (Documentation/algorithms.md):
            # the opacity times the scalar normalized to the array's range.
            lo, hi = scalar_range
            on = [min(max(prop.GetScalarOpacity().GetValue(f[1]), 0.0), 1.0) *
                  ((f[1] - lo) / (hi - lo) if hi > lo else 1.0) for f in found]
            spacing = length / args.samples
            if case["mapper"]["blend"] == 3:
                value = np.mean(on)
            else:
                value = sum(on) * spacing / prop.GetScalarOpacityUnitDistance()
            print("  %s along the ray: %.1f/255" % (
                "average" if case["mapper"]["blend"] == 3 else "sum",
                255 * min(value, 1.0)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
