// A run that goes unstable stops with a diagnosis naming step, time, particle and quantity.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "io/scene.hpp"
#include "sim/simulation.hpp"
#include "soil/soil_fields.hpp"
#include "test_scenes.hpp"

using namespace geosph;
namespace fs = std::filesystem;

namespace {
nlohmann::json tank_scene(double max_density_variation) {
  auto j = nlohmann::json::parse(R"({
    "name": "tank", "dimension": 2, "dx": 0.02,
    "domain": {"min": [-0.1, -0.1], "max": [0.5, 0.5]},
    "gravity": [0, -9.81],
    "time": {"end": 0.5},
    "materials": {"water": {"model": "tait_fluid", "density": 1000, "sound_speed": 20,
                            "artificial_viscosity": 0.02}},
    "bodies": [{"material": "water", "shape": "box", "min": [0, 0], "max": [0.2, 0.2]}],
    "walls": {"type": "dummy", "containers": [{"min": [0, 0], "max": [0.3, 0.3], "open": ["top"]}]}
  })");
  j["numerics"] = {{"max_density_variation", max_density_variation}};
  return j;
}
}  // namespace

TEST(Stability, NonFiniteVelocityIsDiagnosed) {
  Simulation sim(parse_scene(tank_scene(0.5), "tank.json"));
  Particles& P = sim.particles();
  std::size_t k = 0;
  while (P.kind[k] != Kind::Fluid) ++k;
  const auto id = P.id[k];
  P.vx[k] = std::nan("");
  try {
    sim.step();
    FAIL() << "no instability reported";
  } catch (const InstabilityError& e) {
    EXPECT_EQ(e.diagnosis.step, 1);
    EXPECT_EQ(e.diagnosis.particle_id, id);
    EXPECT_NE(e.diagnosis.quantity.find("not finite"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("particle id " + std::to_string(id)), std::string::npos);
  }
}

// Released from rest under gravity, the bottom particles compress by ~rho g H / (rho0 c0^2)
// = 0.5%; with a 0.1% density bound the run must stop with a density diagnosis.
TEST(Stability, DensityBlowUpIsDiagnosed) {
  Simulation sim(parse_scene(tank_scene(0.001), "tank.json"));
  try {
    sim.run();
    FAIL() << "no instability reported";
  } catch (const InstabilityError& e) {
    EXPECT_GT(e.diagnosis.step, 0);
    EXPECT_GT(e.diagnosis.time, 0.0);
    EXPECT_NE(e.diagnosis.quantity.find("density ratio"), std::string::npos) << e.what();
  }
}

TEST(Stability, CommandLineWritesDiagnosisAndExitsWithCode3) {
  const fs::path dir = fs::temp_directory_path() / "geosph_cli_unstable";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "scene.json") << tank_scene(0.001).dump(2);
  const std::string cmd = std::string(GEOSPH_EXE) + " run " + (dir / "scene.json").string() + " --out " +
                          (dir / "out").string() + " --quiet 2> " + (dir / "stderr.txt").string();
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 3);
  std::stringstream d;
  d << std::ifstream(dir / "out" / "diagnosis.txt").rdbuf();
  EXPECT_NE(d.str().find("simulation unstable at step"), std::string::npos) << d.str();
  EXPECT_NE(d.str().find("density ratio"), std::string::npos) << d.str();
}

TEST(Stability, StableRunWritesHdf5AndXdmf) {
  const fs::path dir = fs::temp_directory_path() / "geosph_cli_stable";
  fs::remove_all(dir);
  fs::create_directories(dir);
  auto j = tank_scene(0.5);
  j["time"]["end"] = 0.02;
  j["output"] = {{"interval", 0.01}};
  std::ofstream(dir / "scene.json") << j.dump(2);
  const std::string cmd = std::string(GEOSPH_EXE) + " run " + (dir / "scene.json").string() + " --out " +
                          (dir / "out").string() + " --quiet 2> " + (dir / "stderr.txt").string();
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  EXPECT_TRUE(fs::exists(dir / "out" / "particles.xdmf"));
  EXPECT_TRUE(fs::exists(dir / "out" / "particles_000000.h5"));
  EXPECT_TRUE(fs::exists(dir / "out" / "summary.json"));
  int snapshots = 0;
  for (const auto& e : fs::directory_iterator(dir / "out")) snapshots += e.path().extension() == ".h5";
  EXPECT_EQ(snapshots, 3);  // t = 0, 0.01, 0.02
  for (const auto& e : fs::directory_iterator(dir / "out")) EXPECT_NE(e.path().extension(), ".tmp");
}

TEST(Stability, NonFiniteSoilStressIsDiagnosed) {
  const auto j = geosph::test::soil_column_scene();
  Simulation sim(parse_scene(j, "column.json"));
  Particles& P = sim.particles();
  std::size_t k = 0;
  while (P.kind[k] != Kind::Soil) ++k;
  const auto id = P.id[k];
  P.field(SoilFields::xy)[k] = std::numeric_limits<double>::infinity();
  try {
    sim.step();
    FAIL() << "no instability reported";
  } catch (const InstabilityError& e) {
    EXPECT_EQ(e.diagnosis.particle_id, id) << e.what();
    EXPECT_NE(e.diagnosis.quantity.find("soil stress is not finite"), std::string::npos) << e.what();
  }
}

// A soil column at rest under gravity with its geostatic stress stays at rest: the dummy walls
// carry the stress (no particle deficiency at the floor) and the vertical stress at the floor
// stays rho g H within the kernel's discretisation error.
TEST(Stability, GeostaticSoilColumnStaysAtRest) {
  auto j = geosph::test::soil_column_scene(0.005);
  j["domain"] = {{"min", {-0.05, -0.05}}, {"max", {0.25, 0.2}}};
  j["time"]["end"] = 0.05;
  j["materials"]["sand"]["density"] = 2000;
  j["materials"]["sand"]["young_modulus"] = 5e6;
  j["materials"]["sand"]["friction_angle"] = 30;
  j["walls"]["containers"][0]["max"] = {0.2, 0.15};
  Simulation sim(parse_scene(j, "column.json"));
  sim.run();
  const Particles& P = sim.particles();
  double vmax = 0, syy_bottom = 0;
  int n_bottom = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Soil) continue;
    vmax = std::max(vmax, std::hypot(P.vx[i], P.vy[i]));
    if (P.y[i] < 0.005 && P.x[i] > 0.05 && P.x[i] < 0.15) { syy_bottom += P.extra_fields().at(SoilFields::yy)[i]; ++n_bottom; }
  }
  ASSERT_GT(n_bottom, 0);
  const double expect = -2000 * 9.81 * (0.1 - 0.0025);  // at the bottom row's centre
  // elastic settling speed scale: g t for t ~ H / c is ~0.02 m/s; a leaking wall would give ~ g t = 0.5 m/s
  EXPECT_LT(vmax, 0.05);
  EXPECT_NEAR(syy_bottom / n_bottom, expect, 0.05 * std::abs(expect));
}
