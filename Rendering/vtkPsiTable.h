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
 * process and shared by every mapper.
 *
 * Moreland and Angel index the table by gamma = a / (a + 1) (Eq. 10). Along
 * gamma_b -> 1 with small a, Psi ~ sqrt(pi (1 - gamma_b) / 2): a square-root
 * edge where bilinear lookup errs by 1e-2 at any practical size (measured in
 * TestPsiTable). The table here is indexed by u = 1 - sqrt(1 - gamma)
 * = 1 - 1 / sqrt(a + 1) instead, which turns that edge linear (Psi ~ 1 - u)
 * and keeps the gamma_f -> 1 edge smooth (Psi ~ (1 - u)^2). Psi itself is evaluated in double
 * precision by Gauss-Legendre quadrature on geometrically growing sub-intervals that follow the
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
   * The size x size table, row-major with u_b along rows and u_f along
   * columns, texel (i, j) at u_f = i / (size - 1), u_b = j / (size - 1).
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
