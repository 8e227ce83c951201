#pragma once
#include <vector>

#include "harness/case_config.hpp"
#include "harness/record.hpp"

namespace geosph::verify {
std::vector<Record> run_soil_under_free_water(const CaseContext& ctx);
}
