// Mirror walls (boundary/mirror_wall.hpp): the images of a particle near a container face and near a
// corner (positions, the map's linear part for velocities), the multiple boundary tangents of a point
// near a polygon's corner and a cylindrical tank's floor edge with their corner type, the filter that
// keeps each image on the solid side its plane fills, the bounce of a particle that crossed a wall,
// and the scene checks.
#include <gtest/gtest.h>

#include <cmath>

#include "boundary/geometry.hpp"
#include "boundary/mirror_wall.hpp"
#include "io/scene.hpp"
#include "soil/soil_mirror_images.hpp"

using namespace geosph;
using nlohmann::json;

namespace {

// A 2D tank of the given walls holding a square of water [lo, hi]^2.
json mirror_tank(const json& walls, double lo = 0.2, double hi = 0.8) {
  json j = json::parse(R"({
    "name": "tank", "dimension": 2, "dx": 0.05,
    "kernel": {"type": "wendland_c2"},
    "domain": {"min": [-0.3, -0.3], "max": [1.3, 1.3]},
    "time": {"end": 0.01},
    "materials": {"water": {"model": "tait_fluid", "density": 1000, "sound_speed": 20}},
    "bodies": [{"material": "water", "shape": "box", "min": [0.2, 0.2], "max": [0.8, 0.8]}]
  })");
  j["walls"] = walls;
  j["bodies"][0]["min"] = {lo, lo};
  j["bodies"][0]["max"] = {hi, hi};
  return j;
}

bool near(const std::array<double, 3>& a, double x, double y, double z = 0) {
  return std::abs(a[0] - x) < 1e-12 && std::abs(a[1] - y) < 1e-12 && std::abs(a[2] - z) < 1e-12;
}

}  // namespace

TEST(MirrorWall, ImagesAcrossAFaceAndThroughACorner) {
  const Scene s = parse_scene(mirror_tank(json::parse(R"({"type": "mirror", "slip": "free_slip",
      "containers": [{"min": [0, 0], "max": [1, 1.25], "open": ["top"]}]})")), "ok.json");
  const MirrorWalls walls(s);
  MirrorSet set;
  // support 2 h = 2.6 dx = 0.13: a particle 0.05 above the floor, far from the sides, has one image
  const double x1[3] = {0.5, 0.05, 0};
  walls.images(x1, set);
  ASSERT_EQ(set.images.size(), 1u);
  EXPECT_TRUE(near(set.images[0].apply(x1), 0.5, -0.05));
  const double v[3] = {0.3, -0.2, 0};
  EXPECT_TRUE(near(set.images[0].rotate(v), 0.3, 0.2));  // free slip: the normal velocity reverses
  EXPECT_TRUE(set.images[0].free_slip);
  // near the lower left corner: the two faces and the corner's double mirror
  const double x2[3] = {0.03, 0.07, 0};
  walls.images(x2, set);
  ASSERT_EQ(set.images.size(), 3u);
  int found = 0;
  for (const auto& T : set.images) {
    const auto y = T.apply(x2);
    found += near(y, -0.03, 0.07) + 2 * near(y, 0.03, -0.07) + 4 * near(y, -0.03, -0.07);
    EXPECT_TRUE(near(T.apply(y.data()), 0.03, 0.07));  // each map is its own inverse
  }
  EXPECT_EQ(found, 7);
  // the open top has no image; the centre none at all
  const double x3[3] = {0.5, 1.2, 0}, x4[3] = {0.5, 0.5, 0};
  walls.images(x3, set);
  EXPECT_TRUE(set.images.empty());
  walls.images(x4, set);
  EXPECT_TRUE(set.images.empty());
}

TEST(MirrorWall, MultipleTangentsAtAPolygonCornerKeepEachImageOnItsSide) {
  // a tank of a 45-degree slope meeting the floor at (0.4, 0): the water is in a 135-degree corner,
  // the solid concave around it
  const Scene s = parse_scene(mirror_tank(json::parse(R"({"type": "mirror", "boundaries": [{"shape":
      {"type": "difference", "parts": [{"type": "box", "min": [-0.2, -0.2], "max": [1.2, 1.2]},
       {"type": "polygon", "vertices": [[0, 0], [0.4, 0], [1.1, 0.7], [0, 0.7]]}]}}]})"), 0.1, 0.3), "ok.json");
  const MirrorWalls walls(s);
  MirrorSet set;
  const double x[3] = {0.38, 0.03, 0};
  walls.images(x, set);
  ASSERT_EQ(set.planes.size(), 2u);  // the floor and the slope
  ASSERT_EQ(set.images.size(), 2u);  // no double image at a 135-degree corner
  EXPECT_EQ(set.convex[1], 0);
  int floor = set.planes[0].n[1] > 0.99 ? 0 : 1, slope = 1 - floor;
  EXPECT_NEAR(set.planes[slope].n[0], -std::sqrt(0.5), 1e-9);  // out of the solid, into the water
  EXPECT_NEAR(set.planes[slope].n[1], std::sqrt(0.5), 1e-9);
  // the floor's image of a point above the floor, in front of the slope: kept
  const double y1[3] = {0.3, -0.02, 0};
  EXPECT_TRUE(set.keep(set.images[floor], y1));
  // a point behind both, deeper behind the slope than the floor: the slope fills it, not the floor
  const double y2[3] = {0.46, -0.01, 0};
  EXPECT_GT(set.planes[floor].side(y2), set.planes[slope].side(y2));
  EXPECT_FALSE(set.keep(set.images[floor], y2));
  EXPECT_TRUE(set.keep(set.images[slope], y2));
  // an image in front of its own plane is in the water: dropped
  const double y3[3] = {0.3, 0.02, 0};
  EXPECT_FALSE(set.keep(set.images[floor], y3));
}

