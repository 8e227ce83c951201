#include "materials/linear_elastic.hpp"

#include "io/json_fields.hpp"

namespace geosph::materials {

ElasticConstants ElasticConstants::parse(const JsonFields& f) {
  ElasticConstants e;
  e.young = f.number("young_modulus", Range::positive());
  e.poisson = f.number("poisson_ratio", Range::open(-1.0, 0.5));
  return e;
}

LinearElastic LinearElastic::parse(const JsonFields& f) {
  LinearElastic m;
  m.elastic = ElasticConstants::parse(f);
  m.hooke_ = soil::DruckerPrager({m.elastic.young, m.elastic.poisson, 0, 0, 0});
  return m;
}

}  // namespace geosph::materials
