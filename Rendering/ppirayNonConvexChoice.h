/**
 * @file   ppirayNonConvexChoice.h
 * @brief  NON_CONVEX_AUTOMATIC: peel or convexify, decided from what a frame measured
 *
 * Documentation/convexification.md's rule of thumb: a frame costs about
 * peels x (a full-screen pass) + (cell steps); convexifying leaves one pass
 * and adds the steps through the imaginary cells. So, per geometry (the
 * same points and cells: ppiray::GridGeometryKey), from the first frame
 * that drew something:
 *  - peel when the frame took fewer than MinimumPeels peels, or the mesh is
 *    marched natively as hexahedra (structured meshes: their fill brings
 *    Steiner points by the thousand and more imaginary cells than cells,
 *    and a convexified hexahedral mesh is marched as tetrahedra);
 *  - else convexify for the next frame, and keep it when the fill is small
 *    (imaginary cells at most the mesh's cells, added points beyond the
 *    box's 8 corners at most SteinerFraction of the mesh's points: the
 *    Steiner points that split boundary faces) and that frame took at most
 *    ConvexifiedPeels peels; otherwise peel from then on.
 * The frame that tries the fill renders convexified: every frame's image is
 * right either way, only the time differs.
 */
#ifndef ppirayNonConvexChoice_h
#define ppirayNonConvexChoice_h

#include "ppirayGridGeometryKey.h" // for ppiray::GridGeometryKey
#include "ppirayMapperModes.h"     // for ppiray::NonConvexMode
#include "vtkUnstructuredGridBase.h"

namespace ppiray
{
class NonConvexChoice
{
public:
  static constexpr int MinimumPeels = 4;
  static constexpr int ConvexifiedPeels = 2;
  static constexpr double SteinerFraction = 1.0e-3;

  /** Whether to render `input` convexified: the choice for its geometry (tried or kept). */
  bool Convexifies(vtkUnstructuredGridBase* input)
  {
    if (this->Key.Update(input) == GridGeometryKey::Match::Changed)
    {
      this->State = Undecided;
      this->Cells = input->GetNumberOfCells();
      this->Points = input->GetNumberOfPoints();
    }
    return this->State == Trying || this->State == Convexify;
  }

  /**
   * What the frame measured: its peels, the grid it rendered (`rendered`:
   * the convexified one while trying) and whether hexahedra were marched
   * natively.
   */
  void Observe(int peels, vtkUnstructuredGridBase* rendered, bool nativeHexahedra)
  {
    if (this->State == Undecided && peels > 0)
    {
      this->State = peels >= MinimumPeels && !nativeHexahedra ? Trying : Peel;
    }
    else if (this->State == Trying)
    {
      const vtkIdType imaginary = rendered->GetNumberOfCells() - this->Cells;
      const vtkIdType steiner = rendered->GetNumberOfPoints() - this->Points - 8;
      const bool small =
        imaginary > 0 && imaginary <= this->Cells &&
        static_cast<double>(steiner) <= SteinerFraction * static_cast<double>(this->Points);
      this->State = small && peels <= ConvexifiedPeels ? Convexify : Peel;
    }
  }

  /** NonConvexConvexify while convexifying (tried or kept), else NonConvexPeel. */
  int GetChoice() const
  {
    return this->State == Trying || this->State == Convexify ? NonConvexConvexify : NonConvexPeel;
  }

private:
  enum
  {
    Undecided,
    Trying,
    Peel,
    Convexify
  } State = Undecided;
  GridGeometryKey Key;
  vtkIdType Cells = 0;
  vtkIdType Points = 0;
};
}

#endif
