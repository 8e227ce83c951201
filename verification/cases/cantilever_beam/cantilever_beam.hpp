#pragma once
#include <vector>

#include "harness/case_config.hpp"
#include "harness/record.hpp"

namespace geosph::verify {
std::vector<Record> run_cantilever_beam(const CaseContext& ctx);
}
