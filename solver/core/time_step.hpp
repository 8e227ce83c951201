// Adaptive time step for explicit weakly compressible SPH (Monaghan 1992, Sec. 10; Morris et al.
// 1997, eqs. 13-15): acoustic CFL, body-force and viscous-diffusion limits.
#pragma once
#include <cmath>
#include <numbers>

namespace geosph {

// Smooth start from 0 to 1 over `duration` (Adami, Hu & Adams 2012, J. Comput. Phys. 231, eq. 33):
// 0.5 (sin((t/duration - 1/2) pi) + 1) for t < duration, then 1. Used for the gravity ramp and for
// prescribed structure motion.
inline double smooth_start(double t, double duration) {
  if (duration <= 0 || t >= duration) return 1.0;
  return 0.5 * (std::sin((-0.5 + t / duration) * std::numbers::pi) + 1.0);
}

struct TimeStepLimits {
  double cfl = 0.2, force = 0.25, viscous = 0.125;
};

struct TimeStepInput {
  double h = 0, c_max = 0, v_max = 0, a_max = 0, nu_max = 0;
};

// dt = min( cfl h / (c + |v|max),  force sqrt(h / |a|max),  viscous h^2 / nu )
double stable_time_step(const TimeStepInput& in, const TimeStepLimits& lim);

}  // namespace geosph
