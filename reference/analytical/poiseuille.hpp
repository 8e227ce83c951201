// Start-up of plane Poiseuille flow between plates at y = 0 and y = L driven by a body force F
// (Morris, Fox & Zhu 1997, J. Comput. Phys. 136, eq. 21), written for 0 <= y <= L:
//   v_x(y, t) = F/(2 nu) y (L - y)
//             - sum_{n>=0} 4 F L^2 / (nu pi^3 (2n+1)^3) sin(pi y (2n+1)/L) exp(-(2n+1)^2 pi^2 nu t / L^2)
#pragma once

namespace geosph::reference {

struct PoiseuilleStartup {
  double F, nu, L;
  double velocity(double y, double t) const;  // series summed until terms are below 1e-15 v_max
  double max_velocity() const { return F * L * L / (8.0 * nu); }
};

}  // namespace geosph::reference
