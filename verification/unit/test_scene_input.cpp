// Bad input: every kind of mistake gives one clear InputError naming the file, the field and what
// is allowed; through the `geosph` command it exits non-zero and leaves no output directory.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "io/json_fields.hpp"
#include "boundary/geometry.hpp"
#include "io/scene.hpp"
#include "sim/simulation.hpp"
#include "test_scenes.hpp"

using namespace geosph;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

json valid_scene() {
  return json::parse(R"({
    "name": "tank", "dimension": 2, "dx": 0.02,
    "kernel": {"type": "wendland_c2"},
    "domain": {"min": [-0.1, -0.1], "max": [0.5, 0.5]},
    "gravity": [0, -9.81],
    "time": {"end": 0.01},
    "materials": {"water": {"model": "tait_fluid", "density": 1000, "sound_speed": 20}},
    "bodies": [{"material": "water", "shape": "box", "min": [0, 0], "max": [0.2, 0.2]}],
    "walls": {"type": "dummy", "containers": [{"min": [0, 0], "max": [0.3, 0.3], "open": ["top"]}]}
  })");
}

// parse_scene must throw an InputError naming the file, `field` and what is allowed.
constexpr auto expect_error = test::expect_scene_error;

}  // namespace

TEST(SceneInput, ValidSceneParses) {
  const Scene s = parse_scene(valid_scene(), "ok.json");
  EXPECT_EQ(s.dim, 2);
  EXPECT_DOUBLE_EQ(s.dx, 0.02);
  EXPECT_EQ(s.materials.size(), 1u);
}

TEST(SceneInput, UnknownField) {
  auto j = valid_scene();
  j["time"]["endd"] = 1.0;
  expect_error(j, "time.endd", "is not a known field here (known: ");
  j = valid_scene();
  j["materials"]["water"]["viscosity"] = 1e-6;
  expect_error(j, "materials.water.viscosity", "kinematic_viscosity");
}

TEST(SceneInput, MissingField) {
  auto j = valid_scene();
  j.erase("dx");
  expect_error(j, "'dx'", "is missing (required)");
  j = valid_scene();
  j["materials"]["water"].erase("sound_speed");
  expect_error(j, "materials.water.sound_speed", "is missing");
}

TEST(SceneInput, WrongType) {
  auto j = valid_scene();
  j["dx"] = "0.02";
  expect_error(j, "'dx'", "must be a number");
  j = valid_scene();
  j["domain"]["min"] = {0.0};
  expect_error(j, "domain.min", "must be an array of 2 finite numbers, got [0.0]");
}

TEST(SceneInput, NonPositiveSpacingOrDensity) {
  auto j = valid_scene();
  j["dx"] = 0.0;
  expect_error(j, "'dx'", "> 0");
  j["dx"] = -0.01;
  expect_error(j, "'dx'", "got -0.01");
  j = valid_scene();
  j["materials"]["water"]["density"] = -1000;
  expect_error(j, "materials.water.density", "> 0");
}

TEST(SceneInput, ParticlesOutsideTheDomain) {
  auto j = valid_scene();
  j["bodies"][0]["max"] = {0.2, 0.7};
  expect_error(j, "bodies[0]", "outside the domain");
  j = valid_scene();
  j["walls"]["containers"][0]["min"] = {-0.09, 0.0};
  expect_error(j, "walls.containers[0]", "outside the domain");
}

TEST(SceneInput, UnknownKernel) {
  auto j = valid_scene();
  j["kernel"]["type"] = "gaussian";
  expect_error(j, "kernel.type", "must be one of {cubic_spline, wendland_c2, quintic_spline}");
}

TEST(SceneInput, OutOfRangeValues) {
  auto j = valid_scene();
  j["materials"]["water"]["artificial_viscosity"] = 2.0;
  expect_error(j, "materials.water.artificial_viscosity", "[0, 1]");
  j = valid_scene();
  j["dimension"] = 4;
  expect_error(j, "dimension", "integer in [2, 3]");
  j = valid_scene();
  j["bodies"][0]["material"] = "oil";
  expect_error(j, "bodies[0].material", "names no material");
}

TEST(SceneInput, FileThatIsNotJson) {
  const fs::path dir = fs::temp_directory_path() / "geosph_scene_input";
  fs::create_directories(dir);
  std::ofstream(dir / "broken.json") << "{ \"dx\": 0.01, ";
  try {
    load_scene(dir / "broken.json");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.json: not valid JSON"), std::string::npos) << e.what();
  }
  EXPECT_THROW(load_scene(dir / "missing.json"), InputError);
}

