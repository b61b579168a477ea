#include "vtkUnstructuredGridGPURayCastMapper.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellTypes.h"
#include "vtkColorTransferFunction.h"
#include "vtkContourValues.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkHexahedralCellTextures.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPPIRayBufferTexture.h"
#include "vtkPreIntegrationTable.h"
#include "vtkPoints.h"
#include "vtkPsiTable.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTetrahedralCellTextures.h"
#include "vtkTextureObject.h"
#include "vtkTransferFunctionControlPoints.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtk_glew.h"

#include "composite_fs.h"
#include "entry_fs.h"
#include "entry_vs.h"
#include "hexahedron_accurate_fs.h"
#include "hexahedron_fast_fs.h"
#include "hexahedron_field_fs.h"
#include "isosurface_fs.h"
#include "march_common_fs.h"
#include "march_fs.h"
#include "march_hexahedra_fs.h"
#include "piece_exact_fs.h"
#include "piece_ppi_fs.h"
#include "ray_fs.h"
#include "segment_average_fs.h"
#include "segment_full_fs.h"
#include "segment_split_fs.h"
#include "transfer_function_fs.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkUnstructuredGridGPURayCastMapper);

//------------------------------------------------------------------------------
// Everything the mapper caches: CPU-side cell textures and control points, and
// their GPU copies, plus the render targets and programs of the three passes.
class vtkUnstructuredGridGPURayCastMapper::vtkInternals
{
public:
  // CPU caches and what they were built from.
  vtkNew<vtkTetrahedralCellTextures> Tetrahedra;
  vtkNew<vtkHexahedralCellTextures> Hexahedra;
  // Whether the mesh is drawn as hexahedra without subdivision (a mesh of
  // hexahedra and voxels only, HexahedronMode ACCURATE or FAST: Hexahedra),
  // else as tetrahedra (its cells split conformingly: Tetrahedra).
  bool NativeHexahedra = false;
  bool GeometryWantsNativeHexahedra = false; // what the geometry cache was built for
  vtkNew<vtkTransferFunctionControlPoints> ControlPoints;
  vtkNew<vtkUnstructuredGrid> InputCopy; // when the input is not a vtkUnstructuredGrid
  vtkUnstructuredGridBase* GeometryInput = nullptr;
  vtkTimeStamp GeometryTime;
  bool GeometryValid = false;
  vtkDataArray* FieldArray = nullptr;
  int FieldCellFlag = -1;
  int FieldVectorMode = -2;
  int FieldVectorComponent = -1;
  vtkTimeStamp FieldTime;
  // The scalar values rendered (the magnitude or one component) relative to
  // FieldShift, when they are not the array itself.
  vtkNew<vtkDoubleArray> FieldValues;
  double FieldShift = 0.0;
  double TexelShift = 0.0; // the shift TransferFunctionTexels were made with
  vtkVolumeProperty* Property = nullptr;
  vtkTimeStamp TransferFunctionCheckTime; // when the property was last looked at
  vtkTimeStamp TransferFunctionTime;      // when its control points last changed
  std::vector<float> TransferFunctionTexels;

  // GPU copies: valid while the flag is set.
  bool GeometryOnGPU = false;
  bool FieldOnGPU = false;
  bool TransferFunctionOnGPU = false;
  vtkPPIRayBufferTexture Planes;
  vtkPPIRayBufferTexture Neighbors;
  vtkPPIRayBufferTexture Field;
  vtkPPIRayBufferTexture BoundaryFaces;
  vtkPPIRayBufferTexture ControlPointTexels;
  vtkNew<vtkOpenGLBufferObject> BoundaryPoints;
  vtkNew<vtkOpenGLBufferObject> BoundaryTriangles;
  size_t BoundaryBytes = 0;
  vtkNew<vtkOpenGLVertexArrayObject> EntryVAO;
  vtkNew<vtkTextureObject> PsiTexture;
  int PsiTextureSize = 0;
  double FieldRange[2] = { 0, 1 };
  vtkNew<vtkPreIntegrationTable> FullTable;
  vtkNew<vtkTextureObject> FullTableTexture;
  size_t FullTableBytes = 0;
  vtkTimeStamp FullTableTime;

  // Render targets, sized to the viewport.
  vtkNew<vtkOpenGLFramebufferObject> Framebuffer;
  vtkNew<vtkTextureObject> EntryTexture;
  vtkNew<vtkTextureObject> Accumulated[2]; // ping-pong: colour so far
  vtkNew<vtkTextureObject> Exit[2];        // ping-pong: where the last march stopped
  vtkNew<vtkTextureObject> LayerDepth[2];
  vtkNew<vtkTextureObject> OpaqueDepth; // same format as VTK's depth buffer
  int OpaqueDepthFormat = -2;
  int TargetSize[2] = { 0, 0 };
  unsigned int Query = 0;

  // Programs.
  vtkShaderProgram* EntryProgram = nullptr;
  std::unique_ptr<vtkOpenGLQuadHelper> MarchQuad;
  int MarchQuadKey = -1; // MarchShaderKey() the march program was built for
  int IsoMode = 0;       // this frame's IsoSurfaceMode()
  std::string IsoWarning; // the last isosurface warning given (given once)
  std::unique_ptr<vtkOpenGLQuadHelper> CompositeQuad;

  // The active cell textures' common data.
  const double* Origin() const
  {
    return this->NativeHexahedra ? this->Hexahedra->GetOrigin() : this->Tetrahedra->GetOrigin();
  }
  vtkIdType NumberOfCells() const
  {
    return this->NativeHexahedra ? this->Hexahedra->GetNumberOfHexahedra()
                        : this->Tetrahedra->GetNumberOfTetrahedra();
  }
  double MaximumCellLength() const
  {
    return this->NativeHexahedra ? this->Hexahedra->GetMaximumCellDiameter()
                        : this->Tetrahedra->GetMaximumEdgeLength();
  }
  const std::vector<float>& BoundaryPointCoordinates() const
  {
    return this->NativeHexahedra ? this->Hexahedra->GetBoundaryPoints()
                                 : this->Tetrahedra->GetBoundaryPoints();
  }
  const std::vector<unsigned int>& BoundaryTriangleIndices() const
  {
    return this->NativeHexahedra ? this->Hexahedra->GetBoundaryTriangles()
                                 : this->Tetrahedra->GetBoundaryTriangles();
  }
  const std::vector<int>& BoundaryFaceCodes() const
  {
    return this->NativeHexahedra ? this->Hexahedra->GetBoundaryFaces()
                                 : this->Tetrahedra->GetBoundaryFaces();
  }

  size_t TargetBytes() const
  {
    // entry id (R32F), 2 accumulated (RGBA32F), 2 exit (R32F), 3 depth (32F).
    return static_cast<size_t>(this->TargetSize[0]) * this->TargetSize[1] *
      (4 + 2 * 16 + 2 * 4 + 3 * 4);
  }

