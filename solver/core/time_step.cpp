#include "core/time_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace geosph {

double stable_time_step(const TimeStepInput& in, const TimeStepLimits& lim) {
  double dt = std::numeric_limits<double>::infinity();
  if (in.c_max + in.v_max > 0) dt = std::min(dt, lim.cfl * in.h / (in.c_max + in.v_max));
  if (in.a_max > 0) dt = std::min(dt, lim.force * std::sqrt(in.h / in.a_max));
  if (in.nu_max > 0) dt = std::min(dt, lim.viscous * in.h * in.h / in.nu_max);
  return dt;
}

}  // namespace geosph
