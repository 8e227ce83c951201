// Balsara's switch of the soil's artificial viscosity (soil/viscosity_switch.hpp): its value for the
// basic flows, and the per-particle field a scene with the switch carries.
#include <gtest/gtest.h>

#include <algorithm>

#include "sim/simulation.hpp"
#include "soil/soil_fields.hpp"
#include "soil/viscosity_switch.hpp"
#include "test_scenes.hpp"

using namespace geosph;

namespace {
constexpr double c = 20.0, h = 0.005;  // 1e-4 c / h = 0.4 1/s
}

TEST(ViscositySwitch, OffInShearAndRotationOnInCompression) {
  const double shear[3][3] = {{0, 10, 0}, {0, 0, 0}, {0, 0, 0}};  // simple shear, 10 1/s
  EXPECT_DOUBLE_EQ(balsara_switch(shear, c, h), 0.0);
  const double spin[3][3] = {{0, -5, 0}, {5, 0, 0}, {0, 0, 0}};  // rigid rotation
  EXPECT_DOUBLE_EQ(balsara_switch(spin, c, h), 0.0);
  const double squeeze[3][3] = {{-5, 0, 0}, {0, -5, 0}, {0, 0, 0}};  // div v = -10 1/s
  EXPECT_NEAR(balsara_switch(squeeze, c, h), 10.0 / 10.4, 1e-15);
  const double stretch[3][3] = {{5, 0, 0}, {0, 5, 0}, {0, 0, 5}};  // |div v| counts, not its sign
  EXPECT_NEAR(balsara_switch(stretch, c, h), 15.0 / 15.4, 1e-15);
  // shear with compression: |div| / (|div| + |curl| + eps), curl = 10 1/s
  const double both[3][3] = {{-5, 10, 0}, {0, -5, 0}, {0, 0, 0}};
  EXPECT_NEAR(balsara_switch(both, c, h), 10.0 / 20.4, 1e-15);
  const double rest[3][3] = {};
  EXPECT_DOUBLE_EQ(balsara_switch(rest, c, h), 0.0);
}

// A collapsing Drucker-Prager column with the switch carries the field, in [0, 1], below 1 where it
// shears; without the switch the field is not allocated.
TEST(ViscositySwitch, SceneWithTheSwitchCarriesItPerParticle) {
  auto j = test::soil_column_scene(0.01);
  j["time"]["end"] = 0.05;
  {
    Simulation plain(parse_scene(j, "plain.json"));
    EXPECT_FALSE(plain.particles().has_field(SoilFields::viscosity_switch));
  }
  j["materials"]["sand"]["artificial_viscosity_switch"] = "balsara";
  Simulation sim(parse_scene(j, "switch.json"));
  sim.run();
  const Particles& P = sim.particles();
  ASSERT_TRUE(P.has_field(SoilFields::viscosity_switch));
  const auto& f = P.field(SoilFields::viscosity_switch);
  double lo = 1, hi = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Soil) continue;
    EXPECT_GE(f[i], 0.0);
    EXPECT_LE(f[i], 1.0);
    lo = std::min(lo, f[i]);
    hi = std::max(hi, f[i]);
  }
  EXPECT_LT(lo, 0.5);  // the shearing flank
  EXPECT_GT(hi, lo);
}
