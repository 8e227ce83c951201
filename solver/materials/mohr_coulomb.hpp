// Mohr-Coulomb soil, elastic-perfectly plastic with the true hexagonal yield surface and
// non-associated flow (psi <= phi); the return in principal stresses with plane, edge and apex
// returns is soil/mohr_coulomb.hpp (de Souza Neto, Peric & Owen 2008, sec. 8.2). phi = 0 is Tresca.
#pragma once
#include "materials/elastic_constants.hpp"
#include "materials/frictional_strength.hpp"
#include "materials/solid_model.hpp"
#include "soil/mohr_coulomb.hpp"

namespace geosph::materials {

struct MohrCoulomb : SolidModelDefaults, FrictionalStrength {
  static constexpr std::string_view name = "mohr_coulomb";
  ElasticConstants elastic;

  static MohrCoulomb parse(const JsonFields& f);
  double poisson_ratio() const { return elastic.poisson; }
  double wave_speed(double /*p*/, double density) const { return elastic.wave_speed(density); }
  SolidUpdate update(const Matrix3d& sigma, const Matrix3d& de, const Matrix3d& dw, const SolidState&,
                     std::size_t) const {
    return perfectly_plastic_update(point_, sigma, de, dw);
  }

 private:
  soil::MohrCoulomb point_{soil::MohrCoulombParams{1, 0, 1, 0, 0}};
};

}  // namespace geosph::materials
