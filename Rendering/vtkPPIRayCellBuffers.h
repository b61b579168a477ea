/**
 * @class   vtkPPIRayCellBuffers
 * @brief   the cells of a mesh on the GPU, as the march shader reads them
 *
 * One kind of cell textures (vtkPPIRayTetrahedralCellBuffers,
 * vtkPPIRayHexahedralCellBuffers) built on the CPU, their copies as buffer
 * textures, the boundary triangles the entry pass rasterizes, and the march
 * traversal that reads them. The one owner of the texel layout: the march
 * shader's layout constants are written from GetLayout() (LayoutDeclarations()),
 * never typed in the GLSL.
 *
 * Caches: the geometry (BuildGeometry(), when points or cells change) and
 * the field (BuildField(), when the scalars change) are uploaded by Upload()
 * when they were rebuilt since the last upload. Internal to PPIRay::Rendering.
 */
#ifndef vtkPPIRayCellBuffers_h
#define vtkPPIRayCellBuffers_h

#include "ppirayStageTimes.h"       // for ppiray::StageTimes
#include "vtkNew.h"                 // for vtkNew
#include "vtkPPIRayBufferTexture.h" // for vtkPPIRayBufferTexture
#include "vtkType.h"                // for vtkIdType

#include <glm/vec3.hpp> // for glm::dvec3
#include <glm/vec4.hpp> // for glm::dvec4

#include <string> // for std::string
#include <vector> // for std::vector

class vtkDataArray;
class vtkObject;
class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkUnstructuredGrid;
class vtkWindow;

class vtkPPIRayCellBuffers
{
public:
  virtual ~vtkPPIRayCellBuffers();

  /**
   * Texels per cell of the geometry, neighbour and field arrays (the
   * march's GEOMETRY_TEXELS, NEIGHBOR_TEXELS, FIELD_TEXELS); the
   * neighbour-code base (code = Faces * cell + face) and markers.
   */
  struct Layout
  {
    int GeometryTexels;
    int NeighborTexels;
    int FieldTexels;
    int Faces;
    int TurnBack;          // added to a folded face's code where the cell it is in is inverted
    float FlatCellMarker;  // w of a flat cell's geometry texels (0: none stored)
    float EmptyCellOffset; // first field value of a cell that renders empty
    int SplitFace = 0;     // neighbour codes from here on name a split face's list (0: none)
    int ReentryFace = 0;   // ... and from here on a reflex-edge face's partners (0: none)
    int PlaneLoops = 4;    // loop iterations reading a cell's planes (PLANE_LOOPS) ...
    int FieldLoops = 0;    // ... and its field after them (FIELD_LOOPS)
    int FaceEdges = 3;     // most edges of a face: partners in a re-entry list (FACE_EDGES)
  };
  virtual Layout GetLayout() const = 0;

  /**
   * GLSL constants of GetLayout(), as the march shaders declare them, the
   * samplers of the cell arrays and the functions reading them
   * (`facePlanesTexel(i)`... after the arrays' names: texel i of an array
   * however many buffer textures hold it; valid after Upload()).
   */
  std::string LayoutDeclarations() const;

  /** What the mesh needs of the march beyond clean cells (compiled in only then). */
  struct Features
  {
    bool FlatCells = false;     // zero-volume cells crossed with zero length
    bool Folds = false;         // folded faces walked back
    int MaximumSplitPieces = 0; // most pieces of a boundary face split by convexification
    bool ReentryEdges = false;  // boundary faces with reflex edges, re-entered across them
    bool LensFaces = false;     // face lists across a lens (ppiray::MatchSplitQuadrilaterals)
  };
  virtual Features GetFeatures() const = 0;

  /** "tetrahedra" or "hexahedra", for messages. */
  virtual const char* GetCellName() const = 0;

  /** What to try when the arrays do not fit on the GPU ("" if nothing), for messages. */
  virtual const char* GetSmallerLayoutHint() const { return ""; }

  enum class BuildResult
  {
    Built,
    Declined, // the mesh is not for this kind of cells: render it another way
    Failed    // an error was reported: render nothing
  };
  /**
   * Cell textures of `grid`; warnings and errors are reported as
   * `reporter`'s.
   */
  virtual BuildResult BuildGeometry(vtkUnstructuredGrid* grid, vtkObject* reporter) = 0;
  /**
   * The field per cell from one-component `values` (point or cell data);
   * cells touching a NaN value render empty (a warning counts them).
   */
  void BuildField(vtkDataArray* values, bool cellData, vtkObject* reporter);

  /** Wall time of each stage of the last BuildGeometry(), in order. */
  virtual const ppiray::StageTimes& GetGeometryStageTimes() const = 0;
  /** The cell layout BuildGeometry() builds (its ProgressEvents are the build's progress). */
  virtual vtkObject* GetGeometryBuilder() const = 0;

  /** Centre of the mesh's bounds: every coordinate is relative to it. */
  virtual const double* GetOrigin() const = 0;
  virtual vtkIdType GetNumberOfCells() const = 0;
  /** No ray segment in one cell is longer. */
  virtual double GetMaximumSegmentLength() const = 0;

