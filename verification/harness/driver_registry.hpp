// Case drivers by name, with no central list: each case's .cpp registers its run function with
// GEOSPH_CASE_DRIVER, and each case.json names the driver that runs it ("driver"), so one driver
// can serve several case folders (rankine_active and rankine_passive both use
// rankine_earth_pressure's).
#pragma once
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "harness/case_config.hpp"
#include "harness/record.hpp"

namespace geosph::verify {

// Runs the case in folder verification/cases/<case_name> at ctx.level; a case may write several
// records (e.g. one per resolution).
using DriverFn = std::function<std::vector<Record>(const CaseContext& ctx, const std::string& case_name)>;

// Every registered driver, by name.
const std::map<std::string, DriverFn>& drivers();
// Adds a driver (called by GEOSPH_CASE_DRIVER); two drivers of one name abort at start-up.
bool register_driver(const std::string& name, DriverFn fn);

}  // namespace geosph::verify

// At namespace scope in a case's .cpp: registers `fn` as driver `name` during static
// initialisation. The case objects are linked whole (an OBJECT library, see
// verification/CMakeLists.txt): from a static library the linker would drop this unreferenced
// registrar, and the driver with it.
#define GEOSPH_CASE_DRIVER(name, fn) \
  [[maybe_unused]] static const bool geosph_case_driver_##name = ::geosph::verify::register_driver(#name, fn)
