// Total Lagrangian structures (structure/total_lagrangian.hpp): the deformation gradient is exact for
// an affine motion at every particle (edges and corners included), so the stress is Saint
// Venant-Kirchhoff's and a rigid rotation carries none; the forces conserve linear and angular
// momentum; an interior particle feels no net force in a uniform stress; the bonds follow the particles
// through a reordering; a material the formulation does not fit is refused with the field named.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <map>
#include <numbers>
#include <random>

#include "io/json_fields.hpp"
#include "io/scene.hpp"
#include "sim/simulation.hpp"
#include "soil/soil_fields.hpp"
#include "structure/total_lagrangian.hpp"

using namespace geosph;
using nlohmann::json;

namespace {

constexpr double kE = 2e6, kNu = 0.3, kRho = 1000;

// A free elastic plate 0.2 m x 0.1 m (dx = 0.01, 20 x 10 particles), total Lagrangian, no gravity.
json plate_json() {
  return json::parse(R"({
    "name": "plate", "dimension": 2, "dx": 0.01,
    "domain": {"min": [-0.5, -0.5], "max": [0.7, 0.6]},
    "gravity": [0, 0],
    "time": {"end": 0.01},
    "materials": {"steel": {"model": "linear_elastic", "density": 1000, "young_modulus": 2e6, "poisson_ratio": 0.3,
                            "artificial_viscosity": 0.0, "formulation": "total_lagrangian"}},
    "bodies": [{"material": "steel", "shape": "box", "min": [0, 0], "max": [0.2, 0.1], "structure": true}]
  })");
}

// Saint Venant-Kirchhoff Cauchy stress of F in plane strain.
Eigen::Matrix3d svk_cauchy(const Eigen::Matrix3d& F) {
  const double mu = kE / (2 * (1 + kNu)), lambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu));
  const Eigen::Matrix3d E = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
  const Eigen::Matrix3d S = lambda * E.trace() * Eigen::Matrix3d::Identity() + 2 * mu * E;
  return F * S * F.transpose() / F.determinant();
}

// Moves every particle to x = F X (X its position at the start).
void deform(Particles& P, const Eigen::Matrix3d& F) {
  const double* X = P.field(TotalLagrangianFields::reference[0]).data();
  const double* Y = P.field(TotalLagrangianFields::reference[1]).data();
  for (std::size_t i = 0; i < P.size(); ++i) {
    P.x[i] = F(0, 0) * X[i] + F(0, 1) * Y[i];
    P.y[i] = F(1, 0) * X[i] + F(1, 1) * Y[i];
  }
}

Eigen::Matrix3d rotation(double deg) {
  const double a = deg * std::numbers::pi / 180;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  R(0, 0) = std::cos(a); R(0, 1) = -std::sin(a); R(1, 0) = std::sin(a); R(1, 1) = std::cos(a);
  return R;
}

}  // namespace

TEST(TotalLagrangian, AnAffineMotionGivesSaintVenantKirchhoffStressAtEveryParticle) {
  const Scene scene = parse_scene(plate_json(), "plate.json");
  Simulation sim(scene);
  Particles& P = sim.particles();
  TotalLagrangianSolids tl(sim.scene());
  Eigen::Matrix3d U = Eigen::Matrix3d::Identity();
  U(0, 0) = 1.02; U(1, 1) = 0.97; U(0, 1) = 0.015; U(1, 0) = 0.015;
  const Eigen::Matrix3d F = rotation(35) * U;
  deform(P, F);
  tl.forces(P, {0, 0, 0}, 0, 0);
  const Eigen::Matrix3d s = svk_cauchy(F);
  const double scale = s.norm();
  const auto& xx = P.field(SoilFields::xx);
  const auto& yy = P.field(SoilFields::yy);
  const auto& zz = P.field(SoilFields::zz);
  const auto& xy = P.field(SoilFields::xy);
  double worst = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    worst = std::max({worst, std::abs(xx[i] - s(0, 0)), std::abs(yy[i] - s(1, 1)), std::abs(zz[i] - s(2, 2)),
                      std::abs(xy[i] - s(0, 1))});
    EXPECT_NEAR(P.rho[i], kRho / F.determinant(), 1e-9 * kRho);
  }
  EXPECT_LT(worst, 1e-9 * scale) << "largest stress error " << worst << " Pa of " << scale;
}

