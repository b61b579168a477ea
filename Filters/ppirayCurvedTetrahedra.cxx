#include "ppirayCurvedTetrahedra.h"

#include "ppirayQuadraticTetrahedra.h"
#include "vtkQuadraticTetra.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace ppiray
{
namespace
{
// A point of the cell's barycentric lattice: integer coordinates summing to
// the lattice's resolution.
using Lattice = std::array<int, 4>;

Lattice Midpoint(const Lattice& a, const Lattice& b)
{
  return { (a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2, (a[3] + b[3]) / 2 };
}

// Red refinement of (a, b, c, d): the four corner tetrahedra and the four
// around the octahedron's diagonal m_ac - m_bd.
void RedRefine(
  const std::array<Lattice, 4>& t, int levels, std::vector<std::array<Lattice, 4>>& out)
{
  if (levels == 0)
  {
    out.push_back(t);
    return;
  }
  const Lattice &a = t[0], &b = t[1], &c = t[2], &d = t[3];
  const Lattice ab = Midpoint(a, b), ac = Midpoint(a, c), ad = Midpoint(a, d);
  const Lattice bc = Midpoint(b, c), bd = Midpoint(b, d), cd = Midpoint(c, d);
  const std::array<Lattice, 4> children[8] = { { a, ab, ac, ad }, { ab, b, bc, bd },
    { ac, bc, c, cd }, { ad, bd, cd, d }, { ac, bd, ab, ad }, { ac, bd, ad, cd },
    { ac, bd, cd, bc }, { ac, bd, bc, ab } };
  for (const auto& child : children)
  {
    RedRefine(child, levels - 1, out);
  }
}

// Nodes of the lattice keyed by the point ids and lattice coordinates of
// their nonzero barycentric coordinates, sorted by id: a face's or an edge's
// nodes have the same key from either cell.
using NodeKey = std::array<vtkIdType, 8>;

class NodeNumbering
{
public:
  NodeNumbering(
    const double* points, vtkIdType numberOfPoints, int resolution, RefinedTetrahedra& refined)
    : Points(points)
    , NumberOfPoints(numberOfPoints)
    , Resolution(resolution)
    , Added(refined.Added)
    , Linear(refined.Linear)
  {
  }

  // The id of lattice point q of the cell with nodes `ids`: a corner or the
  // mid-edge node of an edge, else a point added at the cell's map there.
  vtkIdType Id(const std::array<vtkIdType, 10>& ids, const Lattice& q)
  {
    int nonzero = 0, only = 0;
    for (int i = 0; i < 4; ++i)
    {
      nonzero += q[i] != 0 ? 1 : 0;
      only = q[i] != 0 ? i : only;
    }
    if (nonzero == 1)
    {
      return ids[only];
    }
    for (int k = 0; k < 6; ++k)
    {
      const int a = quadratic_tetrahedron::Edge[k][0], b = quadratic_tetrahedron::Edge[k][1];
      if (nonzero == 2 && 2 * q[a] == this->Resolution && 2 * q[b] == this->Resolution)
      {
        return ids[4 + k];
      }
    }
    std::array<std::pair<vtkIdType, int>, 4> terms;
    int n = 0;
    for (int i = 0; i < 4; ++i)
    {
      if (q[i] != 0)
      {
        terms[n++] = { ids[i], q[i] };
      }
    }
    std::sort(terms.begin(), terms.begin() + n);
    NodeKey key;
    key.fill(-1);
    for (int i = 0; i < n; ++i)
    {
      key[2 * i] = terms[i].first;
      key[2 * i + 1] = terms[i].second;
    }
    const auto found = this->Nodes.find(key);
    if (found != this->Nodes.end())
    {
      return found->second;
    }
    const vtkIdType id = this->NumberOfPoints + this->Added.GetNumberOfPoints();
    this->Nodes.emplace(key, id);
    this->Add(ids, q);
    return id;
  }

private:
  // x = sum_i N_i(p) X_i at p = (l_1, l_2, l_3), the weights N_i kept.
  void Add(const std::array<vtkIdType, 10>& ids, const Lattice& q)
  {
    const double p[3] = { static_cast<double>(q[1]) / this->Resolution,
      static_cast<double>(q[2]) / this->Resolution, static_cast<double>(q[3]) / this->Resolution };
    double weights[10], x[3] = { 0, 0, 0 };
    vtkQuadraticTetra::InterpolationFunctions(p, weights);
    for (int i = 0; i < 10; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        x[k] += weights[i] * this->Points[3 * ids[i] + k];
      }
      if (weights[i] != 0.0)
      {
        this->Added.Ids.push_back(ids[i]);
        this->Added.Weights.push_back(weights[i]);
      }
    }
    this->Added.Offsets.push_back(static_cast<vtkIdType>(this->Added.Ids.size()));
    this->Added.Points.insert(this->Added.Points.end(), x, x + 3);
    for (int i = 0; i < 4; ++i)
    {
      if (q[i] != 0)
      {
        this->Linear.Ids.push_back(ids[i]);
        this->Linear.Weights.push_back(static_cast<double>(q[i]) / this->Resolution);
      }
    }
    this->Linear.Offsets.push_back(static_cast<vtkIdType>(this->Linear.Ids.size()));
    this->Linear.Points.insert(this->Linear.Points.end(), x, x + 3);
  }

  const double* Points;
  vtkIdType NumberOfPoints;
  int Resolution;
  AddedPoints& Added;
  AddedPoints& Linear;
  std::map<NodeKey, vtkIdType> Nodes;
};
}

//------------------------------------------------------------------------------
void RefineQuadraticTetrahedra(const double* points, vtkIdType numberOfPoints,
  const std::vector<std::array<vtkIdType, 10>>& cells, int levels, RefinedTetrahedra& out)
{
  out = RefinedTetrahedra();
  // Pieces' corners on the lattice of resolution 2^levels, their mid-edge
  // nodes on that of 2^(levels + 1).
  const int resolution = 2 << levels;
  std::vector<std::array<Lattice, 4>> pieces;
  RedRefine({ Lattice{ resolution, 0, 0, 0 }, Lattice{ 0, resolution, 0, 0 },
              Lattice{ 0, 0, resolution, 0 }, Lattice{ 0, 0, 0, resolution } },
    levels, pieces);
  NodeNumbering numbering(points, numberOfPoints, resolution, out);
  out.Resolution = resolution;
  out.Pieces.reserve(cells.size() * pieces.size());
  out.Cell.reserve(cells.size() * pieces.size());
  for (size_t c = 0; c < cells.size(); ++c)
  {
    for (const auto& piece : pieces)
    {
      std::array<vtkIdType, 10> nodes;
      for (int i = 0; i < 4; ++i)
      {
        nodes[i] = numbering.Id(cells[c], piece[i]);
      }
      for (int k = 0; k < 6; ++k)
      {
        nodes[4 + k] = numbering.Id(cells[c], Midpoint(piece[quadratic_tetrahedron::Edge[k][0]],
                                                piece[quadratic_tetrahedron::Edge[k][1]]));
      }
      out.Pieces.push_back(nodes);
      out.Cell.push_back(static_cast<vtkIdType>(c));
      PieceCorners corners;
      for (int i = 0; i < 4; ++i)
      {
        for (int k = 0; k < 4; ++k)
        {
          corners[i][k] = static_cast<unsigned char>(piece[i][k]);
        }
      }
      out.Corners.push_back(corners);
    }
  }
}

//------------------------------------------------------------------------------
void LinearCornerValues(
  const PieceCorners& corners, int resolution, const double s[4], double out[4])
{
  for (int i = 0; i < 4; ++i)
  {
    out[i] = 0;
    for (int k = 0; k < 4; ++k)
    {
      out[i] += corners[i][k] * s[k] / resolution;
    }
  }
}

//------------------------------------------------------------------------------
int RefinementLevels(
  double deviation, double tolerance, vtkIdType cells, int maximumLevels, vtkIdType maximumPieces)
{
  int levels = 0;
  double pieces = static_cast<double>(cells);
  while (levels < maximumLevels && deviation > tolerance &&
         8.0 * pieces <= static_cast<double>(maximumPieces))
  {
    deviation *= 0.25;
    pieces *= 8.0;
    ++levels;
  }
  return levels;
}
}
