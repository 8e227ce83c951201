// Mohr–Coulomb elastic–perfectly-plastic point model (solver/soil/mohr_coulomb.*): elastic
// exactness, returns onto the hexagonal pyramid (plane, both edges, apex) with unchanged principal
// directions, the triaxial compression/extension and plane-strain limit states against their
// closed forms, step-size independence of radial paths, the non-associated flow rule and parameter
// validation. Tension positive throughout; principal stresses sigma_1 >= sigma_2 >= sigma_3.
// Parameter sets: a cohesive, dilatant soil (E = 10 MPa, nu = 0.3, c = 10 kPa, phi = 30 deg,
// psi = 10 deg), the same with associated flow, a cohesionless sand (E = 0.84 MPa, c = 0,
// phi = 19.8 deg, psi = 0) and a Tresca clay (c = 20 kPa, phi = psi = 0).
#include <gtest/gtest.h>

#include "test_validation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "soil/mohr_coulomb.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>

using geosph::soil::Matrix3d;
using geosph::soil::MohrCoulomb;
using geosph::soil::MohrCoulombParams;
using RT = geosph::soil::MohrCoulombReturnType;

namespace {

double deg(double d) { return d * std::numbers::pi / 180.0; }

MohrCoulombParams cohesive() { return {10e6, 0.3, 10e3, deg(30.0), deg(10.0)}; }
MohrCoulombParams associated() { return {10e6, 0.3, 10e3, deg(30.0), deg(30.0)}; }
MohrCoulombParams sand() { return {0.84e6, 0.3, 0.0, deg(19.8), 0.0}; }
MohrCoulombParams tresca() { return {10e6, 0.3, 20e3, 0.0, 0.0}; }

// Isotropic elasticity written with the Lame constants (independent of the model's K, G form).
struct Elastic {
  double E, nu, lambda, mu;
  explicit Elastic(const MohrCoulombParams& p)
      : E(p.young), nu(p.poisson), lambda(p.young * p.poisson / ((1 + p.poisson) * (1 - 2 * p.poisson))),
        mu(p.young / (2 * (1 + p.poisson))) {}
  Matrix3d D(const Matrix3d& e) const { return lambda * e.trace() * Matrix3d::Identity() + 2 * mu * e; }
  Matrix3d Dinv(const Matrix3d& s) const { return (1 + nu) / E * s - nu / E * s.trace() * Matrix3d::Identity(); }
  // N_phi . D . N_psi in principal space, from the 3x3 principal elastic matrix lambda + 2 mu delta_ij
  double coupling(const Eigen::Vector3d& n, const Eigen::Vector3d& m) const {
    Eigen::Matrix3d Dp = Eigen::Matrix3d::Constant(lambda);
    Dp.diagonal().array() += 2 * mu;
    return n.dot(Dp * m);
  }
};

Matrix3d dev(const Matrix3d& s) { return s - s.trace() / 3.0 * Matrix3d::Identity(); }

// principal stresses, sigma_1 >= sigma_2 >= sigma_3
Eigen::Vector3d principal(const Matrix3d& s) {
  return Eigen::SelfAdjointEigenSolver<Matrix3d>(s).eigenvalues().reverse();
}

// max over the six Mohr–Coulomb planes (s_i - s_j) + (s_i + s_j) sin phi - 2 c cos phi, i != j
double six_plane_max(const Matrix3d& sigma, const MohrCoulombParams& p) {
  const Eigen::Vector3d s = principal(sigma);
  double f = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (i != j)
        f = std::max(f, (s(i) - s(j)) + (s(i) + s(j)) * std::sin(p.friction_angle) -
                            2 * p.cohesion * std::cos(p.friction_angle));
  return f;
}

Matrix3d random_symmetric(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  Matrix3d m;
  for (int a = 0; a < 3; ++a)
    for (int b = a; b < 3; ++b) m(a, b) = m(b, a) = u(rng);
  return m;
}

Matrix3d random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
}

Matrix3d diag(double xx, double yy, double zz) { return Eigen::Vector3d(xx, yy, zz).asDiagonal(); }

double n_phi(double phi) { return (1 + std::sin(phi)) / (1 - std::sin(phi)); }

