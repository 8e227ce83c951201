#include "harness/tolerance_check.hpp"

#include <limits>
#include <set>

#include "harness/case_record.hpp"

namespace geosph::verify {

std::vector<std::string> flag_unreported_tolerances(const CaseConfig& cfg, const CaseContext& ctx,
                                                    std::vector<Record>& records) {
  std::set<std::string> reported;
  for (const auto& r : records)
    for (const auto& m : r.metrics) reported.insert(m.name);
  std::vector<std::string> missing;
  for (const auto& [name, tol] : cfg.tolerances)
    if (!reported.count(name)) missing.push_back(name);
  if (missing.empty()) return missing;

  Record* target = nullptr;
  for (auto& r : records)
    if (r.scored) target = &r;
  if (!target) {
    records.push_back(start_record(cfg, ctx));
    target = &records.back();
  }
  for (const auto& name : missing) {
    target->add_metric(name, std::numeric_limits<double>::quiet_NaN(), cfg.tolerances.at(name).value,
                       "case.json names this tolerance but the case reported no such metric");
  }
  return missing;
}

}  // namespace geosph::verify
