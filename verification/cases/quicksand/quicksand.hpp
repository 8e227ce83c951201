#pragma once
#include <vector>

#include "harness/case_config.hpp"
#include "harness/record.hpp"

namespace geosph::verify {
std::vector<Record> run_quicksand(const CaseContext& ctx);
}
