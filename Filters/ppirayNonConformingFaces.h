/**
 * @file   ppirayNonConformingFaces.h
 * @brief  open faces that meet other open faces geometrically (hanging nodes, T-junctions)
 *
 * The adjacency pairs faces by point ids (ppirayCellAdjacency.h). Where a
 * mesh is non-conforming (a face next to four smaller ones at a hanging
 * node, a triangle whose edge holds another's vertex, the two sides of a
 * fault with consistent geometry, or the same face through duplicated
 * points) both sides stay open and a ray would leave the mesh there and
 * need a peel to come back. MatchNonConformingFaces() finds, for each open
 * face, the open faces of other cells across it: coplanar (every corner
 * within 1e-5 of the larger face's diameter of the other's plane), facing
 * it (unit normals n_a . n_b < -(1 - 1e-6)), overlapping with positive area
 * (the area of the intersection of their triangles projected on the plane,
 * by clipping, above 1e-6 of the smaller face's area). A face is covered
 * when its overlaps add up to its area (within 1e-5): a ray leaving it
 * anywhere enters one of them. Faces at exactly the same places (a seam's
 * duplicated points) are paired first, planar or not
 * (PairCoincidentFaces()). A quadrilateral whose two sides are split along
 * different diagonals (a curved face tetrahedralized differently on each
 * side) is two surfaces with a thin lens between them that both cells or
 * neither cover; each of its triangles is linked to the two across
 * (MatchSplitQuadrilaterals()), and the march enters the one the ray
 * crosses (listed_faces_fs.glsl).
 */
#ifndef ppirayNonConformingFaces_h
#define ppirayNonConformingFaces_h

#include "ppirayFiltersModule.h" // for export macro
#include "vtkType.h"

#include <algorithm>
#include <array>
#include <vector>