// One strain-driven step of a mixed-control path: the axial (zz or yy) strain increment is
// prescribed, sigma_xx is held at `target` by a secant iteration on d eps_xx; `lateral_yy` also
// gives d eps_yy = d eps_xx (triaxial), otherwise d eps_yy = d_axial and d eps_zz = 0 (plane strain).
MohrCoulomb::Result held_lateral_step(const MohrCoulomb& m, const Matrix3d& sigma, double d_axial,
                                      double target, bool triaxial) {
  auto step = [&](double x) {
    const Matrix3d de = triaxial ? diag(x, x, d_axial) : diag(x, d_axial, 0.0);
    return m.update(sigma, de, Matrix3d::Zero());
  };
  // the response is piecewise linear in x: the secant converges in a few iterations per regime
  double x0 = 0.0, x1 = 1e-7;
  double g0 = step(x0).stress(0, 0) - target, g1 = step(x1).stress(0, 0) - target;
  for (int it = 0; it < 60 && std::abs(g1) > 1e-14 * std::abs(target) && g1 != g0; ++it) {
    const double x2 = x1 - g1 * (x1 - x0) / (g1 - g0);
    x0 = x1; g0 = g1;
    x1 = x2; g1 = step(x1).stress(0, 0) - target;
  }
  return step(x1);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Elastic range

TEST(MohrCoulomb, ElasticStepsAreExact) {
  std::mt19937_64 rng(11);
  for (const auto& prm : {cohesive(), sand(), tresca()}) {
    const MohrCoulomb m(prm);
    const Elastic el(prm);
    EXPECT_NEAR(m.bulk_modulus(), prm.young / (3 * (1 - 2 * prm.poisson)), 1e-9 * prm.young);
    EXPECT_NEAR(m.shear_modulus(), el.mu, 1e-9 * prm.young);
    Matrix3d sigma0 = diag(-40e3, -60e3, -45e3);
    sigma0(0, 1) = sigma0(1, 0) = 3e3;
    ASSERT_LT(m.yield(sigma0), -1e3);
    double worst = 0;
    for (int k = 0; k < 500; ++k) {
      const Matrix3d de = random_symmetric(rng, 1e-4);  // |D de| ~ 1 kPa << distance to the surface
      const Matrix3d expect = sigma0 + el.D(de);
      ASSERT_LT(m.yield(expect), 0.0);
      const auto r = m.update(sigma0, de, Matrix3d::Zero());
      EXPECT_EQ(r.return_type, RT::Elastic);
      EXPECT_EQ(r.plastic_multiplier, 0.0);
      EXPECT_EQ(r.volumetric_plastic_strain_increment, 0.0);
      EXPECT_EQ(r.equivalent_plastic_strain_increment, 0.0);
      EXPECT_TRUE(r.plastic_strain_increment.isZero(0.0));
      EXPECT_EQ(r.stress, r.stress.transpose());
      worst = std::max(worst, (r.stress - expect).cwiseAbs().maxCoeff() / sigma0.cwiseAbs().maxCoeff());
    }
    // the elastic step is not decomposed: only the rounding of two algebraically equal forms of
    // D : de (K, G vs Lame) differs, a few ulp of |sigma|
    EXPECT_LE(worst, 1e-12);
    RecordProperty("elastic_rel_error", std::to_string(worst));
  }
}

// ---------------------------------------------------------------------------------------------
// Return mapping: on the surface, coaxial, non-negative multipliers, every region reached

TEST(MohrCoulomb, ReturnLandsOnTheSurfaceWithUnchangedPrincipalDirections) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> mean(-300e3, 150e3), unit(0.0, 1.0);
  for (const auto& prm : {cohesive(), associated(), sand(), tresca()}) {
    const MohrCoulomb m(prm);
    const Elastic el(prm);
    std::array<int, 5> count{};
    double worst_f = 0, worst_comm = 0;
    for (int k = 0; k < 6000; ++k) {
      Matrix3d trial;
      if (k % 3 == 0) {
        // exactly repeated trial eigenvalues (triaxial states) in a random frame
        const double a = -300e3 * unit(rng), b = a + 200e3 * (unit(rng) - 0.5);
        const Matrix3d Q = random_rotation(rng);
        trial = Q * (k % 2 ? diag(a, a, b) : diag(b, a, a)) * Q.transpose();
        trial = 0.5 * (trial + trial.transpose()) + mean(rng) * 0.2 * Matrix3d::Identity();
      } else {
        trial = random_symmetric(rng, 100e3) + mean(rng) * Matrix3d::Identity();
      }
      const double scale = std::max(trial.cwiseAbs().maxCoeff(), prm.cohesion);
      const auto r = m.return_map(trial);
      if (r.return_type == RT::Elastic) {
        ++count[0];
        EXPECT_LE(six_plane_max(trial, prm), 1e-12 * scale);
        continue;
      }
      ++count[static_cast<int>(r.return_type)];
      // on the surface: the largest of the six planes is zero (the apex and edges lie on several)
      const double f = six_plane_max(r.stress, prm);
      worst_f = std::max(worst_f, std::abs(f) / scale);
      EXPECT_LE(std::abs(f), 1e-9 * scale) << "k=" << k << " type " << static_cast<int>(r.return_type);
      // coaxial: sigma_new commutes with sigma_trial (independent of the eigenvector choice inside
      // repeated eigenvalues); round-off of the eigen-decomposition is ~1e-15 |sigma|^2
      const double comm = (r.stress * trial - trial * r.stress).cwiseAbs().maxCoeff() / (scale * scale);
      worst_comm = std::max(worst_comm, comm);
      EXPECT_LE(comm, 1e-12);
      EXPECT_EQ(r.stress, r.stress.transpose());
      // consistency: multipliers non-negative; de_p is D^-1 : (trial - new)
      if (r.return_type != RT::Apex) {
        EXPECT_GE(r.plastic_multipliers[0], -1e-12 * scale / prm.young);
        EXPECT_GE(r.plastic_multipliers[1], -1e-12 * scale / prm.young);
      }
      EXPECT_GE(r.plastic_multiplier, 0.0);
      EXPECT_LE((r.plastic_strain_increment - el.Dinv(trial - r.stress)).cwiseAbs().maxCoeff(),
                1e-9 * scale / prm.young);
      if (r.return_type == RT::Apex) {
        EXPECT_EQ(r.stress, m.apex_mean_stress() * Matrix3d::Identity());
      }
    }
    const bool has_apex = prm.friction_angle > 0;
    for (int t = 0; t < 5; ++t) {
      if (t == static_cast<int>(RT::Apex) && !has_apex) {
        EXPECT_EQ(count[t], 0);  // Tresca: no apex
      } else {
        EXPECT_GT(count[t], 50) << "return type " << t;
      }
    }
    RecordProperty("worst_f_rel", std::to_string(worst_f));
    RecordProperty("worst_commutator_rel", std::to_string(worst_comm));
    std::printf("  [%s] elastic %d plane %d left %d right %d apex %d; max|f|/scale %.2e, commutator %.2e\n",
                prm.friction_angle == 0 ? "tresca" : "phi>0", count[0], count[1], count[2], count[3], count[4],
                worst_f, worst_comm);
  }
}

