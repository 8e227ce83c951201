// Linear elastic solid (Hooke, with the Jaumann stress rate): structures and elastic skeletons.
#pragma once
#include "materials/elastic_constants.hpp"
#include "materials/solid_model.hpp"
#include "soil/drucker_prager.hpp"

namespace geosph::materials {

struct LinearElastic : SolidModelDefaults {
  static constexpr std::string_view name = "linear_elastic";
  static constexpr bool structure_allowed = true;
  ElasticConstants elastic;

  static LinearElastic parse(const JsonFields& f);
  // Hooke's law with these constants (also another model's elastic part: sim/gravity_loading.hpp).
  static LinearElastic with(const ElasticConstants& e);
  double poisson_ratio() const { return elastic.poisson; }
  double wave_speed(double /*p*/, double density) const { return elastic.wave_speed(density); }
  SolidUpdate update(const Matrix3d& sigma, const Matrix3d& de, const Matrix3d& dw, const SolidState&,
                     std::size_t) const {
    return {soil::DruckerPrager::jaumann_rotate(sigma, dw) + hooke_.elastic_increment(de), 0.0, true};
  }

 private:
  soil::DruckerPrager hooke_{soil::DruckerPragerParams{1, 0, 0, 0, 0}};  // its elastic part only
};

}  // namespace geosph::materials
