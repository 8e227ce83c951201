// The scene reference comes from the code: every field the reader takes from any catalogue or
// unit-test scene is declared by its module (io/scene_reference.hpp), the committed
// docs/scene-reference.md is what `geosph scene-reference` prints, and unknown-field errors list the
// section's documented fields.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "harness/case_config.hpp"
#include "io/json_fields.hpp"
#include "io/scene.hpp"
#include "io/scene_reference.hpp"
#include "materials/solid_material.hpp"
#include "materials/tait_fluid.hpp"
#include "test_scenes.hpp"

namespace {

using namespace geosph;
using json = nlohmann::json;

TEST(SceneReference, EveryFieldReadIsDocumented) {
  std::set<std::pair<std::string, std::string>> read;
  record_scene_fields(&read);
  int scenes = 0;
  for (const auto& dir : std::filesystem::directory_iterator(verify::default_data_dir() / "verification" / "cases")) {
    const auto file = dir.path() / "scene.json";
    if (!std::filesystem::exists(file)) continue;
    load_scene(file);
    ++scenes;
  }
  parse_scene(test::soil_column_scene(), "column.json");
  parse_scene(test::soil_structure_scene(), "wall.json");
  record_scene_fields(nullptr);
  EXPECT_GE(scenes, 18);
  EXPECT_GT(read.size(), 60u);
  for (const auto& [tag, key] : read) EXPECT_TRUE(is_documented(tag, key)) << "undocumented: " << tag << " / " << key;
}

TEST(SceneReference, EveryModelHasItsSection) {
  for (const auto& m : solid_model_names()) EXPECT_FALSE(documented_keys("materials:solid:" + m).empty()) << m;
  for (const auto& m : fluid_model_names()) EXPECT_FALSE(documented_keys("materials:" + m).empty()) << m;
  const json schema = scene_reference_schema();
  EXPECT_EQ(schema["properties"]["materials"]["additionalProperties"]["oneOf"].size(),
            solid_model_names().size() + fluid_model_names().size());
  EXPECT_TRUE(schema["properties"]["bodies"]["items"]["properties"].contains("ocr"));  // a model's body field
}

TEST(SceneReference, CommittedMarkdownIsCurrent) {
  const auto path = verify::default_data_dir() / "docs" / "scene-reference.md";
  std::ifstream in(path);
  ASSERT_TRUE(in) << path << " is missing: geosph scene-reference > docs/scene-reference.md";
  std::stringstream s;
  s << in.rdbuf();
  EXPECT_EQ(s.str(), scene_reference_markdown()) << "regenerate with: geosph scene-reference > docs/scene-reference.md";
}

TEST(SceneReference, UnknownFieldListsTheDocumentedOnes) {
  json j = test::soil_column_scene();
  j["bodies"][0]["k00"] = 0.5;  // misspelt k0
  try {
    parse_scene(j, "scene.json");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("bodies[0].k00"), std::string::npos) << msg;
    for (const char* k : {"k0", "pressure", "velocity", "surcharge"}) EXPECT_NE(msg.find(k), std::string::npos) << k << ": " << msg;
    EXPECT_EQ(msg.find("ocr"), std::string::npos) << "a Drucker-Prager body has no ocr: " << msg;
  }
}

}  // namespace
