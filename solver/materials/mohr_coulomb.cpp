#include "materials/mohr_coulomb.hpp"

#include <numbers>
#include <string>

#include "io/json_fields.hpp"

namespace geosph::materials {

namespace {
std::vector<FieldDoc> docs() {
  auto d = ElasticConstants::docs();
  for (auto& f : std::vector<FieldDoc>{number_doc("cohesion", Range::non_negative(), "0", "Pa", "Mohr-Coulomb cohesion c"),
            number_doc("friction_angle", Range{0, 90, false, true}, "required", "deg", "friction angle phi"),
            number_doc("dilatancy_angle", Range{0, 90, false, true}, "0", "deg", "dilatancy angle psi <= phi")}) d.push_back(f);
  return d;
}
const bool documented = register_section({"materials:solid:mohr_coulomb", "materials.<name> with \"model\": \"mohr_coulomb\"",
                                          "Mohr-Coulomb, elastic-perfectly plastic, hexagonal surface with edge and apex returns (de Souza Neto et al. 2008, ch. 8); phi = 0 is Tresca.", docs()});
}  // namespace

MohrCoulomb MohrCoulomb::parse(const JsonFields& f) {
  MohrCoulomb m;
  m.elastic = ElasticConstants::parse(f);
  m.cohesion = f.number("cohesion", Range::non_negative(), 0.0);
  m.friction_angle = f.number("friction_angle", Range{0, 90, false, true});
  m.dilatancy_angle = f.number("dilatancy_angle", Range{0, 90, false, true}, 0.0);
  if (m.dilatancy_angle > m.friction_angle)
    f.fail("dilatancy_angle", "must not exceed friction_angle (" + std::to_string(m.friction_angle) + " deg), got " +
                                  std::to_string(m.dilatancy_angle));
  if (m.cohesion == 0 && m.friction_angle == 0)
    f.fail("cohesion", "must be > 0 when friction_angle is 0 (the material would have no strength)");
  constexpr double deg = std::numbers::pi / 180.0;
  m.point_ = soil::MohrCoulomb({m.elastic.young, m.elastic.poisson, m.cohesion, m.friction_angle * deg,
                                m.dilatancy_angle * deg});
  return m;
}

}  // namespace geosph::materials