  /**
   * The march pass's GLSL (glsl/march_fs.glsl, the one march for every cell
   * kind) with this kind's cells (GetCellShader()), its layout and features
   * declared, and the integration of a cubic stretch (`accurateCubics`:
   * HEXAHEDRON_ACCURATE's quadrature, else HEXAHEDRON_FAST's linear pieces);
   * the integration mode, transfer function and isosurfaces are left to
   * vtkPPIRayMarchShader.
   */
  std::string GetMarchShader(bool accurateCubics) const;

  /** Every cell lies within this distance of GetOrigin(). */
  virtual double GetBoundingRadius() const = 0;

  /**
   * The sections of the cells cut by the plane n . x = d (plane = (n, d),
   * local frame) as triangles: 3 vertices each, 4 floats per vertex (x, y,
   * z, the cell's entry code) appended to `vertices` (ppirayPlaneSection.h).
   */
  virtual void PlaneSection(const glm::dvec4& plane, std::vector<float>& vertices) const = 0;

  /** Uploads what was rebuilt since the last upload; false (error reported) on failure. */
  bool Upload(vtkOpenGLRenderWindow* context, vtkObject* reporter);

  /**
   * Texels per buffer texture at most, below GL_MAX_TEXTURE_BUFFER_SIZE (0:
   * that limit): an array longer than that is stored in several (testing,
   * and drivers whose limit is wrong). A change uploads again.
   */
  void SetMaximumBufferTexels(size_t texels);
  int GetGeometryUploadCount() const { return this->GeometryUploadCount; }
  int GetFieldUploadCount() const { return this->FieldUploadCount; }

  /** Activates the cell textures and sets their samplers in `program`. */
  void Bind(vtkShaderProgram* program, std::vector<vtkTextureObject*>& active);

  ///@{
  /** The boundary triangles (wound outward) the entry pass draws. */
  vtkOpenGLBufferObject* GetBoundaryPoints() { return this->BoundaryPoints; }
  vtkOpenGLBufferObject* GetBoundaryTriangles() { return this->BoundaryTriangles; }
  size_t GetNumberOfBoundaryIndices() const { return this->GetBoundary().Triangles.size(); }
  ///@}

  /**
   * Whether the boundary bounds a convex solid (ppiray::IsConvexSurface,
   * corners within 1e-6 of the bounding radius of a plane count as on it):
   * every ray then enters the mesh once and one entry layer is all a frame
   * needs. Checked once per geometry upload.
   */
  bool IsBoundaryConvex();

  size_t GetGPUBytes() const;
  size_t GetCellArrayBytes() const; // the cell arrays alone
  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkPPIRayCellBuffers();

  // One array of the cell textures, as the march reads it.
  struct CellArray
  {
    const char* Name; // the sampler; GLSL reads texel i as `NameTexel(i)`
    const char* What; // for messages: "the neighbours"
    const void* Data;
    size_t Texels;
    int Components; // 1 or 4 (a texel is read as a vec4 or ivec4 either way)
    int Type;       // VTK_FLOAT or VTK_INT
    bool Field;     // rebuilt with the field (else with the geometry)
  };
  static constexpr int MaximumArrays = 4;
  // The cell kind's GLSL (march_fs.glsl lists what it supplies), with any
  // declarations it needs beyond LayoutDeclarations().
  virtual std::string GetCellShader() const = 0;
  // The CPU arrays, laid out as GetLayout() says (at most MaximumArrays).
  virtual std::vector<CellArray> GetCellArrays() const = 0;
  // The boundary the entry pass draws.
  struct Boundary
  {
    const std::vector<float>& Points;           // 3 per point
    const std::vector<unsigned int>& Triangles; // 3 point indices each
    const std::vector<int>& Faces;              // per triangle: the cell and face
  };
  virtual Boundary GetBoundary() const = 0;
  // Builds the field texels; returns the number of cells touching a NaN value.
  virtual vtkIdType ComputeField(vtkDataArray* values, bool cellData) = 0;
  // Warns about what the field's build changed beyond empty cells (none here).
  virtual void ReportField(vtkObject* /*reporter*/) const {}
  // Appends a cell's section triangles to PlaneSection()'s vertices.
  static void AppendSection(
    const std::vector<glm::dvec3>& triangles, vtkIdType cell, std::vector<float>& vertices);
  // Warns about the folded faces of a tangled mesh.
  void ReportFoldedFaces(vtkIdType folded, vtkObject* reporter) const;

  // Set by the builders: what the next Upload() sends.
  bool GeometryOnGPU = false;
  bool FieldOnGPU = false;

private:
  vtkPPIRayCellBuffers(const vtkPPIRayCellBuffers&) = delete;
  void operator=(const vtkPPIRayCellBuffers&) = delete;

  vtkPPIRayBufferTexture Arrays[MaximumArrays]; // as GetCellArrays() lists them
  vtkPPIRayBufferTexture BoundaryFaces;
  vtkNew<vtkOpenGLBufferObject> BoundaryPoints;
  vtkNew<vtkOpenGLBufferObject> BoundaryTriangles;
  size_t BoundaryBytes = 0;
  size_t MaximumBufferTexels = 0;
  int GeometryUploadCount = 0;
  int ConvexityCheckedAt = -1; // the GeometryUploadCount IsBoundaryConvex() was checked at
  bool Convex = false;
  int FieldUploadCount = 0;
};

#endif
