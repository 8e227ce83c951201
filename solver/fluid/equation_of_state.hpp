// Tait equation of state for weakly compressible SPH (Monaghan 1994, J. Comput. Phys. 110, eq. 3.3;
// Batchelor 1967): p = B [(rho/rho0)^gamma - 1] + p_bg, with B = rho0 c0^2 / gamma.
#pragma once
#include <cmath>

#include "io/scene.hpp"

namespace geosph {

struct TaitEos {
  double rho0, c0, gamma, B, p_bg;
  explicit TaitEos(const FluidMaterial& m)
      : rho0(m.density), c0(m.sound_speed), gamma(m.gamma), B(m.density * m.sound_speed * m.sound_speed / m.gamma),
        p_bg(m.background_pressure) {}
  double pressure(double rho) const { return B * (std::pow(rho / rho0, gamma) - 1.0) + p_bg; }
  double density(double p) const {
    const double u = (p - p_bg) / B + 1.0;
    return u > 0 ? rho0 * std::pow(u, 1.0 / gamma) : rho0 * 1e-3;
  }
  // Closed-form hydrostatic state of a Tait fluid: dp/dz = -rho(p) g integrates to
  // (p/B + 1)^(1 - 1/gamma) = 1 + (1 - 1/gamma) rho0 g depth / B.
  double hydrostatic_pressure(double g, double depth) const {
    const double e = 1.0 - 1.0 / gamma;
    return B * (std::pow(1.0 + e * rho0 * g * depth / B, 1.0 / e) - 1.0) + p_bg;
  }
};

}  // namespace geosph
