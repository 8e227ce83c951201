#include "materials/mohr_coulomb.hpp"

#include <numbers>

#include "io/json_fields.hpp"
#include "io/scene_reference.hpp"

namespace geosph::materials {

namespace {
const bool documented = register_section(
    {"materials:solid:mohr_coulomb", "materials.<name> with \"model\": \"mohr_coulomb\"",
     "Mohr-Coulomb, elastic-perfectly plastic, hexagonal surface with edge and apex returns (de Souza Neto et al. "
     "2008, ch. 8); phi = 0 is Tresca.",
     FrictionalStrength::docs_with_elastic()});
}  // namespace

MohrCoulomb MohrCoulomb::parse(const JsonFields& f) {
  MohrCoulomb m;
  m.elastic = ElasticConstants::parse(f);
  static_cast<FrictionalStrength&>(m) = FrictionalStrength::parse(f);
  if (m.cohesion == 0 && m.friction_angle == 0)
    f.fail("cohesion", "must be > 0 when friction_angle is 0 (the material would have no strength)");
  constexpr double deg = std::numbers::pi / 180.0;
  m.point_ = soil::MohrCoulomb({m.elastic.young, m.elastic.poisson, m.cohesion, m.friction_angle * deg,
                                m.dilatancy_angle * deg});
  return m;
}

}  // namespace geosph::materials
