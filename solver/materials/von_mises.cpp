#include "materials/von_mises.hpp"

#include <cmath>

#include "io/json_fields.hpp"

namespace geosph::materials {

VonMises VonMises::parse(const JsonFields& f) {
  VonMises m;
  m.elastic = ElasticConstants::parse(f);
  m.yield_stress = f.number("yield_stress", Range::positive());
  m.point_ = soil::DruckerPrager({m.elastic.young, m.elastic.poisson, m.yield_stress / std::sqrt(3.0), 0, 0});
  return m;
}

}  // namespace geosph::materials
