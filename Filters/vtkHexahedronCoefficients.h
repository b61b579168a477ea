/**
 * @class   vtkHexahedronCoefficients
 * @brief   per hexahedron: a frame attached to the cell, the trilinear field
 *          in that frame, and quality flags
 *
 * For every hexahedron (VTK_HEXAHEDRON, VTK_VOXEL, and the corners of
 * quadratic hexahedra) with corners p0..p7 in VTK's order and point scalars
 * s0..s7:
 *
 * - the frame: origin p0 and axes a = p1 - p0, b = p3 - p0, c = p4 - p0 (the
 *   cell's three edges from p0). A point x has frame coordinates
 *   (u, v, w) = [a b c]^-1 (x - p0); a parallelepiped maps to the unit cube.
 * - the coefficients of
 *     f(u, v, w) = c0 + c1 u + c2 v + c3 w + c4 uv + c5 vw + c6 uw + c7 uvw
 *   that take the corner values at the corners' frame coordinates. For a
 *   parallelepiped the corners sit at the unit cube's and f is exactly the
 *   isoparametric (trilinear) field: c0 = s0, c1 = s1 - s0, c2 = s3 - s0,
 *   c3 = s4 - s0, c4 = s0 - s1 + s2 - s3, c5 = s0 - s3 - s4 + s7,
 *   c6 = s0 - s1 - s4 + s5, c7 = -s0 + s1 - s2 + s3 + s4 - s5 + s6 - s7.
 *   For other hexahedra c0..c3 are the same (p0, p1, p3, p4 are at the unit
 *   cube's corners by construction) and c4..c7 solve the 4x4 system of the
 *   other four corners (Gaussian elimination, partial pivoting, in double).
 *
 * Miranda (2011, Sec. 3.1) fits c0..c7 in world coordinates instead: for a
 * cube turned 45 degrees about z, xy and xyz vanish at all eight corners and
 * that 8x8 system is singular. In the cell's frame the system is the identity
 * for every parallelepiped, whatever its rotation, shear or scale.
 *
 * Quality flags (bit mask): NON_PLANAR_FACE (on some face the two diagonals,
 * as lines, are further apart than NonPlanarityTolerance times the longer
 * one; zero exactly when the face is planar), COLLAPSED_EDGE (an edge shorter than
 * CollapsedEdgeTolerance times the cell's longest edge: degenerate
 * hexahedra, e.g. reservoir pinch-outs), INVERTED (a corner's three edges
 * form a left-handed frame), SINGULAR (the 4x4 system has no usable pivot;
 * the parallelepiped formulas are used), NOT_A_HEXAHEDRON (other cells:
 * frame and coefficients zero).
 *
 * Output: the input with cell data "HexahedronFrame" (12 components: origin,
 * a, b, c), "HexahedronCoefficients" (8), "HexahedronQuality" (flags) and
 * "FaceNonPlanarity" (the largest relative deviation above). Scalars: the
 * input array to process 0 (default: the active point scalars), component 0.
 * Parallel over cells (OpenMP) in blocks, with progress events between
 * blocks.
 */
#ifndef vtkHexahedronCoefficients_h
#define vtkHexahedronCoefficients_h

#include "ppirayFiltersModule.h" // for export macro
#include "vtkUnstructuredGridAlgorithm.h"

class PPIRAYFILTERS_EXPORT vtkHexahedronCoefficients : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkHexahedronCoefficients* New();
  vtkTypeMacro(vtkHexahedronCoefficients, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum QualityFlags
  {
    NON_PLANAR_FACE = 1,
    COLLAPSED_EDGE = 2,
    INVERTED = 4,
    SINGULAR = 8,
    NOT_A_HEXAHEDRON = 16
  };

  ///@{
  /** Relative face deviation above which NON_PLANAR_FACE is set (default 1e-3). */
  vtkSetClampMacro(NonPlanarityTolerance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(NonPlanarityTolerance, double);
  ///@}

  ///@{
  /** Relative edge length below which COLLAPSED_EDGE is set (default 1e-6). */
  vtkSetClampMacro(CollapsedEdgeTolerance, double, 0.0, 1.0);
  vtkGetMacro(CollapsedEdgeTolerance, double);
  ///@}

  /**
   * One hexahedron: corners in VTK_HEXAHEDRON order and their scalars in,
   * frame (origin, a, b, c), coefficients and the largest relative face
   * deviation out; returns the quality flags.
   */
  static int ComputeCell(const double corners[8][3], const double scalars[8],
    double tolerancePlanarity, double toleranceCollapse, double frame[12], double coefficients[8],
    double* nonPlanarity);

  /**
   * The field's coefficients in the cell frame of corners p (VTK_HEXAHEDRON
   * order) with scalars s, and that frame (origin, a, b, c): the fit above,
   * without the quality checks of ComputeCell(). Returns false when the 4x4
   * system is singular (the parallelepiped formulas are then kept).
   */
  static bool FitCoefficients(
    const double corners[8][3], const double scalars[8], double frame[12], double coefficients[8]);

  /**
   * Neighbour `axis` (0..2) of corner `corner` along its edges, ordered so that
   * the three span a right-handed frame at every corner of a valid
   * hexahedron: det[p_n0 - p_i, p_n1 - p_i, p_n2 - p_i] > 0. Corner 0's are
   * 1, 3, 4 (the cell frame).
   */
  static int CornerNeighbor(int corner, int axis);

  /** Frame coordinates (u, v, w) of world point x. Returns false if the frame is singular. */
  static bool ToFrame(const double frame[12], const double x[3], double uvw[3]);

  /** f(u, v, w) of the coefficients (the polynomial above). */
  static double EvaluateField(const double coefficients[8], const double uvw[3]);

protected:
  vtkHexahedronCoefficients();
  ~vtkHexahedronCoefficients() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double NonPlanarityTolerance = 1e-3;
  double CollapsedEdgeTolerance = 1e-6;

private:
  vtkHexahedronCoefficients(const vtkHexahedronCoefficients&) = delete;
  void operator=(const vtkHexahedronCoefficients&) = delete;
};

#endif
