#include "PPIRayDataReaders.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <vector>

namespace
{
//------------------------------------------------------------------------------
// A whole file in memory, read big-endian; reads past the end give zeros.
class BigEndianFile
{
public:
  bool Load(const std::string& path)
  {
    std::ifstream in(path, std::ios::binary);
    this->Bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return !this->Bytes.empty();
  }
  size_t Size() const { return this->Bytes.size(); }
  uint64_t Unsigned(size_t at, int bytes) const
  {
    uint64_t v = 0;
    for (int i = 0; i < bytes; ++i)
    {
      const size_t k = at + i;
      v = (v << 8) | (k < this->Bytes.size() ? static_cast<unsigned char>(this->Bytes[k]) : 0u);
    }
    return v;
  }
  int32_t Int(size_t at) const { return static_cast<int32_t>(this->Unsigned(at, 4)); }
  int64_t Int64(size_t at) const { return static_cast<int64_t>(this->Unsigned(at, 8)); }
  float Float(size_t at) const
  {
    const uint32_t bits = static_cast<uint32_t>(this->Unsigned(at, 4));
    float v;
    std::memcpy(&v, &bits, 4);
    return v;
  }
  double Double(size_t at) const
  {
    const uint64_t bits = this->Unsigned(at, 8);
    double v;
    std::memcpy(&v, &bits, 8);
    return v;
  }
  std::string Text(size_t at, size_t n) const
  {
    return at < this->Bytes.size()
             ? std::string(&this->Bytes[at], std::min(n, this->Bytes.size() - at))
             : std::string();
  }

private:
  std::vector<char> Bytes;
};

//------------------------------------------------------------------------------
// What Exodus II needs of a netCDF classic file (CDF-1, or CDF-2 with 64-bit
// offsets): dimensions, variables (shape, type, offset, text attributes) and
// their values, a record variable's from one record.
class NetCDFClassic
{
public:
  struct Variable
  {
    std::vector<size_t> Shape; // without the record dimension
    int Type = 0;              // 1 byte, 2 char, 3 short, 4 int, 5 float, 6 double
    size_t Begin = 0;
    bool Record = false;
    std::map<std::string, std::string> TextAttributes;
    size_t Count() const
    {
      size_t n = 1;
      for (size_t d : this->Shape)
      {
        n *= d;
      }
      return n;
    }
  };

  bool Open(const std::string& path)
  {
    if (!this->File.Load(path) || this->File.Text(0, 3) != "CDF")
    {
      return false;
    }
    const int version = this->File.Text(3, 1)[0];
    if (version != 1 && version != 2)
    {
      return false; // netCDF-4 (HDF5) files are not this format
    }
    size_t at = 8; // magic, number of records
    std::vector<size_t> lengths;
    const bool hasDimensions = this->File.Int(at) == 0x0A; // NC_DIMENSION, else ABSENT
    const int dimensions = this->File.Int(at + 4);
    at += 8;
    for (int i = 0; hasDimensions && i < dimensions; ++i)
    {
      const std::string name = this->Name(at);
      lengths.push_back(static_cast<size_t>(this->File.Int(at)));
      this->Dimensions[name] = lengths.back();
      at += 4;
    }
    this->Attributes(at, nullptr);  // global attributes
    if (this->File.Int(at) != 0x0B) // NC_VARIABLE
    {
      return false;
    }
    const int variables = this->File.Int(at + 4);
    at += 8;
    for (int i = 0; i < variables && at < this->File.Size(); ++i)
    {
      const std::string name = this->Name(at);
      Variable v;
      const int rank = this->File.Int(at);
      at += 4;
      for (int d = 0; d < rank; ++d, at += 4)
      {
        const size_t dimension = static_cast<size_t>(this->File.Int(at));
        if (dimension >= lengths.size())
        {
          return false;
        }
        if (lengths[dimension] == 0) // the record (unlimited) dimension, always first
        {
          v.Record = true;
        }
        else
        {
          v.Shape.push_back(lengths[dimension]);
        }
      }
      this->Attributes(at, &v.TextAttributes);
      v.Type = this->File.Int(at);
      const size_t vsize = static_cast<size_t>(this->File.Int(at + 4));
      v.Begin =
        static_cast<size_t>(version == 1 ? this->File.Int(at + 8) : this->File.Int64(at + 8));
      at += version == 1 ? 12 : 16;
      // One record holds every record variable's vsize (padded to 4 bytes;
      // the unpadded special case of a single byte or short record variable
      // does not occur in Exodus).
      this->RecordSize += v.Record ? vsize : 0;
      this->Variables[name] = v;
    }
    return true;
  }

