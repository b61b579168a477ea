/**
 * @class   vtkPPIRayGridInput
 * @brief   the grid the cells are built from: convexified when asked, a vtkUnstructuredGrid, valid
 *
 * What the mapper's input becomes before cells are built from it: the
 * Convexifier's output (NON_CONVEX_CONVEXIFY, run again when the input or
 * the Convexifier changes), a vtkUnstructuredGrid (a copy of another
 * vtkUnstructuredGridBase), with finite coordinates (else nothing is
 * rendered) and cells of valid point ids (the others emptied). Each problem
 * is reported through the mapper. Internal to PPIRay::Rendering.
 */
#ifndef vtkPPIRayGridInput_h
#define vtkPPIRayGridInput_h

#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkTimeStamp.h"

class vtkObject;
class vtkUnstructuredGrid;
class vtkUnstructuredGridAlgorithm;
class vtkUnstructuredGridBase;

class vtkPPIRayGridInput
{
public:
  vtkPPIRayGridInput();
  ~vtkPPIRayGridInput();

  /**
   * `convexifier`'s output for `input`, kept until either changes; `input`
   * itself, with one warning, when there is no convexifier or `input` is
   * not a vtkUnstructuredGrid.
   */
  vtkUnstructuredGridBase* Convexified(
    vtkUnstructuredGridBase* input, vtkUnstructuredGridAlgorithm* convexifier, vtkObject* reporter);

  /**
   * `input` as a vtkUnstructuredGrid whose cells list valid point ids only
   * (cells that do not are emptied: one error counts them); null, with an
   * error, when a point coordinate is infinite or NaN.
   */
  vtkUnstructuredGrid* Validated(vtkUnstructuredGridBase* input, vtkObject* reporter);

private:
  vtkPPIRayGridInput(const vtkPPIRayGridInput&) = delete;
  void operator=(const vtkPPIRayGridInput&) = delete;

  vtkNew<vtkUnstructuredGrid> Copy;        // an input that is not a vtkUnstructuredGrid
  vtkNew<vtkUnstructuredGrid> Convexifier; // the Convexifier's output
  vtkUnstructuredGridBase* ConvexifiedInput = nullptr;
  vtkTimeStamp ConvexifiedTime;
  bool ConvexifyWarned = false;
  vtkSmartPointer<vtkUnstructuredGrid> ValidCells; // cells of invalid ids emptied
};

#endif