// Associated flow: the return is the closest point in the energy norm, equivalently (convex elastic
// domain) the variational inequality (trial - new) : D^-1 : (tau - new) <= 0 for every admissible
// tau. Checked against random admissible points near the return and deep inside: this tests the
// choice between plane, edge and apex, not only that the result is on the surface.
TEST(MohrCoulomb, AssociatedReturnSatisfiesTheVariationalInequality) {
  const auto prm = associated();
  const MohrCoulomb m(prm);
  const Elastic el(prm);
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> mean(-300e3, 200e3), unit(-1.0, 1.0);
  std::array<int, 5> count{};
  double worst = -1e300;
  for (int k = 0; k < 2000; ++k) {
    const Matrix3d trial = random_symmetric(rng, 100e3) + mean(rng) * Matrix3d::Identity();
    const auto r = m.return_map(trial);
    if (r.return_type == RT::Elastic) continue;
    ++count[static_cast<int>(r.return_type)];
    const Matrix3d g = el.Dinv(trial - r.stress);
    const double scale = std::max(trial.cwiseAbs().maxCoeff(), prm.cohesion);
    for (int j = 0; j < 100; ++j) {
      const double eps = scale * std::pow(10.0, -4.0 + 3.5 * (0.5 + 0.5 * unit(rng)));
      const Matrix3d tau = r.stress + random_symmetric(rng, eps);
      if (six_plane_max(tau, prm) > 0) continue;
      const double v = (g.array() * (tau - r.stress).array()).sum();
      // the returned stress is exact to ~1e-14 scale (max|f| above): 1e-12 bounds its effect
      const double tol = 1e-12 * scale * (g.norm() + (tau - r.stress).norm() / prm.young);
      worst = std::max(worst, v / tol);
      EXPECT_LE(v, tol) << "trial " << k << " type " << static_cast<int>(r.return_type);
    }
  }
  for (int t = 1; t < 5; ++t) EXPECT_GT(count[t], 20) << "return type " << t;
  std::printf("  max of (trial-new):D^-1:(tau-new) / tol = %.2e (must be <= 1)\n", worst);
}

