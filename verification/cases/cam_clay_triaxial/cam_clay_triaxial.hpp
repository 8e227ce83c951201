#pragma once
#include <vector>

#include "harness/case_config.hpp"
#include "harness/record.hpp"

namespace geosph::verify {
std::vector<Record> run_cam_clay_triaxial(const CaseContext& ctx);
}
