#pragma once
#include <vector>

#include "harness/case_config.hpp"
#include "harness/record.hpp"

namespace geosph::verify {
std::vector<Record> run_granular_collapse_bui(const CaseContext& ctx);
std::vector<Record> run_granular_collapse_cam_clay(const CaseContext& ctx);
}