// Non-associated apex (psi > 0): the plastic strain D^-1 : (trial - c cot(phi) I) must be a
// non-negative combination of the potential normals of the six planes meeting there,
// N_ij = (1 + s_psi) e_i - (1 - s_psi) e_j (i != j, principal frame). By Caratheodory's theorem a
// point of this 3-D cone is a non-negative combination of three of them: all 20 triples are tried.
// The multipliers' sum is then fixed by the trace, tr = 2 s_psi sum (what plastic_multiplier reports).
// (With psi = 0 the apex's volume change is the tension crack of the cut-off, outside that cone.)
TEST(MohrCoulomb, ApexPlasticStrainIsAnAdmissibleFlow) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> mean(-50e3, 200e3);
  for (const auto& prm : {cohesive(), associated()}) {
    const MohrCoulomb m(prm);
    const Elastic el(prm);
    const double s = std::sin(prm.dilatancy_angle);
    std::vector<Eigen::Vector3d> gen;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (i != j) gen.push_back((1 + s) * Eigen::Vector3d::Unit(i) - (1 - s) * Eigen::Vector3d::Unit(j));
    int apex = 0;
    for (int k = 0; k < 3000; ++k) {
      const Matrix3d trial = random_symmetric(rng, 100e3) + mean(rng) * Matrix3d::Identity();
      const auto r = m.return_map(trial);
      if (r.return_type != RT::Apex) continue;
      ++apex;
      const Eigen::Vector3d e = principal(el.Dinv(trial - r.stress));
      double best = -1e300, sum = 0;  // the largest smallest coefficient over the triples
      for (int a = 0; a < 6; ++a)
        for (int b = a + 1; b < 6; ++b)
          for (int c = b + 1; c < 6; ++c) {
            Eigen::Matrix3d N;
            N << gen[a], gen[b], gen[c];
            if (std::abs(N.determinant()) < 1e-12) continue;
            const Eigen::Vector3d x = N.partialPivLu().solve(e);
            if (x.minCoeff() > best) best = x.minCoeff(), sum = x.sum();
          }
      EXPECT_GE(best, -1e-12 * e.norm()) << "trial " << k;  // round-off of the 3x3 solve
      EXPECT_NEAR(r.plastic_multiplier, sum, 1e-10 * sum);
    }
    EXPECT_GT(apex, 100);
  }
}

// update() = the Jaumann rotation of DruckerPrager::update, the elastic predictor, then the return.
TEST(MohrCoulomb, UpdateRotatesLikeDruckerPragerThenReturns) {
  std::mt19937_64 rng(19);
  const auto prm = cohesive();
  const MohrCoulomb m(prm);
  const Elastic el(prm);
  int plastic = 0;
  for (int k = 0; k < 200; ++k) {
    const Matrix3d sigma = random_symmetric(rng, 30e3) - 60e3 * Matrix3d::Identity();
    const Matrix3d de = random_symmetric(rng, 5e-3);
    const Eigen::Vector3d w = random_symmetric(rng, 0.05).diagonal();  // three random spin components
    Matrix3d W;
    W << 0, -w(2), w(1), w(2), 0, -w(0), -w(1), w(0), 0;  // antisymmetric
    const auto r = m.update(sigma, de, W);
    const auto ref = m.return_map(geosph::soil::DruckerPrager::jaumann_rotate(sigma, W) + el.D(de));
    plastic += r.return_type != RT::Elastic;
    EXPECT_EQ(r.return_type, ref.return_type);
    // the predictor differs from el.D(de) by the rounding of the two forms of D (1e-15 relative)
    EXPECT_LE((r.stress - ref.stress).cwiseAbs().maxCoeff(), 1e-12 * sigma.cwiseAbs().maxCoeff());
  }
  EXPECT_GT(plastic, 20);
}

// update() on a const model from many threads gives the serial results bit for bit.
TEST(MohrCoulomb, ConcurrentUpdatesOnAConstModelMatchSerial) {
  const MohrCoulomb m(cohesive());
  std::mt19937_64 rng(5);
  const int n = 4000;
  std::vector<Matrix3d> sigma(n), de(n), serial(n), parallel(n);
  for (int k = 0; k < n; ++k) {
    sigma[k] = random_symmetric(rng, 50e3) - 100e3 * Matrix3d::Identity();
    de[k] = random_symmetric(rng, 2e-2);
  }
  for (int k = 0; k < n; ++k) serial[k] = m.update(sigma[k], de[k], Matrix3d::Zero()).stress;
#pragma omp parallel for schedule(dynamic, 16)
  for (int k = 0; k < n; ++k) parallel[k] = m.update(sigma[k], de[k], Matrix3d::Zero()).stress;
  for (int k = 0; k < n; ++k) ASSERT_EQ(parallel[k], serial[k]) << k;
}

