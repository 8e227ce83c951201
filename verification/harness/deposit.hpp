// Measures of a granular deposit (soil particles on a horizontal floor), shared by the column
// collapse cases.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/particles.hpp"
#include "harness/case_config.hpp"

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

// Root-mean-square speed of the solids (soil and structures), mass-weighted: sqrt(2 E_kin / M), their
// kinetic energy (solid_kinetic_energy, sim/gravity_loading.hpp) as a speed.
double rms_solid_speed(const Particles& P);

// Soil particles faster than v.
std::size_t soil_particles_faster_than(const Particles& P, double v);

// One sand model of a collapse case: case.json's "sand_models" maps a name to
// {"material": <the scene's material object>, "scored": bool, "why": "..."}; an unscored model's
// records are studies shown beside the scored one (the reason is "why").
struct SandModel {
  std::string name;
  nlohmann::json material;
  bool scored = true;
  std::string why;  // what the model is and why it is (not) scored, into each record as "sand_model"
  nlohmann::json describe() const { return {{"name", name}, {"scored", scored}, {"why", why}}; }
};
// The models the level asks for (its "sand_models" list, in that order; all of them, by name, when
// the level names none). The case's scene gets the model's material as "sand".
std::vector<SandModel> sand_models(const CaseConfig& cfg);

}  // namespace geosph::verify
