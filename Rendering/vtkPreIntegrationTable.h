/**
 * @class   vtkPreIntegrationTable
 * @brief   the 3D pre-integration table of a transfer function (full pre-integration)
 *
 * Röttger et al.'s table over (s_front, s_back, length): the premultiplied
 * colour and opacity of a ray segment whose scalar goes linearly from s_front
 * to s_back over the given length (Weiler et al. 2003, Sec. 4, Eqs. 3-4).
 * Built with Weiler's incremental method (Sec. 4, Eqs. 5-6): slice 1 (length
 * dl) is integrated directly, here exactly (split at every control point,
 * each piece by partial pre-integration); slice k + 1 composites a front
 * part of length dl from slice 1 with a back part of length k dl from slice
 * k, split at s_p = (k dl s_f + dl s_b) / ((k + 1) dl), both looked up with
 * linear interpolation. It depends on the transfer function, so it is rebuilt
 * on every transfer-function change; BuildTime reports the cost.
 *
 * Layout: RGBA float, s_front fastest, then s_back, then length; texel
 * (i, j, k) at s_f = sMin + i (sMax - sMin) / (N - 1), s_b likewise, length
 * k lMax / (M - 1).
 */
#ifndef vtkPreIntegrationTable_h
#define vtkPreIntegrationTable_h

#include "ppirayRenderingModule.h" // for export macro
#include "vtkObject.h"

#include <vector> // for std::vector

class vtkTransferFunctionControlPoints;

class PPIRAYRENDERING_EXPORT vtkPreIntegrationTable : public vtkObject
{
public:
  static vtkPreIntegrationTable* New();
  vtkTypeMacro(vtkPreIntegrationTable, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Tabulate `controlPoints` over s in [sMin, sMax] and lengths in
   * [0, maximumLength] with `scalarSize` x `scalarSize` x `lengthSize` texels.
   */
  void Build(vtkTransferFunctionControlPoints* controlPoints, double sMin, double sMax,
    double maximumLength, int scalarSize, int lengthSize);

  /** The table, 4 floats per texel (see the class description). */
  const std::vector<float>& GetTable() const { return this->Table; }

  vtkGetMacro(ScalarSize, int);
  vtkGetMacro(LengthSize, int);
  vtkGetVector2Macro(ScalarRange, double);
  vtkGetMacro(MaximumLength, double);

  /** Seconds the last Build() took. */
  vtkGetMacro(BuildTime, double);

protected:
  vtkPreIntegrationTable() = default;
  ~vtkPreIntegrationTable() override = default;

  std::vector<float> Table;
  int ScalarSize = 0;
  int LengthSize = 0;
  double ScalarRange[2] = { 0, 1 };
  double MaximumLength = 1;
  double BuildTime = 0;

private:
  vtkPreIntegrationTable(const vtkPreIntegrationTable&) = delete;
  void operator=(const vtkPreIntegrationTable&) = delete;
};

#endif