TEST(TotalLagrangian, InThreeDimensionsAnAffineMotionGivesTheStressAtEveryParticle) {
  json j = plate_json();
  j["dimension"] = 3;
  j["domain"] = {{"min", {-0.5, -0.5, -0.5}}, {"max", {0.7, 0.6, 0.6}}};
  j["gravity"] = {0, 0, 0};
  j["bodies"][0]["min"] = {0, 0, 0};
  j["bodies"][0]["max"] = {0.08, 0.05, 0.04};
  Simulation sim(parse_scene(j, "block.json"));
  Particles& P = sim.particles();
  TotalLagrangianSolids tl(sim.scene());
  Eigen::Matrix3d F;
  F << 1.02, 0.01, -0.02, 0.015, 0.98, 0.01, 0.0, -0.01, 1.01;
  F = rotation(20) * F;
  const double* X[3];
  for (int a = 0; a < 3; ++a) X[a] = P.field(TotalLagrangianFields::reference[a]).data();
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Eigen::Vector3d x = F * Eigen::Vector3d(X[0][i], X[1][i], X[2][i]);
    P.x[i] = x(0); P.y[i] = x(1); P.z[i] = x(2);
  }
  tl.forces(P, {0, 0, 0}, 0, 0);
  const Eigen::Matrix3d s = svk_cauchy(F);
  const char* names[6] = {SoilFields::xx, SoilFields::yy, SoilFields::zz, SoilFields::xy, SoilFields::xz, SoilFields::yz};
  const int rows[6] = {0, 1, 2, 0, 0, 1}, cols[6] = {0, 1, 2, 1, 2, 2};
  double worst = 0;
  for (int c = 0; c < 6; ++c) {
    const auto& f = P.field(names[c]);
    for (std::size_t i = 0; i < P.size(); ++i) worst = std::max(worst, std::abs(f[i] - s(rows[c], cols[c])));
  }
  EXPECT_LT(worst, 1e-9 * s.norm()) << "largest stress error " << worst << " Pa of " << s.norm();
}

TEST(TotalLagrangian, ARigidRotationCarriesNoStress) {
  Simulation sim(parse_scene(plate_json(), "plate.json"));
  Particles& P = sim.particles();
  TotalLagrangianSolids tl(sim.scene());
  deform(P, rotation(60));
  tl.forces(P, {0, 0, 0}, 0, 0);
  const auto& xx = P.field(SoilFields::xx);
  const auto& xy = P.field(SoilFields::xy);
  for (std::size_t i = 0; i < P.size(); ++i) {
    EXPECT_LT(std::abs(xx[i]), 1e-9 * kE);
    EXPECT_LT(std::abs(xy[i]), 1e-9 * kE);
    EXPECT_LT(std::hypot(P.ax[i], P.ay[i]), 1e-6);  // [m/s^2]; 0.01 of strain would give ~1e3
  }
}

