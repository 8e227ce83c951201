#include "materials/von_mises.hpp"

#include <cmath>

#include "io/json_fields.hpp"

namespace geosph::materials {

namespace {
std::vector<FieldDoc> docs() {
  auto d = ElasticConstants::docs();
  d.push_back(number_doc("yield_stress", Range::positive(), "required", "Pa", "uniaxial yield stress sigma_y"));
  return d;
}
const bool documented = register_section({"materials:solid:von_mises", "materials.<name> with \"model\": \"von_mises\"",
                                          "von Mises (J2) elastic-perfectly plastic structure material.", docs()});
}  // namespace

VonMises VonMises::parse(const JsonFields& f) {
  VonMises m;
  m.elastic = ElasticConstants::parse(f);
  m.yield_stress = f.number("yield_stress", Range::positive());
  m.point_ = soil::DruckerPrager({m.elastic.young, m.elastic.poisson, m.yield_stress / std::sqrt(3.0), 0, 0});
  return m;
}

}  // namespace geosph::materials
