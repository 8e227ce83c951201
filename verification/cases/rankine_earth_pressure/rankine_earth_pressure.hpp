#pragma once
#include <vector>

#include "harness/case_config.hpp"
#include "harness/record.hpp"

namespace geosph::verify {
// Cases rankine_active and rankine_passive (one implementation, two case folders).
std::vector<Record> run_rankine_active(const CaseContext& ctx);
std::vector<Record> run_rankine_passive(const CaseContext& ctx);
}  // namespace geosph::verify