// Through the command line: exit code, message on stderr, and no output directory created.
TEST(SceneInput, CommandLineRejectsBadSceneWithoutWritingOutput) {
  const fs::path dir = fs::temp_directory_path() / "geosph_cli_bad_input";
  fs::remove_all(dir);
  fs::create_directories(dir);
  auto j = valid_scene();
  j["dx"] = -1;
  std::ofstream(dir / "scene.json") << j.dump(2);
  const fs::path out = dir / "out", err = dir / "stderr.txt";
  const std::string cmd = std::string(GEOSPH_EXE) + " run " + (dir / "scene.json").string() + " --out " +
                          out.string() + " --quiet 2> " + err.string();
  const int status = std::system(cmd.c_str());
  EXPECT_NE(status, 0);
  EXPECT_FALSE(fs::exists(out)) << "output directory left behind";
  std::stringstream msg;
  msg << std::ifstream(err).rdbuf();
  EXPECT_NE(msg.str().find("scene.json: field 'dx': must be > 0, got -1"), std::string::npos) << msg.str();
}

// Soil materials: moduli, Poisson ratio, friction and dilatancy angles are range-checked and the
// message names the material and the field.
namespace {
json soil_scene() { return geosph::test::soil_column_scene(); }
}  // namespace

TEST(SceneInput, SoilMaterialRanges) {
  EXPECT_NO_THROW(parse_scene(soil_scene(), "bad.json"));
  auto j = soil_scene();
  j["materials"]["sand"]["young_modulus"] = 0;
  expect_error(j, "materials.sand.young_modulus", "> 0");
  j = soil_scene();
  j["materials"]["sand"]["young_modulus"] = -5e6;
  expect_error(j, "materials.sand.young_modulus", "got -5");
  j = soil_scene();
  j["materials"]["sand"]["poisson_ratio"] = 0.5;
  expect_error(j, "materials.sand.poisson_ratio", "(-1, 0.5)");
  j["materials"]["sand"]["poisson_ratio"] = -1.0;
  expect_error(j, "materials.sand.poisson_ratio", "(-1, 0.5)");
  j = soil_scene();
  j["materials"]["sand"]["friction_angle"] = 90;
  expect_error(j, "materials.sand.friction_angle", "[0, 90)");
  j["materials"]["sand"]["friction_angle"] = -1;
  expect_error(j, "materials.sand.friction_angle", "[0, 90)");
  j = soil_scene();
  j["materials"]["sand"]["dilatancy_angle"] = 25;
  expect_error(j, "materials.sand.dilatancy_angle", "must not exceed friction_angle");
  j = soil_scene();
  j["walls"]["type"] = "repulsive";
  expect_error(j, "walls.type", "soil needs dummy, ghost or mirror walls");
  j = soil_scene();
  j["materials"]["sand"]["artificial_viscosity_switch"] = "monaghan";
  expect_error(j, "materials.sand.artificial_viscosity_switch", "balsara");
}

// Modified Cam Clay: lambda <= kappa, non-positive M, p' <= 0 at start.
namespace {
json cam_clay_scene() {
  auto j = geosph::test::soil_column_scene();
  j["materials"] = json::parse(R"({"clay": {"model": "modified_cam_clay", "density": 1800, "lambda": 0.093,
      "kappa": 0.035, "critical_state_slope": 0.95, "poisson_ratio": 0.3, "void_ratio": 0.6}})");
  j["bodies"][0]["material"] = "clay";
  return j;
}
}  // namespace

