/**
 * @class   vtkPPIRayGridInput
 * @brief   the grid the cells are built from: convexified when asked, a vtkUnstructuredGrid, valid
 *
 * What the mapper's input becomes before cells are built from it: the
 * Convexifier's output (NON_CONVEX_CONVEXIFY, run again when the input or
 * the Convexifier changes; NON_CONVEX_AUTOMATIC where
 * ppiray::NonConvexChoice decides so), a vtkUnstructuredGrid (a copy of another
 * vtkUnstructuredGridBase), with finite coordinates (else nothing is
 * rendered) and cells of valid point ids (the others emptied). Each problem
 * is reported through the mapper. Internal to PPIRay::Rendering.
 */
#ifndef vtkPPIRayGridInput_h
#define vtkPPIRayGridInput_h

#include "ppirayNonConvexChoice.h" // for ppiray::NonConvexChoice
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
   * The grid to render for `input` in non-convex `mode` (ppiray::
   * NonConvexMode): `input`, or Convexified() where the mode (or, automatic,
   * the choice) says so.
   */
  vtkUnstructuredGridBase* Rendered(vtkUnstructuredGridBase* input, int mode,
    vtkUnstructuredGridAlgorithm* convexifier, vtkObject* reporter);

  /**
   * `convexifier`'s output for `input`, kept until either changes; `input`
   * itself, with one warning, when there is no convexifier or `input` is
   * not a vtkUnstructuredGrid.
   */
  vtkUnstructuredGridBase* Convexified(
    vtkUnstructuredGridBase* input, vtkUnstructuredGridAlgorithm* convexifier, vtkObject* reporter);

  /** What a frame of the last Rendered() grid measured (NON_CONVEX_AUTOMATIC's choice). */
  void ObserveFrame(int peels, bool nativeHexahedra)
  {
    if (this->LastMode == ppiray::NonConvexAutomatic)
    {
      this->Choice.Observe(peels, this->LastRendered, nativeHexahedra);
    }
  }
  /** NON_CONVEX_PEEL or NON_CONVEX_CONVEXIFY: how the last Rendered() grid is followed. */
  int GetNonConvexChoice() const { return this->LastChoice; }

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
  ppiray::NonConvexChoice Choice;                  // NON_CONVEX_AUTOMATIC's
  vtkUnstructuredGridBase* LastRendered = nullptr;
  int LastChoice = ppiray::NonConvexPeel;
  int LastMode = ppiray::NonConvexPeel;
};

#endif
