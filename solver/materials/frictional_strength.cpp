#include "materials/frictional_strength.hpp"

#include <string>

#include "io/json_fields.hpp"
#include "materials/elastic_constants.hpp"

namespace geosph::materials {

FrictionalStrength FrictionalStrength::parse(const JsonFields& f) {
  FrictionalStrength s;
  s.cohesion = f.number("cohesion", Range::non_negative(), 0.0);
  s.friction_angle = f.number("friction_angle", Range{0, 90, false, true});
  s.dilatancy_angle = f.number("dilatancy_angle", Range{0, 90, false, true}, 0.0);
  if (s.dilatancy_angle > s.friction_angle)
    f.fail("dilatancy_angle", "must not exceed friction_angle (" + std::to_string(s.friction_angle) + " deg), got " +
                                  std::to_string(s.dilatancy_angle));
  return s;
}

std::vector<FieldDoc> FrictionalStrength::docs_with_elastic() {
  auto d = ElasticConstants::docs();
  d.push_back(number_doc("cohesion", Range::non_negative(), "0", "Pa", "Mohr-Coulomb cohesion c"));
  d.push_back(number_doc("friction_angle", Range{0, 90, false, true}, "required", "deg", "friction angle phi"));
  d.push_back(number_doc("dilatancy_angle", Range{0, 90, false, true}, "0", "deg", "dilatancy angle psi <= phi"));
  return d;
}

}  // namespace geosph::materials
