// The check that every tolerance a case.json names is judged: a metric renamed in the code, or a
// misspelt tolerance, would otherwise leave that tolerance silently unchecked.
#pragma once
#include <string>
#include <vector>

#include "harness/case_config.hpp"
#include "harness/record.hpp"

namespace geosph::verify {

// For each tolerance of cfg that no metric of `records` (scored or not) reports, adds a failing
// metric of that name (value NaN) to the last scored record, or to a new record when none is
// scored, so that the run fails and the report shows why. Returns the names added.
std::vector<std::string> flag_unreported_tolerances(const CaseConfig& cfg, const CaseContext& ctx,
                                                    std::vector<Record>& records);

}  // namespace geosph::verify