// ---------------------------------------------------------------------------------------------
// Conventional triaxial tests, strain driven, lateral stress held at -sigma_c

namespace {

struct TriaxialOutcome {
  double axial;  // -sigma_zz at the end (compression positive)
  double lateral_error;
  RT type;
};

TriaxialOutcome triaxial(const MohrCoulomb& m, double sigma_c, double d_axial, int steps) {
  Matrix3d sigma = -sigma_c * Matrix3d::Identity();
  MohrCoulomb::Result r{};
  for (int k = 0; k < steps; ++k) {
    r = held_lateral_step(m, sigma, d_axial, -sigma_c, true);
    sigma = r.stress;
  }
  return {-sigma(2, 2), std::max(std::abs(sigma(0, 0) + sigma_c), std::abs(sigma(1, 1) + sigma_c)) / sigma_c,
          r.return_type};
}

}  // namespace

// Compression positive: sigma_a = sigma_c N_phi + 2 c sqrt(N_phi). Tension positive the two
// lateral stresses are the equal LARGER ones, sigma_1 = sigma_2 = -sigma_c, sigma_3 = -sigma_a:
// the LEFT edge.
TEST(MohrCoulomb, TriaxialCompressionLimitIsOnTheLeftEdge) {
  for (const auto& prm : {cohesive(), associated(), sand()}) {
    const MohrCoulomb m(prm);
    const double sc = 100e3, N = n_phi(prm.friction_angle);
    const double expect = sc * N + 2 * prm.cohesion * std::sqrt(N);
    // 400 steps of -1e-4: elastic part (expect - sc)/E ~ 2.3 % (cohesive), then plastic flow
    const double strain = prm.young < 1e6 ? -4e-3 : -1e-4;  // the soft sand needs larger steps
    const auto o = triaxial(m, sc, strain, 400);
    const double err = std::abs(o.axial - expect) / expect;
    // the lateral secant converges to 1e-14 sc; the edge return is a closed-form 2x2 solve, so
    // the limit is reproduced to round-off (~1e-15); 1e-10 allows the accumulated rounding
    EXPECT_LE(err, 1e-10) << o.axial << " vs " << expect;
    EXPECT_LE(o.lateral_error, 1e-12);
    EXPECT_EQ(o.type, RT::LeftEdge);
    std::printf("  compression phi=%.1f: axial %.6f kPa, rel error %.2e\n", prm.friction_angle * 180 / std::numbers::pi,
                o.axial / 1e3, err);
  }
}

// Compression positive: sigma_a = sigma_c / N_phi - 2 c / sqrt(N_phi) (axial the minor principal
// stress). Tension positive the two lateral stresses are the equal SMALLER ones,
// sigma_2 = sigma_3 = -sigma_c, sigma_1 = -sigma_a: the RIGHT edge.
TEST(MohrCoulomb, TriaxialExtensionLimitIsOnTheRightEdge) {
  for (const auto& prm : {cohesive(), associated(), sand()}) {
    const MohrCoulomb m(prm);
    const double sc = 100e3, N = n_phi(prm.friction_angle);
    const double expect = sc / N - 2 * prm.cohesion / std::sqrt(N);
    ASSERT_GT(expect, 0.0);
    const double strain = prm.young < 1e6 ? 1e-3 : 5e-5;
    const auto o = triaxial(m, sc, strain, 400);
    const double err = std::abs(o.axial - expect) / expect;
    EXPECT_LE(err, 1e-10) << o.axial << " vs " << expect;  // as for compression
    EXPECT_LE(o.lateral_error, 1e-12);
    EXPECT_EQ(o.type, RT::RightEdge);
    std::printf("  extension phi=%.1f: axial %.6f kPa, rel error %.2e\n", prm.friction_angle * 180 / std::numbers::pi,
                o.axial / 1e3, err);
  }
}

// ---------------------------------------------------------------------------------------------
// Apex (tension cut-off) and non-finite input

