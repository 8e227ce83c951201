#include "harness/case_record.hpp"

#include <limits>

namespace geosph::verify {

Record start_record(const CaseConfig& cfg, const CaseContext& ctx) {
  Record r;
  r.case_name = cfg.name;
  r.title = cfg.title;
  r.level = ctx.level;
  r.reference = cfg.reference;
  return r;
}

void add_case_metric(Record& rec, const CaseConfig& cfg, const std::string& name, double value, bool ok) {
  const auto& tol = cfg.tolerance(name);
  rec.add_metric(name, ok ? value : std::numeric_limits<double>::quiet_NaN(), tol.value, tol.why);
}

Series linear_depth_profile(const Series& profile, const std::string& name, double at_base, double depth) {
  return {name, "analytical", profile.plot, profile.xlabel, profile.ylabel, {0.0, at_base}, {0.0, -depth}};
}

}  // namespace geosph::verify