namespace ppiray
{
/** An open face: its cell and its triangles (point ids, wound outward). */
struct OpenFace
{
  vtkIdType Cell;
  int Triangles; // 1 or 2
  std::array<vtkIdType, 6> Points;
  vtkIdType Apex = -1; // a corner of its cell off the face (-1: not given)
};

/** What MatchNonConformingFaces() finds, per open face (indices into the faces). */
struct FaceOverlaps
{
  /** The faces across face i: Across[Offsets[i] .. Offsets[i + 1]). */
  std::vector<vtkIdType> Offsets{ 0 };
  std::vector<vtkIdType> Across;
  /** Whether the faces across face i cover it. */
  std::vector<unsigned char> Covered;
};

/** `points`: 3 doubles per point id. */
PPIRAYFILTERS_EXPORT FaceOverlaps MatchNonConformingFaces(
  const double* points, const std::vector<OpenFace>& faces);

/**
 * Open faces that make one quadrilateral split along one diagonal on one
 * side and along the other (or the same) on the other: per face, the faces
 * across (1 or 2), all Covered. Points at the same places count as one
 * (a seam). A side is a face of two triangles, or two one-triangle faces
 * (of any cells) that share an edge (the only two open faces on it, wound
 * alike, unit normals within 60 degrees); two sides with the same four
 * corners face each other across a lens: area vectors opposite, no cell
 * on both, and each side's cells beyond the other side (their apexes on
 * its outer side: not the top and bottom of one thin body). Sides are built
 * only where they may face one (not on a boundary surface): two triangles
 * whose other diagonal is an edge of open triangles too or splits an open
 * face of two, or whose diagonal splits one; a face of two one of whose
 * diagonals is an edge of open triangles. Corners on more than two sides,
 * and matches with a face in another match, are left alone.
 */
PPIRAYFILTERS_EXPORT FaceOverlaps MatchSplitQuadrilaterals(
  const double* points, const std::vector<OpenFace>& faces);

/**
 * Per open face, the other open face whose distinct corners are at the same
 * places (the same face through duplicated points: a seam), of another cell
 * and facing it (area vectors opposite); -1 where there is none or more than
 * one. Planar or not: the two sides may split a quadrilateral along
 * different diagonals (their ids differ), which the caller then aligns.
 */
PPIRAYFILTERS_EXPORT std::vector<vtkIdType> PairCoincidentFaces(
  const double* points, const std::vector<OpenFace>& faces);

/**
 * A face list's count carries this when its faces are the other side of a
 * lens (MatchSplitQuadrilaterals()): the march enters the face the ray
 * crosses, where it crosses it (listed_faces_fs.glsl).
 */
constexpr int LensList()
{
  return 1 << 16;
}

/**
 * Appends a list of neighbour codes to a neighbour array (their number n,
 * plus LensList() for a lens, then the codes, padded with -1 to whole texels
 * of 4) and returns the code that names it: `listBase` + its first texel.
 */
PPIRAYFILTERS_EXPORT int AppendFaceList(
  std::vector<int>& neighbors, const std::vector<int>& codes, int listBase, bool lens = false);

/** What LinkNonConformingFaces() did. */
struct NonConformingLinks
{
  /** Open faces linked to the faces across them (covered or not). */
  vtkIdType Faces = 0;
  /** Of those, faces at the same places as the one across (PairCoincidentFaces()). */
  vtkIdType Coincident = 0;
  /** Of those, the faces of a quadrilateral split otherwise across (MatchSplitQuadrilaterals()). */
  vtkIdType Lenses = 0;
  /** Of those, the faces that need a list (lenses, more than one face across, or not covered). */
  vtkIdType Lists = 0;
  /** The longest list. */
  int MaximumPieces = 0;
  /** Per open face: covered and linked (no longer a boundary face to enter by). */
  std::vector<unsigned char> Covered;
};

/**
 * Links each open face to the open faces across it: a face at the same places
 * as another (PairCoincidentFaces()) gets its code, and `paired(i, j)` is
 * called for each such pair, both ways; the faces of a quadrilateral split
 * otherwise across (MatchSplitQuadrilaterals()) a lens list of the faces
 * across; of the others (MatchNonConformingFaces()), a face that one face
 * covers gets that face's
 * code, any other a list of their codes (AppendFaceList(); the march takes
 * the one the exit point lies in, or none: listed_faces_fs.glsl), at most
 * `maximumPieces` (else left open). `code(i)`: the neighbour code that
 * enters open face i; `slot(i)`: its entry in `neighbors`. A face not
 * covered stays a boundary face too (rays enter the mesh where it is
 * exposed).
 */
template<typename Code, typename Slot, typename Paired>
NonConformingLinks LinkNonConformingFaces(const double* points, const std::vector<OpenFace>& faces,
  Code code, Slot slot, Paired paired, int listBase, int maximumPieces, std::vector<int>& neighbors)
{
  NonConformingLinks links;
  links.Covered.assign(faces.size(), 0);
  const std::vector<vtkIdType> partner = PairCoincidentFaces(points, faces);
  std::vector<OpenFace> rest;
  std::vector<vtkIdType> restIndex; // face of each of the rest
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(faces.size()); ++i)
  {
    if (partner[i] < 0)
    {
      rest.push_back(faces[i]);
      restIndex.push_back(i);
      continue;
    }
    neighbors[slot(i)] = code(partner[i]);
    links.Covered[i] = 1;
    ++links.Faces;
    ++links.Coincident;
    paired(i, partner[i]);
  }
  std::vector<int> codes;
  const FaceOverlaps lenses = MatchSplitQuadrilaterals(points, rest);
  std::vector<OpenFace> planar;
  std::vector<vtkIdType> planarIndex;
  for (vtkIdType r = 0; r < static_cast<vtkIdType>(rest.size()); ++r)
  {
    const vtkIdType i = restIndex[r];
    if (!lenses.Covered[r])
    {
      planar.push_back(rest[r]);
      planarIndex.push_back(i);
      continue;
    }
    codes.clear();
    for (vtkIdType k = lenses.Offsets[r]; k < lenses.Offsets[r + 1]; ++k)
    {
      codes.push_back(code(restIndex[lenses.Across[k]]));
    }
    neighbors[slot(i)] = AppendFaceList(neighbors, codes, listBase, true);
    links.Covered[i] = 1;
    ++links.Faces;
    ++links.Lenses;
    ++links.Lists;
    links.MaximumPieces = std::max(links.MaximumPieces, static_cast<int>(codes.size()));
  }
  rest.swap(planar);
  restIndex.swap(planarIndex);
  const FaceOverlaps overlaps = MatchNonConformingFaces(points, rest);
  for (vtkIdType r = 0; r < static_cast<vtkIdType>(rest.size()); ++r)
  {
    const vtkIdType i = restIndex[r];
    const vtkIdType first = overlaps.Offsets[r], n = overlaps.Offsets[r + 1] - first;
    if (n == 0 || n > maximumPieces)
    {
      continue;
    }
    ++links.Faces;
    links.Covered[i] = overlaps.Covered[r];
    if (n == 1 && overlaps.Covered[r])
    {
      neighbors[slot(i)] = code(restIndex[overlaps.Across[first]]);
      continue;
    }
    codes.clear();
    for (vtkIdType k = first; k < first + n; ++k)
    {
      codes.push_back(code(restIndex[overlaps.Across[k]]));
    }
    neighbors[slot(i)] = AppendFaceList(neighbors, codes, listBase);
    ++links.Lists;
    links.MaximumPieces = std::max(links.MaximumPieces, static_cast<int>(n));
  }
  return links;
}
}

#endif
