// Helpers for a case's drivers to fill its result records from its case.json.
#pragma once
#include <string>

#include "harness/case_config.hpp"
#include "harness/record.hpp"

namespace geosph::verify {

// Fills the fields every record of a case shares (name, title, level, reference).
Record start_record(const CaseConfig& cfg, const CaseContext& ctx);
// Adds metric `name` with the tolerance and reason from case.json; NaN (failing) unless `ok`.
void add_case_metric(Record& rec, const CaseConfig& cfg, const std::string& name, double value, bool ok = true);
// An analytical stress growing linearly with depth, from 0 at the top to `at_base` at depth `depth`,
// drawn on the axes of `profile` (stress along x, depth downwards along y).
Series linear_depth_profile(const Series& profile, const std::string& name, double at_base, double depth);

}  // namespace geosph::verify