TEST(MohrCoulomb, IsotropicTensionBeyondTheApexReturnsToIt) {
  std::mt19937_64 rng(3);
  for (const auto& prm : {cohesive(), associated(), sand()}) {
    const MohrCoulomb m(prm);
    const double apex = prm.cohesion * std::cos(prm.friction_angle) / std::sin(prm.friction_angle);
    EXPECT_NEAR(m.apex_mean_stress(), apex, 1e-12 * std::max(apex, 1.0));
    for (double p : {1e3, 1e5, 1e8}) {
      const Matrix3d trial = (apex + p) * Matrix3d::Identity() + dev(random_symmetric(rng, 0.01 * p));
      const auto r = m.return_map(trial);
      EXPECT_EQ(r.return_type, RT::Apex);
      EXPECT_EQ(r.stress, m.apex_mean_stress() * Matrix3d::Identity());  // exactly c cot(phi) I
      EXPECT_NEAR(six_plane_max(r.stress, prm), 0.0, 1e-12 * std::max(prm.cohesion, 1.0));
      // plastic volume change (p_tr - p_apex)/K, positive: the tension crack opens
      EXPECT_NEAR(r.volumetric_plastic_strain_increment, (trial.trace() / 3 - apex) / m.bulk_modulus(),
                  1e-12 * p / m.bulk_modulus());
      EXPECT_NEAR(r.plastic_strain_increment.trace(), r.volumetric_plastic_strain_increment,
                  1e-12 * r.volumetric_plastic_strain_increment);
    }
    // the same through update(): uniaxial stretching of a stress-free point
    EXPECT_EQ(m.update(Matrix3d::Zero(), diag(0.05, 0, 0), Matrix3d::Zero()).return_type, RT::Apex);
  }
}

TEST(MohrCoulomb, NonFiniteInputGivesNonFiniteStressWithoutThrowing) {
  const MohrCoulomb m(cohesive());
  Matrix3d bad = -50e3 * Matrix3d::Identity();
  bad(0, 1) = bad(1, 0) = std::numeric_limits<double>::quiet_NaN();
  const auto r = m.update(bad, Matrix3d::Zero(), Matrix3d::Zero());
  EXPECT_FALSE(r.stress.allFinite());
  Matrix3d inf_strain = Matrix3d::Zero();
  inf_strain(2, 2) = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(m.update(Matrix3d::Zero(), inf_strain, Matrix3d::Zero()).stress.allFinite());
  static_assert(noexcept(m.update(bad, bad, bad)));
}

// ---------------------------------------------------------------------------------------------
// Plane strain: the limit state of a biaxial test touches the envelope

// d eps_zz = 0, sigma_xx held at -sigma_c, eps_yy compressed. At the limit the elastic strain rate
// vanishes, so the plastic strain rate is plane: with associated flow the main-plane normal
// (1 + s, 0, -1 + s) has zero intermediate component, so sigma_zz is the intermediate stress and
// Mohr's circle of sigma_1 = sigma_xx, sigma_3 = sigma_yy touches the envelope:
// (sigma_1 - sigma_3)/2 = c cos(phi) - (sigma_1 + sigma_3)/2 sin(phi)   (tension positive).
TEST(MohrCoulomb, PlaneStrainBiaxialLimitTouchesTheEnvelope) {
  for (const auto& prm : {associated(), tresca()}) {
    const MohrCoulomb m(prm);
    const double sc = 100e3;
    Matrix3d sigma = -sc * Matrix3d::Identity();
    MohrCoulomb::Result r{};
    for (int k = 0; k < 400; ++k) {
      r = held_lateral_step(m, sigma, -1e-4, -sc, false);
      sigma = r.stress;
    }
    const double s1 = sigma(0, 0), s3 = sigma(1, 1), s2 = sigma(2, 2);
    const double t = 0.5 * (s1 - s3), p = 0.5 * (s1 + s3);
    const double envelope = prm.cohesion * std::cos(prm.friction_angle) - p * std::sin(prm.friction_angle);
    const double err = std::abs(t - envelope) / envelope;
    EXPECT_LE(err, 1e-10);  // closed-form plane return: round-off only (see triaxial)
    EXPECT_EQ(r.return_type, RT::Plane);
    EXPECT_GT(s2, s3);  // sigma_zz intermediate
    EXPECT_LT(s2, s1);
    // no out-of-plane plastic strain (associated main plane: zero intermediate component)
    EXPECT_LE(std::abs(r.plastic_strain_increment(2, 2)), 1e-12 * r.plastic_strain_increment.norm());
    if (prm.friction_angle == 0) {
      EXPECT_NEAR(t, prm.cohesion, 1e-10 * prm.cohesion);  // Tresca: max shear stress = c
    }
    std::printf("  biaxial phi=%.1f: t %.6f kPa, envelope %.6f kPa, rel error %.2e\n",
                prm.friction_angle * 180 / std::numbers::pi, t / 1e3, envelope / 1e3, err);
  }
}

