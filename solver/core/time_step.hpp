// Adaptive time step for explicit weakly compressible SPH (Monaghan 1992, Sec. 10; Morris et al.
// 1997, eqs. 13-15): acoustic CFL, body-force and viscous-diffusion limits.
#pragma once

namespace geosph {

struct TimeStepLimits {
  double cfl = 0.2, force = 0.25, viscous = 0.125;
};

struct TimeStepInput {
  double h = 0, c_max = 0, v_max = 0, a_max = 0, nu_max = 0;
};

// dt = min( cfl h / (c + |v|max),  force sqrt(h / |a|max),  viscous h^2 / nu )
double stable_time_step(const TimeStepInput& in, const TimeStepLimits& lim);

}  // namespace geosph
