// The extension points of the solver (issue 15): the typed particle-field registry, the stage table
// of the time step and the model list that drives the scene reader.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>

#include "boundary/body_fields.hpp"
#include "io/json_fields.hpp"
#include "io/scene.hpp"
#include "sim/simulation.hpp"
#include "sim/stages.hpp"
#include "soil/soil_fields.hpp"
#include "test_scenes.hpp"

namespace {

using namespace geosph;
using json = nlohmann::json;

std::string error_of(const json& j) {
  try {
    parse_scene(j, "scene.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::vector<std::string> names_of(const std::vector<Stage>& stages, Hook h) {
  std::vector<std::string> v;
  for (const auto& s : stages)
    if (s.hook == h) v.push_back(s.name);
  return v;
}

TEST(ParticleFields, MissingFieldThrowsNamingIt) {
  Simulation sim(parse_scene(test::soil_column_scene(0.02), "column.json"));
  const Particles& P = sim.particles();
  EXPECT_NO_THROW(P.field(SoilFields::yy));
  try {
    P.field("stress_yyy");  // misspelt
    ADD_FAILURE() << "a misspelt field was accepted";
  } catch (const FieldError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("'stress_yyy'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("stress_yy"), std::string::npos) << msg;  // lists the fields there are
  }
  EXPECT_EQ(P.find("stress_yyy"), nullptr);
  EXPECT_EQ(P.owner(SoilFields::yy), SoilFields::owner);
}

TEST(ParticleFields, OwnersAndTypesAreKept) {
  Particles P;
  P.add(0, 0, 0, 1, 1, Kind::Soil, 0);
  P.add_field("a", "module_a")[0] = 2.0;
  EXPECT_EQ(P.add_field("a", "module_a")[0], 2.0);  // the owner may ask again
  EXPECT_THROW(P.add_field("a", "module_b"), FieldError);
  EXPECT_THROW(P.add_int_field("a", "module_a"), FieldError);  // one name, one type
  P.add_int_field("flag", "module_a")[0] = 7;
  P.add(1, 0, 0, 1, 1, Kind::Soil, 0);  // new particles extend every field with zero
  EXPECT_EQ(P.int_field("flag").size(), 2u);
  EXPECT_EQ(P.int_field("flag")[1], 0);
  P.permute({1, 0});
  EXPECT_EQ(P.int_field("flag")[1], 7);
  EXPECT_EQ(P.field("a")[1], 2.0);
}

TEST(ParticleFields, FlagsAndIndicesAreIntegers) {
  json j = test::soil_structure_scene();
  j["time"]["end"] = 1e-4;
  Simulation sim(parse_scene(j, "wall.json"));
  const auto& body = sim.particles().int_field(BodyFields::structure_body);
  EXPECT_EQ(*std::max_element(body.begin(), body.end()), 2);  // the wall is bodies[1]
  EXPECT_FALSE(sim.particles().has_field(BodyFields::structure_body));  // not also a real field
}

TEST(Stages, TableFollowsTheSceneAndKeepsTheOrder) {
  Simulation sim(parse_scene(test::soil_column_scene(0.02), "column.json"));
  const auto& st = sim.stages();
  EXPECT_EQ(names_of(st, Hook::Rates), std::vector<std::string>{"solid_stress"});
  EXPECT_EQ(names_of(st, Hook::Forces), (std::vector<std::string>{"soil_walls", "solid_momentum"}));
  EXPECT_TRUE(names_of(st, Hook::Drift).empty());  // no rigid structures in this scene
  EXPECT_NO_THROW(check_stages(st));
  EXPECT_NE(describe_stages(st).find("forces  solid_momentum"), std::string::npos);
}

TEST(Stages, TwoWritersOfOneFieldInAHookAreRefused) {
  const auto nop = [] {};
  std::vector<Stage> st = {{"first", Hook::Forces, {}, {"a[soil]"}, {}, nop},
                           {"second", Hook::Forces, {}, {"a[soil]"}, {}, nop}};
  try {
    check_stages(st);
    ADD_FAILURE() << "two writers accepted";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("'first' and 'second' both write 'a[soil]'"), std::string::npos) << e.what();
  }
  st[1].hook = Hook::Rates;  // another hook: fine
  EXPECT_NO_THROW(check_stages(st));
  std::vector<Stage> orphan = {{"adder", Hook::Forces, {}, {}, {"a[fluid]"}, nop}};
  EXPECT_THROW(check_stages(orphan), std::logic_error);
}

TEST(MaterialList, DrivesTheAcceptedModelsAndTheirMessages) {
  json j = test::soil_column_scene(0.02);
  j["materials"]["sand"]["model"] = "cam_clay";
  const std::string e = error_of(j);
  for (const char* m : {"tait_fluid", "drucker_prager", "modified_cam_clay", "linear_elastic", "von_mises", "mohr_coulomb"})
    EXPECT_NE(e.find(m), std::string::npos) << m << " missing from: " << e;
  // Mohr-Coulomb parses through its own file; a strengthless one is refused naming the field
  j["materials"]["sand"] = json::parse(R"({"model": "mohr_coulomb", "density": 2000, "young_modulus": 1e7,
                                            "poisson_ratio": 0.3, "cohesion": 0, "friction_angle": 0})");
  EXPECT_NE(error_of(j).find("materials.sand.cohesion"), std::string::npos) << error_of(j);
  j["materials"]["sand"]["friction_angle"] = 30;
  j["materials"]["sand"]["dilatancy_angle"] = 35;
  EXPECT_NE(error_of(j).find("materials.sand.dilatancy_angle"), std::string::npos) << error_of(j);
  j["materials"]["sand"]["dilatancy_angle"] = 10;
  EXPECT_EQ(error_of(j), "");
  // the structure check lists the models that may form structures
  json w = test::soil_structure_scene();
  w["materials"]["steel"] = j["materials"]["sand"];
  EXPECT_NE(error_of(w).find("needs a linear_elastic or von_mises material"), std::string::npos) << error_of(w);
}

}  // namespace

namespace {

// Wall slip per container: the column's box is no-slip (walls.slip), a second container beside it
// free-slip; its wall particles carry the flag, the others not, and a short run stays finite.
TEST(WallSlip, SettablePerContainer) {
  json j = geosph::test::soil_column_scene(0.02);
  j["domain"]["max"] = {1.0, 0.5};
  j["walls"]["containers"].push_back({{"min", {0.5, 0}}, {"max", {0.8, 0.3}}, {"open", {"top"}}, {"slip", "free_slip"}});
  geosph::Simulation sim(geosph::parse_scene(j, "two_boxes.json"));
  const auto& P = sim.particles();
  const auto& slip = P.int_field(geosph::BodyFields::wall_free_slip);
  int free = 0, no_slip = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != geosph::Kind::DummyWall) continue;
    (P.x[i] > 0.42 ? free : no_slip) += 1;  // first box walls end at 0.35 + 3 dx, the second begin at 0.5 - 3 dx
    EXPECT_EQ(slip[i], P.x[i] > 0.42 ? 1 : 0) << "wall particle at x = " << P.x[i];
  }
  EXPECT_GT(free, 0);
  EXPECT_GT(no_slip, 0);
  EXPECT_NO_THROW(sim.run());
  // without a differing container no flag field is made (a scene pays only for what it declares)
  geosph::Simulation plain(geosph::parse_scene(geosph::test::soil_column_scene(0.02), "column.json"));
  EXPECT_FALSE(plain.particles().has_int_field(geosph::BodyFields::wall_free_slip));
  j["walls"]["containers"][1]["slip"] = "sticky";
  EXPECT_NE(error_of(j).find("walls.containers[1].slip"), std::string::npos) << error_of(j);
}

}  // namespace
