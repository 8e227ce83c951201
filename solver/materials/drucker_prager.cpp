#include "materials/drucker_prager.hpp"

#include <numbers>
#include <string>

#include "io/json_fields.hpp"

namespace geosph::materials {

DruckerPrager DruckerPrager::parse(const JsonFields& f) {
  DruckerPrager m;
  m.elastic = ElasticConstants::parse(f);
  m.cohesion = f.number("cohesion", Range::non_negative(), 0.0);
  m.friction_angle = f.number("friction_angle", Range{0, 90, false, true});
  m.dilatancy_angle = f.number("dilatancy_angle", Range{0, 90, false, true}, 0.0);
  if (m.dilatancy_angle > m.friction_angle)
    f.fail("dilatancy_angle", "must not exceed friction_angle (" + std::to_string(m.friction_angle) + " deg), got " +
                                  std::to_string(m.dilatancy_angle));
  constexpr double deg = std::numbers::pi / 180.0;
  m.point_ = soil::DruckerPrager({m.elastic.young, m.elastic.poisson, m.cohesion, m.friction_angle * deg,
                                  m.dilatancy_angle * deg});
  return m;
}

}  // namespace geosph::materials
