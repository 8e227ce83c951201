// The discovered catalogue: case folders, their drivers (self-registered) and the check that every
// tolerance a case.json names is reported by the case. No simulation runs here.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include "harness/catalogue.hpp"
#include "harness/driver_registry.hpp"
#include "harness/tolerance_check.hpp"
#include "io/json_fields.hpp"

using namespace geosph;
using namespace geosph::verify;
namespace fs = std::filesystem;

namespace {
// A data dir holding verification/cases/<name>/case.json for each (name, text).
fs::path synthetic_catalogue(const std::string& tag, const std::vector<std::pair<std::string, std::string>>& cases) {
  const fs::path root = fs::temp_directory_path() / ("geosph_catalogue_" + tag);
  fs::remove_all(root);
  for (const auto& [name, text] : cases) {
    fs::create_directories(root / "verification" / "cases" / name);
    std::ofstream(root / "verification" / "cases" / name / "case.json") << text;
  }
  return root;
}

std::string thrown_by(const fs::path& data_dir) {
  try {
    discover_cases(data_dir);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

// Each case.json names a driver that some linked case object registered (a registrar dropped by the
// linker would show here), and each registered driver serves at least one case folder.
TEST(Catalogue, EveryCaseNamesARegisteredDriver) {
  const auto cases = discover_cases(default_data_dir());
  ASSERT_GE(cases.size(), 18u);
  std::set<std::string> used;
  for (const auto& c : cases) {
    EXPECT_TRUE(drivers().count(c.driver)) << c.name << ": driver '" << c.driver << "' is not registered";
    EXPECT_FALSE(c.labels.empty()) << c.name;
    used.insert(c.driver);
  }
  for (const auto& [name, fn] : drivers()) EXPECT_TRUE(used.count(name)) << "driver '" << name << "' serves no case";
  EXPECT_TRUE(std::is_sorted(cases.begin(), cases.end(),
                             [](const CaseEntry& a, const CaseEntry& b) { return a.name < b.name; }));
  // shared drivers: two case folders, no code of their own
  for (const auto& c : cases) {
    if (c.name == "rankine_active" || c.name == "rankine_passive") {
      EXPECT_EQ(c.driver, "rankine_earth_pressure");
    }
    if (c.name == "granular_collapse_cam_clay") {
      EXPECT_EQ(c.driver, "granular_collapse_bui");
    }
  }
}

TEST(Catalogue, DiscoversFoldersWithACaseJsonSorted) {
  const auto dir = synthetic_catalogue("sorted", {{"b_case", R"({"driver": "hydrostatic_tank", "labels": ["verification"], "levels": {"quick": {}}})"},
                                                   {"a_case", R"({"driver": "hydrostatic_tank", "labels": [], "levels": {"convergence": {}}})"}});
  fs::create_directories(dir / "verification" / "cases" / "code_only");  // a shared driver's folder
  const auto cases = discover_cases(dir);
  ASSERT_EQ(cases.size(), 2u);
  EXPECT_EQ(cases[0].name, "a_case");
  EXPECT_FALSE(cases[0].has_level("quick"));
  EXPECT_TRUE(cases[0].has_level("convergence"));
  EXPECT_EQ(cases[1].labels, std::vector<std::string>{"verification"});
}

TEST(Catalogue, MissingOrUnknownDriverIsAnInputError) {
  const auto missing = thrown_by(synthetic_catalogue("no_driver", {{"x", R"({"labels": [], "levels": {}})"}}));
  EXPECT_NE(missing.find("x/case.json"), std::string::npos) << missing;
  EXPECT_NE(missing.find("field 'driver'"), std::string::npos) << missing;

  const auto unknown = thrown_by(synthetic_catalogue("bad_driver", {{"y", R"({"driver": "nope", "labels": [], "levels": {}})"}}));
  EXPECT_NE(unknown.find("y/case.json"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("unknown driver 'nope'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("hydrostatic_tank"), std::string::npos) << unknown;  // lists the known drivers

  const auto labels = thrown_by(synthetic_catalogue("no_labels", {{"z", R"({"driver": "hydrostatic_tank", "levels": {}})"}}));
  EXPECT_NE(labels.find("field 'labels'"), std::string::npos) << labels;
}

// A tiny synthetic case: tolerances a and b, records reporting a only (b a misspelt or renamed metric).
TEST(ToleranceCheck, AToleranceNoMetricReportsFailsTheCase) {
  CaseConfig cfg;
  cfg.name = "synthetic";
  cfg.tolerances = {{"a", {0.1, "why a"}}, {"b", {0.2, "why b"}}};
  CaseContext ctx;
  Record study, scored;
  study.scored = false;
  study.add_metric("b_study", 0.0, 1.0, "");
  scored.add_metric("a", 0.05, 0.1, "why a");
  std::vector<Record> records = {study, scored};
  ASSERT_TRUE(records[1].passed());

  EXPECT_EQ(flag_unreported_tolerances(cfg, ctx, records), std::vector<std::string>{"b"});
  ASSERT_EQ(records.size(), 2u);
  const auto& m = records[1].metrics.back();
  EXPECT_EQ(m.name, "b");
  EXPECT_TRUE(std::isnan(m.value));
  EXPECT_FALSE(m.passed);
  EXPECT_NE(m.why_tolerance.find("reported no such metric"), std::string::npos);
  EXPECT_FALSE(records[1].passed());
  EXPECT_EQ(records[0].metrics.size(), 1u);  // the unscored study is left as it was

  // every tolerance reported (here b by an unscored record): nothing added
  records[0].add_metric("b", 0.0, 0.2, "why b");
  const auto before = records[1].metrics.size();
  EXPECT_TRUE(flag_unreported_tolerances(cfg, ctx, records).empty());
  EXPECT_EQ(records[1].metrics.size(), before);

  // no scored record (or none at all): a new failing record carries the missing metric
  std::vector<Record> none;
  EXPECT_EQ(flag_unreported_tolerances(cfg, ctx, none).size(), 2u);
  ASSERT_EQ(none.size(), 1u);
  EXPECT_EQ(none[0].case_name, "synthetic");
  EXPECT_FALSE(none[0].passed());
}

// Every spacing a case's levels name gives a scene that parses and passes the scene checks (walls
// inside the domain, bodies clear of the wall layers): a coarse convergence level must not be refused
// by its own scene. Drivers may edit the scene further; this checks the part every level shares.
TEST(Catalogue, EveryLevelsSpacingGivesAValidScene) {
  CaseContext ctx;
  ctx.data_dir = default_data_dir();
  int checked = 0;
  for (const auto& c : discover_cases(ctx.data_dir)) {
    for (const auto& level : c.levels) {
      ctx.level = level;
      const CaseConfig cfg = load_case(ctx, c.name);
      if (cfg.scene_json.is_null() || !cfg.level.contains("dx")) continue;
      for (const double dx : cfg.level_numbers("dx")) {
        try {
          (void)cfg.scene(dx);
          ++checked;
        } catch (const std::exception& e) {
          ADD_FAILURE() << c.name << ", level " << level << ", dx = " << dx << ": " << e.what();
        }
      }
    }
  }
  EXPECT_GE(checked, 40);
}
