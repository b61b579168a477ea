#include "vtkUnstructuredGridGPURayCastMapper.h"

#include "ppirayLinearCellKinds.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPPIRayDepthPeeling.h"
#include "vtkPPIRayHexahedralCellBuffers.h"
#include "vtkPPIRayIsoSurfaceUniforms.h"
#include "vtkPPIRayMarchShader.h"
#include "vtkPPIRayScalarField.h"
#include "vtkPPIRaySegmentIntegrator.h"
#include "vtkPPIRayTetrahedralCellBuffers.h"
#include "vtkPPIRayTransferFunctionTexture.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPoints.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridAlgorithm.h"
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"
#include "vtkVolumeProperty.h"
#include "vtkWeakPointer.h"

#include "ppirayValidPointIds.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkUnstructuredGridGPURayCastMapper);

static_assert(
  int(vtkUnstructuredGridGPURayCastMapper::SETUP_PASS) == vtkPPIRayPassTimes::Setup &&
    int(vtkUnstructuredGridGPURayCastMapper::NEAR_PLANE_ENTRY_PASS) ==
      vtkPPIRayPassTimes::NearPlaneEntry &&
    int(vtkUnstructuredGridGPURayCastMapper::ENTRY_PASS) == vtkPPIRayPassTimes::Entry &&
    int(vtkUnstructuredGridGPURayCastMapper::MARCH_PASS) == vtkPPIRayPassTimes::March &&
    int(vtkUnstructuredGridGPURayCastMapper::CONTINUATION_CHECK_PASS) ==
      vtkPPIRayPassTimes::ContinuationCheck &&
    int(vtkUnstructuredGridGPURayCastMapper::COMPOSITE_PASS) == vtkPPIRayPassTimes::Composite &&
    int(vtkUnstructuredGridGPURayCastMapper::NUMBER_OF_PASS_KINDS) ==
      vtkPPIRayPassTimes::NumberOfPasses,
  "one set of pass kinds");

static_assert(
  int(vtkUnstructuredGridGPURayCastMapper::NO_ISOSURFACES) == ppiray::NoIsoSurfaces &&
    int(vtkUnstructuredGridGPURayCastMapper::EMBEDDED_ISOSURFACES) == ppiray::EmbeddedIsoSurfaces &&
    int(vtkUnstructuredGridGPURayCastMapper::ISOSURFACES_ONLY) == ppiray::IsoSurfacesOnly,
  "one set of isosurface mode values");

//------------------------------------------------------------------------------
// The collaborators, each owning one concept and its GL objects, and what the
// cells were built from.
class vtkUnstructuredGridGPURayCastMapper::vtkInternals
{
public:
  vtkPPIRayTetrahedralCellBuffers Tetrahedra;
  vtkPPIRayHexahedralCellBuffers Hexahedra;
  vtkPPIRayCellBuffers* Cells = nullptr; // the kind the mesh is rendered as
  vtkUnstructuredGridBase* CellsInput = nullptr;
  vtkTimeStamp CellsTime;
  bool CellsForHexahedra = false; // built with a hexahedron mode other than SUBDIVIDE
  int CellsLayout = 0;            // the tetrahedron layout built
  bool CellsValid = false;
  vtkNew<vtkUnstructuredGrid> InputCopy;   // when the input is not a vtkUnstructuredGrid
  vtkNew<vtkUnstructuredGrid> Convexified; // NON_CONVEX_CONVEXIFY: the Convexifier's output
  vtkUnstructuredGridBase* ConvexifiedInput = nullptr;
  vtkTimeStamp ConvexifiedTime;
  bool ConvexifyWarned = false;
  vtkSmartPointer<vtkUnstructuredGrid> ValidCells; // the input with cells of invalid ids emptied

  vtkPPIRayScalarField Field;
  vtkPPIRayTransferFunctionTexture TransferFunction;
  std::unique_ptr<vtkPPIRaySegmentIntegrator> Integrator;
  vtkPPIRayIsoSurfaceUniforms IsoSurfaces;
  vtkPPIRayMarchShader MarchShader;
  vtkPPIRayDepthPeeling Peeling;
  int ClippingPlanesWarned = 0;      // the count of planes last warned about
  bool OverlapWarned = false;        // overlapping PPIRay volumes were reported
  std::vector<float> Section;        // this frame's near-plane sections
  std::vector<float> ClippingPlanes; // this frame's clipping planes, local frame
  // The context the GL objects live in (one at a time, as VTK's own mappers
  // keep them).
  vtkWeakPointer<vtkOpenGLRenderWindow> Context;

