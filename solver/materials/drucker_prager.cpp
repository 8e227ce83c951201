#include "materials/drucker_prager.hpp"

#include <numbers>

#include "io/scene_reference.hpp"

namespace geosph::materials {

namespace {
const bool documented = register_section(
    {"materials:solid:drucker_prager", "materials.<name> with \"model\": \"drucker_prager\"",
     "Drucker-Prager, elastic-perfectly plastic, non-associated; the cone matched to Mohr-Coulomb c, phi, psi in "
     "plane strain (Bui et al. 2008).",
     FrictionalStrength::docs_with_elastic()});
}  // namespace

DruckerPrager DruckerPrager::parse(const JsonFields& f) {
  DruckerPrager m;
  m.elastic = ElasticConstants::parse(f);
  static_cast<FrictionalStrength&>(m) = FrictionalStrength::parse(f);
  constexpr double deg = std::numbers::pi / 180.0;
  m.point_ = soil::DruckerPrager({m.elastic.young, m.elastic.poisson, m.cohesion, m.friction_angle * deg,
                                  m.dilatancy_angle * deg});
  return m;
}

}  // namespace geosph::materials
