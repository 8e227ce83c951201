// Soil-structure contact (coupling/soil_structure_contact.hpp) and prescribed rigid motion
// (structure/rigid_motion.hpp): a stiff soil block on a rigid slab under tilted gravity slides with
// the Coulomb acceleration g (sin theta - tan delta cos theta) or sticks when tan delta > tan theta;
// a rigid body translated and rotated follows its prescribed path exactly.
#include "boundary/soil_wall.hpp"
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "coupling/soil_structure_contact.hpp"
#include "io/scene.hpp"
#include "sim/simulation.hpp"
#include "test_scenes.hpp"

using namespace geosph;
using nlohmann::json;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Block of stiff elastic "soil" resting on a rigid slab (held in place by a zero prescribed motion);
// gravity tilted by theta emulates an incline of angle theta.
Scene sliding_scene(double theta_deg, double delta_deg, double t_end) {
  const double g = 9.81, th = theta_deg * kDeg;
  json j = json::parse(R"({
    "name": "slide", "dimension": 2, "dx": 0.01,
    "domain": {"min": [-0.1, -0.1], "max": [1.2, 0.2]},
    "time": {"end": 0.2},
    "materials": {
      "block": {"model": "linear_elastic", "density": 2000, "young_modulus": 2e6, "poisson_ratio": 0.3},
      "slab": {"model": "linear_elastic", "density": 2000, "young_modulus": 2e6, "poisson_ratio": 0.3}
    },
    "bodies": [
      {"material": "block", "shape": "box", "min": [0, 0], "max": [0.1, 0.05]},
      {"material": "slab", "shape": "box", "min": [-0.05, -0.05], "max": [1.1, 0], "structure": true,
       "interface_friction_angle": 0, "motion": {"velocity": [0, 0]}}
    ]
  })");
  j["gravity"] = {g * std::sin(th), -g * std::cos(th)};
  j["time"]["end"] = t_end;
  j["bodies"][1]["interface_friction_angle"] = delta_deg;
  return parse_scene(j, "slide.json");
}

// A stiff elastic soil layer 0.3 m x 0.06 m at rest, without gravity, under a held rigid block 0.1 m
// wide standing on it, reaching beyond both of the block's lower corners (dx = 0.01).
Scene layer_under_block_scene(double t_end) {
  json j = json::parse(R"({
    "name": "layer_under_block", "dimension": 2, "dx": 0.01,
    "domain": {"min": [-0.2, -0.2], "max": [0.3, 0.2]},
    "materials": {
      "soil": {"model": "linear_elastic", "density": 2000, "young_modulus": 2e6, "poisson_ratio": 0.3},
      "block": {"model": "linear_elastic", "density": 2000, "young_modulus": 2e6, "poisson_ratio": 0.3}
    },
    "bodies": [
      {"material": "soil", "shape": "box", "min": [-0.1, -0.06], "max": [0.2, 0]},
      {"material": "block", "shape": "box", "min": [0, 0], "max": [0.1, 0.1], "structure": true,
       "interface_friction_angle": 0, "motion": {"velocity": [0, 0]}}
    ]
  })");
  j["time"] = {{"end", t_end}};
  return parse_scene(j, "layer_under_block.json");
}

double mean_soil_vx(const Simulation& sim) {
  const Particles& P = sim.particles();
  double s = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::Soil) { s += P.vx[i]; ++n; }
  return s / static_cast<double>(n);
}

}  // namespace

TEST(SoilStructureContact, BlockSlidesWithTheCoulombAcceleration) {
  const double theta = 30, delta = 15, t = 0.2;
  Simulation sim(sliding_scene(theta, delta, t));
  sim.run();
  const double a = 9.81 * (std::sin(theta * kDeg) - std::tan(delta * kDeg) * std::cos(theta * kDeg));
  // the block's own elastic settling and the contact's one-step closure delay sliding by a few steps
  EXPECT_NEAR(mean_soil_vx(sim), a * t, 0.03 * a * t);
  // the slab carries the block's weight normal to it and the friction force along it
  const auto F = SoilStructureContact::body_force(sim.particles(), 1);
  const double W = 2000 * 0.1 * 0.05 * 9.81;
  EXPECT_NEAR(-F[1], W * std::cos(theta * kDeg), 0.05 * W);
  EXPECT_NEAR(F[0], std::tan(delta * kDeg) * -F[1], 0.05 * W);
}

TEST(SoilStructureContact, FrictionHoldsTheBlockWhenDeltaExceedsTheSlope) {
  const double theta = 20, delta = 35, t = 0.2;
  Simulation sim(sliding_scene(theta, delta, t));
  sim.run();
  EXPECT_LT(std::abs(mean_soil_vx(sim)), 0.01 * 9.81 * std::sin(theta * kDeg) * t);
}

