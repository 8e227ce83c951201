// The Mohr-Coulomb strength parameters c, phi, psi that the frictional models (Drucker-Prager and
// Mohr-Coulomb) share: read and range-checked once here, with their scene-reference entries.
#pragma once
#include <vector>

#include "io/scene_reference.hpp"
#include "materials/solid_model.hpp"

namespace geosph::materials {

struct FrictionalStrength {
  double cohesion = 0;         // c [Pa]
  double friction_angle = 0;   // phi [deg], in [0, 90)
  double dilatancy_angle = 0;  // psi [deg], in [0, phi]

  static FrictionalStrength parse(const JsonFields& f);  // dilatancy_angle <= friction_angle checked
  // young_modulus, poisson_ratio and the three above, for a model's section
  static std::vector<FieldDoc> docs_with_elastic();
};

// One step of a point model without state fields (perfectly plastic: no hardening variable).
template <class Point>
SolidUpdate perfectly_plastic_update(const Point& point, const Matrix3d& sigma, const Matrix3d& de, const Matrix3d& dw) {
  const auto r = point.update(sigma, de, dw);
  return {r.stress, r.equivalent_plastic_strain_increment, true};
}

}  // namespace geosph::materials
