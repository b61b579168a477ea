"""The notch tetrahedralized (Documentation/datasets/notch_tetrahedralized.py;
accuracy.md, "The notch tetrahedralized"), against the reference under a
field linear in the coordinates, 256²:

- its cells typed as what they are (VTK_QUADRATIC_HEXAHEDRON and
  VTK_QUADRATIC_WEDGE): one peel, quadrilaterals split differently on their
  two sides linked as lenses, every pixel within 1/255 (p99 and max, at
  least 10,000 pixels, no NaN);
- its cells as the file types them (VTK_HEXAHEDRON with 20 ids: VTK makes a
  tangle of them): never more than 8/255 brighter than the reference (the
  union of its overlapping cells; 173 before the rule for cells behind their
  entry face), no NaN.

Skipped (exit 125) when the data root has no notch folder. About 30 s here.
By hand: Module/run python Testing/Python/TestNotchTetrahedralized.py [--data ROOT]
"""
import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "Documentation", "datasets"))
import ppiray_datasets  # noqa: E402


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--data", default=ppiray_datasets.DATA, help="the data root")
    ppiray_datasets.DATA = parser.parse_args().data
    if not os.path.exists(os.path.join(ppiray_datasets.DATA, "notch", "notch_stress.vtk")):
        print("SKIP: no notch/notch_stress.vtk in", ppiray_datasets.DATA)
        return 125
    from notch_tetrahedralized import measure, notch_with_linear_field, retyped
    grid = notch_with_linear_field()
    failures = []
    typed = measure("retyped VTK_QUADRATIC_HEXAHEDRON", retyped(grid), 256)
    if (typed["peels"] != 1 or typed["lenses"] < 1 or typed["covered"] < 10000 or typed["nan"]
            or typed["p99"] > 1.0 or typed["max"] > 1.0):
        failures.append("retyped: expected one peel, lenses, within 1/255 over 10,000 pixels")
    tangle = measure("as typed in the file (VTK_HEXAHEDRON, 20 ids)", grid, 256)
    if tangle["brighter"] > 8.0 or tangle["nan"] or tangle["covered"] < 10000:
        failures.append("as typed: more than 8/255 brighter than the union of its cells")
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