TEST(SoilStructureContact, SoilDoesNotPenetrateTheStructure) {
  Simulation sim(sliding_scene(0, 0, 0.2));
  sim.run();
  const Particles& P = sim.particles();
  double ymin = 1e9;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::Soil) ymin = std::min(ymin, P.y[i]);
  EXPECT_GT(ymin, 0.5 * 0.01 - 0.1 * 0.01);  // bottom row centre dx/2 above the slab, within 0.1 dx
}

// A soil layer at rest under a rigid block, without gravity, reaching beyond the block's convex
// corners: the corner particles' normals are diagonal, and the soil particle one spacing below each
// corner touches it without penetrating (a penetration counts at most as the centres' overlap); no
// force may arise. Without the cap those particles were pushed off at about 0.06 dx / dt per step.
TEST(SoilStructureContact, SoilAtAConvexCornerIsNotPushedOff) {
  Simulation sim(layer_under_block_scene(0.01));
  sim.run();
  const Particles& P = sim.particles();
  double vmax = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::Soil) vmax = std::max(vmax, std::hypot(P.vx[i], P.vy[i]));
  EXPECT_GT(sim.steps(), 20);
  EXPECT_LT(vmax, 1e-9);  // at rest to round-off: no contact force on a layer that only touches
}

// A soil layer moved 0.3 dx into a rigid block, without gravity: the contact pushes the penetrating
// soil out by position, beta |g| = 0.2 x 0.3 dx in the first step, and adds no momentum (a velocity
// bias -beta g/dt gave those particles 0.2 x 0.3 dx / dt and kept it after the penetration was gone);
// after 100 steps the penetration is gone.
TEST(SoilStructureContact, APenetrationIsPushedOutByPositionWithoutMomentum) {
  Simulation sim(layer_under_block_scene(1.0));
  const double dx = 0.01, depth = 0.003;
  {
    Particles& Q = sim.particles();  // the whole layer up into the block (scenes may not overlap)
    for (std::size_t i = 0; i < Q.size(); ++i)
      if (Q.kind[i] == Kind::Soil) Q.y[i] += depth;
  }
  const auto top_row_under_block = [&](const Particles& P, std::size_t i) {
    return P.kind[i] == Kind::Soil && P.y[i] > depth - dx && P.x[i] > 0.03 && P.x[i] < 0.07;
  };
  std::map<std::uint64_t, double> y0;  // by particle id (the step may reorder the particles)
  for (std::size_t i = 0; i < sim.particles().size(); ++i)
    if (top_row_under_block(sim.particles(), i)) y0[sim.particles().id[i]] = sim.particles().y[i];
  ASSERT_EQ(y0.size(), 4u);
  sim.step();
  const Particles& P = sim.particles();
  double py = 0, vmax = 0;
  std::size_t k = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Soil) continue;
    py += P.m[i] * P.vy[i];
    vmax = std::max(vmax, std::hypot(P.vx[i], P.vy[i]));
    if (y0.count(P.id[i])) {
      EXPECT_NEAR(P.y[i], y0[P.id[i]] - SoilStructureContact::kPenetrationRecovery * depth, 1e-6 * dx);  // full support along the block: the normal is vertical
      ++k;
    }
  }
  EXPECT_EQ(k, y0.size());
  EXPECT_EQ(py, 0.0);
  EXPECT_EQ(vmax, 0.0);  // no stress and no contact force yet: the step moved the particles, not their momentum
  for (int s = 0; s < 100; ++s) sim.step();
  double deepest = 0;  // the largest overlap dx - |x_soil - x_block| over soil-block pairs
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Soil) continue;
    for (std::size_t b = 0; b < P.size(); ++b)
      if (is_structure(P.kind[b])) deepest = std::max(deepest, dx - std::hypot(P.x[i] - P.x[b], P.y[i] - P.y[b]));
  }
  EXPECT_LT(deepest, 0.01 * dx);
}

TEST(RigidMotion, TranslationAndRotationFollowThePrescribedPath) {
  json j = json::parse(R"({
    "name": "rigid", "dimension": 2, "dx": 0.01,
    "domain": {"min": [-1, -1], "max": [1, 1]},
    "time": {"end": 0.5},
    "materials": {"steel": {"model": "linear_elastic", "density": 7800, "young_modulus": 2e8, "poisson_ratio": 0.3}},
    "bodies": [{"material": "steel", "shape": "box", "min": [-0.05, -0.2], "max": [0.05, 0.2], "structure": true,
                "motion": {"velocity": [0.2, 0], "angular_velocity": 0.5, "centre": [0, -0.2]}}]
  })");
  Simulation sim(parse_scene(j, "rigid.json"));
  const Particles& P0 = sim.particles();
  std::vector<std::array<double, 2>> x0(P0.size());
  for (std::size_t i = 0; i < P0.size(); ++i) x0[static_cast<std::size_t>(P0.id[i])] = {P0.x[i], P0.y[i]};
  sim.run();
  const double t = sim.time(), th = 0.5 * t;
  const Particles& P = sim.particles();
  double err = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const auto& q = x0[static_cast<std::size_t>(P.id[i])];
    const double rx = q[0], ry = q[1] + 0.2;  // relative to the centre (0, -0.2)
    const double ex = 0.2 * t + std::cos(th) * rx - std::sin(th) * ry, ey = -0.2 + std::sin(th) * rx + std::cos(th) * ry;
    err = std::max(err, std::hypot(P.x[i] - ex, P.y[i] - ey));
  }
  EXPECT_LT(err, 1e-9);
  EXPECT_NEAR(sim.rigid_motions()->rotation(0), th, 1e-12);
}

