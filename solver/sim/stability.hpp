// Blow-up detection: a run that goes unstable stops with a diagnosis naming the step, the time,
// the particle (original id and position) and the quantity that went wrong.
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

#include "core/cell_list.hpp"
#include "core/particles.hpp"

namespace geosph {

struct Diagnosis {
  long step = 0;
  double time = 0;
  long long particle_id = -1;
  double x = 0, y = 0, z = 0;
  std::string quantity;  // e.g. "velocity is not finite", "density ratio rho/rho0 = 2.3 > 1.5"
  std::string message() const;
};

struct InstabilityError : std::runtime_error {
  Diagnosis diagnosis;
  explicit InstabilityError(const Diagnosis& d) : std::runtime_error(d.message()), diagnosis(d) {}
};

// Limits per material kind: reference densities by material index and the wave speed (|v| above
// it means weak compressibility / the stress wave resolution is lost).
struct PhaseBounds {
  std::vector<double> rho0;
  double max_speed = 0;
};

struct StateBounds {
  PhaseBounds fluid, soil;
  double max_density_variation = 0;  // |rho/rho0 - 1| above this is a blow-up
};

// Also returns the largest speed and acceleration magnitudes of the moving particles.
struct StateSummary {
  double v_max = 0, a_max = 0;
};

// Throws InstabilityError for the first offending particle.
StateSummary check_state(const Particles& P, const Box& domain, const StateBounds& bounds, long step, double time);

}  // namespace geosph
