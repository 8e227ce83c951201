// Drucker-Prager soil, elastic-perfectly plastic with non-associated flow, matched to Mohr-Coulomb
// c, phi, psi in plane strain (Bui et al. 2008; the return mapping is soil/drucker_prager.hpp).
#pragma once
#include "materials/elastic_constants.hpp"
#include "materials/frictional_strength.hpp"
#include "materials/solid_model.hpp"
#include "soil/drucker_prager.hpp"

namespace geosph::materials {

struct DruckerPrager : SolidModelDefaults, FrictionalStrength {
  static constexpr std::string_view name = "drucker_prager";
  ElasticConstants elastic;

  static DruckerPrager parse(const JsonFields& f);
  double poisson_ratio() const { return elastic.poisson; }
  double wave_speed(double /*p*/, double density) const { return elastic.wave_speed(density); }
  SolidUpdate update(const Matrix3d& sigma, const Matrix3d& de, const Matrix3d& dw, const SolidState&,
                     std::size_t) const {
    return perfectly_plastic_update(point_, sigma, de, dw);
  }
  const soil::DruckerPrager& point_model() const { return point_; }

 private:
  soil::DruckerPrager point_{soil::DruckerPragerParams{1, 0, 0, 0, 0}};
};

}  // namespace geosph::materials
