// Measures of a granular deposit (soil particles on a horizontal floor), shared by the column
// collapse cases.
#pragma once
#include <vector>

#include <nlohmann/json.hpp>

#include "core/particles.hpp"

namespace geosph::verify {

struct Profile {
  std::vector<double> x, h;  // bin centres and surface heights above the floor
};

// Free surface: the highest soil particle's top (centre + dx/2) in bins of width dx along x from x0.
Profile surface_profile(const Particles& P, double x0, double floor_y, double dx);

// Run-out: the front of the soil on the floor (particles within 2 dx of it), at the particle's edge
// (absolute x).
double runout_front(const Particles& P, double floor_y, double dx);

// A piecewise power law of a reference JSON (the scaling-law files of reference/experimental):
// coefficient * a^exponent on the entry whose [a_min, a_max) holds a (a_max null: no upper end); NaN
// in a gap between entries.
double scaling_law(const nlohmann::json& entries, double a);

// Largest speed of any soil particle.
double max_soil_speed(const Particles& P);

}  // namespace geosph::verify