  size_t Dimension(const std::string& name) const
  {
    auto it = this->Dimensions.find(name);
    return it == this->Dimensions.end() ? 0 : it->second;
  }

  const Variable* Find(const std::string& name) const
  {
    auto it = this->Variables.find(name);
    return it == this->Variables.end() ? nullptr : &it->second;
  }

  // `count` values from element `first` on (of record `record`), as doubles;
  // empty if out of range.
  std::vector<double> Values(const Variable& v, size_t first, size_t count, size_t record = 0) const
  {
    const size_t size = TypeSize(v.Type);
    const size_t begin = v.Begin + (v.Record ? record * this->RecordSize : 0) + first * size;
    std::vector<double> values;
    if (size == 0 || v.Type == 2 || first + count > v.Count() ||
        begin + count * size > this->File.Size())
    {
      return values;
    }
    values.resize(count);
    for (size_t i = 0; i < count; ++i)
    {
      const size_t at = begin + i * size;
      switch (v.Type)
      {
        case 1:
          values[i] = static_cast<signed char>(this->File.Unsigned(at, 1));
          break;
        case 3:
          values[i] = static_cast<int16_t>(this->File.Unsigned(at, 2));
          break;
        case 4:
          values[i] = this->File.Int(at);
          break;
        case 5:
          values[i] = this->File.Float(at);
          break;
        default:
          values[i] = this->File.Double(at);
      }
    }
    return values;
  }

  // Row `row` of a 2D char variable (a list of names), up to its first NUL.
  std::string Text(const Variable& v, size_t row) const
  {
    if (v.Type != 2 || v.Shape.size() != 2 || row >= v.Shape[0])
    {
      return std::string();
    }
    const std::string s = this->File.Text(v.Begin + row * v.Shape[1], v.Shape[1]);
    return s.substr(0, s.find('\0'));
  }

private:
  static size_t TypeSize(int type)
  {
    static const size_t sizes[7] = { 0, 1, 1, 2, 4, 4, 8 };
    return type >= 1 && type <= 6 ? sizes[type] : 0;
  }

  // A name: length, characters, padding to 4 bytes.
  std::string Name(size_t& at) const
  {
    const size_t n = static_cast<size_t>(this->File.Int(at));
    const std::string name = this->File.Text(at + 4, n);
    at += 4 + (n + 3) / 4 * 4;
    return name;
  }

  // An attribute list (or ABSENT); keeps the text (char) attributes.
  void Attributes(size_t& at, std::map<std::string, std::string>* text) const
  {
    const bool present = this->File.Int(at) == 0x0C; // NC_ATTRIBUTE
    const int count = this->File.Int(at + 4);
    at += 8;
    for (int i = 0; present && i < count && at < this->File.Size(); ++i)
    {
      const std::string name = this->Name(at);
      const int type = this->File.Int(at);
      const size_t n = static_cast<size_t>(this->File.Int(at + 4));
      at += 8;
      if (text && type == 2)
      {
        const std::string s = this->File.Text(at, n);
        (*text)[name] = s.substr(0, s.find('\0'));
      }
      at += (n * std::max<size_t>(TypeSize(type), 1) + 3) / 4 * 4;
    }
  }

  BigEndianFile File;
  std::map<std::string, size_t> Dimensions;
  std::map<std::string, Variable> Variables;
  size_t RecordSize = 0;
};
}

