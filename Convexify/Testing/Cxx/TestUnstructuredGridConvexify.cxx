// vtkUnstructuredGridConvexify on meshes with a cavity, a tunnel, two parts
// across a thin gap, an O-grid's seam, hexahedra and tetrahedra, an image
// clipped and tetrahedralized (PPIRayClippedImage.h), and the
// repository's carved wavelets; a tangled mesh is refused. Every output is checked by means
// that share nothing with the filter (no ppiray code, no CGAL):
// - volume: the cells' volumes (verdict, vtkMeshQuality) add up to the box's
//   (relative 1e-9): nothing missing, nothing counted twice;
// - faces: of all faces of all cells (hidden ones too), those that appear
//   once lie on the box (their area the box's surface) or are matched by
//   coverage: every imaginary face not shared with a cell lies inside an
//   input cell's face that is not shared either, and the two sides' areas
//   are equal (a boundary face split by Steiner points);
// - the input's points and cells come first, unchanged; HIDDENCELL marks
//   exactly the imaginary cells; "ppirayBoundaryCell" names a cell whose
//   boundary the face lies on; no NaN anywhere.
// A time series: a new grid with the same geometry and new scalars keeps the
// fill (the last output's points and cells arrays, the same counts) with the
// new scalars, equal to a fresh filter's output in every point, cell and
// array; a moved point makes a new fill (equal to a fresh one again).
#include "PPIRayClippedImage.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataSetAttributes.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkGenericCell.h"
#include "vtkIdTypeArray.h"
#include "vtkMeshQuality.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridConvexify.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace
{
struct Messages : public vtkCommand
{
  static Messages* New() { return new Messages; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings) +=
      static_cast<const char*>(data);
  }
  std::string Errors, Warnings;
};

// Voxels of an n^3 lattice over [x0, x0 + size]^3 as hexahedra, except those
// `removed` says to leave out; point scalar x + 2y + 3z.
vtkSmartPointer<vtkUnstructuredGrid> Lattice(int n, double x0, double size,
  const std::function<bool(int, int, int)>& removed, vtkUnstructuredGrid* into = nullptr)
{
  auto grid =
    into ? vtkSmartPointer<vtkUnstructuredGrid>(into) : vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkPoints* points = grid->GetPoints();
  vtkDoubleArray* scalars = vtkDoubleArray::SafeDownCast(grid->GetPointData()->GetScalars());
  if (!points)
  {
    vtkNew<vtkPoints> p;
    p->SetDataTypeToDouble();
    grid->SetPoints(p);
    points = p;
    vtkNew<vtkDoubleArray> s;
    s->SetName("s");
    grid->GetPointData()->SetScalars(s);
    scalars = s;
  }
  const vtkIdType o = points->GetNumberOfPoints();
  const double h = size / n;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
      {
        const double x = x0 + i * h, y = j * h, z = k * h;
        points->InsertNextPoint(x, y, z);
        scalars->InsertNextValue(x + 2 * y + 3 * z);
      }
  auto id = [&](int i, int j, int k) { return o + (k * (n + 1) + j) * (n + 1) + i; };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        if (removed(i, j, k))
        {
          continue;
        }
        const vtkIdType hex[8] = { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k),
          id(i, j + 1, k), id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
          id(i, j + 1, k + 1) };
        grid->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
      }
  return grid;
}

vtkSmartPointer<vtkUnstructuredGrid> Tetrahedralized(vtkUnstructuredGrid* grid)
{
  vtkNew<vtkDataSetTriangleFilter> split;
  split->SetInputData(grid);
  split->Update();
  return split->GetOutput();
}

// The grid's hexahedra as polyhedra (VTK_POLYHEDRON, six quadrilaterals).
vtkSmartPointer<vtkUnstructuredGrid> AsPolyhedra(vtkUnstructuredGrid* grid)
{
  static const int quads[6][4] = { { 0, 3, 2, 1 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 }, { 1, 2, 6, 5 },
    { 2, 3, 7, 6 }, { 3, 0, 4, 7 } };
  auto polyhedra = vtkSmartPointer<vtkUnstructuredGrid>::New();
  polyhedra->SetPoints(grid->GetPoints());
  polyhedra->GetPointData()->ShallowCopy(grid->GetPointData());
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    const vtkIdType* hex;
    vtkIdType npts;
    grid->GetCellPoints(c, npts, hex);
    std::vector<vtkIdType> faces;
    for (const auto& quad : quads)
    {
      faces.push_back(4);
      for (int v : quad)
      {
        faces.push_back(hex[v]);
      }
    }
    polyhedra->InsertNextCell(VTK_POLYHEDRON, npts, hex, 6, faces.data());
  }
  return polyhedra;
}

