// Morris no-slip walls (boundary/morris_wall.hpp): the extrapolated velocity factor against its
// formula, the depth and normal each wall particle carries, and the scenes that may not use them.
#include <gtest/gtest.h>

#include <cmath>

#include "boundary/geometry.hpp"
#include "boundary/morris_wall.hpp"
#include "boundary/body_fields.hpp"
#include "test_scenes.hpp"

using namespace geosph;
using nlohmann::json;

namespace {

json morris_channel() {
  return json::parse(R"({
    "name": "channel", "dimension": 2, "dx": 0.1,
    "kernel": {"type": "wendland_c2"},
    "domain": {"min": [-0.5, -0.5], "max": [1.5, 1.5]},
    "time": {"end": 0.01},
    "materials": {"water": {"model": "tait_fluid", "density": 1000, "sound_speed": 10, "kinematic_viscosity": 1e-3}},
    "bodies": [{"material": "water", "shape": "box", "min": [0, 0], "max": [1, 0.5]}],
    "walls": {"type": "morris", "layers": 3,
              "containers": [{"min": [0, 0], "max": [1, 1], "open": ["top"]}],
              "blocks": [{"min": [0.4, 0.6], "max": [0.6, 0.9]}]}
  })");
}

}  // namespace

// beta = min(1.5, 1 + d_b / d_a) (Morris, Fox & Zhu 1997): with it the velocity interpolated linearly
// between the fluid particle (v_a) and the wall particle (v_b = v_a - beta v_a) vanishes on the surface.
TEST(MorrisWall, VelocityFactorIsTheCappedExtrapolation) {
  EXPECT_DOUBLE_EQ(morris_velocity_factor(4.0, 1.0), 1.25);
  EXPECT_DOUBLE_EQ(morris_velocity_factor(2.0, 1.0), 1.5);
  EXPECT_DOUBLE_EQ(morris_velocity_factor(1.0, 1.0), 1.5);   // capped
  EXPECT_DOUBLE_EQ(morris_velocity_factor(0.0, 1.0), 1.5);   // on the surface
  EXPECT_DOUBLE_EQ(morris_velocity_factor(-0.1, 1.0), 1.5);  // behind it
  for (const double da : {2.5, 3.0, 7.0}) {
    const double db = 1.0, va = 0.3, vb = va - morris_velocity_factor(da, db) * va;
    EXPECT_NEAR(va + (vb - va) * da / (da + db), 0.0, 1e-15) << "d_a = " << da;
  }
}

// A container's wall particles: depth behind the nearest point of the inner box and the unit vector to
// it (a corner's diagonal); a block's: depth below the nearest face and its outward normal.
TEST(MorrisWall, WallParticlesCarryDepthAndNormal) {
  const Scene s = parse_scene(morris_channel(), "ok.json");
  const Particles P = build_particles(s);
  const double* d = P.find(WallSurfaceFields::depth);
  const double* nx = P.find(BodyFields::wall_nx);
  const double* ny = P.find(BodyFields::wall_ny);
  ASSERT_TRUE(d && nx && ny);
  int bottom = 0, corner = 0, block = 0, fluid = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double x = P.x[i], y = P.y[i];
    if (P.kind[i] == Kind::Fluid) {
      EXPECT_EQ(d[i], 0.0);
      ++fluid;
      continue;
    }
    if (x > 0 && x < 1 && y < 0) {  // below the floor
      EXPECT_NEAR(d[i], -y, 1e-12);
      EXPECT_NEAR(nx[i], 0.0, 1e-12);
      EXPECT_NEAR(ny[i], 1.0, 1e-12);
      ++bottom;
    } else if (std::abs(x + 0.05) < 1e-9 && std::abs(y + 0.15) < 1e-9) {  // the lower-left corner
      EXPECT_NEAR(d[i], std::hypot(0.05, 0.15), 1e-12);
      EXPECT_NEAR(nx[i], 0.05 / std::hypot(0.05, 0.15), 1e-12);
      EXPECT_NEAR(ny[i], 0.15 / std::hypot(0.05, 0.15), 1e-12);
      ++corner;
    } else if (std::abs(x - 0.45) < 1e-9 && std::abs(y - 0.75) < 1e-9) {  // block, 0.05 from its left face
      EXPECT_NEAR(d[i], 0.05, 1e-12);
      EXPECT_NEAR(nx[i], -1.0, 1e-12);
      EXPECT_NEAR(ny[i], 0.0, 1e-12);
      ++block;
    }
    EXPECT_GT(d[i], 0.0);
    EXPECT_NEAR(std::hypot(nx[i], ny[i]), 1.0, 1e-12);
  }
  EXPECT_EQ(bottom, 30);  // 10 columns x 3 layers
  EXPECT_EQ(corner, 1);
  EXPECT_EQ(block, 1);
  EXPECT_EQ(fluid, 50);
}

TEST(MorrisWall, FreeSlipAndSoilAreRejected) {
  json j = morris_channel();
  j["walls"]["slip"] = "free_slip";
  test::expect_scene_error(j, "walls.slip", "Morris walls (walls.type \"morris\") are no-slip walls");
  j = morris_channel();
  j["walls"]["containers"][0]["slip"] = "free_slip";
  test::expect_scene_error(j, "walls.containers[0].slip", "no-slip walls");
  j = test::soil_column_scene();
  j["walls"]["type"] = "morris";
  test::expect_scene_error(j, "walls.type", "soil needs dummy, ghost or mirror walls");
  j = morris_channel();
  j["walls"]["type"] = "image";
  test::expect_scene_error(j, "walls.type", "must be one of {dummy, repulsive, morris, ghost, mirror}");
}
