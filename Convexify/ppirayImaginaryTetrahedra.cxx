#include "ppirayImaginaryTetrahedra.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/make_conforming_constrained_Delaunay_triangulation_3.h>

#include <algorithm>
#include <deque>
#include <exception>
#include <iterator>
#include <map>
#include <optional>
#include <unordered_map>
#include <utility>

namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Polygon = std::vector<std::size_t>;

// Box corner i: bit 0 picks x max, bit 1 y max, bit 2 z max.
Point BoxCorner(const double box[6], int i)
{
  return Point(box[i & 1 ? 1 : 0], box[i & 2 ? 3 : 2], box[i & 4 ? 5 : 4]);
}

// The box's faces as quadrilaterals over corners 0..7 (offset `o`).
void AppendBoxFaces(std::size_t o, std::vector<Polygon>& polygons)
{
  static const std::size_t faces[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 },
    { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  for (const auto& f : faces)
  {
    polygons.push_back({ o + f[0], o + f[1], o + f[2], o + f[3] });
  }
}
}

namespace ppiray
{
//------------------------------------------------------------------------------
ImaginaryTetrahedra FillBoxAroundSurface(const std::vector<double>& points,
  const std::vector<vtkIdType>& triangles, const double box[6],
  const std::function<void(double)>& progress)
{
  ImaginaryTetrahedra result;
  const vtkIdType numberOfPoints = static_cast<vtkIdType>(points.size() / 3);

  // The soup: box corners first, then the points the triangles use.
  std::vector<Point> soup;
  std::vector<vtkIdType> soupToInput; // -1: box corner
  for (int i = 0; i < 8; ++i)
  {
    soup.push_back(BoxCorner(box, i));
    soupToInput.push_back(-1);
  }
  std::unordered_map<vtkIdType, std::size_t> inputToSoup;
  for (vtkIdType id : triangles)
  {
    if (inputToSoup.emplace(id, soup.size()).second)
    {
      soup.emplace_back(points[3 * id], points[3 * id + 1], points[3 * id + 2]);
      soupToInput.push_back(id);
    }
  }
  // The constraints: the box's faces, then the boundary triangles except
  // those that bound nothing: degenerate ones (collinear corners, exactly)
  // and pairs on the same points (both sides of a seam, inside the mesh).
  std::vector<Polygon> polygons;
  AppendBoxFaces(0, polygons);
  const std::size_t numberOfBoxFaces = polygons.size();
  std::vector<vtkIdType> polygonTriangle; // input triangle of each boundary polygon
  std::map<std::array<std::size_t, 3>, std::vector<vtkIdType>> samePlace;
  for (std::size_t t = 0; 3 * t < triangles.size(); ++t)
  {
    const Polygon p{ inputToSoup[triangles[3 * t]], inputToSoup[triangles[3 * t + 1]],
      inputToSoup[triangles[3 * t + 2]] };
    if (p[0] == p[1] || p[1] == p[2] || p[0] == p[2] ||
        CGAL::collinear(soup[p[0]], soup[p[1]], soup[p[2]]))
    {
      ++result.DroppedTriangles;
      continue;
    }
    std::array<std::size_t, 3> key{ p[0], p[1], p[2] };
    std::sort(key.begin(), key.end());
    samePlace[key].push_back(static_cast<vtkIdType>(t));
  }
  for (const auto& entry : samePlace)
  {
    if (entry.second.size() != 1)
    {
      // Both sides of a seam: inside the mesh, no constraint.
      result.DroppedTriangles += static_cast<vtkIdType>(entry.second.size());
      continue;
    }
    const vtkIdType t = entry.second.front();
    polygons.push_back({ inputToSoup[triangles[3 * t]], inputToSoup[triangles[3 * t + 1]],
      inputToSoup[triangles[3 * t + 2]] });
    polygonTriangle.push_back(t);
  }

  // Preconditions of the triangulation, checked: no two constraints
  // intersect other than along shared edges or corners. Two boundary
  // triangles that lie on each other facing opposite ways are the two sides
  // of a crack whose triangulations differ (an O-grid's cut split into
  // tetrahedra): they bound nothing and are left out; any other
  // intersection is an error.
  {
    std::vector<Polygon> boundary(polygons.begin() + numberOfBoxFaces, polygons.end());
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    CGAL::Polygon_mesh_processing::triangle_soup_self_intersections(
      soup, boundary, std::back_inserter(pairs));
    std::vector<bool> dropped(boundary.size(), false);
    for (const auto& pair : pairs)
    {
      const Polygon& a = boundary[pair.first];
      const Polygon& b = boundary[pair.second];
      bool coplanar = true;
      for (std::size_t v : b)
      {
        coplanar = coplanar && CGAL::coplanar(soup[a[0]], soup[a[1]], soup[a[2]], soup[v]);
      }
      const auto na = CGAL::normal(soup[a[0]], soup[a[1]], soup[a[2]]);
      const auto nb = CGAL::normal(soup[b[0]], soup[b[1]], soup[b[2]]);
      if (!coplanar || na * nb >= 0)
      {
        result.Error = std::string("the mesh's boundary intersects itself (") +
                       (coplanar ? "faces on each other facing the same way" : "faces crossing") +
                       ": tangled or overlapping cells); it bounds no volume to fill around";
        return result;
      }
      dropped[pair.first] = dropped[pair.second] = true;
    }
    if (!pairs.empty())
    {
      std::vector<Polygon> kept(polygons.begin(), polygons.begin() + numberOfBoxFaces);
      std::vector<vtkIdType> keptTriangle;
      for (std::size_t i = 0; i < boundary.size(); ++i)
      {
        if (dropped[i])
        {
          ++result.DroppedTriangles;
          continue;
        }
        kept.push_back(boundary[i]);
        keptTriangle.push_back(polygonTriangle[i]);
      }
      polygons.swap(kept);
      polygonTriangle.swap(keptTriangle);
    }
    std::vector<Polygon> checked(polygons.begin() + numberOfBoxFaces, polygons.end());
    for (std::size_t f = 0; f < numberOfBoxFaces; ++f)
    {
      const Polygon& q = polygons[f];
      checked.push_back({ q[0], q[1], q[2] });
      checked.push_back({ q[0], q[2], q[3] });
    }
    std::vector<std::pair<std::size_t, std::size_t>> left;
    CGAL::Polygon_mesh_processing::triangle_soup_self_intersections(
      soup, checked, std::back_inserter(left));
    if (!left.empty())
    {
      result.Error =
        std::to_string(left.size()) +
        " pairs of boundary faces still intersect once the two sides of cracks are left out: "
        "the boundary bounds no volume to fill around";
      return result;
    }
  }
  progress(0.2);

  using CCDT = decltype(CGAL::make_conforming_constrained_Delaunay_triangulation_3(
    std::vector<Point>(), std::vector<Polygon>()));
  std::optional<CCDT> triangulation;
  try
  {
    triangulation.emplace(
      CGAL::make_conforming_constrained_Delaunay_triangulation_3(soup, polygons));
  }
  catch (const std::exception& e)
  {
    result.Error =
      std::string("the conforming constrained Delaunay triangulation failed: ") + e.what();
    return result;
  }
  progress(0.7);
  const CCDT& ccdt = *triangulation;
  const auto& tr = ccdt.triangulation();
  using CellHandle = std::decay_t<decltype(tr)>::Cell_handle;
  using VertexHandle = std::decay_t<decltype(tr)>::Vertex_handle;

  // Parity flood fill from the cells on the box: crossing a boundary
  // triangle (a constraint that is not a box face) toggles inside/outside.
  std::map<CellHandle, int> inside;
  std::deque<CellHandle> queue;
  for (CellHandle c : tr.finite_cell_handles())
  {
    for (int i = 0; i < 4; ++i)
    {
      if (tr.is_infinite(c->neighbor(i)) && inside.emplace(c, 0).second)
      {
        queue.push_back(c);
      }
    }
  }
  vtkIdType conflicts = 0;
  while (!queue.empty())
  {
    const CellHandle c = queue.front();
    queue.pop_front();
    for (int i = 0; i < 4; ++i)
    {
      const CellHandle n = c->neighbor(i);
      if (tr.is_infinite(n))
      {
        continue;
      }
      int side = inside[c];
      if (ccdt.is_facet_constrained(c, i) &&
          static_cast<std::size_t>(ccdt.face_constraint_index(c, i)) >= numberOfBoxFaces)
      {
        side ^= 1;
      }
      const auto found = inside.emplace(n, side);
      if (found.second)
      {
        queue.push_back(n);
      }
      else if (found.first->second != side)
      {
        ++conflicts;
      }
    }
  }
  if (conflicts > 0 || inside.size() != tr.number_of_finite_cells())
  {
    result.Error = "the mesh's boundary is not closed: its inside and outside cannot be told apart";
    return result;
  }
  progress(0.8);

  // Output ids: input points keep theirs; box corners and Steiner points
  // follow the input's points.
  std::map<std::array<double, 3>, std::size_t> soupIndex;
  for (std::size_t i = 0; i < soup.size(); ++i)
  {
    soupIndex.emplace(std::array<double, 3>{ soup[i].x(), soup[i].y(), soup[i].z() }, i);
  }
  std::map<VertexHandle, vtkIdType> outputId;
  auto idOf = [&](VertexHandle v)
  {
    const auto known = outputId.find(v);
    if (known != outputId.end())
    {
      return known->second;
    }
    const Point& p = v->point();
    const auto s = soupIndex.find({ p.x(), p.y(), p.z() });
    vtkIdType id;
    if (s != soupIndex.end() && soupToInput[s->second] >= 0)
    {
      id = soupToInput[s->second];
    }
    else
    {
      id = numberOfPoints + static_cast<vtkIdType>(result.NewPoints.size());
      result.NewPoints.push_back({ p.x(), p.y(), p.z() });
      result.SteinerPoints += s == soupIndex.end() ? 1 : 0;
    }
    outputId.emplace(v, id);
    return id;
  };
  for (CellHandle c : tr.finite_cell_handles())
  {
    if (inside[c])
    {
      ++result.InsideCells;
      continue;
    }
    for (int v = 0; v < 4; ++v)
    {
      result.Tets.push_back(idOf(c->vertex(v)));
    }
    for (int f = 0; f < 4; ++f)
    {
      vtkIdType triangle = -1;
      if (ccdt.is_facet_constrained(c, f))
      {
        const auto index = static_cast<std::size_t>(ccdt.face_constraint_index(c, f));
        triangle = index >= numberOfBoxFaces ? polygonTriangle[index - numberOfBoxFaces] : -1;
      }
      result.BoundaryTriangle.push_back(triangle);
    }
  }
  progress(1.0);
  return result;
}
}
