#include "ppirayHigherOrderPieces.h"

#include "ppirayConformingTetrahedra.h"
#include "ppirayLinearCellKinds.h"
#include "ppirayQuadraticTetrahedra.h"
#include "vtkGenericCell.h"
#include "vtkHexahedron.h"
#include "vtkNew.h"
#include "vtkPyramid.h"
#include "vtkTetra.h"
#include "vtkUnstructuredGrid.h"
#include "vtkWedge.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace ppiray
{
namespace
{
// A point of a kind's reference cell, its coordinates times the resolution
// R: VTK's parametric coordinates for the tetrahedron, hexahedron and wedge,
// the pyramid with its apex over the base centre (RefinementLevels' header).
using Reference = std::array<int, 3>;

// A sub-cell of the reference cell: a kind and its corners in VTK's order.
struct SubCell
{
  int Kind;
  std::array<Reference, 8> Corner;
};

Reference Midpoint(const Reference& a, const Reference& b)
{
  return { (a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2 };
}

// Red refinement of (a, b, c, d): the four corner tetrahedra and the four
// around the octahedron's diagonal m_ac - m_bd.
void RefineTetrahedron(const std::array<Reference, 4>& t, int levels, std::vector<SubCell>& out)
{
  if (levels == 0)
  {
    out.push_back({ TETRAHEDRON_KIND, { t[0], t[1], t[2], t[3] } });
    return;
  }
  const Reference &a = t[0], &b = t[1], &c = t[2], &d = t[3];
  const Reference ab = Midpoint(a, b), ac = Midpoint(a, c), ad = Midpoint(a, d);
  const Reference bc = Midpoint(b, c), bd = Midpoint(b, d), cd = Midpoint(c, d);
  const std::array<Reference, 4> children[8] = { { a, ab, ac, ad }, { ab, b, bc, bd },
    { ac, bc, c, cd }, { ad, bd, cd, d }, { ac, bd, ab, ad }, { ac, bd, ad, cd },
    { ac, bd, cd, bc }, { ac, bd, bc, ab } };
  for (const auto& child : children)
  {
    RefineTetrahedron(child, levels - 1, out);
  }
}

// A pyramid (base b0..b3, apex a) into the pyramids at its base corners, the
// one at its apex, the one upside down between them (base: the lateral
// edges' midpoints l_i, apex: the base centre c) and the tetrahedra
// (m_i,i+1, c, l_i, l_i+1) along the base edges.
void RefinePyramid(const std::array<Reference, 5>& p, int levels, std::vector<SubCell>& out)
{
  if (levels == 0)
  {
    out.push_back({ PYRAMID_KIND, { p[0], p[1], p[2], p[3], p[4] } });
    return;
  }
  Reference m[4], l[4];
  for (int i = 0; i < 4; ++i)
  {
    m[i] = Midpoint(p[i], p[(i + 1) % 4]);
    l[i] = Midpoint(p[i], p[4]);
  }
  const Reference c = Midpoint(p[0], p[2]);
  const std::array<Reference, 5> pyramids[6] = { { p[0], m[0], c, m[3], l[0] },
    { m[0], p[1], m[1], c, l[1] }, { c, m[1], p[2], m[2], l[2] }, { m[3], c, m[2], p[3], l[3] },
    { l[0], l[1], l[2], l[3], p[4] }, { l[0], l[1], l[2], l[3], c } };
  for (const auto& pyramid : pyramids)
  {
    RefinePyramid(pyramid, levels - 1, out);
  }
  for (int i = 0; i < 4; ++i)
  {
    RefineTetrahedron({ m[i], c, l[i], l[(i + 1) % 4] }, levels - 1, out);
  }
}

// The sub-cells of a kind's reference cell refined `levels` times, corners
// on multiples of 4 of the resolution 4 * 2^levels (the pyramid's apexes on
// multiples of 2, the pieces' edge midpoints on integers).
std::vector<SubCell> ReferenceSubCells(int kind, int levels)
{
  const int n = 1 << levels, h = 4, R = h * n;
  std::vector<SubCell> out;
  if (kind == TETRAHEDRON_KIND)
  {
    RefineTetrahedron({ Reference{ 0, 0, 0 }, { R, 0, 0 }, { 0, R, 0 }, { 0, 0, R } }, levels, out);
  }
  else if (kind == PYRAMID_KIND)
  {
    RefinePyramid(
      { Reference{ 0, 0, 0 }, { R, 0, 0 }, { R, R, 0 }, { 0, R, 0 }, { R / 2, R / 2, R } }, levels,
      out);
  }
  for (int k = 0; k < n && kind == HEXAHEDRON_KIND; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const int x = h * i, y = h * j, z = h * k;
        out.push_back({ HEXAHEDRON_KIND,
          { Reference{ x, y, z }, { x + h, y, z }, { x + h, y + h, z }, { x, y + h, z },
            { x, y, z + h }, { x + h, y, z + h }, { x + h, y + h, z + h }, { x, y + h, z + h } } });
      }
    }
  }
  // A wedge: the triangle's red refinement (up and down triangles) in layers.
  for (int k = 0; k < n && kind == WEDGE_KIND; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i + j < n; ++i)
      {
        const int x = h * i, y = h * j, z = h * k;
        out.push_back(
          { WEDGE_KIND, { Reference{ x, y, z }, { x + h, y, z }, { x, y + h, z }, { x, y, z + h },
                          { x + h, y, z + h }, { x, y + h, z + h } } });
        if (i + j + 1 < n)
        {
          out.push_back(
            { WEDGE_KIND, { Reference{ x + h, y, z }, { x + h, y + h, z }, { x, y + h, z },
                            { x + h, y, z + h }, { x + h, y + h, z + h }, { x, y + h, z + h } } });
        }
      }
    }
  }
  return out;
}

