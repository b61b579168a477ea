"""Psi table lookup error against table size, for Moreland and Angel's
gamma = tau D / (tau D + 1) index and for PPIRay's u = 1 - sqrt(1 - gamma).

Writes Documentation/plots/psi_table_error.png and prints the table.
Run: Module/run python Documentation/plots/psi_table_error.py
"""
import numpy as np

import ppiray
from loglog import save_loglog

psi_of_gamma = np.vectorize(ppiray.vtkPsiTable.PsiOfGamma)


def lookup_error(n, to_gamma):
    """Max |bilinear(table) - Psi| over texel-cell centres and edge midpoints."""
    grid = np.linspace(0.0, 1.0, n)
    gf, gb = np.meshgrid(to_gamma(grid), to_gamma(grid))
    table = psi_of_gamma(gf, gb)
    fine = np.linspace(0.0, 1.0, 2 * (n - 1) + 1)
    gf, gb = np.meshgrid(to_gamma(fine), to_gamma(fine))
    exact = psi_of_gamma(gf, gb)
    # Bilinear interpolation at half-texel steps = averages of neighbours.
    up = np.zeros_like(exact)
    up[::2, ::2] = table
    up[1::2, ::2] = 0.5 * (table[:-1, :] + table[1:, :])
    up[::2, 1::2] = 0.5 * (table[:, :-1] + table[:, 1:])
    up[1::2, 1::2] = 0.25 * (table[:-1, :-1] + table[1:, :-1] + table[:-1, 1:] + table[1:, 1:])
    return np.abs(up - exact).max()


sizes = [32, 64, 128, 256, 512]
gamma_index = [lookup_error(n, lambda g: g) for n in sizes]
u_index = [lookup_error(n, lambda u: 1.0 - (1.0 - u) ** 2) for n in sizes]
print("| size | gamma index | u index |")
print("|---:|---:|---:|")
for n, a, b in zip(sizes, gamma_index, u_index):
    print("| %d | %.2e | %.2e |" % (n, a, b))

out = save_loglog(
    "psi_table_error",
    [(sizes, gamma_index, "o-", r"index $\gamma = \tau D/(\tau D+1)$ (Moreland & Angel)"),
     (sizes, u_index, "s-", r"index $u = 1-\sqrt{1-\gamma}$ (PPIRay)")],
    "table size N (N x N texels)", r"max bilinear error in $\Psi$", r"$\Psi$ table lookup error",
    hline=(0.5 / 255, "0.5/255"))
print("wrote", out)
