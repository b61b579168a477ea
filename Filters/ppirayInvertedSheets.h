/**
 * @file   ppirayInvertedSheets.h
 * @brief  which cells of a tangled mesh are inverted: the minority side of its folds
 *
 * A face whose two cells lie on one side of it is folded: the mesh turns back
 * on itself there. Going from cell to cell, the orientation of the mesh
 * flips across every folded face and stays across every other; each
 * connected part takes the orientation that holds the larger volume as
 * forward, and the cells of the other orientation are inverted. (A cell's
 * own vertex order does not say this: vtkDataSetTriangleFilter orders
 * tetrahedra arbitrarily.) Where the flips contradict each other around a
 * cycle, the first orientation reached (breadth first from the lowest cell
 * id) stands.
 *
 * The ray casters use it at a folded face: leaving a forward cell into an
 * inverted one, the ray walks back through the inverted cell; leaving an
 * inverted cell into a forward one, it walks back through the cell it is in
 * (Documentation/algorithms.md, "Degenerate, inverted and tangled cells").
 */
#ifndef ppirayInvertedSheets_h
#define ppirayInvertedSheets_h

#include "vtkType.h"

#include <cstddef> // for size_t
#include <vector>  // for std::vector

namespace ppiray
{
/**
 * Inverted flags (1) for `numberOfCells` cells with `facesPerCell` faces:
 * neighbor(c, f) is the cell across face f of c (< 0: none), folded(c, f)
 * whether that face is folded, volume(c) the cell's unsigned volume.
 */
template<typename Neighbor, typename Folded, typename Volume>
std::vector<unsigned char> InvertedSheets(
  vtkIdType numberOfCells, int facesPerCell, Neighbor&& neighbor, Folded&& folded, Volume&& volume)
{
  std::vector<signed char> orientation(numberOfCells, 0);
  std::vector<vtkIdType> part;
  for (vtkIdType seed = 0; seed < numberOfCells; ++seed)
  {
    if (orientation[seed] != 0)
    {
      continue;
    }
    part.assign(1, seed);
    orientation[seed] = 1;
    double forward = 0, backward = 0;
    for (size_t k = 0; k < part.size(); ++k)
    {
      const vtkIdType c = part[k];
      (orientation[c] > 0 ? forward : backward) += volume(c);
      for (int f = 0; f < facesPerCell; ++f)
      {
        const vtkIdType n = neighbor(c, f);
        if (n >= 0 && orientation[n] == 0)
        {
          const int flip = folded(c, f) ? -1 : 1;
          orientation[n] = static_cast<signed char>(flip * orientation[c]);
          part.push_back(n);
        }
      }
    }
    if (backward > forward)
    {
      for (vtkIdType c : part)
      {
        orientation[c] = static_cast<signed char>(-orientation[c]);
      }
    }
  }
  std::vector<unsigned char> inverted(static_cast<size_t>(numberOfCells));
  for (vtkIdType c = 0; c < numberOfCells; ++c)
  {
    inverted[c] = orientation[c] < 0 ? 1 : 0;
  }
  return inverted;
}

/**
 * At a folded face from `cell` into `neighbor`: whether the ray walks back
 * through the cell it is in (it is inverted, the neighbour is not) rather
 * than through the neighbour.
 */
inline bool WalksBackInPlace(
  const std::vector<unsigned char>& inverted, vtkIdType cell, vtkIdType neighbor)
{
  return inverted[cell] && !inverted[neighbor];
}
}

#endif