double Area(const std::vector<std::array<double, 3>>& p)
{
  // Polygon area: half the norm of the sum of cross products (fan from p0).
  double n[3] = { 0, 0, 0 };
  for (size_t i = 1; i + 1 < p.size(); ++i)
  {
    const double a[3] = { p[i][0] - p[0][0], p[i][1] - p[0][1], p[i][2] - p[0][2] };
    const double b[3] = { p[i + 1][0] - p[0][0], p[i + 1][1] - p[0][1], p[i + 1][2] - p[0][2] };
    n[0] += a[1] * b[2] - a[2] * b[1];
    n[1] += a[2] * b[0] - a[0] * b[2];
    n[2] += a[0] * b[1] - a[1] * b[0];
  }
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

// Whether q lies in triangle (a, b, c) within `tolerance` (distance to its
// plane and barycentric coordinates).
bool InTriangle(const std::array<double, 3>& q, const std::array<double, 3>& a,
  const std::array<double, 3>& b, const std::array<double, 3>& c, double tolerance)
{
  const std::array<double, 3> ab{ b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const std::array<double, 3> ac{ c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const std::array<double, 3> aq{ q[0] - a[0], q[1] - a[1], q[2] - a[2] };
  const std::array<double, 3> n{ ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2],
    ab[0] * ac[1] - ab[1] * ac[0] };
  const double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  if (nn == 0.0)
  {
    return false;
  }
  const double height = (aq[0] * n[0] + aq[1] * n[1] + aq[2] * n[2]) / std::sqrt(nn);
  auto dot = [](const std::array<double, 3>& u, const std::array<double, 3>& v)
  { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
  const double d00 = dot(ab, ab), d01 = dot(ab, ac), d11 = dot(ac, ac);
  const double d20 = dot(aq, ab), d21 = dot(aq, ac), den = d00 * d11 - d01 * d01;
  const double v = (d11 * d20 - d01 * d21) / den, w = (d00 * d21 - d01 * d20) / den;
  const double eps = 1e-9;
  return std::abs(height) <= tolerance && v >= -eps && w >= -eps && v + w <= 1 + eps;
}

// `seam`: the input has cells that meet without sharing point ids (the face
// check by point ids does not apply; volumes and the rest do).
int Check(const char* name, vtkUnstructuredGrid* input, bool seam = false)
{
  vtkNew<vtkUnstructuredGridConvexify> convexify;
  vtkNew<Messages> messages;
  convexify->AddObserver(vtkCommand::ErrorEvent, messages);
  convexify->AddObserver(vtkCommand::WarningEvent, messages);
  convexify->SetInputData(input);
  convexify->Update();
  vtkUnstructuredGrid* out = convexify->GetOutput();
  const vtkIdType n = input->GetNumberOfCells();
  const vtkIdType imaginary = convexify->GetNumberOfImaginaryCells();
  int errors = 0;
  auto fail = [&](const std::string& why)
  {
    std::cout << "FAILED: " << name << ": " << why << "\n";
    ++errors;
  };
  if (!messages->Errors.empty() || !messages->Warnings.empty())
  {
    fail("messages [" + messages->Warnings + messages->Errors + "]");
  }
  if (imaginary <= 0 || out->GetNumberOfCells() != n + imaginary)
  {
    fail("no imaginary cells added");
    return errors;
  }

  // The input first, unchanged; imaginary cells exactly the hidden ones.
  for (vtkIdType p = 0; p < input->GetNumberOfPoints(); ++p)
  {
    double a[3], b[3];
    input->GetPoint(p, a);
    out->GetPoint(p, b);
    if (a[0] != b[0] || a[1] != b[1] || a[2] != b[2])
    {
      fail("input point moved");
      break;
    }
  }
  vtkUnsignedCharArray* ghosts = out->GetCellGhostArray();
  vtkIdType hidden = 0;
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    const bool isHidden = ghosts && (ghosts->GetValue(c) & vtkDataSetAttributes::HIDDENCELL);
    hidden += isHidden ? 1 : 0;
    if (isHidden != (c >= n) || (c < n && out->GetCellType(c) != input->GetCellType(c)) ||
        (c >= n && out->GetCellType(c) != VTK_TETRA))
    {
      fail("cell " + std::to_string(c) + " is not where it should be");
      break;
    }
  }
  for (auto* data : { static_cast<vtkDataSetAttributes*>(out->GetPointData()),
         static_cast<vtkDataSetAttributes*>(out->GetCellData()) })
  {
    for (int a = 0; a < data->GetNumberOfArrays(); ++a)
    {
      vtkDataArray* array = data->GetArray(a);
      for (vtkIdType i = 0; array && i < array->GetNumberOfValues(); ++i)
      {
        if (!std::isfinite(array->GetComponent(i / array->GetNumberOfComponents(),
              static_cast<int>(i % array->GetNumberOfComponents()))))
        {
          fail(std::string("non-finite value in ") + array->GetName());
          break;
        }
      }
    }
  }

  // Volume: verdict's cell volumes against the box's.
  vtkNew<vtkMeshQuality> quality;
  vtkNew<vtkUnstructuredGrid> unhidden; // vtkMeshQuality reads every cell
  unhidden->ShallowCopy(out);
  unhidden->GetCellData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
  quality->SetInputData(unhidden);
  quality->SetTetQualityMeasureToVolume();
  quality->SetHexQualityMeasureToVolume();
  quality->SetWedgeQualityMeasureToVolume();
  quality->SetPyramidQualityMeasureToVolume();
  quality->Update();
  vtkDataArray* qualities = quality->GetOutput()->GetCellData()->GetArray("Quality");
  vtkNew<vtkGenericCell> polyhedron;
  auto volumeOf = [&](vtkIdType c)
  {
    if (out->GetCellType(c) != VTK_POLYHEDRON)
    {
      return qualities->GetTuple1(c);
    }
    // verdict has none for polyhedra: the divergence theorem over its faces
    // (fans from each face's centroid), V = 1/3 sum over triangles of
    // centroid . (area-weighted normal), faces wound outward.
    out->GetCell(c, polyhedron);
    double volume = 0.0;
    for (int f = 0; f < polyhedron->GetNumberOfFaces(); ++f)
    {
      vtkCell* face = polyhedron->GetFace(f);
      const vtkIdType k = face->GetNumberOfPoints();
      double m[3] = { 0, 0, 0 }, p[3], q[3];
      for (vtkIdType i = 0; i < k; ++i)
      {
        face->Points->GetPoint(i, p);
        for (int a = 0; a < 3; ++a)
        {
          m[a] += p[a] / k;
        }
      }
      for (vtkIdType i = 0; i < k; ++i)
      {
        face->Points->GetPoint(i, p);
        face->Points->GetPoint((i + 1) % k, q);
        // det(m, p, q) / 6: the tetrahedron from the origin.
        volume += (m[0] * (p[1] * q[2] - p[2] * q[1]) - m[1] * (p[0] * q[2] - p[2] * q[0]) +
                    m[2] * (p[0] * q[1] - p[1] * q[0])) /
                  6.0;
      }
    }
    return volume;
  };
  // The box: the bounds of the cells (a grid may hold points no cell uses).
  double b[6] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX,
    -VTK_DOUBLE_MAX };
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    double cb[6];
    out->GetCellBounds(c, cb);
    for (int a = 0; a < 3; ++a)
    {
      b[2 * a] = std::min(b[2 * a], cb[2 * a]);
      b[2 * a + 1] = std::max(b[2 * a + 1], cb[2 * a + 1]);
    }
  }
  const double boxVolume = (b[1] - b[0]) * (b[3] - b[2]) * (b[5] - b[4]);
  // Steiner points are rounded to doubles, so a sliver that is positive in
  // exact arithmetic can come out at 0 in floating point: inverted means
  // below -1e-12 of the box, and slivers are counted.
  double inputVolume = 0, imaginaryVolume = 0;
  vtkIdType negative = 0, slivers = 0;
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    const double v = volumeOf(c);
    negative += c >= n && v < -1e-12 * boxVolume ? 1 : 0; // the input's cells are as given
    slivers += std::abs(v) <= 1e-12 * boxVolume ? 1 : 0;
    (c < n ? inputVolume : imaginaryVolume) += std::abs(v);
  }
  const double boxArea = 2 * ((b[1] - b[0]) * (b[3] - b[2]) + (b[3] - b[2]) * (b[5] - b[4]) +
                               (b[1] - b[0]) * (b[5] - b[4]));
  const double volumeError = std::abs(inputVolume + imaginaryVolume - boxVolume) / boxVolume;
  if (!(volumeError <= 1e-9) || negative > 0)
  {
    fail("volumes: input + imaginary - box = " + std::to_string(volumeError) + " of the box, " +
         std::to_string(negative) + " inverted cells");
  }

  // Faces: all faces of all cells, keyed by their sorted point ids.
  struct Face
  {
    int Count = 0;
    vtkIdType Cell = -1;
    std::vector<std::array<double, 3>> Points;
  };
  // Input cells of zero volume bound nothing: their faces are left out.
  std::map<std::vector<vtkIdType>, Face> faces;
  vtkNew<vtkGenericCell> cell;
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    if (c < n && std::abs(volumeOf(c)) <= 1e-12 * boxVolume)
    {
      continue;
    }
    out->GetCell(c, cell);
    for (int f = 0; f < cell->GetNumberOfFaces(); ++f)
    {
      vtkCell* face = cell->GetFace(f);
      std::vector<vtkIdType> key(
        face->PointIds->GetPointer(0), face->PointIds->GetPointer(0) + face->GetNumberOfPoints());
      std::sort(key.begin(), key.end());
      Face& entry = faces[key];
      if (entry.Count++ == 0)
      {
        entry.Cell = c;
        for (vtkIdType i = 0; i < face->GetNumberOfPoints(); ++i)
        {
          entry.Points.push_back({});
          face->Points->GetPoint(i, entry.Points.back().data());
        }
      }
    }
  }
  const double tolerance = 1e-9 * std::sqrt(boxVolume > 0 ? std::cbrt(boxVolume) : 1.0);
  double onBox = 0, inputSide = 0, imaginarySide = 0;
  std::vector<const Face*> inputFaces;
  std::vector<const Face*> imaginaryFaces;
  vtkIdType tooMany = 0;
  for (const auto& entry : faces)
  {
    const Face& face = entry.second;
    tooMany += face.Count > 2 ? 1 : 0;
    if (face.Count != 1)
    {
      continue;
    }
    bool box = false;
    for (int a = 0; a < 3 && !box; ++a)
    {
      for (double plane : { b[2 * a], b[2 * a + 1] })
      {
        bool all = true;
        for (const auto& p : face.Points)
        {
          all = all && std::abs(p[a] - plane) <= tolerance;
        }
        box = box || all;
      }
    }
    if (box)
    {
      onBox += Area(face.Points);
      if (face.Cell < n)
      {
        fail("an input face is on the box");
        break;
      }
    }
    else if (face.Cell < n)
    {
      inputFaces.push_back(&face);
    }
    else
    {
      imaginarySide += Area(face.Points);
      imaginaryFaces.push_back(&face);
    }
  }
  // Input faces on another input face (the two sides of a crack, triangulated
  // differently) are inside the mesh; the others bound it.
  auto centroidOf = [](const Face* face)
  {
    std::array<double, 3> centroid{ 0, 0, 0 };
    for (const auto& p : face->Points)
    {
      for (int a = 0; a < 3; ++a)
      {
        centroid[a] += p[a] / face->Points.size();
      }
    }
    return centroid;
  };
  auto onFace = [&](const std::array<double, 3>& x, const Face* under)
  {
    const auto& q = under->Points;
    bool on = false;
    for (size_t t = 1; t + 1 < q.size() && !on; ++t)
    {
      on = InTriangle(x, q[0], q[t], q[t + 1], tolerance);
    }
    return on;
  };
  for (const Face* face : inputFaces)
  {
    bool crack = false;
    for (const Face* other : inputFaces)
    {
      crack = crack || (other != face && onFace(centroidOf(face), other));
    }
    inputSide += crack ? 0.0 : Area(face->Points);
  }
  vtkIdType uncovered = 0;
  for (const Face* face : imaginaryFaces)
  {
    std::array<double, 3> centroid{ 0, 0, 0 };
    for (const auto& p : face->Points)
    {
      for (int a = 0; a < 3; ++a)
      {
        centroid[a] += p[a] / face->Points.size();
      }
    }
    bool covered = false;
    for (const Face* under : inputFaces)
    {
      const auto& q = under->Points;
      for (size_t t = 1; t + 1 < q.size() && !covered; ++t)
      {
        covered = InTriangle(centroid, q[0], q[t], q[t + 1], tolerance);
      }
      if (covered)
      {
        break;
      }
    }
    uncovered += covered ? 0 : 1;
  }
  const double areaError =
    std::abs(onBox - boxArea) / boxArea + std::abs(inputSide - imaginarySide) / boxArea;
  if (!seam && (tooMany > 0 || uncovered > 0 || areaError > 1e-9))
  {
    fail(std::to_string(tooMany) + " faces shared by more than two cells, " +
         std::to_string(uncovered) + " imaginary faces on no input face, area error " +
         std::to_string(areaError));
  }

  // ppirayBoundaryCell: the named cell's boundary holds the face.
  vtkIdTypeArray* across = vtkIdTypeArray::SafeDownCast(
    out->GetCellData()->GetArray(vtkUnstructuredGridConvexify::BoundaryCellArrayName()));
  vtkIdType named = 0, wrong = 0;
  for (vtkIdType c = n; across && c < out->GetNumberOfCells(); ++c)
  {
    const vtkIdType* tet = nullptr;
    vtkIdType npts;
    out->GetCellPoints(c, npts, tet);
    for (int f = 0; f < 4; ++f)
    {
      const vtkIdType owner = across->GetTypedComponent(c, f);
      if (owner < 0)
      {
        continue;
      }
      ++named;
      input->GetCell(owner, cell);
      for (int v = 0; v < 4; ++v)
      {
        if (v == f)
        {
          continue;
        }
        double x[3], closest[3], pcoords[3], dist2;
        double weights[VTK_CELL_SIZE];
        int subId;
        out->GetPoint(tet[v], x);
        cell->EvaluatePosition(x, closest, subId, pcoords, dist2, weights);
        bool onFace = false;
        for (int g = 0; g < cell->GetNumberOfFaces() && !onFace; ++g)
        {
          vtkCell* face = cell->GetFace(g);
          std::vector<std::array<double, 3>> q(face->GetNumberOfPoints());
          for (size_t i = 0; i < q.size(); ++i)
          {
            face->Points->GetPoint(static_cast<vtkIdType>(i), q[i].data());
          }
          for (size_t t = 1; t + 1 < q.size() && !onFace; ++t)
          {
            onFace = InTriangle({ x[0], x[1], x[2] }, q[0], q[t], q[t + 1], tolerance);
          }
        }
        wrong += onFace ? 0 : 1;
      }
    }
  }
  if (seam && convexify->GetNumberOfMergedPoints() == 0)
  {
    fail("the seam was not found: " + std::to_string(convexify->GetNumberOfMergedPoints()) +
         " points merged, " + std::to_string(convexify->GetNumberOfDroppedTriangles()) +
         " boundary triangles dropped");
  }
  if (!across || named == 0 || wrong > 0)
  {
    fail("ppirayBoundaryCell: " + std::to_string(named) + " faces named, " + std::to_string(wrong) +
         " corners off the named cell's boundary");
  }

  std::printf("%s: %lld input cells, %lld imaginary tetrahedra, %lld Steiner points, %.3f s; "
              "volume error %.2e, area error %.2e, %lld slivers, %zu imaginary faces on %zu input "
              "faces not shared by point ids\n",
    name, static_cast<long long>(n), static_cast<long long>(imaginary),
    static_cast<long long>(convexify->GetNumberOfSteinerPoints()), convexify->GetExecutionTime(),
    volumeError, areaError, static_cast<long long>(slivers), imaginaryFaces.size(),
    inputFaces.size());
  return errors;
}

