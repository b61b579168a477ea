/**
 * @file   ppirayGridGeometryKey.h
 * @brief  whether a grid's points and cells are those of the grid last seen, by identity or content
 *
 * What a time-series reader hands over at every step is a new grid object,
 * often with new arrays, whose points and cells are those of the step
 * before; only the field changed. GridGeometryKey recognizes that, so that
 * everything built from the geometry (cell textures, adjacency, boundary,
 * folds) is kept and only the field is built again.
 *
 * The geometry is every array the cell textures are built from: the points,
 * the cells (offsets, connectivity), the cell types, the polyhedron faces and
 * the cell ghost array (hidden cells). Each is recognized first by identity
 * (the same array object, not modified since: VTK's convention that a
 * changed array is Modified()), else by content: a 128-bit digest of its
 * type, shape and values (ContentDigest), compared with the one recorded.
 */
#ifndef ppirayGridGeometryKey_h
#define ppirayGridGeometryKey_h

#include "ppirayFiltersModule.h" // for export macro
#include "vtkType.h"             // for vtkMTimeType

#include <array>   // for std::array
#include <cstddef> // for size_t
#include <cstdint> // for uint64_t
#include <vector>  // for std::vector

class vtkDataArray;
class vtkObject;
class vtkUnstructuredGridBase;

namespace ppiray
{
/**
 * A 128-bit digest of a byte string: two lanes over its 64-bit words, each
 * step h <- rotl(h ^ k1 w, r) k2 a bijection of h, so strings that differ
 * in one word always differ; the length is mixed in last.
 */
struct ContentDigest
{
  uint64_t Low = 0;
  uint64_t High = 0;
  bool operator==(const ContentDigest& other) const
  {
    return this->Low == other.Low && this->High == other.High;
  }
  bool operator!=(const ContentDigest& other) const { return !(*this == other); }
};

/** Digest of `bytes` bytes at `data`, continuing `seed`. */
PPIRAYFILTERS_EXPORT ContentDigest DigestBytes(
  const void* data, size_t bytes, const ContentDigest& seed = ContentDigest());

/**
 * Digest of an array's data type, components, tuples and values (its memory
 * where the layout is standard, else its values as doubles); of a null
 * array, a digest of its own.
 */
PPIRAYFILTERS_EXPORT ContentDigest DigestArray(vtkDataArray* array);

class PPIRAYFILTERS_EXPORT GridGeometryKey
{
public:
  enum class Match
  {
    Same,        // the same arrays, not modified since
    SameContent, // other arrays (or modified ones) holding the same values
    Changed      // a point, a cell, a type, a face or a hidden flag differs
  };

  /**
   * How `grid`'s geometry compares with the one last recorded (Changed the
   * first time); records `grid`'s. A grid that is not a vtkUnstructuredGrid
   * is Same only as the same object not modified since.
   */
  Match Update(vtkUnstructuredGridBase* grid);

  /** Forget what was recorded: the next Update() is Changed. */
  void Reset();

private:
  // One array of the geometry: its identity (object and modification time)
  // and, once read, its content.
  struct Part
  {
    vtkObject* Object = nullptr;
    vtkMTimeType Time = 0;
    ContentDigest Digest;
  };
  bool Recorded = false;
  vtkObject* Grid = nullptr; // a grid that is not a vtkUnstructuredGrid
  vtkMTimeType GridTime = 0;
  std::vector<Part> Parts;
};
}

#endif