TEST(SceneInput, CamClayMaterialRanges) {
  const Scene s = parse_scene(cam_clay_scene(), "ok.json");
  EXPECT_TRUE(s.soils.front().is<materials::ModifiedCamClay>());
  EXPECT_DOUBLE_EQ(s.bodies.front().ocr, 1.0);
  auto j = cam_clay_scene();
  j["materials"]["clay"]["lambda"] = 0.035;
  expect_error(j, "materials.clay.lambda", "must be greater than kappa");
  j["materials"]["clay"]["lambda"] = 0.02;
  expect_error(j, "materials.clay.lambda", "must be greater than kappa");
  j = cam_clay_scene();
  j["materials"]["clay"]["kappa"] = 0;
  expect_error(j, "materials.clay.kappa", "> 0");
  j = cam_clay_scene();
  j["materials"]["clay"]["critical_state_slope"] = 0;
  expect_error(j, "materials.clay.critical_state_slope", "(0, 3)");
  j["materials"]["clay"]["critical_state_slope"] = -1.0;
  expect_error(j, "materials.clay.critical_state_slope", "(0, 3)");
  j = cam_clay_scene();
  j["materials"]["clay"]["void_ratio"] = 0;
  expect_error(j, "materials.clay.void_ratio", "(0, 20)");
  j = cam_clay_scene();
  j["materials"]["clay"]["young_modulus"] = 1e6;  // pressure-dependent elasticity: no Young's modulus
  expect_error(j, "materials.clay.young_modulus", "is not a known field");
  // p' <= 0 at start
  j = cam_clay_scene();
  j["bodies"][0]["initial"] = "rest";
  expect_error(j, "bodies[0].initial", "needs an initial mean effective stress p' > 0");
  j = cam_clay_scene();
  j["gravity"] = {0, 0};
  expect_error(j, "bodies[0].initial", "needs p' > 0 at start");
  j = cam_clay_scene();
  j["bodies"][0]["initial"] = "isotropic";
  j["bodies"][0]["pressure"] = 0;
  expect_error(j, "bodies[0].pressure", "> 0");
  j = cam_clay_scene();
  j["bodies"][0]["ocr"] = 0.5;
  expect_error(j, "bodies[0].ocr", "[1, 1000]");
  // OCR is a Cam Clay field only
  j = soil_scene();
  j["bodies"][0]["ocr"] = 2;
  expect_error(j, "bodies[0].ocr", "is not a known field");
}

using geosph::test::soil_structure_scene;

TEST(SceneInput, SoilStructureSceneParses) {
  const Scene s = parse_scene(soil_structure_scene(), "ok.json");
  ASSERT_EQ(s.bodies.size(), 2u);
  EXPECT_TRUE(s.bodies[1].is_rigid_structure());
  EXPECT_DOUBLE_EQ(s.bodies[1].interface_friction_angle, 20.0);
  EXPECT_DOUBLE_EQ(s.bodies[1].motion.centre[1], 0.6);  // default reference point: the box centre
}

TEST(SceneInput, StructureOverlappingSoilIsRejected) {
  auto j = soil_structure_scene();
  j["bodies"][1]["max"] = {0.1, 1.2};
  expect_error(j, "bodies[1]", "overlaps the soil body bodies[0]");
}

TEST(SceneInput, StructureOutsideTheDomainIsRejected) {
  auto j = soil_structure_scene();
  j["bodies"][1]["min"] = {-0.6, 0};
  expect_error(j, "bodies[1]", "extends outside the domain along x");
  j = soil_structure_scene();
  j["bodies"][1]["motion"]["velocity"] = {-1.0, 0};  // 1 m to the left within time.end
  expect_error(j, "bodies[1].motion", "carries the structure outside the domain along x");
}

TEST(SceneInput, StructureNeedsInterfaceFrictionAndAStructuralMaterial) {
  auto j = soil_structure_scene();
  j["bodies"][1].erase("interface_friction_angle");
  expect_error(j, "bodies[1].interface_friction_angle", "is required for a structure in a scene with soil");
  j = soil_structure_scene();
  j["bodies"][1]["interface_friction_angle"] = 95;
  expect_error(j, "interface_friction_angle", "[0, 90)");
  j = soil_structure_scene();
  j["bodies"][1]["material"] = "sand";
  expect_error(j, "structure", "needs a linear_elastic or von_mises material");
  j = soil_structure_scene();
  j["materials"]["steel"] = json::parse(R"({"model": "von_mises", "density": 7800, "young_modulus": 2e8,
                                             "poisson_ratio": 0.3, "yield_stress": -1})");
  expect_error(j, "yield_stress", "");
  j = soil_structure_scene();
  j["bodies"][1]["fixed"] = true;
  expect_error(j, "motion", "cannot be combined with \"fixed\"");
}