// Whether two outputs hold the same points, cells and arrays (value by value).
bool SameOutput(vtkUnstructuredGrid* a, vtkUnstructuredGrid* b)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints() ||
      a->GetNumberOfCells() != b->GetNumberOfCells())
  {
    return false;
  }
  auto same = [](vtkDataArray* x, vtkDataArray* y)
  {
    if (!x || !y || x->GetNumberOfValues() != y->GetNumberOfValues())
    {
      return x == y;
    }
    for (vtkIdType i = 0; i < x->GetNumberOfValues(); ++i)
    {
      if (x->GetVariantValue(i) != y->GetVariantValue(i))
      {
        return false;
      }
    }
    return true;
  };
  bool equal = same(a->GetPoints()->GetData(), b->GetPoints()->GetData()) &&
               same(a->GetCells()->GetConnectivityArray(), b->GetCells()->GetConnectivityArray()) &&
               same(a->GetCells()->GetOffsetsArray(), b->GetCells()->GetOffsetsArray()) &&
               a->GetPointData()->GetNumberOfArrays() == b->GetPointData()->GetNumberOfArrays() &&
               a->GetCellData()->GetNumberOfArrays() == b->GetCellData()->GetNumberOfArrays();
  for (int k = 0; equal && k < a->GetPointData()->GetNumberOfArrays(); ++k)
  {
    equal = same(a->GetPointData()->GetArray(k),
      b->GetPointData()->GetArray(a->GetPointData()->GetArrayName(k)));
  }
  for (int k = 0; equal && k < a->GetCellData()->GetNumberOfArrays(); ++k)
  {
    equal = same(
      a->GetCellData()->GetArray(k), b->GetCellData()->GetArray(a->GetCellData()->GetArrayName(k)));
  }
  return equal;
}