namespace ppiray_test
{
//------------------------------------------------------------------------------
// PLOT3D, one 3D grid, whole (no record markers), big-endian: "ni nj nk" then
// x, y, z (an IBlank block may follow: skipped, the data's README says nothing
// is blanked); the solution "ni nj nk fsmach alpha re time" then density,
// three momentum components and stagnation energy. Cells as VTK_HEXAHEDRON in
// vtkStructuredGrid's corner order (i fastest, then j, then k).
// `function`: 100 Density, 110 Pressure, 153 VelocityMagnitude, with
// vtkMultiBlockPLOT3DReader's numbers, names and formulas.
vtkSmartPointer<vtkUnstructuredGrid> ReadPLOT3D(
  const std::string& xyzPath, const std::string& qPath, int function, std::string* error)
{
  BigEndianFile xyz, q;
  if (!xyz.Load(xyzPath) || !q.Load(qPath))
  {
    *error = "cannot read " + xyzPath + " or " + qPath;
    return nullptr;
  }
  const int dims[3] = { xyz.Int(0), xyz.Int(4), xyz.Int(8) };
  const size_t n =
    static_cast<size_t>(std::max(dims[0], 0)) * std::max(dims[1], 0) * std::max(dims[2], 0);
  if (dims[0] < 2 || dims[1] < 2 || dims[2] < 2 || xyz.Size() < 12 + 12 * n ||
      q.Int(0) != dims[0] || q.Int(4) != dims[1] || q.Int(8) != dims[2] || q.Size() < 28 + 20 * n)
  {
    *error = "not a whole single-grid 3D PLOT3D pair: " + xyzPath;
    return nullptr;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(n));
  for (size_t p = 0; p < n; ++p)
  {
    points->SetPoint(static_cast<vtkIdType>(p), xyz.Float(12 + 4 * p), xyz.Float(12 + 4 * (n + p)),
      xyz.Float(12 + 4 * (2 * n + p)));
  }
  vtkNew<vtkFloatArray> scalars;
  scalars->SetName(
    function == 110 ? "Pressure" : (function == 153 ? "VelocityMagnitude" : "Density"));
  scalars->SetNumberOfTuples(static_cast<vtkIdType>(n));
  const double gamma = 1.4;
  for (size_t p = 0; p < n; ++p)
  {
    const size_t at = 28 + 4 * p;
    const double rho = q.Float(at);
    const double m[3] = { q.Float(at + 4 * n), q.Float(at + 8 * n), q.Float(at + 12 * n) };
    const double energy = q.Float(at + 16 * n);
    const double d = rho != 0.0 ? rho : 1.0;
    const double v2 = (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]) / (d * d);
    double value = rho;
    if (function == 110)
    {
      value = (gamma - 1.0) * (energy - 0.5 * d * v2);
    }
    else if (function == 153)
    {
      value = std::sqrt(v2);
    }
    scalars->SetValue(static_cast<vtkIdType>(p), static_cast<float>(value));
  }
  vtkNew<vtkCellArray> cells;
  auto id = [&](int i, int j, int k)
  { return static_cast<vtkIdType>(i + static_cast<vtkIdType>(dims[0]) * (j + dims[1] * k)); };
  for (int k = 0; k + 1 < dims[2]; ++k)
  {
    for (int j = 0; j + 1 < dims[1]; ++j)
    {
      for (int i = 0; i + 1 < dims[0]; ++i)
      {
        const vtkIdType hex[8] = { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k),
          id(i, j + 1, k), id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
          id(i, j + 1, k + 1) };
        cells->InsertNextCell(8, hex);
      }
    }
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->SetCells(VTK_HEXAHEDRON, cells);
  grid->GetPointData()->SetScalars(scalars);
  return grid;
}

