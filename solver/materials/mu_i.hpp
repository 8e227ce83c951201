// mu(I) granular rheology (Jop, Forterre & Pouliquen 2006) in its elasto-viscoplastic form
// (Dunatunga & Kamrin 2015); the point model and its return are soil/mu_i_rheology.hpp.
#pragma once
#include "materials/elastic_constants.hpp"
#include "materials/solid_model.hpp"
#include "soil/mu_i_rheology.hpp"

namespace geosph::materials {

struct MuI : SolidModelDefaults {
  static constexpr std::string_view name = "mu_i";
  static constexpr bool saturable = false;  // not verified as the skeleton of a two-phase soil
  ElasticConstants elastic;

  static MuI parse(const JsonFields& f);
  double poisson_ratio() const { return elastic.poisson; }
  double wave_speed(double /*p*/, double density) const { return elastic.wave_speed(density); }
  SolidUpdate update(const Matrix3d& sigma, const Matrix3d& de, const Matrix3d& dw, const SolidState& s,
                     std::size_t) const {
    const auto r = point_.update(sigma, de, dw, s.dt);
    return {r.stress, r.equivalent_plastic_strain_increment, true};
  }
  const soil::MuIRheology& point_model() const { return point_; }

 private:
  soil::MuIRheology point_{soil::MuIParams{1, 0, 0, 0, 1, 1, 1}};
};

}  // namespace geosph::materials