// Tresca in plane-strain simple shear from an isotropic state: the flow is deviatoric, sigma_xx =
// sigma_yy = sigma_zz stay at p and tau_xy saturates at c.
TEST(MohrCoulomb, TrescaSimpleShearSaturatesAtTheCohesion) {
  const auto prm = tresca();
  const MohrCoulomb m(prm);
  Matrix3d sigma = -50e3 * Matrix3d::Identity();
  Matrix3d de = Matrix3d::Zero();
  de(0, 1) = de(1, 0) = 0.5 * 2e-4;  // engineering shear strain 2e-4 per step
  MohrCoulomb::Result r{};
  for (int k = 0; k < 100; ++k) {
    r = m.update(sigma, de, Matrix3d::Zero());
    sigma = r.stress;
  }
  EXPECT_EQ(r.return_type, RT::Plane);
  const double err = std::abs(sigma(0, 1) - prm.cohesion) / prm.cohesion;
  EXPECT_LE(err, 1e-12);  // one closed-form return per step from an exact isotropic start
  EXPECT_NEAR(sigma.trace(), -150e3, 1e-10 * 150e3);
  EXPECT_NEAR(sigma(0, 0), -50e3, 1e-10 * 50e3);
  std::printf("  Tresca simple shear: tau %.9f kPa, rel error %.2e\n", sigma(0, 1) / 1e3, err);
}

// ---------------------------------------------------------------------------------------------
// Step-size independence of radial paths

// With fixed principal directions and a fixed principal ordering, each return onto a plane (or an
// edge) is an affine projection that leaves points of the plane fixed, so one large step and
// N small ones give the same stress in exact arithmetic; the difference is the round-off of N
// steps, ~N * 10 eps |sigma| ~ 2e-13 |sigma| for N = 100, tested at 1e-12.
TEST(MohrCoulomb, RadialPathsAreStepSizeIndependent) {
  std::mt19937_64 rng(13);
  const MohrCoulomb m(cohesive());
  struct Case {
    Eigen::Vector3d sigma0, total_strain;
    RT type;
  };
  const Case cases[] = {
      {{-50e3, -60e3, -80e3}, {6e-3, 0.0, -10e-3}, RT::Plane},
      {{-50e3, -50e3, -80e3}, {5e-3, 5e-3, -12e-3}, RT::LeftEdge},
      {{-50e3, -80e3, -80e3}, {6e-3, -2e-3, -2e-3}, RT::RightEdge},
  };
  for (const auto& c : cases) {
    const Matrix3d Q = random_rotation(rng);
    const Matrix3d sigma0 = Q * Matrix3d(c.sigma0.asDiagonal()) * Q.transpose();
    const Matrix3d E = Q * Matrix3d(c.total_strain.asDiagonal()) * Q.transpose();
    const auto big = m.update(sigma0, E, Matrix3d::Zero());
    ASSERT_EQ(big.return_type, c.type);
    const int n = 100;
    Matrix3d s = sigma0;
    for (int k = 0; k < n; ++k) {
      const auto r = m.update(s, E / n, Matrix3d::Zero());
      if (r.return_type != RT::Elastic) {
        ASSERT_EQ(r.return_type, c.type) << "step " << k;
      }
      s = r.stress;
    }
    const double err = (s - big.stress).cwiseAbs().maxCoeff() / big.stress.cwiseAbs().maxCoeff();
    EXPECT_LE(err, 1e-12);
    std::printf("  radial path type %d: one step vs %d steps rel difference %.2e\n",
                static_cast<int>(c.type), n, err);
  }
}

// ---------------------------------------------------------------------------------------------
// Non-associated flow: the plastic strain follows the potential Psi (psi), not Phi (phi)

