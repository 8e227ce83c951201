// Monaghan's artificial viscosity of a particle pair (Monaghan 1992, Annu. Rev. Astron. Astrophys. 30,
// 543-574, eq. 4.2), for the soil's and the structures' momentum equations:
//   Pi_ij = (-alpha c_ij mu_ij + beta mu_ij^2) / rho_ij,  mu_ij = h v_ij . r_ij / (r_ij^2 + eta^2),
// with rho_ij = (rho_i + rho_j) / 2, only for approaching pairs (v_ij . r_ij < 0). Written with one
// division, Pi = hvr (beta hvr - alpha c d) / (d^2 rho_ij), hvr = h v.r, d = r^2 + eta^2: a caller passes
// hvr = h min(v.r, 0), so that a receding pair gets 0 without a branch and the pair loop vectorises.
#pragma once

namespace geosph {

inline double monaghan_viscosity(double hvr, double d, double c, double alpha, double beta, double rho_i,
                                 double rho_j) {
  return hvr * (beta * hvr - alpha * c * d) / (0.5 * d * d * (rho_i + rho_j));
}

}  // namespace geosph
