// The catalogue: every verification case by name.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "harness/case_config.hpp"
#include "harness/record.hpp"

namespace geosph::verify {

struct CaseEntry {
  std::string name;
  // A case may write several records (e.g. one per resolution).
  std::function<std::vector<Record>(const CaseContext&)> run;
};

const std::vector<CaseEntry>& catalogue();

// Fills the fields every record of a case shares (name, title, level, reference).
Record start_record(const CaseConfig& cfg, const CaseContext& ctx);
// Adds metric `name` with the tolerance and reason from case.json; NaN (failing) unless `ok`.
void add_case_metric(Record& rec, const CaseConfig& cfg, const std::string& name, double value, bool ok = true);

}  // namespace geosph::verify