// Plane: de_p = dgamma (1 + s_psi, 0, -1 + s_psi) with dgamma = Phi^tr / (N_phi . D . N_psi), so
// tr(de_p) = 2 s_psi dgamma. Edges: tr(de_p) = 2 s_psi (dgamma_a + dgamma_b) (both normals have the
// same trace). Zero for psi = 0, dilation (> 0, tension positive) for psi > 0.
TEST(MohrCoulomb, NonAssociatedFlowVolumetricStrain) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> mean(-300e3, 50e3);
  for (const auto& prm : {cohesive(), associated(), sand(), tresca()}) {
    const MohrCoulomb m(prm);
    const Elastic el(prm);
    const double sphi = std::sin(prm.friction_angle), spsi = std::sin(prm.dilatancy_angle);
    const Eigen::Vector3d Nphi(1 + sphi, 0, -1 + sphi), Npsi(1 + spsi, 0, -1 + spsi);
    const double a = el.coupling(Nphi, Npsi);
    int plane = 0, edge = 0;
    double worst = 0;
    for (int k = 0; k < 3000; ++k) {
      const Matrix3d trial = random_symmetric(rng, 100e3) + mean(rng) * Matrix3d::Identity();
      const auto r = m.return_map(trial);
      if (r.return_type == RT::Elastic || r.return_type == RT::Apex) continue;
      const Matrix3d& dep = r.plastic_strain_increment;
      const double vol = 2 * spsi * (r.plastic_multipliers[0] + r.plastic_multipliers[1]);
      if (r.return_type == RT::Plane) {
        ++plane;
        const double dgamma = m.yield(trial) / a;  // closed form from the trial alone
        EXPECT_NEAR(r.plastic_multiplier, dgamma, 1e-12 * dgamma);
        EXPECT_EQ(r.plastic_multipliers[1], 0.0);
        // principal components: dgamma N_psi, sorted like the stress
        const Eigen::Vector3d e = principal(dep);
        EXPECT_LE((e - dgamma * Npsi).cwiseAbs().maxCoeff(), 1e-12 * dgamma);
      } else {
        ++edge;
      }
      EXPECT_NEAR(r.volumetric_plastic_strain_increment, vol, 1e-14 * std::abs(vol) + 1e-300);
      const double tr_err = std::abs(dep.trace() - vol) / dep.norm();
      worst = std::max(worst, tr_err);
      EXPECT_LE(tr_err, 1e-13);  // rotation of the principal de_p: a few ulp of |de_p|
      EXPECT_NEAR(r.equivalent_plastic_strain_increment, std::sqrt(2.0 / 3.0 * dev(dep).squaredNorm()),
                  1e-12 * dep.norm());
      if (spsi == 0) {
        EXPECT_EQ(r.volumetric_plastic_strain_increment, 0.0);
        EXPECT_NEAR(r.stress.trace(), trial.trace(), 1e-12 * trial.norm());  // no volumetric return
      } else {
        EXPECT_GT(r.volumetric_plastic_strain_increment, 0.0);
        EXPECT_LT(r.stress.trace(), trial.trace());  // mean stress pushed into compression
      }
    }
    EXPECT_GT(plane, 100);
    EXPECT_GT(edge, 50);
    std::printf("  psi=%.1f: plane %d edge %d, max |tr(de_p) - 2 sin(psi) sum dgamma| / |de_p| %.2e\n",
                prm.dilatancy_angle * 180 / std::numbers::pi, plane, edge, worst);
  }
}

// ---------------------------------------------------------------------------------------------
// Parameter validation

TEST(MohrCoulomb, ValidationRejectsEachBadField) {
  using geosph::test::expect_rejects;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto with = [](auto field, double v) {
    MohrCoulombParams p = cohesive();
    p.*field = v;
    return p;
  };
  for (double v : {0.0, -1.0, nan, inf}) expect_rejects<MohrCoulomb>(with(&MohrCoulombParams::young, v), "young");
  for (double v : {-1.0, 0.5, 0.7, nan}) expect_rejects<MohrCoulomb>(with(&MohrCoulombParams::poisson, v), "poisson");
  for (double v : {-1.0, nan, inf}) expect_rejects<MohrCoulomb>(with(&MohrCoulombParams::cohesion, v), "cohesion");
  for (double v : {-0.01, deg(90), deg(120), nan})
    expect_rejects<MohrCoulomb>(with(&MohrCoulombParams::friction_angle, v), "friction_angle");
  for (double v : {-0.01, deg(31), nan})
    expect_rejects<MohrCoulomb>(with(&MohrCoulombParams::dilatancy_angle, v), "dilatancy_angle");
  // no strength at all: c = 0 and phi = 0 together
  expect_rejects<MohrCoulomb>(MohrCoulombParams{10e6, 0.3, 0.0, 0.0, 0.0}, "cohesion");
  // the boundary cases that are allowed
  EXPECT_NO_THROW(MohrCoulomb{sand()});      // c = 0, phi > 0
  EXPECT_NO_THROW(MohrCoulomb{tresca()});    // phi = 0, c > 0
  EXPECT_NO_THROW(MohrCoulomb{associated()});  // psi = phi
}