TEST(TotalLagrangian, ForcesConserveMomentumAndAngularMomentumAndVanishInsideAUniformStress) {
  Simulation sim(parse_scene(plate_json(), "plate.json"));
  Particles& P = sim.particles();
  TotalLagrangianSolids tl(sim.scene());
  // a uniform stretch: interior particles (two supports from every edge) feel no net force
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  F(0, 0) = 1.01;
  deform(P, F);
  tl.forces(P, {0, 0, 0}, 0, 0);
  const double support = sim.scene().support();
  double edge_max = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double x = P.field(TotalLagrangianFields::reference[0])[i], y = P.field(TotalLagrangianFields::reference[1])[i];
    const bool interior = x > 2 * support && x < 0.2 - 2 * support && y > 2 * support && y < 0.1 - 2 * support;
    if (interior) EXPECT_LT(std::hypot(P.ax[i], P.ay[i]), 1e-6 * 1.0) << "particle " << i;
    else edge_max = std::max(edge_max, std::hypot(P.ax[i], P.ay[i]));
  }
  EXPECT_GT(edge_max, 1.0);  // the free edges are pulled back (the test can see a force)
  // a random deformation with random velocities (viscosity on): sum m a = 0 and sum x x m a = 0
  Scene s = sim.scene();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (std::size_t i = 0; i < P.size(); ++i) {
    P.x[i] += 0.002 * u(rng);
    P.y[i] += 0.002 * u(rng);
    P.vx[i] = 0.1 * u(rng);
    P.vy[i] = 0.1 * u(rng);
  }
  s.soils[0].artificial_viscosity = 0.5;
  TotalLagrangianSolids viscous(s);
  viscous.forces(P, {0, 0, 0}, 0, 0);
  double fx = 0, fy = 0, torque = 0, scale = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    fx += P.m[i] * P.ax[i];
    fy += P.m[i] * P.ay[i];
    torque += P.m[i] * (P.x[i] * P.ay[i] - P.y[i] * P.ax[i]);
    scale += P.m[i] * std::hypot(P.ax[i], P.ay[i]);
  }
  ASSERT_GT(scale, 0);
  EXPECT_LT(std::abs(fx), 1e-12 * scale);
  EXPECT_LT(std::abs(fy), 1e-12 * scale);
  EXPECT_LT(std::abs(torque), 1e-12 * scale * 0.2);  // relative to the plate's size
}

TEST(TotalLagrangian, TheBondsFollowTheParticlesThroughAReordering) {
  Simulation sim(parse_scene(plate_json(), "plate.json"));
  Particles& P = sim.particles();
  TotalLagrangianSolids tl(sim.scene());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (std::size_t i = 0; i < P.size(); ++i) { P.x[i] += 0.001 * u(rng); P.y[i] += 0.001 * u(rng); }
  tl.forces(P, {0, 0, 0}, 0, 0);
  std::map<std::int64_t, std::pair<double, double>> before;
  for (std::size_t i = 0; i < P.size(); ++i) before[P.id[i]] = {P.ax[i], P.ay[i]};
  std::vector<std::uint32_t> order(P.size());
  for (std::size_t i = 0; i < P.size(); ++i) order[i] = static_cast<std::uint32_t>(P.size() - 1 - i);
  P.permute(order);
  tl.forces(P, {0, 0, 0}, 0, 0);
  for (std::size_t i = 0; i < P.size(); ++i) {
    EXPECT_NEAR(P.ax[i], before[P.id[i]].first, 1e-9 * (1 + std::abs(before[P.id[i]].first)));
    EXPECT_NEAR(P.ay[i], before[P.id[i]].second, 1e-9 * (1 + std::abs(before[P.id[i]].second)));
  }
}

TEST(TotalLagrangian, MaterialsTheFormulationDoesNotFitAreRefused) {
  const auto expect_refused = [](const json& j, const std::string& what) {
    try {
      Simulation sim(parse_scene(j, "bad.json"));
      ADD_FAILURE() << "no error for " << what;
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind("bad.json: field '", 0), 0u) << msg;
      EXPECT_NE(msg.find(what), std::string::npos) << msg;
    }
  };
  json soil_body = plate_json();
  soil_body["bodies"][0].erase("structure");
  expect_refused(soil_body, "deformable structure bodies");
  json with_as = plate_json();
  with_as["materials"]["steel"]["artificial_stress"] = {{"epsilon", 0.3}};
  expect_refused(with_as, "artificial_stress");
  json dp = plate_json();
  dp["materials"]["steel"] = {{"model", "drucker_prager"}, {"density", 2000}, {"young_modulus", 2e6}, {"poisson_ratio", 0.3},
                              {"friction_angle", 30}, {"formulation", "total_lagrangian"}};
  expect_refused(dp, "linear_elastic");
  json one_row = plate_json();
  one_row["bodies"][0]["max"] = {0.2, 0.01};
  expect_refused(one_row, "two particles across");
}