//------------------------------------------------------------------------------
// An Exodus II file's element blocks (HEX8 only) as one vtkUnstructuredGrid
// over all its nodes, the nodal variable `name` of the first time step as
// point scalars: what vtkExodusIIReader with SetPointResultArrayStatus(name, 1)
// gives with its blocks appended, points merged (they share one numbering).
vtkSmartPointer<vtkUnstructuredGrid> ReadExodusHexahedra(
  const std::string& path, const std::string& name, std::string* error)
{
  NetCDFClassic file;
  if (!file.Open(path))
  {
    *error = "not a netCDF classic file: " + path;
    return nullptr;
  }
  const size_t nodes = file.Dimension("num_nodes");
  std::vector<double> xyz[3];
  const char* axes[3] = { "coordx", "coordy", "coordz" };
  for (int c = 0; c < 3; ++c)
  {
    if (const auto* v = file.Find(axes[c])) // current layout: a variable per axis
    {
      xyz[c] = file.Values(*v, 0, nodes);
    }
    else if (const auto* coord = file.Find("coord")) // older: coord[num_dim][num_nodes]
    {
      xyz[c] = file.Values(*coord, c * nodes, nodes);
    }
    if (nodes == 0 || xyz[c].size() != nodes)
    {
      *error = "no coordinates in " + path;
      return nullptr;
    }
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(nodes));
  for (size_t p = 0; p < nodes; ++p)
  {
    points->SetPoint(static_cast<vtkIdType>(p), xyz[0][p], xyz[1][p], xyz[2][p]);
  }
  vtkNew<vtkCellArray> cells;
  for (size_t b = 1; b <= file.Dimension("num_el_blk"); ++b)
  {
    const auto* connect = file.Find("connect" + std::to_string(b));
    if (!connect)
    {
      continue; // an empty block
    }
    auto it = connect->TextAttributes.find("elem_type");
    std::string type = it == connect->TextAttributes.end() ? std::string() : it->second;
    std::transform(type.begin(), type.end(), type.begin(),
      [](unsigned char ch) { return static_cast<char>(std::toupper(ch)); });
    if (type.compare(0, 3, "HEX") != 0 || connect->Shape.size() != 2 || connect->Shape[1] != 8)
    {
      *error = "element block " + std::to_string(b) + " is " + type + ", not HEX8";
      return nullptr;
    }
    const auto ids = file.Values(*connect, 0, connect->Count());
    for (size_t e = 0; e + 8 <= ids.size(); e += 8)
    {
      vtkIdType hex[8]; // Exodus numbers HEX8 corners like VTK_HEXAHEDRON, from 1
      for (int i = 0; i < 8; ++i)
      {
        hex[i] = static_cast<vtkIdType>(ids[e + i]) - 1;
        if (hex[i] < 0 || hex[i] >= static_cast<vtkIdType>(nodes))
        {
          *error = "node id out of range in " + path;
          return nullptr;
        }
      }
      cells->InsertNextCell(8, hex);
    }
  }
  std::vector<double> values;
  const auto* names = file.Find("name_nod_var");
  for (size_t i = 0; names && names->Shape.size() == 2 && i < names->Shape[0]; ++i)
  {
    if (file.Text(*names, i) != name)
    {
      continue;
    }
    if (const auto* v = file.Find("vals_nod_var" + std::to_string(i + 1)))
    {
      values = file.Values(*v, 0, nodes);
    }
    else if (const auto* all = file.Find("vals_nod_var")) // older: [time][variable][node]
    {
      values = file.Values(*all, i * nodes, nodes);
    }
  }
  if (values.size() != nodes || cells->GetNumberOfCells() == 0)
  {
    *error = "no hexahedra or no nodal variable " + name + " in " + path;
    return nullptr;
  }
  vtkNew<vtkFloatArray> scalars;
  scalars->SetName(name.c_str());
  scalars->SetNumberOfTuples(static_cast<vtkIdType>(nodes));
  for (size_t p = 0; p < nodes; ++p)
  {
    scalars->SetValue(static_cast<vtkIdType>(p), static_cast<float>(values[p]));
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->SetCells(VTK_HEXAHEDRON, cells);
  grid->GetPointData()->SetScalars(scalars);
  return grid;
}

//------------------------------------------------------------------------------
// UNISIM-II with the derived point scalars "Depth" = -z.
vtkSmartPointer<vtkUnstructuredGrid> ReadUNISIM(const std::string& path, std::string* error)
{
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->ShallowCopy(reader->GetOutput());
  if (grid->GetNumberOfCells() == 0)
  {
    *error = "no cells in " + path;
    return nullptr;
  }
  vtkNew<vtkDoubleArray> depth;
  depth->SetName("Depth");
  depth->SetNumberOfTuples(grid->GetNumberOfPoints());
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p)
  {
    double x[3];
    grid->GetPoint(p, x);
    depth->SetValue(p, -x[2]);
  }
  grid->GetPointData()->SetScalars(depth);
  return grid;
}
}
