// The discovered catalogue: case folders and their drivers (self-registered). No simulation runs here.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "harness/catalogue.hpp"
#include "harness/driver_registry.hpp"
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
