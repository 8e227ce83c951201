#include "harness/catalogue.hpp"

#include <algorithm>
#include <cstdio>

#include "boundary/wall_input.hpp"
#include "core/provenance.hpp"
#include "harness/driver_registry.hpp"
#include "harness/tolerance_check.hpp"
#include "io/json_fields.hpp"

namespace geosph::verify {

bool CaseEntry::has_level(const std::string& level) const {
  return std::find(levels.begin(), levels.end(), level) != levels.end();
}

namespace {
CaseEntry read_entry(const std::filesystem::path& file) {
  const nlohmann::json j = read_json_file(file);
  JsonFields f(j, file.string(), "");
  CaseEntry c;
  c.name = file.parent_path().filename().string();
  c.driver = f.text("driver");
  if (!drivers().count(c.driver)) {
    std::string known;
    for (const auto& [name, fn] : drivers()) known += (known.empty() ? "" : ", ") + name;
    f.fail("driver", "unknown driver '" + c.driver + "' (known: " + known + ")");
  }
  c.levels = f.object("levels").keys();
  if (!j.contains("labels")) f.fail("labels", "is missing (required; ctest labels, e.g. [\"verification\"])");
  if (!j["labels"].is_array()) f.fail("labels", "must be an array of strings");
  for (const auto& l : j["labels"]) {
    if (!l.is_string()) f.fail("labels", "must be an array of strings");
    c.labels.push_back(l.get<std::string>());
  }
  if (f.has("wall_treatments")) {  // the boundary comparison needs the scene's own treatment
    const auto scene_file = file.parent_path() / "scene.json";
    if (std::filesystem::exists(scene_file)) {
      const nlohmann::json scene = read_json_file(scene_file);
      if (scene.contains("walls") && scene["walls"].contains("type") && scene["walls"]["type"].is_string())
        c.own_walls = scene["walls"]["type"].get<std::string>();
    }
    c.wall_treatments = f.texts("wall_treatments", wall_types());
    if (c.own_walls.empty()) f.fail("wall_treatments", "the case's scene has no walls (scene.json walls.type)");
    if (std::find(c.wall_treatments.begin(), c.wall_treatments.end(), c.own_walls) == c.wall_treatments.end())
      f.fail("wall_treatments", "must list the scene's own walls.type \"" + c.own_walls + "\"");
  }
  if (f.has("open_wall_treatments")) {
    const JsonFields open = f.object("open_wall_treatments");
    for (const auto& t : open.keys()) {
      if (t == c.own_walls ||
          std::find(c.wall_treatments.begin(), c.wall_treatments.end(), t) == c.wall_treatments.end())
        f.fail("open_wall_treatments." + t, "must name a treatment of wall_treatments other than the scene's own");
      c.open_wall_treatments[t] = open.text(t);
    }
  }
  return c;
}
}  // namespace

std::vector<CaseEntry> discover_cases(const std::filesystem::path& data_dir) {
  const auto root = data_dir / "verification" / "cases";
  if (!std::filesystem::is_directory(root))
    throw InputError(root.string() + ": no catalogue here (set GEOSPH_DATA_DIR to the folder holding verification/)");
  std::vector<CaseEntry> cases;
  // a folder without case.json (e.g. rankine_earth_pressure) holds only a shared driver's code
  for (const auto& d : std::filesystem::directory_iterator(root))
    if (d.is_directory() && std::filesystem::exists(d.path() / "case.json"))
      cases.push_back(read_entry(d.path() / "case.json"));
  std::sort(cases.begin(), cases.end(), [](const CaseEntry& a, const CaseEntry& b) { return a.name < b.name; });
  return cases;
}

std::vector<Record> run_case(const CaseEntry& entry, const CaseContext& ctx) {
  std::vector<Record> records = drivers().at(entry.driver)(ctx, entry.name);
  // the case's inputs: case.json and scene.json as parsed (canonical), the hash in every record
  const CaseConfig cfg = load_case(ctx, entry.name);
  nlohmann::json inputs = {{"case", read_json_file(cfg.dir / "case.json")}, {"scene", cfg.scene_json}};
  const nlohmann::json prov = provenance(content_hash(inputs.dump())).to_json();
  const std::string walls = cfg.scene_json.is_object() && cfg.scene_json.contains("walls")
                                ? cfg.scene_json["walls"].value("type", std::string())
                                : std::string();
  for (auto& r : records) {
    r.provenance = prov;
    if (walls.empty()) continue;
    r.extra["wall_treatment"] = walls;
    if (ctx.walls.empty()) continue;
    r.extra["wall_comparison"] = true;
    if (const auto open = entry.open_wall_treatments.find(walls); open != entry.open_wall_treatments.end())
      r.extra["wall_treatment_open"] = open->second;
    if (!r.variant.empty()) r.variant += ' ';
    r.variant += "walls=";
    r.variant += walls;
  }
  for (const auto& name : flag_unreported_tolerances(cfg, ctx, records))
    std::fprintf(stderr, "%s: case.json names tolerance '%s' but the case reported no such metric (failed)\n",
                 entry.name.c_str(), name.c_str());
  return records;
}

}  // namespace geosph::verify