  // Releases the GL objects in the context they live in (made current for
  // it, then restored), else in `window`'s.
  void ReleaseInTheirContext(vtkWindow* window)
  {
    if (vtkOpenGLRenderWindow* context = this->Context)
    {
      context->PushContext();
      this->ReleaseGraphicsResources(context);
      context->PopContext();
      this->Context = nullptr;
      // PopContext restores the earlier context only for X windows (VTK's
      // default PushContext just makes the window current): `window`, where
      // the caller renders next, is made current again.
      if (auto* next = vtkOpenGLRenderWindow::SafeDownCast(window))
      {
        next->MakeCurrent();
      }
    }
    else
    {
      this->ReleaseGraphicsResources(window);
    }
  }

  void ReleaseGraphicsResources(vtkWindow* window)
  {
    this->Tetrahedra.ReleaseGraphicsResources(window);
    this->Hexahedra.ReleaseGraphicsResources(window);
    this->TransferFunction.ReleaseGraphicsResources(window);
    if (this->Integrator)
    {
      this->Integrator->ReleaseGraphicsResources(window);
    }
    this->MarchShader.ReleaseGraphicsResources(window);
    this->Peeling.ReleaseGraphicsResources(window);
  }
};

namespace
{
// Whether every point coordinate is finite.
bool FiniteCoordinates(vtkPoints* points)
{
  if (!points)
  {
    return true;
  }
  vtkDataArray* data = points->GetData();
  const vtkIdType n = data->GetNumberOfValues();
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (!std::isfinite(data->GetComponent(i / 3, static_cast<int>(i % 3))))
    {
      return false;
    }
  }
  return true;
}

// The point at normalized device coordinates (x, y, z) in the frame
// `clipToLocal` maps clip space to.
glm::dvec3 Unproject(vtkMatrix4x4* clipToLocal, double x, double y, double z)
{
  const double clip[4] = { x, y, z, 1.0 };
  double local[4];
  clipToLocal->MultiplyPoint(clip, local);
  return glm::dvec3(local[0], local[1], local[2]) / local[3];
}

// The near plane (n, d), n . x = d, n unit and towards the far plane, in
// the frame `clipToLocal` maps clip space to.
glm::dvec4 NearPlane(vtkMatrix4x4* clipToLocal)
{
  const glm::dvec3 a = Unproject(clipToLocal, -1, -1, -1);
  glm::dvec3 n = glm::normalize(
    glm::cross(Unproject(clipToLocal, 1, -1, -1) - a, Unproject(clipToLocal, -1, 1, -1) - a));
  n = glm::dot(n, Unproject(clipToLocal, 0, 0, 1) - a) < 0 ? -n : n;
  return glm::dvec4(n, glm::dot(n, a));
}

// The viewing ray's direction through the pixel at NDC (x, y),
//   d(x, y) = far(x, y) - near(x, y) = D (x, y, 1),
// is affine in (x, y) for perspective and parallel projections alike (eye
// space: (f - n) ((x + P02) / P00, (y + P12) / P11, -1), or (0, 0, n - f)):
// D, column-major, from d at three pixels, in double. In float the far
// point's w is a difference of two terms of about 1 / (2 n) that cancel to
// 1 / f: with the near plane 1e-4 of the far one (a camera inside a mesh)
// a ray passed cell edges on the wrong side.
void NdcToDirection(vtkMatrix4x4* clipToLocal, float out[9])
{
  auto direction = [clipToLocal](double x, double y)
  { return Unproject(clipToLocal, x, y, 1) - Unproject(clipToLocal, x, y, -1); };
  const glm::dvec3 d0 = direction(0, 0);
  const glm::dvec3 columns[3] = { direction(1, 0) - d0, direction(0, 1) - d0, d0 };
  for (int c = 0; c < 3; ++c)
  {
    for (int r = 0; r < 3; ++r)
    {
      out[3 * c + r] = static_cast<float>(columns[c][r]);
    }
  }
}

// The uniforms of the average-intensity and additive projections
// (projection_fs.glsl): the normalizing map and the averaged range, shifted
// as the scalars are.
void ProjectionUniforms(
  vtkShaderProgram* program, const vtkPPIRayScalarField& field, const double averageRange[2])
{
  double ab[2];
  field.NormalizingMap(ab);
  const float normalizing[2] = { static_cast<float>(ab[0]), static_cast<float>(ab[1]) };
  program->SetUniform2f("normalizedScalar", normalizing);
  const double limit = VTK_FLOAT_MAX;
  float range[2];
  for (int i = 0; i < 2; ++i)
  {
    range[i] =
      static_cast<float>(std::max(-limit, std::min(limit, averageRange[i] - field.GetShift())));
  }
  program->SetUniform2f("averageRange", range);
}

