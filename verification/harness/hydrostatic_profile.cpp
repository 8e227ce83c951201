#include "harness/hydrostatic_profile.hpp"

#include <algorithm>
#include <cmath>

namespace geosph::verify {

void FluidTimeAverage::sample(const Particles& P, double t) {
  if (t < t0_) return;
  ++samples_;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Fluid) continue;
    auto& s = sum_[static_cast<std::size_t>(P.id[i])];
    s[0] += P.p[i]; s[1] += P.x[i]; s[2] += P.y[i]; s[3] += P.z[i];
    seen_[static_cast<std::size_t>(P.id[i])] = 1;
    vmax_ = std::max(vmax_, std::sqrt(P.vx[i] * P.vx[i] + P.vy[i] * P.vy[i] + P.vz[i] * P.vz[i]));
  }
}

void HydrostaticProfile::add(double p, double y) {
  p_sim_.push_back(p);
  p_ref_.push_back(ref_.pressure(y));
  auto& r = rows_[std::lround(y / dx_)];
  r.first += p;
  r.second += 1;
}

std::vector<Series> HydrostaticProfile::series() const {
  Series sim{"SPH (row mean)", "simulation", "pressure", "depth below settled surface [m]", "pressure [Pa]", {}, {}};
  for (const auto& [row, acc] : rows_) {
    sim.x.push_back(ref_.surface_height() - row * dx_);
    sim.y.push_back(acc.first / acc.second);
  }
  Series ana{"hydrostatic (Tait)", "analytical", "pressure", sim.xlabel, sim.ylabel, {}, {}};
  for (int k = 0; k <= 50; ++k) {
    const double d = ref_.surface_height() * k / 50.0;
    ana.x.push_back(d);
    ana.y.push_back(ref_.pressure_at_depth(d));
  }
  return {sim, ana};
}

}  // namespace geosph::verify