// A time series through one filter (see the top): the number of errors.
int CheckTimeSteps()
{
  auto first = Lattice(4, 0, 1, [](int i, int j, int k) { return i == 1 && j == 2 && k == 2; });
  vtkNew<vtkUnstructuredGridConvexify> convexify;
  convexify->SetInputData(first);
  convexify->Update();
  vtkNew<vtkUnstructuredGrid> before;
  before->ShallowCopy(convexify->GetOutput());
  const vtkIdType imaginary = convexify->GetNumberOfImaginaryCells();

  vtkNew<vtkUnstructuredGrid> next; // the next step: same arrays, new scalars
  next->ShallowCopy(first);
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("s");
  for (vtkIdType p = 0; p < next->GetNumberOfPoints(); ++p)
  {
    scalars->InsertNextValue(5.0 - p % 7);
  }
  vtkNew<vtkPointData> data;
  data->SetScalars(scalars);
  next->GetPointData()->ShallowCopy(data);
  int errors = 0;
  auto expect = [&](vtkUnstructuredGrid* input, bool kept, const char* step)
  {
    convexify->SetInputData(input);
    convexify->Update();
    vtkUnstructuredGrid* output = convexify->GetOutput();
    vtkNew<vtkUnstructuredGridConvexify> fresh;
    fresh->SetInputData(input);
    fresh->Update();
    const bool shared =
      output->GetPoints()->GetData() == before->GetPoints()->GetData() &&
      output->GetCells()->GetConnectivityArray() == before->GetCells()->GetConnectivityArray();
    const bool equal = SameOutput(output, fresh->GetOutput());
    std::cout << "time step, " << step << ": fill kept " << shared << ", equal to a fresh one "
              << equal << ", imaginary cells " << convexify->GetNumberOfImaginaryCells() << "\n";
    if (shared != kept || !equal || (kept && convexify->GetNumberOfImaginaryCells() != imaginary) ||
        output->GetPointData()->GetScalars()->GetTuple1(3) !=
          input->GetPointData()->GetScalars()->GetTuple1(3))
    {
      std::cout << "FAILED: time step, " << step << ": expected the fill "
                << (kept ? "kept" : "made again") << " and the output equal to a fresh one\n";
      ++errors;
    }
    before->ShallowCopy(output);
  };
  expect(next, true, "same geometry, new scalars");
  vtkNew<vtkUnstructuredGrid> moved;
  moved->DeepCopy(next);
  double x[3];
  moved->GetPoint(0, x);
  moved->GetPoints()->SetPoint(0, x[0] - 0.05, x[1], x[2]);
  expect(moved, false, "a point moved");
  return errors;
}
}