  void ReleaseGraphicsResources(vtkWindow* window)
  {
    this->Planes.ReleaseGraphicsResources(window);
    this->Neighbors.ReleaseGraphicsResources(window);
    this->Field.ReleaseGraphicsResources(window);
    this->BoundaryFaces.ReleaseGraphicsResources(window);
    this->ControlPointTexels.ReleaseGraphicsResources(window);
    this->BoundaryPoints->ReleaseGraphicsResources();
    this->BoundaryTriangles->ReleaseGraphicsResources();
    this->BoundaryBytes = 0;
    this->EntryVAO->ReleaseGraphicsResources();
    this->PsiTexture->ReleaseGraphicsResources(window);
    this->PsiTextureSize = 0;
    this->FullTableTexture->ReleaseGraphicsResources(window);
    this->FullTableBytes = 0;
    this->Framebuffer->ReleaseGraphicsResources(window);
    this->EntryTexture->ReleaseGraphicsResources(window);
    for (int i = 0; i < 2; ++i)
    {
      this->Accumulated[i]->ReleaseGraphicsResources(window);
      this->Exit[i]->ReleaseGraphicsResources(window);
    }
    this->LayerDepth[0]->ReleaseGraphicsResources(window);
    this->LayerDepth[1]->ReleaseGraphicsResources(window);
    this->OpaqueDepth->ReleaseGraphicsResources(window);
    this->OpaqueDepthFormat = -2;
    this->TargetSize[0] = this->TargetSize[1] = 0;
    if (this->Query)
    {
      glDeleteQueries(1, &this->Query);
      this->Query = 0;
    }
    this->EntryProgram = nullptr; // owned by the shader cache
    if (this->MarchQuad)
    {
      this->MarchQuad->ReleaseGraphicsResources(window);
      this->MarchQuad.reset();
    }
    if (this->CompositeQuad)
    {
      this->CompositeQuad->ReleaseGraphicsResources(window);
      this->CompositeQuad.reset();
    }
    this->GeometryOnGPU = this->FieldOnGPU = this->TransferFunctionOnGPU = false;
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

std::string UnsupportedCellsMessage(const std::vector<vtkIdType>& unsupported)
{
  std::ostringstream message;
  for (size_t i = 0; i < unsupported.size(); i += 2)
  {
    message << (i ? ", " : "") << unsupported[i + 1] << " "
            << vtkCellTypes::GetClassNameFromTypeId(static_cast<int>(unsupported[i]));
  }
  return message.str();
}

// What the mesh needs of the march: flat cells to cross, folds to walk back
// (code a clean mesh does not need is compiled out).
struct MeshFeatures
{
  bool FlatCells = false;
  bool Folds = false;
};

// Which march program: the integration mode, for native hexahedra the
// hexahedron mode, the isosurface mode and the mesh features.
int MarchShaderKey(int mode, bool native, int hexahedronMode, int isoMode, MeshFeatures mesh)
{
  return mode + 4 * (native ? 1 + hexahedronMode : 0) + 16 * isoMode +
    64 * ((mesh.FlatCells ? 1 : 0) + (mesh.Folds ? 2 : 0));
}

constexpr int MaximumIsoValues = 16; // isosurface_fs.glsl
constexpr int MaximumLights = 8;

// The march shader of an integration mode: the traversal (tetrahedra, or
// hexahedra with their field along the ray and hexahedron mode) with the
// mode's segment integral (and piece integral) substituted in.
std::string MarchShader(
  int mode, bool native, int hexahedronMode, int isoMode, MeshFeatures mesh)
{
  std::string integrate;
  switch (mode)
  {
    case vtkUnstructuredGridGPURayCastMapper::EXACT_LINEAR:
      integrate = std::string(piece_exact_fs) + segment_split_fs;
      break;
    case vtkUnstructuredGridGPURayCastMapper::AVERAGE_COLOR:
      integrate = segment_average_fs;
      break;
    case vtkUnstructuredGridGPURayCastMapper::FULL_PRE_INTEGRATION:
      integrate = segment_full_fs;
      break;
    default:
      integrate = std::string(piece_ppi_fs) + segment_split_fs;
  }
  std::string march = native ? march_hexahedra_fs : march_fs;
  if (native)
  {
    vtkShaderProgram::Substitute(march, "//PPIRay::HexahedronField::Impl", hexahedron_field_fs);
    vtkShaderProgram::Substitute(march, "//PPIRay::Hexahedron::Impl",
      hexahedronMode == vtkUnstructuredGridGPURayCastMapper::HEXAHEDRON_ACCURATE
        ? hexahedron_accurate_fs
        : hexahedron_fast_fs);
  }
  vtkShaderProgram::Substitute(march, "//PPIRay::MarchCommon::Impl", march_common_fs);
  vtkShaderProgram::Substitute(march, "//PPIRay::Mesh::Features",
    std::string("const bool FLAT_CELLS = ") + (mesh.FlatCells ? "true" : "false") +
      ";\nconst bool FOLDS = " + (mesh.Folds ? "true" : "false") + ";");
  vtkShaderProgram::Substitute(march, "//PPIRay::TransferFunction::Impl", transfer_function_fs);
  vtkShaderProgram::Substitute(march, "//PPIRay::IsoSurface::Impl", isosurface_fs);
  vtkShaderProgram::Substitute(march, "//PPIRay::IsoSurface::Mode",
    "const int ISO_MODE = " + std::to_string(isoMode) + ";");
  vtkShaderProgram::Substitute(march, "//PPIRay::Integrate::Impl", integrate);
  vtkShaderProgram::Substitute(march, "//PPIRay::Ray::Impl", ray_fs);
  return march;
}

bool AllocateTarget(vtkTextureObject* texture, vtkOpenGLRenderWindow* context, int w, int h,
  int components)
{
  texture->SetContext(context);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  return texture->Allocate2D(w, h, components, VTK_FLOAT);
}

bool AllocateDepthTarget(vtkTextureObject* texture, vtkOpenGLRenderWindow* context, int w, int h)
{
  texture->SetContext(context);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  return texture->AllocateDepth(w, h, vtkTextureObject::Float32);
}
}

//------------------------------------------------------------------------------
vtkUnstructuredGridGPURayCastMapper::vtkUnstructuredGridGPURayCastMapper()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkUnstructuredGridGPURayCastMapper::~vtkUnstructuredGridGPURayCastMapper() = default;

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
  return this->Internals->NativeHexahedra ? this->Internals->Hexahedra->GetNumberOfHexahedra() : 0;
}

//------------------------------------------------------------------------------
double vtkUnstructuredGridGPURayCastMapper::GetPreIntegrationTableBuildTime()
{
  return this->Internals->FullTable->GetBuildTime();
}

//------------------------------------------------------------------------------
vtkIdType vtkUnstructuredGridGPURayCastMapper::GetNumberOfTetrahedra()
{
  if (this->Internals->NativeHexahedra)
  {
    return 0;
  }
  auto& cells = *this->Internals->Tetrahedra;
  return cells.GetNumberOfTetrahedra() - cells.GetNumberOfDegenerateTetrahedra();
}

