// The catalogue: one case per folder verification/cases/<name>/ that holds a case.json, found at
// run time under the data dir (no list to keep). Its case.json names the registered driver that
// runs it ("driver", harness/driver_registry.hpp) and its ctest labels ("labels", read by
// verification/CMakeLists.txt too).
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "harness/case_config.hpp"
#include "harness/record.hpp"

namespace geosph::verify {

struct CaseEntry {
  std::string name;    // the folder's name
  std::string driver;  // case.json "driver"
  std::vector<std::string> levels;  // the keys of case.json "levels"
  std::vector<std::string> labels;  // case.json "labels"
  // case.json "wall_treatments": the walls.type values the case is also run with in the boundary
  // comparison (ctest label walls; geosph verify --walls); own_walls: its scene's walls.type (read with wall_treatments)
  std::vector<std::string> wall_treatments;
  std::string own_walls;
  // case.json "open_wall_treatments": {treatment: why it misses the tolerance today}; those
  // comparison runs carry the ctest label open as well and the report prints the reason
  std::map<std::string, std::string> open_wall_treatments;
  bool has_level(const std::string& level) const;
};

// The cases under data_dir/verification/cases, sorted by name. Throws InputError naming the
// case.json and field when "driver" is missing or names no registered driver (the message lists
// the known ones) or "labels" is not an array of strings.
std::vector<CaseEntry> discover_cases(const std::filesystem::path& data_dir);

// Runs the case's driver at ctx.level (with ctx.walls in place of the scene's walls.type when set;
// every record of a case with walls carries its treatment in "wall_treatment"), then fails every tolerance of its case.json that none of
// its records reports (harness/tolerance_check.hpp).
std::vector<Record> run_case(const CaseEntry& entry, const CaseContext& ctx);

}  // namespace geosph::verify
