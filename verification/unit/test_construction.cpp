// Construction and excavation stages (sim/construction.hpp): an excavation removes exactly the soil
// lattice points inside its shape at its time, a placed body appears at its time with its own count,
// both with unique particle ids; with gravity_loading.after_construction the column settles again
// after each event; a restart after an event continues with the changed particle set; bad input and
// a placement onto existing particles are refused naming the field.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "io/scene.hpp"
#include "sim/checkpoint.hpp"
#include "sim/simulation.hpp"
#include "soil/soil_fields.hpp"
#include "test_scenes.hpp"

using namespace geosph;
using nlohmann::json;

namespace {

// A 1 m x 4 m elastic column loaded from rest; a 1 m layer placed on it at 0.01 s and its top 2 m
// excavated at 0.02 s.
json staged_column() {
  return json::parse(R"({
    "name": "staged_column", "dimension": 2, "dx": 0.1,
    "domain": {"min": [-0.5, -0.5], "max": [1.5, 6.5]},
    "gravity": [0, -9.81],
    "time": {"end": 0.03},
    "materials": {"soil": {"model": "linear_elastic", "density": 2000, "young_modulus": 1e7, "poisson_ratio": 0.3}},
    "bodies": [{"material": "soil", "shape": "box", "min": [0, 0], "max": [1, 4]},
               {"material": "soil", "shape": "box", "min": [0, 4], "max": [1, 5], "placed_at": 0.01}],
    "excavations": [{"time": 0.02, "shape": {"type": "box", "min": [-0.2, 3], "max": [1.2, 6]}}],
    "walls": {"type": "dummy", "slip": "free_slip", "containers": [{"min": [0, 0], "max": [1, 6], "open": ["top"]}]},
    "gravity_loading": {"model": "elastic", "ramp": 0.5, "max_time": 20, "after_construction": true}
  })");
}

double soil_mass(const Particles& P) {
  double m = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::Soil) m += P.m[i];
  return m;
}

bool ids_unique(const Particles& P) { return std::set<std::int64_t>(P.id.begin(), P.id.end()).size() == P.size(); }

}  // namespace

// Without settling: the counts and masses at each event are the lattice's exactly (10 x 10 placed,
// 10 x 20 excavated), the events happen at their times, and the run reaches time.end.
TEST(Construction, EventsChangeTheParticleSetAtTheirTimes) {
  json j = staged_column();
  j.erase("gravity_loading");
  Simulation sim(parse_scene(j, "staged.json"));
  EXPECT_EQ(sim.soil_count(), 400u);
  ASSERT_EQ(sim.fills().size(), 2u);
  EXPECT_EQ(sim.fills()[1].particles, 100u);  // the placed body's fill is known from the start
  std::map<std::string, std::pair<double, std::size_t>> seen;  // event -> (time, soil count after)
  sim.run([&](const Simulation& s) {
    for (const auto& e : s.construction_log()) seen.try_emplace(e.what, std::make_pair(e.time, s.soil_count()));
  });
  EXPECT_NEAR(sim.time(), 0.03, 1e-12);
  ASSERT_EQ(sim.construction_log().size(), 2u);
  EXPECT_EQ(sim.construction_log()[0].what, "bodies[1]");
  EXPECT_EQ(sim.construction_log()[0].added, 100u);
  EXPECT_NEAR(seen["bodies[1]"].first, 0.01, 1e-12);  // the step is shortened to meet the event
  EXPECT_EQ(seen["bodies[1]"].second, 500u);
  EXPECT_EQ(sim.construction_log()[1].what, "excavations[0]");
  EXPECT_EQ(sim.construction_log()[1].removed, 200u);
  EXPECT_NEAR(seen["excavations[0]"].first, 0.02, 1e-12);
  EXPECT_EQ(sim.soil_count(), 300u);
  EXPECT_NEAR(soil_mass(sim.particles()), 2000.0 * 3.0, 1e-6);
  EXPECT_TRUE(ids_unique(sim.particles()));
  EXPECT_EQ(sim.construction_log()[1].settle_steps, 0);
}