//------------------------------------------------------------------------------
vtkIdType vtkUnstructuredGridGPURayCastMapper::GetGPUMemorySize()
{
  vtkInternals& in = *this->Internals;
  size_t bytes = in.Planes.GetBytes() + in.Neighbors.GetBytes() + in.Field.GetBytes() +
    in.BoundaryFaces.GetBytes() + in.ControlPointTexels.GetBytes() + in.BoundaryBytes +
    static_cast<size_t>(in.PsiTextureSize) * in.PsiTextureSize * sizeof(float) +
    in.FullTableBytes + in.TargetBytes();
  return static_cast<vtkIdType>(bytes);
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Internals->ReleaseGraphicsResources(window);
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
bool vtkUnstructuredGridGPURayCastMapper::UpdateGeometry(vtkUnstructuredGridBase* input)
{
  vtkInternals& in = *this->Internals;
  vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(input);
  vtkMTimeType sourceTime = input->GetPoints() ? input->GetPoints()->GetMTime() : 0;
  if (grid && grid->GetCells())
  {
    sourceTime = std::max(sourceTime, grid->GetCells()->GetMTime());
  }
  else
  {
    sourceTime = std::max(sourceTime, input->GetMTime());
  }
  const bool wantsNative = this->HexahedronMode != HEXAHEDRON_SUBDIVIDE;
  if (in.GeometryInput == input && sourceTime <= in.GeometryTime.GetMTime() &&
    in.GeometryWantsNativeHexahedra == wantsNative)
  {
    return in.GeometryValid;
  }
  in.GeometryInput = input;
  in.GeometryWantsNativeHexahedra = wantsNative;
  in.GeometryTime.Modified();
  in.GeometryOnGPU = false;
  in.FieldArray = nullptr; // the field follows the geometry
  if (!grid)
  {
    in.InputCopy->DeepCopy(input);
    grid = in.InputCopy;
  }
  in.NativeHexahedra = false;
  if (!FiniteCoordinates(grid->GetPoints()))
  {
    vtkErrorMacro("The input has infinite or NaN point coordinates; nothing is rendered.");
    in.GeometryValid = false;
    return false;
  }
  if (wantsNative && this->UpdateHexahedralGeometry(grid))
  {
    return in.GeometryValid;
  }
  in.GeometryValid = in.Tetrahedra->BuildGeometry(grid);
  vtkTetrahedralCellTextures& cells = *in.Tetrahedra;
  if (cells.GetNumberOfUnsupportedCells() > 0)
  {
    vtkErrorMacro("Skipped " << cells.GetNumberOfUnsupportedCells()
                             << " cells that are not 3D cells with 4 to 8 corners: "
                             << UnsupportedCellsMessage(cells.GetUnsupportedCellTypes()));
  }
  if (cells.GetNumberOfQuadraticCells() > 0)
  {
    vtkWarningMacro(<< cells.GetNumberOfQuadraticCells()
                    << " quadratic (or higher-order) cells are rendered through their linear "
                       "corners only.");
  }
  if (!in.GeometryValid)
  {
    vtkErrorMacro("No 3D cells to render (" << input->GetNumberOfCells() << " cells).");
    return false;
  }
  if (cells.GetNumberOfTetrahedra() > (VTK_INT_MAX / 4) ||
    cells.GetBoundaryFaces().size() > (1u << 24))
  {
    vtkErrorMacro("Mesh too large: " << cells.GetNumberOfTetrahedra() << " tetrahedra and "
                                     << cells.GetBoundaryFaces().size()
                                     << " boundary faces (limits 536870911 and 16777216).");
    in.GeometryValid = false;
    return false;
  }
  if (cells.GetNumberOfDegenerateTetrahedra() > 0)
  {
    vtkWarningMacro(<< cells.GetNumberOfDegenerateTetrahedra()
                    << " zero-volume tetrahedra: crossed with zero length.");
  }
  if (cells.GetNumberOfNonManifoldFaces() > 0)
  {
    vtkWarningMacro(<< cells.GetNumberOfNonManifoldFaces()
                    << " tetrahedron faces are shared by more than two tetrahedra (non-manifold"
                       " mesh): paired by side.");
  }
  if (cells.GetNumberOfFoldedFaces() > 0)
  {
    vtkWarningMacro(<< cells.GetNumberOfFoldedFaces()
                    << " faces join two tetrahedra on the same side (inverted cells, a tangled"
                       " mesh): each stretch of a ray is integrated once.");
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkUnstructuredGridGPURayCastMapper::UpdateHexahedralGeometry(vtkUnstructuredGrid* grid)
{
  vtkInternals& in = *this->Internals;
  vtkHexahedralCellTextures& hexes = *in.Hexahedra;
  hexes.BuildGeometry(grid);
  if (hexes.GetNumberOfHexahedra() == 0)
  {
    return false;
  }
  if (hexes.GetNumberOfOtherCells() > 0)
  {
    vtkWarningMacro(<< this->GetHexahedronModeAsString() << " needs a mesh of hexahedra only; "
                    << hexes.GetNumberOfOtherCells() << " other cells: splitting all "
                    << grid->GetNumberOfCells() << " cells into tetrahedra instead.");
    return false;
  }
  if (hexes.GetNumberOfFlatHexahedra() > 0)
  {
    vtkWarningMacro(<< hexes.GetNumberOfFlatHexahedra() << " zero-volume hexahedra skipped.");
  }
  if (hexes.GetNumberOfSingularFrames() > 0)
  {
    vtkWarningMacro(<< hexes.GetNumberOfSingularFrames()
                    << " hexahedra have no frame at any corner (flat cells): splitting all "
                    << grid->GetNumberOfCells() << " cells into tetrahedra instead of "
                    << this->GetHexahedronModeAsString() << ".");
    return false;
  }
  if (6 * hexes.GetNumberOfHexahedra() > VTK_INT_MAX / 2 ||
    hexes.GetBoundaryFaces().size() > (1u << 24))
  {
    vtkErrorMacro("Mesh too large: " << hexes.GetNumberOfHexahedra() << " hexahedra and "
                                     << hexes.GetBoundaryFaces().size()
                                     << " boundary triangles (limits 178956970 and 16777216).");
    in.NativeHexahedra = true;
    in.GeometryValid = false;
    return true;
  }
  if (hexes.GetNumberOfQuadraticCells() > 0)
  {
    vtkWarningMacro(<< hexes.GetNumberOfQuadraticCells()
                    << " quadratic (or higher-order) hexahedra are rendered through their "
                       "linear corners only.");
  }
  if (hexes.GetNumberOfNonManifoldFaces() > 0)
  {
    vtkWarningMacro(<< hexes.GetNumberOfNonManifoldFaces()
                    << " faces are shared by more than two hexahedra (non-manifold mesh).");
  }
  if (hexes.GetNumberOfFoldedFaces() > 0)
  {
    vtkWarningMacro(<< hexes.GetNumberOfFoldedFaces()
                    << " faces join two hexahedra on the same side (inverted cells, a tangled"
                       " mesh): each stretch of a ray is integrated once.");
  }
  in.NativeHexahedra = true;
  in.GeometryValid = true;
  return true;
}

//------------------------------------------------------------------------------
bool vtkUnstructuredGridGPURayCastMapper::UpdateField(vtkUnstructuredGridBase* input)
{
  vtkInternals& in = *this->Internals;
  int cellFlag = 0;
  vtkDataArray* scalars = vtkDataArray::SafeDownCast(vtkAbstractMapper::GetScalars(input,
    this->ScalarMode, this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag));
  if (!scalars)
  {
    if (in.FieldArray || in.FieldCellFlag != -2)
    {
      vtkErrorMacro("No scalars to render: the input has no "
        << (this->ArrayName && *this->ArrayName ? this->ArrayName : "active")
        << " point or cell scalar array.");
    }
    in.FieldArray = nullptr;
    in.FieldCellFlag = -2;
    return false;
  }
  const int components = scalars->GetNumberOfComponents();
  const int vectorMode = components > 1 ? this->VectorMode : COMPONENT;
  const int component = vectorMode == MAGNITUDE ? -1
                                                : std::min(std::max(this->VectorComponent, 0),
                                                    components - 1);
  if (in.FieldArray == scalars && in.FieldCellFlag == cellFlag &&
    in.FieldVectorMode == vectorMode && in.FieldVectorComponent == component &&
    scalars->GetMTime() <= in.FieldTime.GetMTime())
  {
    return true;
  }
  if (component != this->VectorComponent && vectorMode == COMPONENT && components > 1)
  {
    vtkWarningMacro("VectorComponent " << this->VectorComponent << " is not a component of "
                                       << (scalars->GetName() ? scalars->GetName() : "the array")
                                       << " (" << components << " components); using "
                                       << component << ".");
  }
  in.FieldArray = scalars;
  in.FieldCellFlag = cellFlag;
  in.FieldVectorMode = vectorMode;
  in.FieldVectorComponent = component;
  in.FieldTime.Modified();
  in.FieldOnGPU = false;
  double range[2];
  scalars->GetRange(range, component); // NaN left out; component -1: magnitude
  if (std::isinf(range[0]) || std::isinf(range[1]))
  {
    vtkErrorMacro("Scalar array " << (scalars->GetName() ? scalars->GetName() : "")
                                  << " has infinite values; nothing is rendered.");
    in.FieldArray = nullptr;
    return false;
  }
  if (!(range[0] <= range[1]))
  {
    range[0] = range[1] = 0.0; // every value NaN: every cell empty
  }
  in.FieldRange[0] = range[0];
  in.FieldRange[1] = range[1];
  // Stored relative to the range's centre when it lies far from zero
  // compared to its width (1e6 + O(1) keeps its digits in single precision),
  // as coordinates are relative to the bounds' centre.
  const double centre = 0.5 * (range[0] + range[1]);
  in.FieldShift = std::abs(centre) > range[1] - range[0] ? centre : 0.0;
  vtkDataArray* values = scalars;
  if (components > 1 || in.FieldShift != 0.0)
  {
    const vtkIdType n = scalars->GetNumberOfTuples();
    in.FieldValues->SetNumberOfComponents(1);
    in.FieldValues->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      double value;
      if (component < 0)
      {
        double squares = 0.0;
        for (int c = 0; c < components; ++c)
        {
          const double v = scalars->GetComponent(i, c);
          squares += v * v;
        }
        value = std::sqrt(squares);
      }
      else
      {
        value = scalars->GetComponent(i, component);
      }
      in.FieldValues->SetValue(i, value - in.FieldShift);
    }
    values = in.FieldValues;
  }
  if (in.NativeHexahedra)
  {
    in.Hexahedra->BuildField(values, cellFlag == 1, 0);
    if (in.Hexahedra->GetNumberOfNaNScalars() > 0)
    {
      vtkWarningMacro(<< in.Hexahedra->GetNumberOfNaNScalars()
                      << " hexahedra have NaN scalars; they are rendered empty.");
    }
    return true;
  }
  in.Tetrahedra->BuildField(values, cellFlag == 1, 0);
  if (in.Tetrahedra->GetNumberOfNaNScalars() > 0)
  {
    vtkWarningMacro(<< in.Tetrahedra->GetNumberOfNaNScalars()
                    << " tetrahedra have NaN scalars; they are rendered empty.");
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkUnstructuredGridGPURayCastMapper::UpdateTransferFunction(vtkVolumeProperty* property)
{
  vtkInternals& in = *this->Internals;
  const bool unchanged = in.Property == property &&
    property->GetMTime() <= in.TransferFunctionCheckTime.GetMTime();
  if (unchanged && in.TexelShift == in.FieldShift)
  {
    return in.ControlPoints->GetNumberOfControlPoints() > 0;
  }
  if (unchanged && in.ControlPoints->GetNumberOfControlPoints() > 0)
  {
    // Only the field's shift moved: the same control points, texels anew.
    in.TexelShift = in.FieldShift;
    in.TransferFunctionTexels = in.ControlPoints->GetTexels(in.FieldShift);
    in.TransferFunctionTime.Modified();
    in.TransferFunctionOnGPU = false;
    return true;
  }
  in.Property = property;
  in.TransferFunctionCheckTime.Modified();
  if (!in.ControlPoints->Build(property, 0))
  {
    in.TransferFunctionTexels.clear();
    in.TransferFunctionTime.Modified();
    in.TransferFunctionOnGPU = false;
    vtkErrorMacro("The volume property has no scalar opacity function.");
    return false;
  }
  // A property can be Modified() without a new transfer function (ParaView
  // touches its lookup tables while rendering): only new control points count.
  in.TexelShift = in.FieldShift;
  std::vector<float> texels = in.ControlPoints->GetTexels(in.FieldShift);
  if (texels != in.TransferFunctionTexels)
  {
    in.TransferFunctionTexels = std::move(texels);
    in.TransferFunctionTime.Modified();
    in.TransferFunctionOnGPU = false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkUnstructuredGridGPURayCastMapper::UploadToGPU(vtkOpenGLRenderWindow* context)
{
  vtkInternals& in = *this->Internals;
  vtkTetrahedralCellTextures& cells = *in.Tetrahedra;
  vtkHexahedralCellTextures& hexes = *in.Hexahedra;
  const size_t count = static_cast<size_t>(in.NumberOfCells());
  if (!in.GeometryOnGPU)
  {
    // Tetrahedra: 4 plane texels and 1 neighbour texel each; hexahedra: 6
    // corner texels and 2 neighbour texels each (the same buffer textures).
    bool ok = in.NativeHexahedra
      ? in.Planes.Upload(context, hexes.GetCorners().data(), 6 * count, 4, VTK_FLOAT) &&
        in.Neighbors.Upload(context, hexes.GetNeighbors().data(), 2 * count, 4, VTK_INT)
      : in.Planes.Upload(context, cells.GetFacePlanes().data(), 4 * count, 4, VTK_FLOAT) &&
        in.Neighbors.Upload(context, cells.GetNeighbors().data(), count, 4, VTK_INT);
    ok = ok &&
         in.BoundaryFaces.Upload(
           context, in.BoundaryFaceCodes().data(), in.BoundaryFaceCodes().size(), 1, VTK_INT) &&
         in.BoundaryPoints->Upload(
           in.BoundaryPointCoordinates(), vtkOpenGLBufferObject::ArrayBuffer) &&
         in.BoundaryTriangles->Upload(
           in.BoundaryTriangleIndices(), vtkOpenGLBufferObject::ElementArrayBuffer);
    if (!ok)
    {
      vtkErrorMacro("Could not upload the mesh to the GPU ("
        << count << (in.NativeHexahedra ? " hexahedra)." : " tetrahedra)."));
      return false;
    }
    in.BoundaryBytes = sizeof(float) * in.BoundaryPointCoordinates().size() +
      sizeof(unsigned int) * in.BoundaryTriangleIndices().size();
    in.EntryProgram = nullptr; // re-bind the vertex array to the new buffer
    in.GeometryOnGPU = true;
    ++this->GeometryUploadCount;
  }
  if (!in.FieldOnGPU)
  {
    const bool uploaded = in.NativeHexahedra
      ? in.Field.Upload(context, hexes.GetCoefficients().data(), 2 * count, 4, VTK_FLOAT)
      : in.Field.Upload(context, cells.GetField().data(), count, 4, VTK_FLOAT);
    if (!uploaded)
    {
      vtkErrorMacro("Could not upload the scalar field to the GPU.");
      return false;
    }
    in.FieldOnGPU = true;
    ++this->FieldUploadCount;
  }
  if (!in.TransferFunctionOnGPU)
  {
    const std::vector<float>& texels = in.TransferFunctionTexels;
    if (!in.ControlPointTexels.Upload(context, texels.data(), texels.size() / 4, 4, VTK_FLOAT))
    {
      vtkErrorMacro("Could not upload the transfer function to the GPU.");
      return false;
    }
    in.TransferFunctionOnGPU = true;
    ++this->TransferFunctionUploadCount;
  }
  if (!this->UploadPreIntegrationTable(context))
  {
    return false;
  }
  const bool needsPsi = this->IntegrationMode == PARTIAL_PRE_INTEGRATION;
  if (!needsPsi && in.PsiTextureSize)
  {
    in.PsiTexture->ReleaseGraphicsResources(context);
    in.PsiTextureSize = 0;
  }
  if (needsPsi && in.PsiTextureSize != this->PsiTableSize)
  {
    const std::vector<float>& table = vtkPsiTable::GetTable(this->PsiTableSize);
    in.PsiTexture->SetContext(context);
    in.PsiTexture->SetMinificationFilter(vtkTextureObject::Linear);
    in.PsiTexture->SetMagnificationFilter(vtkTextureObject::Linear);
    in.PsiTexture->SetWrapS(vtkTextureObject::ClampToEdge);
    in.PsiTexture->SetWrapT(vtkTextureObject::ClampToEdge);
    in.PsiTexture->Create2DFromRaw(this->PsiTableSize, this->PsiTableSize, 1, VTK_FLOAT,
      const_cast<float*>(table.data()));
    in.PsiTextureSize = this->PsiTableSize;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkUnstructuredGridGPURayCastMapper::UploadPreIntegrationTable(vtkOpenGLRenderWindow* context)
{
  vtkInternals& in = *this->Internals;
  if (this->IntegrationMode != FULL_PRE_INTEGRATION)
  {
    if (in.FullTableBytes)
    {
      in.FullTableTexture->ReleaseGraphicsResources(context);
      in.FullTableBytes = 0;
    }
    return true;
  }
  const int n = this->PreIntegrationTableSize;
  const vtkMTimeType sources = std::max(
    { in.TransferFunctionTime.GetMTime(), in.FieldTime.GetMTime(), in.GeometryTime.GetMTime() });
  if (in.FullTableBytes && in.FullTable->GetScalarSize() == n &&
    in.FullTableTime.GetMTime() > sources)
  {
    return true;
  }
  in.FullTable->Build(
    in.ControlPoints, in.FieldRange[0], in.FieldRange[1], in.MaximumCellLength(), n, n);
  in.FullTableTexture->SetContext(context);
  in.FullTableTexture->SetMinificationFilter(vtkTextureObject::Linear);
  in.FullTableTexture->SetMagnificationFilter(vtkTextureObject::Linear);
  in.FullTableTexture->SetWrapS(vtkTextureObject::ClampToEdge);
  in.FullTableTexture->SetWrapT(vtkTextureObject::ClampToEdge);
  in.FullTableTexture->SetWrapR(vtkTextureObject::ClampToEdge);
  if (!in.FullTableTexture->Create3DFromRaw(n, n, n, 4, VTK_FLOAT,
        const_cast<float*>(in.FullTable->GetTable().data())))
  {
    vtkErrorMacro("Could not upload the " << n << "^3 pre-integration table.");
    in.FullTableBytes = 0;
    return false;
  }
  in.FullTableBytes = in.FullTable->GetTable().size() * sizeof(float);
  in.FullTableTime.Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkUnstructuredGridGPURayCastMapper::PrepareTargets(
  vtkOpenGLRenderWindow* context, int width, int height)
{
  vtkInternals& in = *this->Internals;
  if (in.TargetSize[0] != width || in.TargetSize[1] != height)
  {
    bool ok = AllocateTarget(in.EntryTexture, context, width, height, 1) &&
      AllocateTarget(in.Accumulated[0], context, width, height, 4) &&
      AllocateTarget(in.Accumulated[1], context, width, height, 4) &&
      AllocateTarget(in.Exit[0], context, width, height, 1) &&
      AllocateTarget(in.Exit[1], context, width, height, 1) &&
      AllocateDepthTarget(in.LayerDepth[0], context, width, height) &&
      AllocateDepthTarget(in.LayerDepth[1], context, width, height);
    if (!ok)
    {
      vtkErrorMacro("Could not allocate " << width << "x" << height << " render targets.");
      in.TargetSize[0] = in.TargetSize[1] = 0;
      return false;
    }
    in.TargetSize[0] = width;
    in.TargetSize[1] = height;
  }
  in.Framebuffer->SetContext(context);
  if (!in.Query)
  {
    glGenQueries(1, &in.Query);
  }

  vtkOpenGLShaderCache* cache = context->GetShaderCache();
  if (!in.EntryProgram)
  {
    in.EntryProgram = cache->ReadyShaderProgram(entry_vs, entry_fs, "");
    if (!in.EntryProgram)
    {
      vtkErrorMacro("Could not build the entry shader.");
      return false;
    }
    in.EntryVAO->Bind();
    in.EntryVAO->AddAttributeArray(
      in.EntryProgram, in.BoundaryPoints, "vertexMC", 0, 3 * sizeof(float), VTK_FLOAT, 3, false);
    in.EntryVAO->Release();
  }
  else
  {
    cache->ReadyShaderProgram(in.EntryProgram);
  }
  MeshFeatures mesh;
  mesh.FlatCells = !in.NativeHexahedra && in.Tetrahedra->GetNumberOfDegenerateTetrahedra() > 0;
  mesh.Folds = in.NativeHexahedra ? in.Hexahedra->GetNumberOfFoldedFaces() > 0
                                  : in.Tetrahedra->GetNumberOfFoldedFaces() > 0;
  const int key = MarchShaderKey(
    this->IntegrationMode, in.NativeHexahedra, this->HexahedronMode, in.IsoMode, mesh);
  if (!in.MarchQuad || in.MarchQuadKey != key)
  {
    if (in.MarchQuad)
    {
      in.MarchQuad->ReleaseGraphicsResources(context);
    }
    in.MarchQuad.reset(new vtkOpenGLQuadHelper(context, nullptr,
      MarchShader(this->IntegrationMode, in.NativeHexahedra, this->HexahedronMode, in.IsoMode,
        mesh)
        .c_str(),
      ""));
    in.MarchQuadKey = key;
  }
  else
  {
    cache->ReadyShaderProgram(in.MarchQuad->Program);
  }
  if (!in.CompositeQuad)
  {
    in.CompositeQuad.reset(new vtkOpenGLQuadHelper(context, nullptr, composite_fs, ""));
  }
  if (!in.MarchQuad->Program || !in.CompositeQuad->Program)
  {
    vtkErrorMacro("Could not build the march or composite shader.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastMapper::CopyOpaqueDepth(
  vtkOpenGLRenderWindow* context, int source, int x0, int y0, int width, int height)
{
  // Blit VTK's depth (resolving multisampling) into a texture of the very same
  // format, as glBlitFramebuffer requires for depth.
  vtkInternals& in = *this->Internals;
  vtkOpenGLState* state = context->GetState();
  state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, source);
  const GLenum attachment = source ? GL_DEPTH_ATTACHMENT : GL_DEPTH;
  GLint bits = 0, type = 0, stencil = 0;
  glGetFramebufferAttachmentParameteriv(
    GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &bits);
  glGetFramebufferAttachmentParameteriv(
    GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &type);
  glGetFramebufferAttachmentParameteriv(
    GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &stencil);
  int format = stencil > 0 ? -1
    : type == GL_FLOAT     ? vtkTextureObject::Float32
    : bits >= 32           ? vtkTextureObject::Fixed32
    : bits >= 24           ? vtkTextureObject::Fixed24
                           : vtkTextureObject::Fixed16;
  if (bits == 0)
  {
    format = vtkTextureObject::Float32; // no depth buffer: nothing is opaque
  }
  if (in.OpaqueDepthFormat != format ||
      in.OpaqueDepth->GetWidth() != static_cast<unsigned>(width) ||
      in.OpaqueDepth->GetHeight() != static_cast<unsigned>(height))
  {
    in.OpaqueDepth->SetContext(context);
    in.OpaqueDepth->SetMinificationFilter(vtkTextureObject::Nearest);
    in.OpaqueDepth->SetMagnificationFilter(vtkTextureObject::Nearest);
    if (format < 0)
    {
      in.OpaqueDepth->AllocateDepthStencil(width, height);
    }
    else
    {
      in.OpaqueDepth->AllocateDepth(width, height, format);
    }
    in.OpaqueDepthFormat = format;
  }
  vtkOpenGLFramebufferObject* fbo = in.Framebuffer;
  fbo->Bind(GL_DRAW_FRAMEBUFFER);
  fbo->AddDepthAttachment(in.OpaqueDepth);
  while (glGetError() != GL_NO_ERROR)
  {
  }
  bool copied = false;
  if (bits > 0)
  {
    glBlitFramebuffer(x0, y0, x0 + width, y0 + height, 0, 0, width, height, GL_DEPTH_BUFFER_BIT,
      GL_NEAREST);
    copied = glGetError() == GL_NO_ERROR;
  }
  if (!copied)
  {
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglClearDepth(1.0);
    state->vtkglClear(GL_DEPTH_BUFFER_BIT);
    if (bits > 0)
    {
      vtkWarningMacro("Could not read the depth buffer (" << bits << " bits): opaque geometry "
                                                           "does not stop the rays.");
    }
  }
  fbo->RemoveDepthAttachment();
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastMapper::Render(vtkRenderer* ren, vtkVolume* vol)
{
  this->NumberOfPeels = 0;
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
    // An empty grid is a valid scene: nothing to draw.
    return;
  }
  this->Internals->IsoMode = this->IsoSurfaceMode(vol->GetProperty());
  if (!this->UpdateGeometry(input) || !this->UpdateField(input) ||
    !this->UpdateTransferFunction(vol->GetProperty()))
  {
    return;
  }
  if (!this->UploadToGPU(context))
  {
    return;
  }
  this->RenderPasses(ren, vol, context);
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastMapper::RenderPasses(
  vtkRenderer* ren, vtkVolume* vol, vtkOpenGLRenderWindow* context)
{
  vtkInternals& in = *this->Internals;
  int width, height, x0, y0;
  ren->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  if (width <= 0 || height <= 0 || !this->PrepareTargets(context, width, height))
  {
    return;
  }

  // Matrices: local frame (mesh coordinates minus the centre of its bounds) to
  // clip space, and back, composed in double precision.
  const double* origin = in.Origin();
  vtkNew<vtkMatrix4x4> localToClip;
  localToClip->Identity();
  for (int i = 0; i < 3; ++i)
  {
    localToClip->SetElement(i, 3, origin[i]);
  }
  vtkMatrix4x4::Multiply4x4(vol->GetMatrix(), localToClip, localToClip);
  vtkMatrix4x4* worldToClip = ren->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
    ren->GetTiledAspectRatio(), -1, 1);
  vtkMatrix4x4::Multiply4x4(worldToClip, localToClip, localToClip);
  vtkNew<vtkMatrix4x4> clipToLocal;
  vtkMatrix4x4::Invert(localToClip, clipToLocal);
  float localToClipF[16], clipToLocalF[16];
  ColumnMajor(localToClip, localToClipF);
  ColumnMajor(clipToLocal, clipToLocalF);

  const vtkIdType cells = in.NumberOfCells();
  const int maximumSteps = this->MaximumNumberOfSteps > 0
    ? this->MaximumNumberOfSteps
    : static_cast<int>(std::min<double>(
        cells + 1.0, std::max(1024.0, 64.0 * std::cbrt(static_cast<double>(cells)))));

  // Save what we change; the Scoped objects restore it on return.
  vtkOpenGLState* state = context->GetState();
  vtkOpenGLState::ScopedglViewport savedViewport(state);
  vtkOpenGLState::ScopedglBlendFuncSeparate savedBlend(state);
  vtkOpenGLState::ScopedglDepthMask savedDepthMask(state);
  vtkOpenGLState::ScopedglClearColor savedClearColor(state);
  vtkOpenGLState::ScopedglColorMask savedColorMask(state);
  vtkOpenGLState::ScopedglEnableDisable savedBlendEnable(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable savedDepthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable savedCullFace(state, GL_CULL_FACE);
  vtkOpenGLState::ScopedglEnableDisable savedScissor(state, GL_SCISSOR_TEST);
  int savedDepthFunc = GL_LESS, savedCullFaceMode = GL_BACK;
  state->vtkglGetIntegerv(GL_DEPTH_FUNC, &savedDepthFunc);
  state->vtkglGetIntegerv(GL_CULL_FACE_MODE, &savedCullFaceMode);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  // Opaque depth: VTK's depth buffer under this renderer's viewport.
  state->PushFramebufferBindings();
  int sourceFramebuffer = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &sourceFramebuffer);
  vtkOpenGLFramebufferObject* fbo = in.Framebuffer;
  this->CopyOpaqueDepth(context, sourceFramebuffer, x0, y0, width, height);
  fbo->Bind();
  state->vtkglViewport(0, 0, width, height);
  // Nothing accumulated yet; no march has stopped anywhere.
  int current = 0;
  fbo->AddColorAttachment(0, in.Accumulated[current]);
  fbo->AddColorAttachment(1, in.Exit[current]);
  fbo->ActivateDrawBuffers(2);
  state->vtkglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  fbo->RemoveColorAttachment(1);

  const float terminationAlpha = static_cast<float>(this->TerminationOpacity);
  vtkShaderProgram* march = in.MarchQuad->Program;
  int layer = 0;
  GLuint samplesPassed = 0;
  int peel = 0;
  for (; peel < this->MaximumNumberOfPeels; ++peel)
  {
    // Entry pass: the next layer of front-facing boundary triangles.
    fbo->AddColorAttachment(0, in.EntryTexture);
    fbo->AddDepthAttachment(in.LayerDepth[layer]);
    fbo->ActivateDrawBuffers(1);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglClearDepth(1.0);
    state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthFunc(GL_LESS);
    state->vtkglDisable(GL_BLEND);
    state->vtkglEnable(GL_CULL_FACE);
    state->vtkglCullFace(GL_BACK);

    context->GetShaderCache()->ReadyShaderProgram(in.EntryProgram);
    vtkShaderProgram* entry = in.EntryProgram;
    vtkTextureObject* entryInputs[] = { in.LayerDepth[1 - layer], in.OpaqueDepth,
      in.Accumulated[current] };
    const char* entryNames[] = { "previousLayerDepth", "opaqueDepth", "accumulated" };
    for (int i = 0; i < 3; ++i)
    {
      entryInputs[i]->Activate();
      entry->SetUniformi(entryNames[i], entryInputs[i]->GetTextureUnit());
    }
    entry->SetUniformMatrix4x4("localToClip", localToClipF);
    entry->SetUniformi("firstLayer", peel == 0 ? 1 : 0);
    entry->SetUniformf("terminationAlpha", terminationAlpha);
    in.EntryVAO->Bind();
    in.BoundaryTriangles->Bind();
    glBeginQuery(GL_SAMPLES_PASSED, in.Query);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(in.BoundaryTriangleIndices().size()),
      GL_UNSIGNED_INT, nullptr);
    glEndQuery(GL_SAMPLES_PASSED);
    in.BoundaryTriangles->Release();
    in.EntryVAO->Release();
    for (auto* texture : entryInputs)
    {
      texture->Deactivate();
    }
    glGetQueryObjectuiv(in.Query, GL_QUERY_RESULT, &samplesPassed);
    if (samplesPassed == 0)
    {
      break;
    }

    // March pass: integrate from the entry cell to where the ray leaves the
    // mesh, composited under what earlier peels accumulated (ping-pong).
    const int next = 1 - current;
    fbo->RemoveDepthAttachment();
    fbo->AddColorAttachment(0, in.Accumulated[next]);
    fbo->AddColorAttachment(1, in.Exit[next]);
    fbo->ActivateDrawBuffers(2);
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDisable(GL_CULL_FACE);

    context->GetShaderCache()->ReadyShaderProgram(march);
    std::vector<vtkTextureObject*> textures = { in.Planes.GetTexture(),
      in.Neighbors.GetTexture(), in.Field.GetTexture(), in.BoundaryFaces.GetTexture(),
      in.ControlPointTexels.GetTexture(), in.EntryTexture, in.OpaqueDepth,
      in.Accumulated[current], in.Exit[current] };
    std::vector<const char*> names = { "facePlanes", "neighbors", "field", "boundaryFaces",
      "controlPoints", "entryTriangle", "opaqueDepth", "previousAccumulated", "previousExit" };
    if (in.NativeHexahedra)
    {
      names[0] = "hexCorners";
      names[1] = "hexNeighbors";
      names[2] = "hexCoefficients";
    }
    if (in.PsiTextureSize)
    {
      textures.push_back(in.PsiTexture);
      names.push_back("psiTable");
    }
    if (in.FullTableBytes)
    {
      textures.push_back(in.FullTableTexture);
      names.push_back("preIntegrationTable");
      const double* tableRange = in.FullTable->GetScalarRange();
      const float range[2] = { static_cast<float>(tableRange[0] - in.FieldShift),
        static_cast<float>(tableRange[1] - in.FieldShift) };
      const float size[3] = { static_cast<float>(in.FullTable->GetScalarSize()),
        static_cast<float>(in.FullTable->GetScalarSize()),
        static_cast<float>(in.FullTable->GetLengthSize()) };
      march->SetUniform2f("tableScalarRange", range);
      march->SetUniformf(
        "tableMaximumLength", static_cast<float>(in.FullTable->GetMaximumLength()));
      march->SetUniform3f("tableSize", size);
    }
    for (size_t i = 0; i < textures.size(); ++i)
    {
      textures[i]->Activate();
      march->SetUniformi(names[i], textures[i]->GetTextureUnit());
    }
    march->SetUniformi("numberOfControlPoints", in.ControlPoints->GetNumberOfControlPoints());
    march->SetUniformMatrix4x4("clipToLocal", clipToLocalF);
    march->SetUniformi("maximumSteps", maximumSteps);
    march->SetUniformf("terminationAlpha", terminationAlpha);
    march->SetUniformf("psiTableSize", static_cast<float>(in.PsiTextureSize));
    if (in.IsoMode)
    {
      this->SetIsoSurfaceUniforms(march, ren, vol, origin);
    }
    in.MarchQuad->Render();
    for (auto* texture : textures)
    {
      texture->Deactivate();
    }
    fbo->RemoveColorAttachment(1);
    current = next;
    layer = 1 - layer;
  }
  this->NumberOfPeels = peel;
  if (peel == this->MaximumNumberOfPeels && samplesPassed > 0)
  {
    vtkWarningMacro("Stopped after MaximumNumberOfPeels = "
      << this->MaximumNumberOfPeels << " depth peels; parts of the mesh may be missing.");
  }
  fbo->RemoveDepthAttachment();
  state->PopFramebufferBindings();

  // Composite the volume over VTK's framebuffer.
  state->vtkglViewport(x0, y0, width, height);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_CULL_FACE);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  state->vtkglDepthMask(GL_FALSE);
  context->GetShaderCache()->ReadyShaderProgram(in.CompositeQuad->Program);
  in.Accumulated[current]->Activate();
  in.CompositeQuad->Program->SetUniformi(
    "accumulated", in.Accumulated[current]->GetTextureUnit());
  in.CompositeQuad->Render();
  in.Accumulated[current]->Deactivate();

  state->vtkglDepthFunc(savedDepthFunc);
  state->vtkglCullFace(savedCullFaceMode);
}

//------------------------------------------------------------------------------
int vtkUnstructuredGridGPURayCastMapper::IsoSurfaceMode(vtkVolumeProperty* property)
{
  vtkInternals& in = *this->Internals;
  const int count = property->GetIsoSurfaceValues()->GetNumberOfContours();
  std::string warning;
  int mode = NO_ISOSURFACES;
  if (this->BlendMode == ISOSURFACE_BLEND)
  {
    mode = ISOSURFACES_ONLY;
    if (count == 0)
    {
      warning = "ISOSURFACE_BLEND without isovalues (vtkVolumeProperty::GetIsoSurfaceValues()): "
                "nothing is drawn.";
    }
  }
  else if (this->BlendMode != COMPOSITE_BLEND)
  {
    warning = "Blend mode " + std::to_string(this->BlendMode) +
      " is not supported (composite and isosurface only); rendering composite.";
  }
  else if (this->EmbedIsoSurfaces && count > 0)
  {
    mode = EMBEDDED_ISOSURFACES;
  }
  if (mode && count > MaximumIsoValues)
  {
    warning = std::to_string(count) + " isovalues; only the lowest " +
      std::to_string(MaximumIsoValues) + " are drawn.";
  }
  if (warning != in.IsoWarning)
  {
    in.IsoWarning = warning;
    if (!warning.empty())
    {
      vtkWarningMacro(<< warning);
    }
  }
  return mode;
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastMapper::SetIsoSurfaceUniforms(
  vtkShaderProgram* program, vtkRenderer* ren, vtkVolume* vol, const double origin[3])
{
  // Isovalues (ascending, NaN dropped) with the transfer function's colour
  // and opacity there.
  vtkVolumeProperty* property = vol->GetProperty();
  vtkContourValues* contours = property->GetIsoSurfaceValues();
  std::vector<double> values;
  for (int i = 0; i < contours->GetNumberOfContours(); ++i)
  {
    if (!std::isnan(contours->GetValue(i)))
    {
      values.push_back(contours->GetValue(i));
    }
  }
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  values.resize(std::min<size_t>(values.size(), MaximumIsoValues));
  float isoValues[MaximumIsoValues] = {};
  float isoColors[MaximumIsoValues][4] = {};
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  for (size_t i = 0; i < values.size(); ++i)
  {
    double rgb[3] = { 1, 1, 1 };
    if (property->GetColorChannels(0) == 3)
    {
      property->GetRGBTransferFunction(0)->GetTable(values[i], values[i], 1, rgb);
    }
    else
    {
      rgb[0] = rgb[1] = rgb[2] = property->GetGrayTransferFunction(0)->GetValue(values[i]);
    }
    isoValues[i] = static_cast<float>(values[i] - this->Internals->FieldShift);
    for (int c = 0; c < 3; ++c)
    {
      isoColors[i][c] = static_cast<float>(rgb[c]);
    }
    isoColors[i][3] =
      static_cast<float>(std::min(1.0, std::max(0.0, opacity->GetValue(values[i]))));
  }
  program->SetUniformi("numberOfIsoValues", static_cast<int>(values.size()));
  program->SetUniform1fv("isoValues", MaximumIsoValues, isoValues);
  program->SetUniform4fv("isoColors", MaximumIsoValues, isoColors);

  // Material and lights (switched on, in world coordinates; positional
  // lights as point lights: no cone, no attenuation).
  const float material[4] = { static_cast<float>(property->GetAmbient(0)),
    static_cast<float>(property->GetDiffuse(0)), static_cast<float>(property->GetSpecular(0)),
    static_cast<float>(property->GetSpecularPower(0)) };
  program->SetUniformi("shade", property->GetShade(0));
  program->SetUniform4f("material", material);
  float lightVector[MaximumLights][3] = {}, lightDiffuse[MaximumLights][3] = {},
        lightSpecular[MaximumLights][3] = {};
  int lightPositional[MaximumLights] = {};
  int lights = 0;
  vtkLightCollection* collection = ren->GetLights();
  vtkCollectionSimpleIterator it;
  collection->InitTraversal(it);
  while (vtkLight* light = collection->GetNextLight(it))
  {
    if (!light->GetSwitch() || lights == MaximumLights)
    {
      continue;
    }
    double position[3], focalPoint[3];
    light->GetTransformedPosition(position);
    light->GetTransformedFocalPoint(focalPoint);
    const double intensity = light->GetIntensity();
    double towards[3] = { position[0] - focalPoint[0], position[1] - focalPoint[1],
      position[2] - focalPoint[2] };
    const double norm = std::max(vtkMath::Norm(towards), 1e-300);
    lightPositional[lights] = light->GetPositional() ? 1 : 0;
    for (int c = 0; c < 3; ++c)
    {
      lightVector[lights][c] =
        static_cast<float>(light->GetPositional() ? position[c] : towards[c] / norm);
      lightDiffuse[lights][c] = static_cast<float>(intensity * light->GetDiffuseColor()[c]);
      lightSpecular[lights][c] = static_cast<float>(intensity * light->GetSpecularColor()[c]);
    }
    ++lights;
  }
  program->SetUniformi("numberOfLights", lights);
  program->SetUniform3fv("lightVector", MaximumLights, lightVector);
  program->SetUniform3fv("lightDiffuse", MaximumLights, lightDiffuse);
  program->SetUniform3fv("lightSpecular", MaximumLights, lightSpecular);
  program->SetUniform1iv("lightPositional", MaximumLights, lightPositional);

  // Local frame (mesh coordinates minus `origin`) to world, and its normal
  // matrix.
  vtkNew<vtkMatrix4x4> localToWorld;
  localToWorld->Identity();
  for (int i = 0; i < 3; ++i)
  {
    localToWorld->SetElement(i, 3, origin[i]);
  }
  vtkMatrix4x4::Multiply4x4(vol->GetMatrix(), localToWorld, localToWorld);
  float localToWorldF[16];
  ColumnMajor(localToWorld, localToWorldF);
  program->SetUniformMatrix4x4("localToWorld", localToWorldF);
  double linear[3][3], inverse[3][3];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      linear[r][c] = localToWorld->GetElement(r, c);
    }
  }
  vtkMath::Invert3x3(linear, inverse);
  float normalToWorld[9]; // column-major (inverse)^T: element (r, c) = inverse[c][r]
  for (int c = 0; c < 3; ++c)
  {
    for (int r = 0; r < 3; ++r)
    {
      normalToWorld[3 * c + r] = static_cast<float>(inverse[c][r]);
    }
  }
  program->SetUniformMatrix3x3("normalToWorld", normalToWorld);
}

//------------------------------------------------------------------------------
void vtkUnstructuredGridGPURayCastMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IntegrationMode: " << this->GetIntegrationModeAsString() << "\n";
  os << indent << "HexahedronMode: " << this->GetHexahedronModeAsString() << "\n";
  os << indent << "EmbedIsoSurfaces: " << this->EmbedIsoSurfaces << "\n";
  os << indent << "VectorMode: " << (this->VectorMode == MAGNITUDE ? "MAGNITUDE" : "COMPONENT")
     << "\n";
  os << indent << "VectorComponent: " << this->VectorComponent << "\n";
  os << indent << "MaximumNumberOfPeels: " << this->MaximumNumberOfPeels << "\n";
  os << indent << "MaximumNumberOfSteps: " << this->MaximumNumberOfSteps << "\n";
  os << indent << "PsiTableSize: " << this->PsiTableSize << "\n";
  os << indent << "PreIntegrationTableSize: " << this->PreIntegrationTableSize << "\n";
  os << indent << "TerminationOpacity: " << this->TerminationOpacity << "\n";
  os << indent << "NumberOfPeels: " << this->NumberOfPeels << "\n";
  os << indent << "GeometryUploadCount: " << this->GeometryUploadCount << "\n";
  os << indent << "FieldUploadCount: " << this->FieldUploadCount << "\n";
  os << indent << "TransferFunctionUploadCount: " << this->TransferFunctionUploadCount << "\n";
}
