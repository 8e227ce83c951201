#include "analytical/poiseuille.hpp"

#include <cmath>
#include <numbers>

namespace geosph::reference {

double PoiseuilleStartup::velocity(double y, double t) const {
  const double pi = std::numbers::pi;
  double v = F / (2.0 * nu) * y * (L - y);
  const double scale = 4.0 * F * L * L / (nu * pi * pi * pi);
  for (int n = 0; n < 100000; ++n) {
    const double k = 2.0 * n + 1.0;
    const double amp = scale / (k * k * k) * std::exp(-k * k * pi * pi * nu * t / (L * L));
    if (amp < 1e-15 * max_velocity()) break;  // later terms are smaller still: the tail is below round-off
    v -= amp * std::sin(pi * y * k / L);
  }
  return v;
}

}  // namespace geosph::reference
