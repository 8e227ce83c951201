// A water column's time-averaged pressures against its hydrostatic Tait profile (the resting-water
// cases): the metric's inputs and the report's pressure-against-depth plot.
#pragma once
#include <map>
#include <utility>
#include <vector>

#include "analytical/hydrostatic_tait.hpp"
#include "harness/record.hpp"

namespace geosph::verify {

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