// VTK's parametric coordinates of reference point q (resolution R).
void ParametricCoordinates(int kind, const Reference& q, int R, double p[3])
{
  for (int k = 0; k < 3; ++k)
  {
    p[k] = static_cast<double>(q[k]) / R;
  }
  if (kind == PYRAMID_KIND && q[2] < R)
  {
    const double z = 0.5 * q[2];
    p[0] = (q[0] - z) / (R - q[2]);
    p[1] = (q[1] - z) / (R - q[2]);
  }
}

// The linear weights of a kind's corners at parametric point p.
int LinearWeights(int kind, const double p[3], double w[8])
{
  switch (kind)
  {
    case HEXAHEDRON_KIND:
      vtkHexahedron::InterpolationFunctions(p, w);
      return 8;
    case WEDGE_KIND:
      vtkWedge::InterpolationFunctions(p, w);
      return 6;
    case PYRAMID_KIND:
      vtkPyramid::InterpolationFunctions(p, w);
      return 5;
    default:
      vtkTetra::InterpolationFunctions(p, w);
      return 4;
  }
}

// A node's key: on the cell's boundary the sorted (corner id, weight x R^2)
// of the face's corners, which are integers there (bilinear or barycentric);
// inside the cell (-1 - cell index, reference coordinates).
using NodeKey = std::array<vtkIdType, 8>;

class NodeNumbering
{
public:
  NodeNumbering(vtkUnstructuredGrid* grid, const double* points, HigherOrderPieces& out)
    : Grid(grid)
    , Points(points)
    , NumberOfPoints(grid->GetNumberOfPoints())
    , Added(out.Added)
    , Linear(out.Linear)
  {
  }

  // Cell `index` of the list (input cell `cellId`, of `kind`), its reference at resolution R.
  void SetCell(vtkIdType index, vtkIdType cellId, int kind, int R)
  {
    this->Index = index;
    this->Kind = kind;
    this->Resolution = R;
    this->Grid->GetCell(cellId, this->Cell);
    this->Weights.resize(this->Cell->GetNumberOfPoints());
  }

  vtkIdType Id(const Reference& q)
  {
    double p[3], w[8];
    ParametricCoordinates(this->Kind, q, this->Resolution, p);
    const int corners = LinearWeights(this->Kind, p, w);
    std::array<std::pair<vtkIdType, vtkIdType>, 8> terms;
    int n = 0;
    bool onFace = false, integral = true;
    const double R2 = static_cast<double>(this->Resolution) * this->Resolution;
    for (int i = 0; i < corners; ++i)
    {
      onFace = onFace || w[i] == 0.0;
      const double scaled = w[i] * R2;
      if (w[i] != 0.0)
      {
        terms[n++] = { this->Cell->GetPointId(i), std::llround(scaled) };
        integral = integral && std::abs(scaled - std::llround(scaled)) < 1e-6;
      }
    }
    const bool boundary = onFace && integral;
    if (n == 1)
    {
      return terms[0].first; // a corner
    }
    NodeKey key;
    key.fill(-2);
    if (boundary)
    {
      std::sort(terms.begin(), terms.begin() + n);
      for (int i = 0; i < n; ++i)
      {
        key[2 * i] = terms[i].first;
        key[2 * i + 1] = terms[i].second;
      }
    }
    else
    {
      key = { -1 - this->Index, q[0], q[1], q[2], -2, -2, -2, -2 };
    }
    const auto found = this->Nodes.find(key);
    if (found != this->Nodes.end())
    {
      return found->second;
    }
    const vtkIdType id = this->NumberOfPoints + this->Added.GetNumberOfPoints();
    this->Nodes.emplace(key, id);
    this->Add(p, w, corners);
    return id;
  }