// A container's dummy particles that a structure covers (the floor under a retaining wall) are the
// structure's space, not an image of the soil: they leave the soil's sums (zero mass), while the
// floor under the soil keeps its ghost mass rho0 dx^2 (boundary/soil_wall.hpp).
TEST(SoilWalls, GhostsCoveredByAStructureLeaveTheSoilSums) {
  // the retaining-wall scene, its wall reaching 0.2 m into a dummy floor that runs on under it
  json j = test::soil_structure_scene();
  j["domain"] = {{"min", {-0.7, -0.5}}, {"max", {2.5, 1.7}}};
  j["time"]["end"] = 1e-4;
  j["bodies"][1]["min"] = {-0.2, -0.2};
  j["bodies"][1]["motion"]["velocity"] = {0, 0};
  j["walls"] = json::parse(R"({"type": "dummy", "slip": "free_slip",
                              "containers": [{"min": [-0.4, 0], "max": [2.0, 1.3], "open": ["left", "top"]}]})");
  Simulation sim(parse_scene(j, "covered.json"));
  sim.run();
  const Particles& P = sim.particles();
  const auto& m = P.field(SoilWallFields::m);  // the soil's ghost mass (boundary/soil_wall.hpp)
  int covered = 0, under_soil = 0, beside = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::DummyWall || P.y[i] > 0) continue;
    if (P.x[i] > -0.2 && P.x[i] < 0) {  // under the wall
      EXPECT_EQ(m[i], 0.0) << "floor ghost at (" << P.x[i] << ", " << P.y[i] << ") inside the wall";
      ++covered;
    } else if (P.x[i] > 0 && P.x[i] < 2.0) {
      EXPECT_NEAR(m[i], 1700 * 0.05 * 0.05, 1e-9);
      ++under_soil;
    } else if (P.x[i] < -0.2) {
      ++beside;  // left of the wall: no soil within reach, kept as a (stress-free) ghost
      EXPECT_GT(m[i], 0.0);
    }
  }
  EXPECT_GT(covered, 0);
  EXPECT_GT(under_soil, 0);
  EXPECT_GT(beside, 0);
}

// A structure standing on a dummy floor (a retaining wall on the ground): the floor particles adjacent to
// the structure and to no soil particle are its support, not an image of the soil, and leave the soil's
// sums; the floor under the soil, up to the wall's face, keeps its ghost mass (boundary/soil_wall.hpp).
TEST(SoilWalls, GhostsUnderAStructureStandingOnTheFloorLeaveTheSoilSums) {
  json j = test::soil_structure_scene();
  j["domain"] = {{"min", {-0.7, -0.5}}, {"max", {2.5, 1.7}}};
  j["time"]["end"] = 1e-4;
  j["bodies"][1]["min"] = {-0.2, 0.0};
  j["bodies"][1]["motion"]["velocity"] = {0, 0};
  j["walls"] = json::parse(R"({"type": "dummy", "slip": "no_slip",
                              "containers": [{"min": [-0.4, 0], "max": [2.0, 1.3], "open": ["left", "top"]}]})");
  const Scene scene = parse_scene(j, "standing.json");
  Simulation sim(scene);
  sim.run();
  const Particles& P = sim.particles();
  const auto& m = P.field(SoilWallFields::m);
  const double dx = 0.05;
  int under_wall = 0, under_soil = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::DummyWall || std::abs(P.y[i] + 0.5 * dx) > 1e-9) continue;  // the floor's top row
    // under the wall, within the support of the soil's corner particle (dx/2, dx/2)
    if (P.x[i] > -0.2 && P.x[i] < 0 && std::hypot(P.x[i] - 0.5 * dx, P.y[i] - 0.5 * dx) < scene.support()) {
      EXPECT_EQ(m[i], 0.0) << "floor ghost at (" << P.x[i] << ", " << P.y[i] << ") under the wall";
      ++under_wall;
    } else if (P.x[i] > 0 && P.x[i] < 2.0) {
      EXPECT_NEAR(m[i], 1700 * dx * dx, 1e-9) << "floor ghost at (" << P.x[i] << ", " << P.y[i] << ") under the soil";
      ++under_soil;
    }
  }
  EXPECT_GE(under_wall, 2);
  EXPECT_GT(under_soil, 0);
}
