// Mohr-Coulomb soil, elastic-perfectly plastic with the true hexagonal yield surface and
// non-associated flow (psi <= phi); the return in principal stresses with plane, edge and apex
// returns is soil/mohr_coulomb.hpp (de Souza Neto, Peric & Owen 2008, sec. 8.2). phi = 0 is Tresca.
#pragma once
#include "materials/elastic_constants.hpp"
#include "materials/solid_model.hpp"
#include "soil/mohr_coulomb.hpp"

namespace geosph::materials {

struct MohrCoulomb : SolidModelDefaults {
  static constexpr std::string_view name = "mohr_coulomb";
  ElasticConstants elastic;
  double cohesion = 0;         // c [Pa]
  double friction_angle = 0;   // phi [deg], in [0, 90)
  double dilatancy_angle = 0;  // psi [deg], in [0, phi]

  static MohrCoulomb parse(const JsonFields& f);
  double poisson_ratio() const { return elastic.poisson; }
  double wave_speed(double /*p*/, double density) const { return elastic.wave_speed(density); }
  SolidUpdate update(const Matrix3d& sigma, const Matrix3d& de, const Matrix3d& dw, const SolidState&,
                     std::size_t) const {
    const auto r = point_.update(sigma, de, dw);
    return {r.stress, r.equivalent_plastic_strain_increment, true};
  }

 private:
  soil::MohrCoulomb point_{soil::MohrCoulombParams{1, 0, 1, 0, 0}};
};

}  // namespace geosph::materials
