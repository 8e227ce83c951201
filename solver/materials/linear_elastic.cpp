#include "materials/linear_elastic.hpp"

#include "io/json_fields.hpp"

namespace geosph::materials {

ElasticConstants ElasticConstants::parse(const JsonFields& f) {
  ElasticConstants e;
  e.young = f.number("young_modulus", Range::positive());
  e.poisson = f.number("poisson_ratio", Range::open(-1.0, 0.5));
  return e;
}

std::vector<FieldDoc> ElasticConstants::docs() {
  return {number_doc("young_modulus", Range::positive(), "required", "Pa", "Young's modulus E"),
          number_doc("poisson_ratio", Range::open(-1.0, 0.5), "required", "-", "Poisson's ratio nu")};
}

namespace {
const bool documented = register_section({"materials:solid:linear_elastic", "materials.<name> with \"model\": \"linear_elastic\"",
                                          "Hooke's law with the Jaumann stress rate (structures, elastic skeletons).",
                                          ElasticConstants::docs()});
}  // namespace

LinearElastic LinearElastic::parse(const JsonFields& f) { return with(ElasticConstants::parse(f)); }

LinearElastic LinearElastic::with(const ElasticConstants& e) {
  LinearElastic m;
  m.elastic = e;
  m.hooke_ = soil::DruckerPrager({e.young, e.poisson, 0, 0, 0});
  return m;
}

}  // namespace geosph::materials
