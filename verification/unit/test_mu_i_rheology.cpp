// mu(I) elasto-viscoplastic point model (solver/soil/mu_i_rheology.*): elastic below mu_s p, the
// steady pure-shear flow stress against Jop et al. (2006)'s mu(I) over three decades of I, the
// one-step return satisfying tau = mu(I(gamma_dot)) p, the rate-independent limit d -> 0, the
// stress-free disconnected state, and parameter validation; the scene entry refuses mu_2 < mu_s.
// Parameters: Jop, Forterre & Pouliquen (2006)'s glass beads (mu_s = tan 20.9 deg, mu_2 = tan 32.76
// deg, I_0 = 0.279, d = 0.5 mm, rho_s = 2450 kg/m^3) on an elastic skeleton E = 10 MPa, nu = 0.3.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "soil/mu_i_rheology.hpp"
#include "test_scenes.hpp"
#include "test_validation.hpp"

using geosph::soil::MuIParams;
using geosph::soil::MuIRheology;
using Eigen::Matrix3d;

namespace {

MuIParams beads() {
  const double deg = std::numbers::pi / 180;
  return {1e7, 0.3, std::tan(20.9 * deg), std::tan(32.76 * deg), 0.279, 5e-4, 2450};
}

double tau_of(const Matrix3d& s) {
  const double p = -s.trace() / 3;
  const Matrix3d d = s + p * Matrix3d::Identity();
  return std::sqrt(0.5 * (d.array() * d.array()).sum());
}

Matrix3d isotropic(double p) { return -p * Matrix3d::Identity(); }

}  // namespace

TEST(MuIRheology, ElasticBelowStaticFriction) {
  const MuIRheology m(beads());
  Matrix3d de = Matrix3d::Zero();
  de(0, 0) = 1e-5; de(1, 1) = -1e-5;  // 2 G * 1e-5 = 77 Pa of deviator on p = 10 kPa: tau/p = 0.008
  const auto r = m.update(isotropic(1e4), de, Matrix3d::Zero(), 1e-4);
  const Matrix3d expect = isotropic(1e4) + 2 * m.shear_modulus() * de;
  EXPECT_LT((r.stress - expect).norm(), 1e-9 * 1e4);
  EXPECT_EQ(r.shear_rate, 0.0);
  EXPECT_EQ(r.equivalent_plastic_strain_increment, 0.0);
}

// Steady pure shear D = diag(e, -e, 0) (gamma_dot = 2 e, no spin, no volume change): after the
// elastic transient all the shear is plastic and tau/p is mu(I) at I = 2 e d / sqrt(p / rho_s).
// The backward-Euler return is exact in steady state, so the tolerance is round-off (1e-9).
TEST(MuIRheology, SteadyPureShearFollowsJopMuI) {
  const MuIParams par = beads();
  const MuIRheology m(par);
  const double p = 1e4, dt = 1e-5;
  for (double I : {1e-3, 1e-2, 1e-1, 1.0}) {
    const double rate = I * std::sqrt(p / par.grain_density) / par.grain_diameter;  // gamma_dot
    Matrix3d de = Matrix3d::Zero();
    de(0, 0) = 0.5 * rate * dt; de(1, 1) = -0.5 * rate * dt;
    Matrix3d s = isotropic(p);
    for (int k = 0; k < 200000 && std::abs(tau_of(s) / p - m.friction(I)) > 1e-12; ++k)
      s = m.update(s, de, Matrix3d::Zero(), dt).stress;
    const auto r = m.update(s, de, Matrix3d::Zero(), dt);
    const double mu = par.mu_s + (par.mu_2 - par.mu_s) / (par.i0 / I + 1);  // Jop et al. 2006, eq. 2
    EXPECT_NEAR(tau_of(r.stress) / p, mu, 1e-9) << "I = " << I;
    EXPECT_NEAR(r.shear_rate / rate, 1.0, 1e-9) << "I = " << I;
    EXPECT_NEAR(r.inertial_number / I, 1.0, 1e-9) << "I = " << I;
    EXPECT_NEAR(-r.stress.trace() / 3, p, 1e-9 * p);  // no plastic volume change
  }
}