// A wall block with a velocity ramp starts at rest and reaches its velocity with the smooth start of
// Adami et al. (2012, eq. 33): after the ramp it has travelled v (t - ramp/2) (the ramp's mean is 1/2).
TEST(SceneInput, WallBlockRampStartsFromRest) {
  nlohmann::json j = nlohmann::json::parse(R"({
    "name": "piston", "dimension": 2, "dx": 0.02,
    "domain": {"min": [0, -0.2], "max": [0.2, 0.6], "periodic": ["x"]},
    "gravity": [0, 0], "time": {"end": 0.3},
    "materials": {"water": {"model": "tait_fluid", "density": 1000, "sound_speed": 20}},
    "bodies": [{"material": "water", "shape": "box", "min": [0, 0.1], "max": [0.2, 0.3]}],
    "walls": {"type": "dummy", "blocks": [{"min": [0, -0.1], "max": [0.2, 0.0], "velocity": [0, 0.01], "ramp": 0.1}]}
  })");
  geosph::Simulation sim(geosph::parse_scene(j, "piston.json"));
  const auto& P0 = sim.particles();
  std::size_t b = P0.size();
  for (std::size_t i = 0; i < P0.size(); ++i)
    if (P0.kind[i] == geosph::Kind::DummyWall) { b = i; break; }
  ASSERT_LT(b, P0.size());
  const double y0 = P0.y[b];
  EXPECT_EQ(P0.vy[b], 0.0);
  sim.run();
  EXPECT_NEAR(sim.particles().y[b] - y0, 0.01 * (0.3 - 0.05), 1e-7);
  EXPECT_DOUBLE_EQ(sim.particles().vy[b], 0.01);
  j["walls"]["blocks"][0]["ramp"] = -1;
  EXPECT_THROW(geosph::parse_scene(j, "piston.json"), geosph::InputError);
}

// A body's initial velocity reaches every particle, also the top row that carries a surcharge (the
// surcharge once took the place of the "not fixed" branch and left the top row at rest).
TEST(SceneInput, SurchargedBodyKeepsItsInitialVelocity) {
  nlohmann::json j = nlohmann::json::parse(R"({
    "name": "block", "dimension": 2, "dx": 0.05,
    "domain": {"min": [0, 0], "max": [1, 1], "periodic": ["x"]},
    "gravity": [0, 0], "time": {"end": 0.2},
    "materials": {"clay": {"model": "linear_elastic", "density": 2000, "young_modulus": 1e6, "poisson_ratio": 0.3}},
    "bodies": [{"material": "clay", "shape": "box", "min": [0, 0.2], "max": [1, 0.5], "velocity": [0.1, 0],
                "surcharge": {"pressure": 100, "ramp": 0.1}}]
  })");
  geosph::Simulation sim(geosph::parse_scene(j, "block.json"));
  const auto& P = sim.particles();
  int top = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != geosph::Kind::Soil) continue;
    EXPECT_DOUBLE_EQ(P.vx[i], 0.1) << "particle at y = " << P.y[i];
    if (P.y[i] > 0.45) ++top;
  }
  EXPECT_EQ(top, 20);
}

// Documents no parser should accept and resources no machine has (issue 20): through the command
// line, each gets one message naming the file and the field, exit code 2 and no output directory.
namespace {
struct BadScene {
  std::string name, text, message;
};

std::string with(const std::string& key_value) {  // valid_scene() with one more top-level member
  std::string t = valid_scene().dump(1);
  return t.insert(1, key_value + ",");
}

std::vector<BadScene> bad_scenes() {
  json overlap = valid_scene(), in_wall = valid_scene(), many = valid_scene(), huge = valid_scene();
  overlap["bodies"].push_back({{"material", "water"}, {"shape", "box"}, {"min", {0.1, 0.1}}, {"max", {0.3, 0.3}}});
  in_wall["bodies"][0]["min"] = {-0.05, 0.0};
  many["dx"] = 2e-7;
  huge["domain"] = {{"min", {-1e5, -1e5}}, {"max", {1e5, 1e5}}};
  std::string deep = "[";
  for (int k = 0; k < 200000; ++k) deep += "[";
  for (int k = 0; k <= 200000; ++k) deep += "]";
  return {
      {"deep", with("\"extra\": " + deep), "scene.json: nested deeper than 64 levels (below 'extra[] x 63')"},
      {"overflow", with("\"gravity_scale\": 1e309"), "scene.json: [json.exception.out_of_range.406] number overflow"},
      {"duplicate", with("\"dx\": 0.03"), "scene.json: field 'dx': given twice in the same object"},
      {"particles", many.dump(), "scene.json: field 'dx': dx = 2e-07 m creates about 1e+12 particles, more than the limit"},
      {"domain", huge.dump(), "scene.json: field 'domain': the domain spans about 3.91e+13 neighbour-search cells"},
      {"overlap", overlap.dump(), "scene.json: field 'bodies[1]': overlaps bodies[0]"},
      {"in_wall", in_wall.dump(), "scene.json: field 'bodies[0]': reaches into the wall layers of walls.containers[0] (its left side"},
  };
}
}  // namespace

