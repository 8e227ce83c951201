#include "harness/case_config.hpp"

#include <cstdlib>
#include <fstream>

#include "io/json_fields.hpp"
#include "io/json_file.hpp"

namespace geosph::verify {

std::filesystem::path default_data_dir() {
  if (const char* env = std::getenv("GEOSPH_DATA_DIR")) return env;
  return GEOSPH_DEFAULT_DATA_DIR;
}

CaseConfig load_case(const CaseContext& ctx, const std::string& name) {
  CaseConfig c;
  c.name = name;
  c.dir = ctx.data_dir / "verification" / "cases" / name;
  const auto file = (c.dir / "case.json").string();
  const nlohmann::json j = read_json_file(file);
  JsonFields f(j, file, "");
  c.title = f.text("title");
  auto ref = f.object("reference");
  ref.choice("kind", {"analytical", "experimental", "dem", "limit_equilibrium", "none"});  // none: an unscored example
  ref.text("source");
  c.reference = j.at("reference");
  auto levels = f.object("levels");
  if (!levels.has(ctx.level)) levels.fail(ctx.level, "this case has no '" + ctx.level + "' level");
  levels.object(ctx.level);
  c.level = j.at("levels").at(ctx.level);
  auto tol = f.object("tolerances");
  for (const auto& key : tol.keys()) {
    auto t = tol.object(key);
    c.tolerances[key] = {t.number("value", Range::non_negative()), t.text("why")};
    t.reject_unknown();
  }
  c.spec = j;
  // element (material-point) tests have no scene
  if (std::filesystem::exists(c.dir / "scene.json")) c.scene_json = read_json_file(c.dir / "scene.json");
  if (!ctx.walls.empty()) {
    if (!c.scene_json.is_object() || !c.scene_json.contains("walls"))
      throw InputError(file + ": --walls " + ctx.walls + ": the case's scene has no walls to replace");
    c.scene_json["walls"]["type"] = ctx.walls;
  }
  return c;
}

const Tolerance& CaseConfig::tolerance(const std::string& metric) const {
  auto it = tolerances.find(metric);
  if (it == tolerances.end())
    throw InputError((dir / "case.json").string() + ": field 'tolerances." + metric + "': is missing (required)");
  return it->second;
}

double CaseConfig::level_number(const std::string& key) const {
  if (!level.contains(key) || !level[key].is_number())
    throw InputError((dir / "case.json").string() + ": field 'levels.<level>." + key + "': must be a number");
  return level[key].get<double>();
}

bool CaseConfig::use_variant_level(const nlohmann::json& variant, const std::string& level_name) {
  if (variant.is_object() && variant.contains("levels") && variant["levels"].contains(level_name))
    level = variant["levels"][level_name];
  return !(level.contains("dx") && level["dx"].is_array() && level["dx"].empty());
}

std::vector<double> CaseConfig::level_numbers(const std::string& key) const {
  if (level.contains(key) && level[key].is_array()) {
    std::vector<double> v;
    for (const auto& e : level[key]) {
      if (!e.is_number())
        throw InputError((dir / "case.json").string() + ": field 'levels.<level>." + key + "': must hold numbers");
      v.push_back(e.get<double>());
    }
    if (!v.empty()) return v;
  }
  return {level_number(key)};
}

Scene CaseConfig::scene(double dx) const {
  if (scene_json.is_null()) throw InputError((dir / "scene.json").string() + ": cannot open (case '" + name + "' has no scene)");
  nlohmann::json j = scene_json;
  j["dx"] = dx;
  return parse_scene(j, (dir / "scene.json").string());
}

std::filesystem::path CaseConfig::reference_file(const CaseContext& ctx, const std::string& relative) const {
  return ctx.data_dir / "reference" / relative;
}

}  // namespace geosph::verify
