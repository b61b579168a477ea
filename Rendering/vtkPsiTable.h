/**
 * @class   vtkPsiTable
 * @brief   Moreland and Angel's Psi function and its table (partial pre-integration)
 *
 * For a ray piece of length D on which the attenuation goes linearly from
 * tau_f (front) to tau_b (back), with a = tau_f D and b = tau_b D,
 *
 *   Psi(a, b) = int_0^1 exp(-(a u + (b - a) u^2 / 2)) du
 *
 * is the piece's mean transparency (Moreland & Angel 2004, Sec. 4, Eq. 9).
 * It does not depend on the transfer function, so it is tabulated once per
 * process over gamma = a / (a + 1) in [0, 1]^2 (Eq. 10) and shared by every
 * mapper. Psi itself is evaluated in double precision by Gauss-Legendre
 * quadrature on geometrically growing sub-intervals that follow the
 * integrand's decay, accurate to about 1e-14 for every a, b >= 0.
 */
#ifndef vtkPsiTable_h
#define vtkPsiTable_h

#include "ppirayRenderingModule.h" // for export macro
#include "vtkObject.h"

#include <vector> // for std::vector

class PPIRAYRENDERING_EXPORT vtkPsiTable : public vtkObject
{
public:
  static vtkPsiTable* New();
  vtkTypeMacro(vtkPsiTable, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Psi(a, b) with a = tau_front * D and b = tau_back * D, both >= 0 (an
   * infinite argument gives 0).
   */
  static double Psi(double tauDFront, double tauDBack);

  /**
   * Psi(gamma_f, gamma_b) with gamma = tau D / (tau D + 1) in [0, 1].
   */
  static double PsiOfGamma(double gammaFront, double gammaBack);

  /**
   * The size x size table, row-major with gamma_b along rows and gamma_f along
   * columns, texel (i, j) at gamma_f = i / (size - 1), gamma_b = j / (size - 1).
   * Computed on first use of each size and kept for the process (thread-safe).
   */
  static const std::vector<float>& GetTable(int size);

protected:
  vtkPsiTable() = default;
  ~vtkPsiTable() override = default;

private:
  vtkPsiTable(const vtkPsiTable&) = delete;
  void operator=(const vtkPsiTable&) = delete;
};

#endif