  // Coordinates of a grid point or an added one.
  const double* Point(vtkIdType id) const
  {
    return id < this->NumberOfPoints ? this->Points + 3 * id
                                     : this->Added.Points.data() + 3 * (id - this->NumberOfPoints);
  }

private:
  // x = sum_i N_i(p) X_i, the weights N_i kept; the linear weights w too.
  void Add(const double p[3], const double w[8], int corners)
  {
    this->Cell->InterpolateFunctions(p, this->Weights.data());
    double x[3] = { 0, 0, 0 };
    for (size_t i = 0; i < this->Weights.size(); ++i)
    {
      const vtkIdType id = this->Cell->GetPointId(static_cast<vtkIdType>(i));
      for (int k = 0; k < 3; ++k)
      {
        x[k] += this->Weights[i] * this->Points[3 * id + k];
      }
      if (this->Weights[i] != 0.0)
      {
        this->Added.Ids.push_back(id);
        this->Added.Weights.push_back(this->Weights[i]);
      }
    }
    this->Added.Offsets.push_back(static_cast<vtkIdType>(this->Added.Ids.size()));
    this->Added.Points.insert(this->Added.Points.end(), x, x + 3);
    for (int i = 0; i < corners; ++i)
    {
      if (w[i] != 0.0)
      {
        this->Linear.Ids.push_back(this->Cell->GetPointId(i));
        this->Linear.Weights.push_back(w[i]);
      }
    }
    this->Linear.Offsets.push_back(static_cast<vtkIdType>(this->Linear.Ids.size()));
    this->Linear.Points.insert(this->Linear.Points.end(), x, x + 3);
  }

  vtkUnstructuredGrid* Grid;
  const double* Points;
  vtkIdType NumberOfPoints;
  AddedPoints& Added;
  AddedPoints& Linear;
  vtkNew<vtkGenericCell> Cell;
  std::vector<double> Weights;
  vtkIdType Index = 0;
  int Kind = TETRAHEDRON_KIND;
  int Resolution = 1;
  std::map<NodeKey, vtkIdType> Nodes;
};

// MidEdgeDeviation of a piece's nodes.
double PieceDeviation(const NodeNumbering& numbering, const std::array<vtkIdType, 10>& nodes)
{
  double x[10][3];
  for (int i = 0; i < 10; ++i)
  {
    std::copy_n(numbering.Point(nodes[i]), 3, x[i]);
  }
  return quadratic_tetrahedron::MidEdgeDeviation(x);
}
}

//------------------------------------------------------------------------------
void RefineHigherOrderCells(vtkUnstructuredGrid* grid, const double* points,
  const std::vector<vtkIdType>& cellIds, int levels, HigherOrderPieces& out)
{
  out = HigherOrderPieces();
  const int R = 4 << levels;
  std::vector<SubCell> subCells[NUMBER_OF_KINDS];
  NodeNumbering numbering(grid, points, out);
  std::vector<int> tets;
  for (size_t c = 0; c < cellIds.size(); ++c)
  {
    const int kind = LinearCellKindOfType(LinearShapeOf(grid->GetCellType(cellIds[c])).Type);
    if (kind < 0)
    {
      continue;
    }
    if (subCells[kind].empty())
    {
      subCells[kind] = ReferenceSubCells(kind, levels);
    }
    numbering.SetCell(static_cast<vtkIdType>(c), cellIds[c], kind, R);
    for (const SubCell& sub : subCells[kind])
    {
      vtkIdType ids[8];
      const int corners = LinearCellKindOf(sub.Kind).Corners;
      for (int i = 0; i < corners; ++i)
      {
        ids[i] = numbering.Id(sub.Corner[i]);
      }
      tets.clear();
      AppendConeSplit(sub.Kind, ids, tets);
      for (size_t t = 0; t < tets.size(); t += 4)
      {
        std::array<vtkIdType, 10> nodes;
        for (int i = 0; i < 4; ++i)
        {
          nodes[i] = ids[tets[t + i]];
        }
        for (int k = 0; k < 6; ++k)
        {
          nodes[4 + k] =
            numbering.Id(Midpoint(sub.Corner[tets[t + quadratic_tetrahedron::Edge[k][0]]],
              sub.Corner[tets[t + quadratic_tetrahedron::Edge[k][1]]]));
        }
        out.Pieces.push_back(nodes);
        out.Cell.push_back(static_cast<vtkIdType>(c));
        out.MaximumMidEdgeDeviation =
          std::max(out.MaximumMidEdgeDeviation, PieceDeviation(numbering, nodes));
      }
    }
  }
}

//------------------------------------------------------------------------------
int RefinementLevels(double deviation, double tolerance, vtkIdType pieces, int minimumLevels,
  int maximumLevels, vtkIdType maximumPieces)
{
  int levels = 0;
  double count = static_cast<double>(pieces);
  while (levels < maximumLevels && (deviation > tolerance || levels < minimumLevels) &&
         8.0 * count <= static_cast<double>(maximumPieces))
  {
    deviation *= 0.25;
    count *= 8.0;
    ++levels;
  }
  return levels;
}
}
