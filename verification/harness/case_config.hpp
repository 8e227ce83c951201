// A catalogue case on disk: verification/cases/<name>/case.json (title, reference and its source,
// resolution per level, every tolerance with the reason it has that value) and scene.json.
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/json_file.hpp"
#include "io/scene.hpp"

namespace geosph::verify {

struct Tolerance {
  double value = 0;
  std::string why;
};

struct CaseContext {
  std::filesystem::path data_dir;  // holds verification/ and reference/
  std::string level = "quick";
  int threads = 1;
  bool progress = false;
  // a wall treatment that replaces the scene's walls.type (the boundary comparison, case.json
  // "wall_treatments"); empty: the scene's own
  std::string walls;
};

struct CaseConfig {
  std::string name, title;
  std::filesystem::path dir;
  nlohmann::json reference, level;  // level: the entry of "levels" for the requested level
  std::map<std::string, Tolerance> tolerances;
  nlohmann::json scene_json;
  nlohmann::json spec;  // the whole case.json, for case-specific fields

  const Tolerance& tolerance(const std::string& metric) const;
  double level_number(const std::string& key) const;
  // A number or a list of numbers (several resolutions, coarse to fine).
  std::vector<double> level_numbers(const std::string& key) const;
  // A variant's own "levels" entry for `level`, if it has one, replaces the case's (a slow variant at
  // fewer spacings); false when that entry lists no spacing (the variant does not run at this level).
  bool use_variant_level(const nlohmann::json& variant, const std::string& level);
  // The case's scene with its particle spacing set to dx.
  Scene scene(double dx) const;
  std::filesystem::path reference_file(const CaseContext& ctx, const std::string& relative) const;
};

CaseConfig load_case(const CaseContext& ctx, const std::string& name);
// A JSON file (comments allowed); InputError naming the file if it cannot be read or parsed.
std::filesystem::path default_data_dir();

}  // namespace geosph::verify
