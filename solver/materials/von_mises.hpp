// von Mises (J2) elastic-perfectly plastic solid for structures: Drucker-Prager with phi = 0,
// sqrt(J2) <= k = yield_stress / sqrt(3) (uniaxial yield stress sigma_y).
#pragma once
#include "materials/elastic_constants.hpp"
#include "materials/frictional_strength.hpp"
#include "materials/solid_model.hpp"
#include "soil/drucker_prager.hpp"

namespace geosph::materials {

struct VonMises : SolidModelDefaults {
  static constexpr std::string_view name = "von_mises";
  static constexpr bool saturable = false;
  static constexpr bool structure_allowed = true;
  ElasticConstants elastic;
  double yield_stress = 0;  // sigma_y [Pa]

  static VonMises parse(const JsonFields& f);
  double poisson_ratio() const { return elastic.poisson; }
  double wave_speed(double /*p*/, double density) const { return elastic.wave_speed(density); }
  SolidUpdate update(const Matrix3d& sigma, const Matrix3d& de, const Matrix3d& dw, const SolidState&,
                     std::size_t) const {
    return perfectly_plastic_update(point_, sigma, de, dw);
  }

 private:
  soil::DruckerPrager point_{soil::DruckerPragerParams{1, 0, 0, 0, 0}};
};

}  // namespace geosph::materials