// With after_construction the column settles after each event: velocities zero, and the elastic
// K0 = nu/(1 - nu) in the final 3 m column from 0.5 m above the floor to 1.5 m below the surface, the
// band test_gravity_loading checks (measured 0.997-1.001 at dx = 0.1 m; 1% as there, for the unbalanced
// force left at the stage's end; the next rows up are 2-4% off), and sigma_v = rho g d below the final
// surface (linear elasticity: the excavated column's stress is the 3 m column's; 2% as in
// test_gravity_loading, the cubic spline's 1% lattice-moment error).
TEST(Construction, SettlesAfterEachEvent) {
  Simulation sim(parse_scene(staged_column(), "staged.json"));
  sim.run();
  ASSERT_EQ(sim.construction_log().size(), 2u);
  for (const auto& e : sim.construction_log()) {
    EXPECT_TRUE(e.settled) << e.what;
    EXPECT_GE(e.settle_steps, 20) << e.what;
  }
  const Particles& P = sim.particles();
  const auto& sxx = P.field(SoilFields::xx), &syy = P.field(SoilFields::yy);
  std::map<long, std::pair<double, double>> rows;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Soil) continue;
    EXPECT_LT(std::abs(P.vy[i]), 1e-3) << "particle " << P.id[i];
    auto& row = rows[std::lround(P.y[i] / 0.1 - 0.5)];
    row.first += sxx[i];
    row.second += syy[i];
  }
  int checked = 0;
  for (const auto& [row, s] : rows) {
    const double y = (row + 0.5) * 0.1;
    if (y > 3.0 - 1.5 || y < 0.5) continue;
    EXPECT_NEAR(s.first / s.second / (0.3 / 0.7), 1.0, 0.01) << "row " << row;
    EXPECT_NEAR(-s.second / 10 / (2000 * 9.81 * (3.0 - y)), 1.0, 0.02) << "row " << row;  // 10 particles a row
    ++checked;
  }
  EXPECT_EQ(checked, 10);
}

// A checkpoint written after the excavation restores into a fresh simulation of the same scene (whose
// particle set is the one of t = 0) with the excavated set, and the events before it are not redone.
TEST(Construction, RestartAfterAnEventKeepsTheChangedSet) {
  json j = staged_column();
  j.erase("gravity_loading");
  Simulation sim(parse_scene(j, "staged.json"));
  sim.run({}, 0.025);
  ASSERT_EQ(sim.soil_count(), 300u);
  const auto dir = std::filesystem::temp_directory_path() / "geosph_construction_restart";
  std::filesystem::create_directories(dir);
  const auto file = dir / "checkpoint.h5";
  write_checkpoint(file, sim, provenance(sim.scene().hash), {{"index", json::array()}, {"next_out", 1.0}});
  Simulation again(parse_scene(j, "staged.json"));
  EXPECT_EQ(again.soil_count(), 400u);
  restore_checkpoint(file, again);
  EXPECT_EQ(again.particles().size(), sim.particles().size());
  again.run();
  sim.run();
  EXPECT_EQ(again.construction_log().size(), 0u);  // both events were before the checkpoint
  EXPECT_EQ(again.particles().size(), sim.particles().size());
  EXPECT_NEAR(again.time(), 0.03, 1e-12);
  std::filesystem::remove_all(dir);
}

TEST(Construction, PlacingOntoParticlesNamesTheField) {
  json j = staged_column();
  j.erase("gravity_loading");
  j["bodies"][1]["min"] = {0, 3.5};  // half inside the column
  j["bodies"][1]["max"] = {1, 4.5};
  Simulation sim(parse_scene(j, "staged.json"));
  try {
    sim.run();
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("staged.json: field 'bodies[1].placed_at': at t = 0.01"), std::string::npos) << e.what();
  }
}

TEST(Construction, BadStagesAreRefused) {
  json j = staged_column();
  j["excavations"][0]["time"] = 0.5;
  test::expect_scene_error(j, "'excavations[0].time'", "must not exceed time.end");
  j = staged_column();
  j["excavations"].push_back({{"time", 0.015}, {"shape", {{"type", "box"}, {"min", {0, 0}}, {"max", {1, 1}}}}});
  test::expect_scene_error(j, "'excavations[1].time'", "in time order");
  j = staged_column();
  j["excavations"][0]["shape"] = {{"type", "box"}, {"min", {7, 0}}, {"max", {8, 1}}};
  test::expect_scene_error(j, "'excavations[0].shape'", "outside the domain");
  j = staged_column();
  j["excavations"][0]["shape"] = {{"type", "box"}, {"min", {0.01, 0.01}}, {"max", {0.02, 0.02}}};
  test::expect_scene_error(j, "'excavations[0].shape'", "holds no lattice point");
  j = staged_column();
  j["bodies"][1]["placed_at"] = 1.0;
  test::expect_scene_error(j, "'bodies[1].placed_at'", "must not exceed time.end");
  j = staged_column();
  j["bodies"][1]["placed_at"] = 0;
  test::expect_scene_error(j, "'bodies[1].placed_at'", "must be");
  j = staged_column();
  j["excavations"][0]["depth"] = 1;
  test::expect_scene_error(j, "'excavations[0].depth'", "");
  j = staged_column();
  j.erase("excavations");
  j["bodies"].erase(1);
  test::expect_scene_error(j, "'gravity_loading.after_construction'", "no excavation and no placed body");
}