// Column-major float copy of a row-major VTK matrix, for glUniformMatrix4fv.
void ColumnMajor(vtkMatrix4x4* m, float out[16])
{
  for (int c = 0; c < 4; ++c)
  {
    for (int r = 0; r < 4; ++r)
    {
      out[4 * c + r] = static_cast<float>(m->GetElement(r, c));
    }
  }
}
}

//------------------------------------------------------------------------------
vtkUnstructuredGridGPURayCastMapper::vtkUnstructuredGridGPURayCastMapper()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkUnstructuredGridGPURayCastMapper::~vtkUnstructuredGridGPURayCastMapper()
{
  if (this->Internals->Context)
  {
    this->Internals->ReleaseInTheirContext(nullptr);
  }
  this->SetConvexifier(nullptr);
}

//------------------------------------------------------------------------------
vtkCxxSetObjectMacro(
  vtkUnstructuredGridGPURayCastMapper, Convexifier, vtkUnstructuredGridAlgorithm);

//------------------------------------------------------------------------------
vtkUnstructuredGridBase* vtkUnstructuredGridGPURayCastMapper::RenderedGrid(
  vtkUnstructuredGridBase* input)
{
  vtkInternals& in = *this->Internals;
  if (this->NonConvexMode != NON_CONVEX_CONVEXIFY)
  {
    return input;
  }
  auto* grid = vtkUnstructuredGrid::SafeDownCast(input);
  if (!this->Convexifier)
  {
    // One registered with VTK's object factory: loading PPIRay::Convexify
    // registers vtkUnstructuredGridConvexify (this module does not link it).
    auto made = vtkSmartPointer<vtkObject>::Take(
      vtkObjectFactory::CreateInstance("vtkUnstructuredGridConvexify"));
    this->SetConvexifier(vtkUnstructuredGridAlgorithm::SafeDownCast(made));
  }
  if (!this->Convexifier || !grid)
  {
    if (!in.ConvexifyWarned)
    {
      vtkWarningMacro(<< (this->Convexifier ? "The input is not a vtkUnstructuredGrid"
                                            : "No Convexifier (e.g. vtkUnstructuredGridConvexify)")
                      << ": NON_CONVEX_CONVEXIFY peels instead.");
      in.ConvexifyWarned = true;
    }
    return input;
  }
  if (in.ConvexifiedInput != input || input->GetMTime() > in.ConvexifiedTime.GetMTime() ||
      this->Convexifier->GetMTime() > in.ConvexifiedTime.GetMTime())
  {
    this->Convexifier->SetInputData(grid);
    this->Convexifier->Update();
    in.Convexified->ShallowCopy(this->Convexifier->GetOutput());
    this->Convexifier->SetInputData(nullptr);
    in.ConvexifiedInput = input;
    in.ConvexifiedTime.Modified();
  }
  return in.Convexified;
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastMapper::SetIntegrationMode(int mode)
{
  if (mode != PARTIAL_PRE_INTEGRATION && mode != EXACT_LINEAR && mode != FULL_PRE_INTEGRATION &&
      mode != AVERAGE_COLOR)
  {
    vtkErrorMacro("Unknown integration mode " << mode << "; keeping "
                                              << this->GetIntegrationModeAsString() << ".");
    return;
  }
  if (mode != this->IntegrationMode)
  {
    this->IntegrationMode = mode;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
const char* vtkUnstructuredGridGPURayCastMapper::GetIntegrationModeAsString()
{
  switch (this->IntegrationMode)
  {
    case EXACT_LINEAR:
      return "EXACT_LINEAR";
    case AVERAGE_COLOR:
      return "AVERAGE_COLOR";
    case FULL_PRE_INTEGRATION:
      return "FULL_PRE_INTEGRATION";
    default:
      return "PARTIAL_PRE_INTEGRATION";
  }
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastMapper::SetHexahedronMode(int mode)
{
  if (mode != HEXAHEDRON_ACCURATE && mode != HEXAHEDRON_FAST && mode != HEXAHEDRON_SUBDIVIDE)
  {
    vtkErrorMacro("Unknown hexahedron mode " << mode << "; keeping "
                                             << this->GetHexahedronModeAsString() << ".");
    return;
  }
  if (mode != this->HexahedronMode)
  {
    this->HexahedronMode = mode;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
const char* vtkUnstructuredGridGPURayCastMapper::GetTetrahedronLayoutAsString()
{
  return this->TetrahedronLayout == TETRAHEDRON_COMPACT ? "TETRAHEDRON_COMPACT"
                                                        : "TETRAHEDRON_PLANES";
}

//------------------------------------------------------------------------------
const char* vtkUnstructuredGridGPURayCastMapper::GetHexahedronModeAsString()
{
  switch (this->HexahedronMode)
  {
    case HEXAHEDRON_ACCURATE:
      return "HEXAHEDRON_ACCURATE";
    case HEXAHEDRON_FAST:
      return "HEXAHEDRON_FAST";
    default:
      return "HEXAHEDRON_SUBDIVIDE";
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkUnstructuredGridGPURayCastMapper::GetNumberOfHexahedra()
{
  vtkInternals& in = *this->Internals;
  return in.Cells == &in.Hexahedra ? in.Hexahedra.GetNumberOfCellsOfKind(ppiray::HEXAHEDRON_KIND)
                                   : 0;
}

//------------------------------------------------------------------------------
vtkIdType vtkUnstructuredGridGPURayCastMapper::GetNumberOfNativeCells()
{
  vtkInternals& in = *this->Internals;
  return in.Cells == &in.Hexahedra ? in.Hexahedra.GetNumberOfCells() : 0;
}

//------------------------------------------------------------------------------
vtkIdType vtkUnstructuredGridGPURayCastMapper::GetNumberOfTetrahedra()
{
  vtkInternals& in = *this->Internals;
  return in.Cells == &in.Tetrahedra ? in.Tetrahedra.GetNumberOfTetrahedra() : 0;
}

//------------------------------------------------------------------------------
vtkIdType vtkUnstructuredGridGPURayCastMapper::GetNumberOfLinkedBoundaryFaces()
{
  vtkInternals& in = *this->Internals;
  return in.Cells == &in.Tetrahedra ? in.Tetrahedra.GetTextures()->GetNumberOfLinkedFaces() : 0;
}

//------------------------------------------------------------------------------
vtkIdType vtkUnstructuredGridGPURayCastMapper::GetNumberOfSplitBoundaryFaces()
{
  vtkInternals& in = *this->Internals;
  return in.Cells == &in.Tetrahedra ? in.Tetrahedra.GetTextures()->GetNumberOfSplitFaces() : 0;
}

//------------------------------------------------------------------------------
vtkIdType vtkUnstructuredGridGPURayCastMapper::GetNumberOfUnlinkedBoundaryFaces()
{
  vtkInternals& in = *this->Internals;
  return in.Cells == &in.Tetrahedra ? in.Tetrahedra.GetTextures()->GetNumberOfUnlinkedFaces() : 0;
}

//------------------------------------------------------------------------------
double vtkUnstructuredGridGPURayCastMapper::GetPreIntegrationTableBuildTime()
{
  vtkInternals& in = *this->Internals;
  return in.Integrator ? in.Integrator->GetTableBuildTime() : 0.0;
}

//------------------------------------------------------------------------------
int vtkUnstructuredGridGPURayCastMapper::GetGeometryUploadCount()
{
  vtkInternals& in = *this->Internals;
  return in.Tetrahedra.GetGeometryUploadCount() + in.Hexahedra.GetGeometryUploadCount();
}

//------------------------------------------------------------------------------
int vtkUnstructuredGridGPURayCastMapper::GetFieldUploadCount()
{
  vtkInternals& in = *this->Internals;
  return in.Tetrahedra.GetFieldUploadCount() + in.Hexahedra.GetFieldUploadCount();
}

//------------------------------------------------------------------------------
int vtkUnstructuredGridGPURayCastMapper::GetTransferFunctionUploadCount()
{
  return this->Internals->TransferFunction.GetUploadCount();
}

//------------------------------------------------------------------------------
double vtkUnstructuredGridGPURayCastMapper::GetPassTime(int kind)
{
  return this->Internals->Peeling.GetPassTimes().GetMilliseconds(kind);
}

//------------------------------------------------------------------------------
int vtkUnstructuredGridGPURayCastMapper::GetNumberOfPasses(int kind)
{
  return this->Internals->Peeling.GetPassTimes().GetCount(kind);
}

//------------------------------------------------------------------------------
const char* vtkUnstructuredGridGPURayCastMapper::GetPassKindName(int kind)
{
  return vtkPPIRayPassTimes::GetName(kind);
}

//------------------------------------------------------------------------------
vtkIdType vtkUnstructuredGridGPURayCastMapper::GetGPUMemorySize()
{
  vtkInternals& in = *this->Internals;
  const size_t bytes =
    (in.Cells ? in.Cells->GetGPUBytes() : 0) + in.TransferFunction.GetGPUBytes() +
    (in.Integrator ? in.Integrator->GetGPUBytes() : 0) + in.Peeling.GetGPUBytes();
  return static_cast<vtkIdType>(bytes);
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  // Whichever window asks (a renderer the volume leaves, a window closing),
  // the objects are deleted in their own context.
  this->Internals->ReleaseInTheirContext(window);
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
bool vtkUnstructuredGridGPURayCastMapper::UpdateCells(
  vtkUnstructuredGridBase* input, vtkOpenGLRenderWindow* context)
{
  vtkInternals& in = *this->Internals;
  vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(input);
  vtkMTimeType sourceTime = input->GetPoints() ? input->GetPoints()->GetMTime() : 0;
  sourceTime = std::max(
    sourceTime, grid && grid->GetCells() ? grid->GetCells()->GetMTime() : input->GetMTime());
  const bool forHexahedra = this->HexahedronMode != HEXAHEDRON_SUBDIVIDE;
  if (in.CellsInput == input && sourceTime <= in.CellsTime.GetMTime() &&
      in.CellsForHexahedra == forHexahedra && in.CellsLayout == this->TetrahedronLayout)
  {
    return in.CellsValid;
  }
  in.CellsInput = input;
  in.CellsForHexahedra = forHexahedra;
  in.CellsLayout = this->TetrahedronLayout;
  in.CellsTime.Modified();
  in.CellsValid = false;
  in.Field.Invalidate(); // the field follows the cells
  if (!grid)
  {
    in.InputCopy->DeepCopy(input);
    grid = in.InputCopy;
  }
  if (!FiniteCoordinates(grid->GetPoints()))
  {
    vtkErrorMacro("The input has infinite or NaN point coordinates; nothing is rendered.");
    return false;
  }
  vtkIdType invalidCells = 0;
  in.ValidCells = ppiray::EmptyCellsWithInvalidPointIds(grid, invalidCells);
  if (in.ValidCells)
  {
    vtkErrorMacro(<< invalidCells << " cells list point ids outside [0, "
                  << grid->GetNumberOfPoints() << "): they are not rendered.");
    grid = in.ValidCells;
  }
  // Hexahedra without subdivision when the mesh is for them, else tetrahedra.
  using Result = vtkPPIRayCellBuffers::BuildResult;
  vtkPPIRayCellBuffers* cells = &in.Hexahedra;
  Result result = forHexahedra ? in.Hexahedra.BuildGeometry(grid, this) : Result::Declined;
  if (result == Result::Declined)
  {
    cells = &in.Tetrahedra;
    in.Tetrahedra.SetLayout(this->TetrahedronLayout == TETRAHEDRON_COMPACT
                              ? vtkTetrahedralCellTextures::COMPACT
                              : vtkTetrahedralCellTextures::PLANES);
    result = in.Tetrahedra.BuildGeometry(grid, this);
  }
  if (in.Cells && in.Cells != cells)
  {
    in.Cells->ReleaseGraphicsResources(context);
  }
  in.Cells = cells;
  in.CellsValid = result == Result::Built;
  return in.CellsValid;
}

//------------------------------------------------------------------------------
bool vtkUnstructuredGridGPURayCastMapper::UpdateField(vtkUnstructuredGridBase* input)
{
  vtkInternals& in = *this->Internals;
  vtkPPIRayScalarField::Selection selection = { this->ScalarMode, this->ArrayAccessMode,
    this->ArrayId, this->ArrayName, this->VectorMode == MAGNITUDE, this->VectorComponent };
  switch (in.Field.Update(input, selection, this))
  {
    case vtkPPIRayScalarField::Status::Failed:
      return false;
    case vtkPPIRayScalarField::Status::Changed:
      in.Cells->BuildField(in.Field.GetValues(), in.Field.IsCellData(), this);
      return true;
    default:
      return true;
  }
}

//------------------------------------------------------------------------------
bool vtkUnstructuredGridGPURayCastMapper::UpdateIntegrator(vtkOpenGLRenderWindow* context)
{
  vtkInternals& in = *this->Internals;
  if (!in.Integrator || in.Integrator->GetIntegrationMode() != this->IntegrationMode)
  {
    if (in.Integrator)
    {
      in.Integrator->ReleaseGraphicsResources(context);
    }
    in.Integrator = vtkPPIRaySegmentIntegrator::New(this->IntegrationMode);
  }
  const double* range = in.Field.GetRange();
  const vtkPPIRaySegmentIntegrator::Inputs inputs = { in.TransferFunction.GetControlPoints(),
    { range[0], range[1] }, in.Field.GetShift(), in.Cells->GetMaximumSegmentLength(),
    std::max({ in.TransferFunction.GetMTime(), in.Field.GetMTime(), in.CellsTime.GetMTime() }),
    this->PsiTableSize, this->PreIntegrationTableSize };
  return in.Integrator->Update(context, inputs, this);
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastMapper::ClippingPlanesInLocalFrame(
  vtkMatrix4x4* localToWorld, std::vector<float>& planes)
{
  // A vtkPlane (origin o, normal n) keeps n . (x - o) >= 0 in world
  // coordinates: p = (n, -n . o); with x = L y (L: local to world) that is
  // (L^T p) . y >= 0 in the local frame.
  planes.clear();
  const int count = this->ClippingPlanes ? this->ClippingPlanes->GetNumberOfItems() : 0;
  if (count > 6 && count != this->Internals->ClippingPlanesWarned)
  {
    vtkWarningMacro(<< count << " clipping planes; only the first 6 clip the volume.");
  }
  this->Internals->ClippingPlanesWarned = count > 6 ? count : 0;
  for (int i = 0; i < std::min(count, 6); ++i)
  {
    vtkPlane* plane = this->ClippingPlanes->GetItem(i);
    const double* n = plane->GetNormal();
    const double* o = plane->GetOrigin();
    const double world[4] = { n[0], n[1], n[2], -(n[0] * o[0] + n[1] * o[1] + n[2] * o[2]) };
    for (int c = 0; c < 4; ++c)
    {
      double local = 0.0;
      for (int r = 0; r < 4; ++r)
      {
        local += world[r] * localToWorld->GetElement(r, c);
      }
      planes.push_back(static_cast<float>(local));
    }
  }
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastMapper::WarnAboutOverlappingVolumes(
  vtkRenderer* ren, vtkVolume* vol)
{
  // Each PPIRay volume composites its whole image over what was drawn before
  // it: overlapping ones are not interleaved per pixel.
  double bounds[6];
  vol->GetBounds(bounds);
  int overlapping = 0;
  vtkVolumeCollection* volumes = ren->GetVolumes();
  vtkCollectionSimpleIterator it;
  volumes->InitTraversal(it);
  while (vtkVolume* other = volumes->GetNextVolume(it))
  {
    // A prop that wraps `vol` (ParaView's vtkPVLODVolume) shares this mapper.
    if (other == vol || other->GetMapper() == this || !other->GetVisibility() ||
        !vtkUnstructuredGridGPURayCastMapper::SafeDownCast(other->GetMapper()))
    {
      continue;
    }
    const double* b = other->GetBounds();
    bool overlaps = b != nullptr;
    for (int i = 0; overlaps && i < 3; ++i)
    {
      overlaps = b[2 * i] <= bounds[2 * i + 1] && bounds[2 * i] <= b[2 * i + 1];
    }
    overlapping += overlaps ? 1 : 0;
  }
  vtkInternals& in = *this->Internals;
  if (overlapping > 0 && !in.OverlapWarned)
  {
    vtkWarningMacro(<< overlapping
                    << " other PPIRay volumes overlap this one: each is composited whole over "
                       "what was rendered before it, in the renderer's order, not interleaved "
                       "per pixel.");
  }
  in.OverlapWarned = overlapping > 0;
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastMapper::Render(vtkRenderer* ren, vtkVolume* vol)
{
  // The frame's wall time, for AutoAdjustSampleDistances.
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  this->RenderFrame(ren, vol);
  timer->StopTimer();
  this->TimeToDraw = timer->GetElapsedTime();
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastMapper::RenderFrame(vtkRenderer* ren, vtkVolume* vol)
{
  vtkNew<vtkTimerLog> preparation;
  preparation->StartTimer();
  this->PreparationTime = 0.0;
  this->NumberOfPeels = 0;
  this->NumberOfContinuations = 0;
  this->NumberOfCellSteps = 0;
  if (this->GetInputAlgorithm())
  {
    this->GetInputAlgorithm()->Update();
  }
  vtkUnstructuredGridBase* input = this->GetInput();
  vtkOpenGLRenderWindow* context = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!input || !context || !vol || !vol->GetProperty())
  {
    vtkErrorMacro("Nothing to render: " << (!input ? "no input" : "no OpenGL window or property"));
    return;
  }
  if (input->GetNumberOfCells() == 0 || input->GetNumberOfPoints() == 0)
  {
    return; // an empty grid is a valid scene: nothing to draw
  }
  input = this->RenderedGrid(input);

  // Find what is stale and update the collaborators, on the CPU, then the GPU.
  // GL objects made in another context (a second window) are released there
  // first and made again in this one.
  vtkInternals& in = *this->Internals;
  if (in.Context != context)
  {
    in.ReleaseInTheirContext(context);
    in.Context = context;
  }
  this->WarnAboutOverlappingVolumes(ren, vol);
  const ppiray::IsoSurfaceMode isoMode =
    in.IsoSurfaces.Update(ren, vol, this->BlendMode, this->EmbedIsoSurfaces != 0, this);
  if (!this->UpdateCells(input, context) || !this->UpdateField(input) ||
      !in.TransferFunction.Update(vol->GetProperty(), in.Field.GetShift(), this))
  {
    return;
  }
  in.Cells->SetMaximumBufferTexels(static_cast<size_t>(this->MaximumBufferTexels));
  if (!in.Cells->Upload(context, this) || !in.TransferFunction.Upload(context, this) ||
      !this->UpdateIntegrator(context))
  {
    return;
  }
  vtkPPIRayDepthPeeling::Frame frame;
  ren->GetTiledSizeAndOrigin(&frame.Width, &frame.Height, &frame.X0, &frame.Y0);
  if (frame.Width <= 0 || frame.Height <= 0)
  {
    return;
  }
  if (this->AutoAdjustSampleDistances)
  {
    // d <- d sqrt(last frame's time / allocated time), clamped
    // (vtkUnstructuredGridVolumeRayCastMapper's rule).
    const double allocated = vol->GetAllocatedRenderTime();
    const double last = this->TimeToDraw;
    const double d = last > 0.0 && allocated > 0.0
                       ? this->ImageSampleDistance * std::sqrt(last / allocated)
                       : this->ImageSampleDistance;
    this->ImageSampleDistance =
      static_cast<float>(std::min<double>(std::max<double>(d, this->MinimumImageSampleDistance),
        std::max(this->MinimumImageSampleDistance, this->MaximumImageSampleDistance)));
  }
  frame.TargetWidth =
    std::max(1, static_cast<int>(std::ceil(frame.Width / this->ImageSampleDistance)));
  frame.TargetHeight =
    std::max(1, static_cast<int>(std::ceil(frame.Height / this->ImageSampleDistance)));
  // A projection (the blend mode's value: maximum, minimum, average intensity,
  // additive), else composite (0).
  const bool projects =
    this->BlendMode >= MAXIMUM_INTENSITY_BLEND && this->BlendMode <= ADDITIVE_BLEND;
  const int projection = projects ? this->BlendMode : 0;
  vtkOpenGLQuadHelper* march = in.MarchShader.Ready(context,
    in.Cells->GetMarchShader(this->HexahedronMode == HEXAHEDRON_ACCURATE),
    in.Integrator->GetShaderCode(), vtkPPIRayIsoSurfaceUniforms::Declarations(isoMode), projection,
    this);
  if (!march)
  {
    return;
  }

  // Matrices: the cells' local frame (mesh coordinates minus the centre of
  // its bounds) to world and to clip space, and back, composed in double.
  vtkNew<vtkMatrix4x4> localToWorld, localToClip, clipToLocal;
  localToWorld->Identity();
  for (int i = 0; i < 3; ++i)
  {
    localToWorld->SetElement(i, 3, in.Cells->GetOrigin()[i]);
  }
  vtkMatrix4x4::Multiply4x4(vol->GetMatrix(), localToWorld, localToWorld);
  vtkMatrix4x4::Multiply4x4(ren->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
                              ren->GetTiledAspectRatio(), -1, 1),
    localToWorld, localToClip);
  vtkMatrix4x4::Invert(localToClip, clipToLocal);
  ColumnMajor(localToClip, frame.LocalToClip);
  ColumnMajor(clipToLocal, frame.ClipToLocal);
  NdcToDirection(clipToLocal, frame.NdcToDirection);
  // A projection's colour is that of its last extreme: no early stop.
  frame.TerminationAlpha = projection ? 2.0f : static_cast<float>(this->TerminationOpacity);
  frame.MaximumPeels = this->MaximumNumberOfPeels;
  // A camera inside the mesh: rays start at the near plane in the cells it
  // cuts (none when it passes outside the mesh's bounding sphere).
  in.Section.clear();
  const glm::dvec4 nearPlane = NearPlane(clipToLocal);
  if (std::abs(nearPlane.w) < in.Cells->GetBoundingRadius())
  {
    in.Cells->PlaneSection(nearPlane, in.Section);
  }
  frame.Section = &in.Section;
  this->ClippingPlanesInLocalFrame(localToWorld, in.ClippingPlanes);
  frame.ClippingPlanes = &in.ClippingPlanes;
  frame.CountCellSteps = this->CountCellSteps;
  frame.TimePasses = this->TimePasses;
  frame.ConvexBoundary = in.Cells->IsBoundaryConvex();
  const double cells = static_cast<double>(in.Cells->GetNumberOfCells());
  const int maximumSteps =
    this->MaximumNumberOfSteps > 0
      ? this->MaximumNumberOfSteps
      : static_cast<int>(std::min(cells + 1.0, std::max(1024.0, 64.0 * std::cbrt(cells))));

  // Peel: each march reads the cells, the transfer function, the integrator's
  // tables and the isosurfaces.
  auto marchInputs = [&](vtkShaderProgram* program, std::vector<vtkTextureObject*>& textures)
  {
    in.Cells->Bind(program, textures);
    in.TransferFunction.Bind(program, textures);
    in.Integrator->Bind(program, textures);
    program->SetUniformi("maximumSteps", maximumSteps);
    program->SetUniformf("terminationAlpha", frame.TerminationAlpha);
    program->SetUniformf("opacityUnitDistance",
      static_cast<float>(in.TransferFunction.GetControlPoints()->GetUnitDistance()));
    if (projection >= AVERAGE_INTENSITY_BLEND)
    {
      ProjectionUniforms(program, in.Field, this->AverageIPScalarRange);
    }
    if (isoMode != ppiray::NoIsoSurfaces)
    {
      in.IsoSurfaces.Bind(program, localToWorld, in.Field.GetShift());
    }
  };
  bool cut = false;
  preparation->StopTimer();
  this->PreparationTime = 1000.0 * preparation->GetElapsedTime();
  this->NumberOfPeels =
    std::max(0, in.Peeling.Render(context, frame, *in.Cells, *march, marchInputs, cut, this));
  this->NumberOfContinuations = in.Peeling.GetNumberOfContinuations();
  this->NumberOfCellSteps = static_cast<vtkIdType>(in.Peeling.GetNumberOfCellSteps());
  if (cut)
  {
    vtkWarningMacro(
      "Stopped after MaximumNumberOfPeels = " << this->MaximumNumberOfPeels
                                              << " depth peels; parts of the mesh may be missing.");
  }
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IntegrationMode: " << this->GetIntegrationModeAsString() << "\n";
  os << indent << "HexahedronMode: " << this->GetHexahedronModeAsString() << "\n";
  os << indent << "TetrahedronLayout: " << this->GetTetrahedronLayoutAsString() << "\n";
  os << indent << "EmbedIsoSurfaces: " << this->EmbedIsoSurfaces << "\n";
  os << indent << "AverageIPScalarRange: (" << this->AverageIPScalarRange[0] << ", "
     << this->AverageIPScalarRange[1] << ")\n";
  os << indent << "VectorMode: " << (this->VectorMode == MAGNITUDE ? "MAGNITUDE" : "COMPONENT")
     << "\n";
  os << indent << "VectorComponent: " << this->VectorComponent << "\n";
  os << indent << "MaximumNumberOfPeels: " << this->MaximumNumberOfPeels << "\n";
  os << indent << "NonConvexMode: "
     << (this->NonConvexMode == NON_CONVEX_CONVEXIFY ? "NON_CONVEX_CONVEXIFY" : "NON_CONVEX_PEEL")
     << "\n";
  os << indent << "Convexifier: " << this->Convexifier << "\n";
  os << indent << "MaximumNumberOfSteps: " << this->MaximumNumberOfSteps << "\n";
  os << indent << "PsiTableSize: " << this->PsiTableSize << "\n";
  os << indent << "PreIntegrationTableSize: " << this->PreIntegrationTableSize << "\n";
  os << indent << "TerminationOpacity: " << this->TerminationOpacity << "\n";
  os << indent << "NumberOfPeels: " << this->NumberOfPeels << "\n";
  os << indent << "NumberOfContinuations: " << this->NumberOfContinuations << "\n";
  os << indent << "CountCellSteps: " << this->CountCellSteps << "\n";
  os << indent << "TimePasses: " << this->TimePasses << "\n";
  os << indent << "PreparationTime: " << this->PreparationTime << "\n";
  os << indent << "ImageSampleDistance: " << this->ImageSampleDistance << "\n";
  os << indent << "MinimumImageSampleDistance: " << this->MinimumImageSampleDistance << "\n";
  os << indent << "MaximumImageSampleDistance: " << this->MaximumImageSampleDistance << "\n";
  os << indent << "AutoAdjustSampleDistances: " << this->AutoAdjustSampleDistances << "\n";
  os << indent << "NumberOfCellSteps: " << this->NumberOfCellSteps << "\n";
  os << indent << "MaximumBufferTexels: " << this->MaximumBufferTexels << "\n";
  os << indent << "GeometryUploadCount: " << this->GetGeometryUploadCount() << "\n";
  os << indent << "FieldUploadCount: " << this->GetFieldUploadCount() << "\n";
  os << indent << "TransferFunctionUploadCount: " << this->GetTransferFunctionUploadCount() << "\n";
}