TEST(MirrorWall, ConvexCornerOfASolidKeepsImagesInsideIt) {
  // water around a solid square post: near its corner the solid is behind both faces
  const Scene s = parse_scene(mirror_tank(json::parse(R"({"type": "mirror", "boundaries": [{"shape":
      {"type": "box", "min": [0.4, 0.9], "max": [0.6, 1.1]}}]})")), "ok.json");
  const MirrorWalls walls(s);
  MirrorSet set;
  const double x[3] = {0.63, 0.87, 0};
  walls.images(x, set);
  ASSERT_EQ(set.planes.size(), 2u);
  EXPECT_EQ(set.convex[1], 1);
  const int right = set.planes[0].n[0] > 0.99 ? 0 : 1;
  const double inside[3] = {0.57, 0.93, 0}, beside[3] = {0.57, 0.85, 0};  // the latter below the post
  EXPECT_TRUE(set.keep(set.images[right], inside));
  EXPECT_FALSE(set.keep(set.images[right], beside));
}

TEST(MirrorWall, CylindricalTankFloorEdgeHasTwoTangentsAndTheDoubleImage) {
  json j = mirror_tank(json::parse(R"({"type": "mirror", "boundaries": [{"shape": {"type": "difference", "parts": [
      {"type": "cylinder", "axis": "z", "centre": [0, 0, 0.12], "radius": 0.16, "length": 0.36},
      {"type": "cylinder", "axis": "z", "centre": [0, 0, 0.25], "radius": 0.1, "length": 0.5}]}}]})"));
  j["dimension"] = 3;
  j["dx"] = 0.01;
  j["domain"] = json::parse(R"({"min": [-0.2, -0.2, -0.1], "max": [0.2, 0.2, 0.4]})");
  j["bodies"] = json::parse(R"([{"material": "water", "shape": "box", "min": [-0.05, -0.05, 0], "max": [0.05, 0.05, 0.1]}])");
  const Scene s = parse_scene(j, "ok.json");
  const MirrorWalls walls(s);
  MirrorSet set;
  const double x[3] = {0.09, 0, 0.01};  // 0.01 from the mantle and from the floor
  walls.images(x, set);
  ASSERT_EQ(set.planes.size(), 2u);
  ASSERT_EQ(set.images.size(), 3u);
  EXPECT_EQ(set.convex[1], 0);
  EXPECT_TRUE(near(set.images[2].apply(x), 0.11, 0, -0.01));  // through the edge: mantle and floor
  // the mantle's tangent at a point off the x axis is the radial plane there
  const double x2[3] = {0.06, 0.06, 0.2};
  walls.images(x2, set);
  ASSERT_EQ(set.planes.size(), 1u);
  EXPECT_NEAR(set.planes[0].n[0], -std::sqrt(0.5), 1e-12);
  const double r = 0.1 / std::sqrt(2.0) * 2 - 0.06;  // reflected across the tangent at (0.0707, 0.0707)
  EXPECT_TRUE(std::abs(set.images[0].apply(x2)[0] - r) < 1e-12);
}

