// A water column's time-averaged pressures against its hydrostatic Tait profile (the resting-water
// cases): the metric's inputs and the report's pressure-against-depth plot.
#pragma once
#include <array>
#include <map>
#include <utility>
#include <vector>

#include "analytical/hydrostatic_tait.hpp"
#include "core/particles.hpp"
#include "harness/record.hpp"

namespace geosph::verify {

// Each fluid particle's pressure and position averaged over the steps from t0 on (by original id), and
// the largest fluid speed in that window.
class FluidTimeAverage {
 public:
  FluidTimeAverage(std::size_t particles, double t0) : sum_(particles, {0, 0, 0, 0}), t0_(t0) {}
  void sample(const Particles& P, double t);  // after each step
  long samples() const { return samples_; }
  double max_speed() const { return vmax_; }
  // f(p, x, y, z) with the averages of every sampled fluid particle
  template <class F>
  void for_each(F&& f) const {
    if (samples_ == 0) return;
    for (std::size_t k = 0; k < sum_.size(); ++k)
      if (seen_[k]) f(sum_[k][0] / samples_, sum_[k][1] / samples_, sum_[k][2] / samples_, sum_[k][3] / samples_);
  }

 private:
  std::vector<std::array<double, 4>> sum_;
  std::vector<char> seen_ = std::vector<char>(sum_.size(), 0);
  double t0_, vmax_ = 0;
  long samples_ = 0;
};

class HydrostaticProfile {
 public:
  HydrostaticProfile(const reference::HydrostaticTait& ref, double dx) : ref_(ref), dx_(dx) {}
  // One particle's pressure averaged at its averaged height y.
  void add(double p, double y);
  const std::vector<double>& simulated() const { return p_sim_; }
  const std::vector<double>& reference() const { return p_ref_; }
  // The row means (rows dx apart) and the analytical line, against depth below the settled surface.
  std::vector<Series> series() const;

 private:
  const reference::HydrostaticTait& ref_;
  double dx_;
  std::vector<double> p_sim_, p_ref_;
  std::map<long, std::pair<double, int>> rows_;  // row index -> (sum of p, count)
};

}  // namespace geosph::verify