int TestUnstructuredGridConvexify(int, char*[])
{
  int errors = 0;
  auto none = [](int, int, int) { return false; };
  // A cube with a cavity (2^3 voxels in the middle of 6^3), hexahedra and
  // their tetrahedra.
  auto cavity = Lattice(6, 0.0, 1.0,
    [](int i, int j, int k) { return i >= 2 && i < 4 && j >= 2 && j < 4 && k >= 2 && k < 4; });
  errors += Check("cavity, hexahedra", cavity);
  errors += Check("cavity, tetrahedra", Tetrahedralized(cavity));
  errors += Check("cavity, polyhedra", AsPolyhedra(cavity));
  // A tunnel through a cube (a hole: the mesh has genus 1).
  auto tunnel = Lattice(5, 0.0, 1.0, [](int i, int j, int) { return i == 2 && j == 2; });
  errors += Check("tunnel, tetrahedra", Tetrahedralized(tunnel));
  // Two parts across a thin gap (1e-3 of their size).
  auto parts = Lattice(3, 0.0, 1.0, none);
  Lattice(3, 1.001, 1.0, none, parts);
  errors += Check("two parts, thin gap, tetrahedra", Tetrahedralized(parts));
  errors += Check("two parts, thin gap, hexahedra", parts);
  // Parts that touch along an edge and at a point (sharing its point ids).
  auto alongEdge = Lattice(2, 0.0, 1.0, [](int i, int j, int k) { return k == 1 || i != j; });
  errors += Check("two cubes along an edge, hexahedra", alongEdge);
  errors += Check("two cubes along an edge, tetrahedra", Tetrahedralized(alongEdge));
  auto atPoint = Lattice(2, 0.0, 1.0, [](int i, int j, int k) { return !(i == j && j == k); });
  errors += Check("two cubes at a point, hexahedra", atPoint);
  errors += Check("two cubes at a point, tetrahedra", Tetrahedralized(atPoint));

  // An image clipped and tetrahedralized as ParaView's filters do it: the
  // fill takes its points a few roundings apart as one and leaves its
  // zero-volume tetrahedra out. With no tolerance, the faces between those
  // points cross others and the filter refuses (an error, no fill).
  {
    auto clipped = ppiray_test::ClippedImage(6);
    errors += Check("image clipped and tetrahedralized", clipped);
    vtkNew<vtkUnstructuredGridConvexify> counted;
    counted->SetInputData(clipped);
    counted->Update();
    vtkNew<vtkUnstructuredGridConvexify> exact;
    vtkNew<Messages> messages;
    exact->AddObserver(vtkCommand::ErrorEvent, messages);
    exact->SetTolerance(0.0);
    exact->SetInputData(clipped);
    exact->Update();
    std::cout << "image clipped and tetrahedralized: " << counted->GetNumberOfMergedPoints()
              << " points merged, " << counted->GetNumberOfFlatTetrahedra()
              << " flat tetrahedra left out; without tolerance: "
              << exact->GetNumberOfImaginaryCells() << " imaginary cells [" << messages->Errors
              << "]\n";
    if (counted->GetNumberOfMergedPoints() == 0 || counted->GetNumberOfFlatTetrahedra() == 0 ||
        exact->GetNumberOfImaginaryCells() != 0 || messages->Errors.empty())
    {
      std::cout << "FAILED: clipped image: expected points merged, flat tetrahedra left out, and "
                   "a refusal without tolerance\n";
      ++errors;
    }
  }

  // An O-grid: a thick ring of hexahedra whose last layer of points repeats
  // the first (a seam where cells meet without sharing point ids), and its
  // tetrahedra (vtkDataSetTriangleFilter: the two sides of the seam split
  // along crossing diagonals).
  {
    const int ni = 24, nj = 3, nk = 3;
    vtkNew<vtkUnstructuredGrid> ring;
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    vtkNew<vtkDoubleArray> scalars;
    scalars->SetName("s");
    auto id = [&](int i, int j, int k) { return (k * (nj + 1) + j) * (ni + 1) + i; };
    for (int k = 0; k <= nk; ++k)
      for (int j = 0; j <= nj; ++j)
        for (int i = 0; i <= ni; ++i)
        {
          const double angle = -2.0 * 3.141592653589793 * (i % ni) / ni, r = 1.0 + 0.2 * j;
          points->InsertNextPoint(r * std::cos(angle), r * std::sin(angle), 0.2 * k);
          scalars->InsertNextValue(r + 0.1 * k);
        }
    ring->SetPoints(points);
    ring->GetPointData()->SetScalars(scalars);
    for (int k = 0; k < nk; ++k)
      for (int j = 0; j < nj; ++j)
        for (int i = 0; i < ni; ++i)
        {
          const vtkIdType hex[8] = { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k),
            id(i, j + 1, k), id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
            id(i, j + 1, k + 1) };
          ring->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
        }
    errors += Check("O-grid ring, hexahedra", ring, true);
    errors += Check("O-grid ring, tetrahedra", Tetrahedralized(ring), true);
    // Five tetrahedra per hexahedron, the split alternating with the parity
    // of i + j + k (conforming between neighbours); 23 cells around, so the
    // two cells at the seam have the same parity and split their shared
    // face along crossing diagonals: a crack whose sides must be dropped.
    const int odd = 23;
    vtkNew<vtkUnstructuredGrid> cracked;
    vtkNew<vtkPoints> crackedPoints;
    crackedPoints->SetDataTypeToDouble();
    vtkNew<vtkDoubleArray> crackedScalars;
    crackedScalars->SetName("s");
    auto at = [&](int i, int j, int k) { return (k * (nj + 1) + j) * (odd + 1) + i; };
    for (int k = 0; k <= nk; ++k)
      for (int j = 0; j <= nj; ++j)
        for (int i = 0; i <= odd; ++i)
        {
          const double angle = -2.0 * 3.141592653589793 * (i % odd) / odd, r = 1.0 + 0.2 * j;
          crackedPoints->InsertNextPoint(r * std::cos(angle), r * std::sin(angle), 0.2 * k);
          crackedScalars->InsertNextValue(r + 0.1 * k);
        }
    cracked->SetPoints(crackedPoints);
    cracked->GetPointData()->SetScalars(crackedScalars);
    static const int five[2][5][4] = { { { 0, 1, 3, 4 }, { 1, 2, 3, 6 }, { 1, 4, 5, 6 },
                                         { 3, 4, 6, 7 }, { 1, 3, 4, 6 } },
      { { 0, 1, 2, 5 }, { 0, 2, 3, 7 }, { 0, 4, 5, 7 }, { 2, 5, 6, 7 }, { 0, 2, 5, 7 } } };
    for (int k = 0; k < nk; ++k)
      for (int j = 0; j < nj; ++j)
        for (int i = 0; i < odd; ++i)
        {
          const vtkIdType c[8] = { at(i, j, k), at(i + 1, j, k), at(i + 1, j + 1, k),
            at(i, j + 1, k), at(i, j, k + 1), at(i + 1, j, k + 1), at(i + 1, j + 1, k + 1),
            at(i, j + 1, k + 1) };
          for (const auto& t : five[(i + j + k) % 2])
          {
            vtkIdType tet[4] = { c[t[0]], c[t[1]], c[t[2]], c[t[3]] };
            double p[4][3];
            for (int v = 0; v < 4; ++v)
            {
              crackedPoints->GetPoint(tet[v], p[v]);
            }
            const double u[3] = { p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2] };
            const double v[3] = { p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2] };
            const double w[3] = { p[3][0] - p[0][0], p[3][1] - p[0][1], p[3][2] - p[0][2] };
            const double det = u[0] * (v[1] * w[2] - v[2] * w[1]) -
                               u[1] * (v[0] * w[2] - v[2] * w[0]) +
                               u[2] * (v[0] * w[1] - v[1] * w[0]);
            if (det < 0)
            {
              std::swap(tet[1], tet[2]);
            }
            cracked->InsertNextCell(VTK_TETRA, 4, tet);
          }
        }
    const int before = errors;
    errors +=
      Check("O-grid ring, 5 tetrahedra per cell, crossing diagonals at the seam", cracked, true);
    vtkNew<vtkUnstructuredGridConvexify> probe;
    probe->SetInputData(cracked);
    probe->Update();
    if (errors == before && probe->GetNumberOfDroppedTriangles() == 0)
    {
      std::cout << "FAILED: no crack sides dropped at the seam\n";
      ++errors;
    }
  }

  // The repository's carved wavelets (tetrahedra; hollowed by holes).
  for (const char* file : { "wavelet_hole.vtu", "graded_holes.vtu" })
  {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((std::string(PPIRAY_SOURCE_DIR) + "/Data/" + file).c_str());
    reader->Update();
    errors += Check(file, reader->GetOutput());
  }

  // Two tetrahedra that overlap: the boundary intersects itself; refused
  // with an error, the output is the input.
  {
    vtkNew<vtkUnstructuredGrid> tangled;
    vtkNew<vtkPoints> points;
    for (const auto& p :
      std::vector<std::array<double, 3>>{ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
        { 0.2, 0.2, 0.2 }, { 1.2, 0.2, 0.2 }, { 0.2, 1.2, 0.2 }, { 0.2, 0.2, 1.2 } })
    {
      points->InsertNextPoint(p.data());
    }
    tangled->SetPoints(points);
    const vtkIdType a[4] = { 0, 1, 2, 3 }, b2[4] = { 4, 5, 6, 7 };
    tangled->InsertNextCell(VTK_TETRA, 4, a);
    tangled->InsertNextCell(VTK_TETRA, 4, b2);
    vtkNew<vtkUnstructuredGridConvexify> convexify;
    vtkNew<Messages> messages;
    convexify->AddObserver(vtkCommand::ErrorEvent, messages);
    convexify->SetInputData(tangled);
    convexify->Update();
    std::cout << "tangled: [" << messages->Errors << "]\n";
    if (messages->Errors.find("intersects itself") == std::string::npos ||
        convexify->GetOutput()->GetNumberOfCells() != 2 ||
        convexify->GetNumberOfImaginaryCells() != 0)
    {
      std::cout << "FAILED: a tangled mesh was not refused with its reason\n";
      ++errors;
    }
  }
  errors += CheckTimeSteps();
  return errors ? 1 : 0;
}