TEST(MirrorWall, ParticleThatCrossedAWallBouncesBack) {
  const Scene s = parse_scene(mirror_tank(json::parse(R"({"type": "mirror",
      "containers": [{"min": [0, 0], "max": [1, 1.25], "open": ["top"]}]})")), "ok.json");
  Particles P = build_particles(s);
  EXPECT_EQ(P.count(Kind::DummyWall), 0u);  // mirror walls have no particles
  P.x[0] = 0.3; P.y[0] = -0.01; P.vx[0] = 0.5; P.vy[0] = -1.0;
  const MirrorWalls walls(s);
  EXPECT_EQ(walls.reflect_crossings(P), 1u);
  EXPECT_NEAR(P.y[0], 0.01, 1e-15);
  EXPECT_EQ(P.vy[0], 1.0);
  EXPECT_EQ(P.vx[0], 0.5);
  EXPECT_EQ(walls.reflect_crossings(P), 0u);
}

TEST(MirrorWall, SceneChecks) {
  auto j = mirror_tank(json::parse(R"({"type": "mirror", "containers": [{"min": [0, 0], "max": [1, 1.25]}],
      "blocks": [{"min": [0.4, 0.9], "max": [0.6, 1.0]}]})"));
  try {
    parse_scene(j, "bad.json");
    FAIL() << "blocks with mirror walls accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("walls.blocks"), std::string::npos) << e.what();
  }
}

TEST(MirrorWall, ShapedWaterIsRelaxedAgainstItsSurface) {
  // water filling a round 2D tank (R/dx = 8): the lattice next to the circle crowds its images until
  // the packing evens it out, inside the circle
  auto j = mirror_tank(json::parse(R"({"type": "mirror", "boundaries": [{"shape": {"type": "difference", "parts": [
      {"type": "box", "min": [0.0, 0.0], "max": [1.0, 1.0]}, {"type": "circle", "centre": [0.5, 0.5], "radius": 0.4}]}}]})"));
  j["bodies"] = json::parse(R"([{"material": "water", "shape": {"type": "circle", "centre": [0.5, 0.5], "radius": 0.4}}])");
  const Scene s = parse_scene(j, "ok.json");
  std::vector<BodyFill> fills;
  const Particles P = build_particles(s, &fills);
  ASSERT_EQ(fills.size(), 1u);
  const RelaxationResult& r = fills[0].relaxation;
  EXPECT_GT(r.iterations, 0);
  EXPECT_LT(r.final_mean, 0.2 * r.initial_mean) << r.initial_mean << " -> " << r.final_mean;
  double outside = 0;
  for (std::size_t i = 0; i < P.size(); ++i) outside = std::max(outside, std::hypot(P.x[i] - 0.5, P.y[i] - 0.5) - 0.4);
  EXPECT_LE(outside, 0.0);
  // other wall types keep the lattice
  j["walls"]["type"] = "dummy";
  std::vector<BodyFill> lattice;
  build_particles(parse_scene(j, "ok.json"), &lattice);
  EXPECT_EQ(lattice[0].relaxation.iterations, 0);
}

TEST(MirrorWall, SoilStressAndVelocityOfAnImage) {
  const Scene s = parse_scene(mirror_tank(json::parse(R"({"type": "mirror", "slip": "free_slip",
      "containers": [{"min": [0, 0], "max": [1, 1.25], "open": ["top"]}]})")), "ok.json");
  const MirrorWalls walls(s);
  MirrorSet set;
  const double x[3] = {0.03, 0.07, 0};  // near the lower left corner
  walls.images(x, set);
  ASSERT_EQ(set.images.size(), 3u);
  const std::array<double, 6> sigma = {-1.0, -2.0, -0.5, 0.3, 0.0, 0.0};  // xx yy zz xy xz yz
  for (const auto& T : set.images) {
    const auto m = mirror_tensor(T, sigma);
    const bool both = T.R[0] < 0 && T.R[4] < 0;  // the corner's double mirror keeps every sign in 2D
    EXPECT_DOUBLE_EQ(m[0], -1.0);
    EXPECT_DOUBLE_EQ(m[1], -2.0);
    EXPECT_DOUBLE_EQ(m[3], both ? 0.3 : -0.3);  // a single mirror turns the wall's shear
  }
  MirrorImage copy = set.images[0];
  copy.free_slip = false;
  EXPECT_EQ(mirror_tensor(copy, sigma), sigma);  // no slip: the stress is copied
}

TEST(MirrorWall, SaturatedSoilIsRejected) {
  auto j = json::parse(R"({
    "name": "column", "dimension": 2, "dx": 0.05, "kernel": {"type": "wendland_c2"},
    "domain": {"min": [-0.3, -0.3], "max": [1.3, 1.3]}, "gravity": [0, -9.81], "time": {"end": 0.01},
    "materials": {"sand": {"model": "drucker_prager", "density": 2000, "young_modulus": 1e6, "poisson_ratio": 0.3,
                           "friction_angle": 30, "porosity": 0.4, "hydraulic_conductivity": 1e-3},
                  "water": {"model": "tait_fluid", "density": 1000, "sound_speed": 20}},
    "bodies": [{"material": "sand", "shape": "box", "min": [0, 0], "max": [1, 0.5]},
               {"material": "water", "shape": "box", "min": [0, 0], "max": [1, 0.5]}],
    "walls": {"type": "mirror", "containers": [{"min": [0, 0], "max": [1, 1], "open": ["top"]}]}
  })");
  try {
    parse_scene(j, "bad.json");
    FAIL() << "two-phase soil with mirror walls accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("two-phase"), std::string::npos) << e.what();
  }
}
