// Shear strength reduction (analysis/strength_reduction.hpp): the trial scene's strength is c/F and
// atan(tan(phi)/F) with the dilatancy capped, only for Drucker-Prager and Mohr-Coulomb materials; the
// slip surface is the base of a moving block; scenes the analysis cannot serve are refused naming the field.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/strength_reduction.hpp"
#include "io/scene.hpp"

using namespace geosph;
using nlohmann::json;

namespace {

json slope() {
  return json::parse(R"({
    "name": "slope", "dimension": 2, "dx": 0.5,
    "domain": {"min": [-3, -3], "max": [13, 9]},
    "gravity": [0, -9.81],
    "time": {"end": 0.01},
    "materials": {"soil": {"model": "mohr_coulomb", "density": 1800, "young_modulus": 2e7, "poisson_ratio": 0.45,
                           "friction_angle": 30, "cohesion": 10000, "dilatancy_angle": 20},
                  "plate": {"model": "von_mises", "density": 7800, "young_modulus": 2e11, "poisson_ratio": 0.3,
                            "yield_stress": 2.5e8}},
    "bodies": [{"material": "soil", "shape": {"type": "polygon", "vertices": [[0, 0], [10, 0], [10, 5], [5, 5], [0, 2.5]]}}],
    "walls": {"type": "dummy", "slip": "free_slip", "containers": [{"min": [0, 0], "max": [10, 6], "open": ["top"]}]},
    "gravity_loading": {"model": "material", "ramp": 0.5, "max_time": 5}
  })");
}

constexpr double kPi = 3.14159265358979323846;

}  // namespace

TEST(StrengthReduction, ReducesCohesionAndTanPhiOnly) {
  const json r = reduce_strength(slope(), 2.0);
  const auto& m = r["materials"]["soil"];
  EXPECT_DOUBLE_EQ(m["cohesion"].get<double>(), 5000.0);
  const double phi_f = std::atan(std::tan(30 * kPi / 180) / 2.0) * 180 / kPi;  // 16.10 deg
  EXPECT_NEAR(m["friction_angle"].get<double>(), phi_f, 1e-12);
  EXPECT_NEAR(m["dilatancy_angle"].get<double>(), phi_f, 1e-12);  // 20 deg capped at phi_F
  EXPECT_EQ(r["materials"]["plate"], slope()["materials"]["plate"]);  // a structure material is not reduced
  EXPECT_EQ(r["bodies"], slope()["bodies"]);
  // F < 1 strengthens; the dilatancy below phi_F stays
  const json s = reduce_strength(slope(), 0.5);
  EXPECT_DOUBLE_EQ(s["materials"]["soil"]["cohesion"].get<double>(), 20000.0);
  EXPECT_DOUBLE_EQ(s["materials"]["soil"]["dilatancy_angle"].get<double>(), 20.0);
  EXPECT_NO_THROW(parse_scene(r, "reduced.json"));
}

// A block of soil particles moving at 1 m/s above y = 2 m over a still layer: in every column the
// slip surface lies mid-way between the rows at 1.75 and 2.25 m.
TEST(StrengthReduction, SlipSurfaceIsTheBaseOfTheMovingMass) {
  Particles P;
  P.dim = 2;
  const double dx = 0.5;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 8; ++j) {
      P.add((i + 0.5) * dx, (j + 0.5) * dx, 0, 1, 1, Kind::Soil, 0);
      if ((j + 0.5) * dx > 2.0) P.vx.back() = 1.0;
    }
  P.add(0.25, -0.25, 0, 1, 1, Kind::DummyWall, 0);  // walls are not soil
  const auto line = slip_surface(P, dx);
  ASSERT_EQ(line.size(), 10u);  // 20 particle columns, 2 dx wide bins
  for (std::size_t k = 0; k < line.size(); ++k) {
    EXPECT_NEAR(line[k][0], (k + 0.5) * 2 * dx, 1e-12);
    EXPECT_NEAR(line[k][1], 2.0, 1e-12);
  }
  for (auto& v : P.vx) v = 0;
  EXPECT_TRUE(slip_surface(P, dx).empty());  // nothing moves: no surface
}

TEST(StrengthReduction, RefusesWhatItCannotServe) {
  const auto expect_error = [](const json& j, const StrengthReductionOptions& o, const std::string& what) {
    try {
      strength_reduction(j, "slope.json", o);
      ADD_FAILURE() << "no error for " << what;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  StrengthReductionOptions o;
  json j = slope();
  j.erase("gravity_loading");
  expect_error(j, o, "slope.json: field 'gravity_loading': strength reduction loads each trial");
  j = slope();
  j["gravity_loading"]["model"] = "elastic";
  j["materials"]["soil"] = {{"model", "linear_elastic"}, {"density", 1800}, {"young_modulus", 2e7}, {"poisson_ratio", 0.3}};
  j["materials"].erase("plate");
  expect_error(j, o, "slope.json: field 'gravity_loading.model': strength reduction needs \"material\"");
  j["gravity_loading"]["model"] = "material";
  expect_error(j, o, "slope.json: field 'materials': no drucker_prager or mohr_coulomb material");
  o.f_low = 2.0;
  o.f_high = 1.0;
  expect_error(slope(), o, "--f-low/--f-high: need 0 < f_low < f_high");
  o = {};
  o.displacement_limit = 0;
  expect_error(slope(), o, "--displacement-limit: must be > 0");
}
