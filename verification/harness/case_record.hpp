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

}  // namespace geosph::verify
