// Balsara's switch for the artificial viscosity (Balsara 1995, J. Comput. Phys. 121, 357-372, eq. 4.1),
// from a particle's velocity gradient L_ab = dv_a/dx_b:
//   f = |div v| / (|div v| + |curl v| + 1e-4 c / h),
// near 1 where the flow compresses or expands and near 0 where it shears or turns; the 1e-4 c/h term
// keeps f finite at rest. The soil's Pi_ij is scaled by (f_i + f_j) / 2 (soil/soil_forces.hpp).
#pragma once
#include <cmath>

namespace geosph {

inline double balsara_switch(const double L[3][3], double wave_speed, double h) {
  const double div = std::abs(L[0][0] + L[1][1] + L[2][2]);
  const double wx = L[2][1] - L[1][2], wy = L[0][2] - L[2][0], wz = L[1][0] - L[0][1];
  const double curl = std::sqrt(wx * wx + wy * wy + wz * wz);
  return div / (div + curl + 1e-4 * wave_speed / h);
}

}  // namespace geosph