TEST(SceneInput, CommandLineRefusesDocumentsAndSizesItCannotHandle) {
  for (const auto& bad : bad_scenes()) {
    const fs::path dir = fs::temp_directory_path() / ("geosph_cli_" + bad.name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "scene.json") << bad.text;
    const fs::path out = dir / "out", err = dir / "stderr.txt";
    const std::string cmd = std::string(GEOSPH_EXE) + " run " + (dir / "scene.json").string() + " --out " + out.string() +
                            " --quiet 2> " + err.string();
    const int status = std::system(cmd.c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2) << bad.name << ": status " << status;
    EXPECT_FALSE(fs::exists(out)) << bad.name << ": output directory left behind";
    std::stringstream msg;
    msg << std::ifstream(err).rdbuf();
    EXPECT_NE(msg.str().find(bad.message), std::string::npos) << bad.name << ": " << msg.str();
  }
}

// An output directory holding an earlier run is refused (never mixed); --overwrite replaces that run's
// files and keeps the user's own.
TEST(SceneInput, CommandLineRefusesAnEarlierRunsOutputUnlessOverwrite) {
  const fs::path dir = fs::temp_directory_path() / "geosph_cli_existing_out";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "scene.json") << valid_scene().dump(1);
  const fs::path out = dir / "out", err = dir / "stderr.txt";
  const std::string run = std::string(GEOSPH_EXE) + " run " + (dir / "scene.json").string() + " --out " + out.string() +
                          " --quiet 2> " + err.string();
  ASSERT_EQ(std::system(run.c_str()), 0);
  std::ofstream(out / "notes.txt") << "mine";
  fs::rename(out / "particles_000001.h5", out / "particles_000009.h5");  // a file no new run writes
  const int again = std::system(run.c_str());
  EXPECT_TRUE(WIFEXITED(again) && WEXITSTATUS(again) == 2);
  std::stringstream msg;
  msg << std::ifstream(err).rdbuf();
  EXPECT_NE(msg.str().find("the directory exists and is not empty"), std::string::npos) << msg.str();
  EXPECT_TRUE(fs::exists(out / "particles_000009.h5")) << "a refused run must not touch the directory";
  ASSERT_EQ(std::system((run + " --overwrite").c_str()), 0);
  EXPECT_FALSE(fs::exists(out / "particles_000009.h5")) << "the earlier run's snapshot was kept next to the new ones";
  EXPECT_TRUE(fs::exists(out / "particles_000001.h5"));
  EXPECT_TRUE(fs::exists(out / "notes.txt")) << "--overwrite removed a file GeoSPH did not write";
}

// A container's sides by axis: in 3D "top" and "bottom" are along z (gravity -z), "front" and "back"
// along y; an open side has no wall layers and needs no room in the domain; 2D containers have no
// front or back.
TEST(SceneInput, ContainerSidesByAxis) {
  auto j = nlohmann::json::parse(R"({
    "name": "box3", "dimension": 3, "dx": 0.1,
    "domain": {"min": [-0.5, -0.5, -0.5], "max": [1.5, 1.5, 1.05]},
    "gravity": [0, 0, -9.81], "time": {"end": 0.001},
    "materials": {"water": {"model": "tait_fluid", "density": 1000, "sound_speed": 20}},
    "bodies": [{"material": "water", "shape": "box", "min": [0, 0, 0], "max": [1, 1, 0.5]}],
    "walls": {"type": "dummy", "containers": [{"min": [0, 0, 0], "max": [1, 1, 1], "open": ["top"]}]}
  })");
  const auto P = geosph::build_particles(geosph::parse_scene(j, "box3.json"));
  double z_max = -1, y_max = -1;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (geosph::is_wall(P.kind[i])) { z_max = std::max(z_max, P.z[i]); y_max = std::max(y_max, P.y[i]); }
  EXPECT_LT(z_max, 1.0);  // no lid: the open top is the z side (its layers would not fit the domain)
  EXPECT_GT(y_max, 1.0);  // the back wall (y max) is closed
  j["walls"]["containers"][0]["open"] = {"back"};
  geosph::test::expect_scene_error(j, "'walls.containers[0]'", "extend outside the domain along z");
  auto j2 = geosph::test::soil_column_scene();
  j2["walls"]["containers"][0]["open"] = {"top", "front"};
  geosph::test::expect_scene_error(j2, "'walls.containers[0].open'", "\"front\" is a side of a 3D container");
}