// One large step from an over-stressed trial: the return lands on tau = mu(I(gamma_dot)) p with
// tau = tau_trial - G dt gamma_dot, keeps the deviator's direction, and reports gamma_dot dt / sqrt 3.
TEST(MuIRheology, OneStepReturnIsConsistent) {
  const MuIParams par = beads();
  const MuIRheology m(par);
  const double p = 2e4, dt = 2e-4;
  Matrix3d de = Matrix3d::Zero();
  de(0, 1) = de(1, 0) = 4e-3;
  de(0, 0) = 1e-3; de(1, 1) = -1e-3;
  const auto r = m.update(isotropic(p), de, Matrix3d::Zero(), dt);
  const Matrix3d trial = isotropic(p) + 2 * m.shear_modulus() * de;
  const double tau = tau_of(r.stress), tau_trial = tau_of(trial);
  ASSERT_GT(r.shear_rate, 0.0);
  const double I = r.shear_rate * par.grain_diameter / std::sqrt(p / par.grain_density);
  EXPECT_NEAR(r.inertial_number, I, 1e-12 * I);
  EXPECT_NEAR(tau, m.friction(I) * p, 1e-9 * p);
  EXPECT_NEAR(tau, tau_trial - m.shear_modulus() * dt * r.shear_rate, 1e-9 * p);
  EXPECT_LT(((r.stress + p * Matrix3d::Identity()) * tau_trial - (trial + p * Matrix3d::Identity()) * tau).norm(),
            1e-6 * p * tau_trial);
  EXPECT_NEAR(r.equivalent_plastic_strain_increment, r.shear_rate * dt / std::sqrt(3.0), 1e-15);
}

// d -> 0 makes every rate quasi-static (I -> 0): the return is onto tau = mu_s p, the
// rate-independent cone of Drucker-Prager with sqrt(J2) = mu_s p and no dilatancy.
TEST(MuIRheology, SmallGrainsGiveTheRateIndependentCone) {
  MuIParams par = beads();
  par.grain_diameter = 1e-12;
  const MuIRheology m(par);
  const double p = 5e3;
  Matrix3d de = Matrix3d::Zero();
  de(0, 1) = de(1, 0) = 1e-3;
  const auto r = m.update(isotropic(p), de, Matrix3d::Zero(), 1e-4);
  EXPECT_NEAR(tau_of(r.stress) / p, par.mu_s, 1e-6);
}

// Tension (p_trial <= 0) leaves the grains out of contact: no stress.
TEST(MuIRheology, DisconnectedInTension) {
  const MuIRheology m(beads());
  Matrix3d de = Matrix3d::Identity() * 1e-3;  // 3 K 1e-3 = 25 kPa of expansion on p = 1 kPa
  const auto r = m.update(isotropic(1e3), de, Matrix3d::Zero(), 1e-4);
  EXPECT_TRUE(r.disconnected);
  EXPECT_EQ(r.stress.norm(), 0.0);
}

TEST(MuIRheology, RejectsBadParameters) {
  using geosph::test::expect_rejects;
  auto p = beads(); p.young = 0; expect_rejects<MuIRheology>(p, "young");
  p = beads(); p.poisson = 0.5; expect_rejects<MuIRheology>(p, "poisson");
  p = beads(); p.mu_s = -0.1; expect_rejects<MuIRheology>(p, "mu_s");
  p = beads(); p.mu_2 = p.mu_s - 0.01; expect_rejects<MuIRheology>(p, "mu_2");
  p = beads(); p.i0 = 0; expect_rejects<MuIRheology>(p, "i0");
  p = beads(); p.grain_diameter = std::nan(""); expect_rejects<MuIRheology>(p, "grain_diameter");
  p = beads(); p.grain_density = -1; expect_rejects<MuIRheology>(p, "grain_density");
}

TEST(MuIRheology, SceneRefusesMu2BelowMuS) {
  auto j = geosph::test::soil_column_scene();
  j["materials"]["sand"] = {{"model", "mu_i"}, {"density", 1600}, {"young_modulus", 1e7}, {"poisson_ratio", 0.3},
                            {"mu_s", 0.5}, {"mu_2", 0.4}, {"grain_diameter", 5e-4}};
  geosph::test::expect_scene_error(j, "materials.sand.mu_2", "must be >= mu_s");
  j["materials"]["sand"]["mu_2"] = 0.6;
  EXPECT_NO_THROW(geosph::parse_scene(j, "ok.json"));
}
