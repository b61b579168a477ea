#include "ppirayGridGeometryKey.h"

#include "ppirayVTKCompatibility.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cstring>

namespace
{
constexpr uint64_t LowScale = 0x9E3779B97F4A7C15ULL, LowMix = 0xC2B2AE3D27D4EB4FULL;
constexpr uint64_t HighScale = 0x165667B19E3779F9ULL, HighMix = 0xD6E8FEB86659FD93ULL;

uint64_t RotateLeft(uint64_t x, int r)
{
  return (x << r) | (x >> (64 - r));
}

// One word into both lanes: h <- rotl(h ^ k1 w, r) k2 (k1, k2 odd).
void MixWord(ppiray::ContentDigest& d, uint64_t w)
{
  d.Low = RotateLeft(d.Low ^ (w * LowScale), 31) * LowMix;
  d.High = RotateLeft(d.High ^ (w * HighScale), 27) * HighMix;
}

// Digest of a double per value, for arrays without a standard memory layout.
ppiray::ContentDigest DigestValues(vtkDataArray* array, ppiray::ContentDigest d)
{
  const vtkIdType tuples = array->GetNumberOfTuples();
  const int components = array->GetNumberOfComponents();
  for (vtkIdType t = 0; t < tuples; ++t)
  {
    for (int c = 0; c < components; ++c)
    {
      const double v = array->GetComponent(t, c);
      uint64_t w;
      std::memcpy(&w, &v, sizeof(w));
      MixWord(d, w);
    }
  }
  return d;
}

// An array of the geometry and the object whose modification time covers it
// (the array itself, or the vtkPoints or vtkCellArray holding it).
struct GeometryArray
{
  vtkDataArray* Array;
  vtkObject* Holder;
};

// Every array the cell textures are built from (ppirayGridGeometryKey.h).
std::vector<GeometryArray> GeometryArrays(vtkUnstructuredGrid* grid)
{
  std::vector<GeometryArray> arrays;
  vtkPoints* points = grid->GetPoints();
  arrays.push_back({ points ? points->GetData() : nullptr, points });
  vtkCellArray* cells = grid->GetCells();
  arrays.push_back({ cells ? cells->GetOffsetsArray() : nullptr, cells });
  arrays.push_back({ cells ? cells->GetConnectivityArray() : nullptr, cells });
  arrays.push_back({ grid->GetCellTypesArray(), grid->GetCellTypesArray() });
  for (const auto& faces : ppiray::compat::PolyhedronFaceArrays(grid))
  {
    arrays.push_back({ faces.first, faces.second });
  }
  arrays.push_back({ grid->GetCellGhostArray(), grid->GetCellGhostArray() });
  return arrays;
}
}

namespace ppiray
{
//------------------------------------------------------------------------------
ContentDigest DigestBytes(const void* data, size_t bytes, const ContentDigest& seed)
{
  ContentDigest d = seed;
  const auto* p = static_cast<const unsigned char*>(data);
  const size_t words = bytes / 8;
  for (size_t i = 0; i < words; ++i)
  {
    uint64_t w;
    std::memcpy(&w, p + 8 * i, sizeof(w));
    MixWord(d, w);
  }
  uint64_t tail = 0;
  std::memcpy(&tail, p + 8 * words, bytes - 8 * words);
  MixWord(d, tail);
  MixWord(d, static_cast<uint64_t>(bytes));
  return d;
}

//------------------------------------------------------------------------------
ContentDigest DigestArray(vtkDataArray* array)
{
  ContentDigest d;
  if (!array)
  {
    MixWord(d, ~0ULL);
    return d;
  }
  MixWord(d, static_cast<uint64_t>(array->GetDataType()));
  MixWord(d, static_cast<uint64_t>(array->GetNumberOfComponents()));
  MixWord(d, static_cast<uint64_t>(array->GetNumberOfTuples()));
  if (!array->HasStandardMemoryLayout() || array->GetDataTypeSize() <= 0)
  {
    return DigestValues(array, d);
  }
  const size_t bytes =
    static_cast<size_t>(array->GetNumberOfValues()) * static_cast<size_t>(array->GetDataTypeSize());
  return bytes > 0 ? DigestBytes(array->GetVoidPointer(0), bytes, d) : d;
}

//------------------------------------------------------------------------------
GridGeometryKey::Match GridGeometryKey::Update(vtkUnstructuredGridBase* input)
{
  auto* grid = vtkUnstructuredGrid::SafeDownCast(input);
  if (!grid)
  {
    const bool same = this->Recorded && this->Parts.empty() && this->Grid == input &&
                      this->GridTime == input->GetMTime();
    this->Reset();
    this->Recorded = true;
    this->Grid = input;
    this->GridTime = input->GetMTime();
    return same ? Match::Same : Match::Changed;
  }
  const std::vector<GeometryArray> arrays = GeometryArrays(grid);
  const bool comparable =
    this->Recorded && this->Grid == nullptr && this->Parts.size() == arrays.size();
  Match match = comparable ? Match::Same : Match::Changed;
  std::vector<Part> parts(arrays.size());
  for (size_t i = 0; i < arrays.size(); ++i)
  {
    Part& part = parts[i];
    part.Object = arrays[i].Array;
    part.Time = arrays[i].Holder ? std::max(arrays[i].Holder->GetMTime(),
                                     arrays[i].Array ? arrays[i].Array->GetMTime() : 0)
                                 : 0;
    const bool identical =
      comparable && part.Object == this->Parts[i].Object && part.Time == this->Parts[i].Time;
    part.Digest = identical ? this->Parts[i].Digest : DigestArray(arrays[i].Array);
    if (!identical && match != Match::Changed)
    {
      match = part.Digest == this->Parts[i].Digest ? Match::SameContent : Match::Changed;
    }
  }
  this->Parts = std::move(parts);
  this->Recorded = true;
  this->Grid = nullptr;
  return match;
}

//------------------------------------------------------------------------------
void GridGeometryKey::Reset()
{
  this->Recorded = false;
  this->Grid = nullptr;
  this->GridTime = 0;
  this->Parts.clear();
}
}
