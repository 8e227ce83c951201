// Mohr–Coulomb elastic–perfectly-plastic point model; sources, equations and conventions in the
// header.
#include "soil/mohr_coulomb.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include <Eigen/Eigenvalues>

namespace geosph::soil {

namespace {

using Vec3 = Eigen::Vector3d;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Principal stresses sigma_1 >= sigma_2 >= sigma_3 and their eigenvectors (columns, same order).
// compute() (tridiagonalisation + implicit QR) rather than computeDirect(): the closed-form 3x3
// solver loses accuracy in the eigenvectors of (nearly) repeated eigenvalues, which the edge states
// are (measured on random rotations of diag(-1e5, -1e5 (1 + gap), -2.3e5): V L V^T - sigma and
// V^T V - I reach 5e-9 / 1e-8 relative for gap <= 1e-8 with computeDirect, 2e-15 with compute()).
struct Principal {
  Vec3 values;
  Matrix3d vectors;
  bool ok;
};

Principal principal(const Matrix3d& sigma) {
  const Eigen::SelfAdjointEigenSolver<Matrix3d> es(sigma, Eigen::ComputeEigenvectors);  // ascending
  return {es.eigenvalues().reverse(), es.eigenvectors().rowwise().reverse(),
          es.info() == Eigen::Success};
}

Matrix3d from_principal(const Vec3& values, const Matrix3d& vectors) {
  const Matrix3d m = vectors * values.asDiagonal() * vectors.transpose();
  return 0.5 * (m + m.transpose());  // exactly symmetric
}

bool ordered(const Vec3& s) { return s(0) >= s(1) && s(1) >= s(2); }

}  // namespace

// The elastic constants and the c, phi, psi ranges are Drucker-Prager's (the same parameters);
// Mohr-Coulomb adds that c = 0 with phi = 0 has no strength at all.
void validate(const MohrCoulombParams& p) {
  validate(DruckerPragerParams{p.young, p.poisson, p.cohesion, p.friction_angle, p.dilatancy_angle});
  if (p.cohesion == 0.0 && p.friction_angle == 0.0)
    throw std::invalid_argument("cohesion must be > 0 when friction_angle = 0 (the material would have no strength), got 0");
}

MohrCoulomb::MohrCoulomb(const MohrCoulombParams& params) : params_(params) {
  validate(params_);
  K_ = params_.young / (3.0 * (1.0 - 2.0 * params_.poisson));
  G_ = params_.young / (2.0 * (1.0 + params_.poisson));
  sin_phi_ = std::sin(params_.friction_angle);
  sin_psi_ = std::sin(params_.dilatancy_angle);
  two_c_cos_phi_ = 2.0 * params_.cohesion * std::cos(params_.friction_angle);
  apex_p_ = sin_phi_ > 0.0 ? params_.cohesion * std::cos(params_.friction_angle) / sin_phi_
                           : std::numeric_limits<double>::infinity();
  const double ss = sin_phi_ * sin_psi_;
  a_ = 4.0 * G_ * (1.0 + ss / 3.0) + 4.0 * K_ * ss;
  b_right_ = 2.0 * G_ * (1.0 + sin_phi_ + sin_psi_ - ss / 3.0) + 4.0 * K_ * ss;
  b_left_ = 2.0 * G_ * (1.0 - sin_phi_ - sin_psi_ - ss / 3.0) + 4.0 * K_ * ss;
}

double MohrCoulomb::yield(const Matrix3d& sigma) const {
  const Vec3 s = Eigen::SelfAdjointEigenSolver<Matrix3d>(sigma, Eigen::EigenvaluesOnly).eigenvalues();
  return (s(2) - s(0)) + (s(2) + s(0)) * sin_phi_ - two_c_cos_phi_;  // ascending: s(2) = sigma_1
}

Matrix3d MohrCoulomb::elastic_increment(const Matrix3d& de) const { return DruckerPrager::hooke_increment(K_, G_, de); }

namespace {

// Everything return_map needs of the model, in principal space.
struct Planes {
  double K, G, sin_phi, sin_psi, two_c_cos_phi;
  // D N = (K - 2G/3) tr(N) 1 + 2 G N
  Vec3 DN(const Vec3& n) const { return Vec3::Constant((K - 2.0 * G / 3.0) * n.sum()) + 2.0 * G * n; }
  // Mohr–Coulomb plane through principal stresses i (major) and j (minor): (s_i - s_j) + (s_i + s_j) sin phi - 2 c cos phi
  double plane(const Vec3& s, int i, int j) const {
    return (s(i) - s(j)) + (s(i) + s(j)) * sin_phi - two_c_cos_phi;
  }
};

}  // namespace

MohrCoulomb::Result MohrCoulomb::return_map(const Matrix3d& trial) const noexcept {
  Result r;
  r.plastic_multipliers = {0.0, 0.0};
  r.plastic_multiplier = 0.0;
  r.volumetric_plastic_strain_increment = 0.0;
  r.equivalent_plastic_strain_increment = 0.0;
  r.plastic_strain_increment.setZero();
  r.return_type = ReturnType::Elastic;
  r.stress = trial;
  if (!trial.allFinite()) return r;  // non-finite in, non-finite out

  const Principal pr = principal(trial);
  const Vec3& v = pr.values;
  const Planes m{K_, G_, sin_phi_, sin_psi_, two_c_cos_phi_};
  const double phi_a = m.plane(v, 0, 2);
  if (!pr.ok) {
    r.stress.setConstant(kNaN);
    return r;
  }
  if (!(phi_a > 0.0)) return r;  // (a) elastic

  // (b) main plane
  const Vec3 Na(1.0 + sin_psi_, 0.0, -1.0 + sin_psi_);
  double ga = phi_a / a_, gb = 0.0;
  Vec3 Nb = Vec3::Zero();
  Vec3 s = v - ga * m.DN(Na);
  r.return_type = ReturnType::Plane;
  if (!ordered(s)) {
    // (c) edge, dSN sign test
    const bool right = (1.0 - sin_psi_) * v(0) - 2.0 * v(1) + (1.0 + sin_psi_) * v(2) > 0.0;
    const double b = right ? b_right_ : b_left_;
    const double phi_b = right ? m.plane(v, 0, 1) : m.plane(v, 1, 2);
    Nb = right ? Vec3(1.0 + sin_psi_, -1.0 + sin_psi_, 0.0) : Vec3(0.0, 1.0 + sin_psi_, -1.0 + sin_psi_);
    const double det = a_ * a_ - b * b;
    ga = (a_ * phi_a - b * phi_b) / det;
    gb = (a_ * phi_b - b * phi_a) / det;
    s = v - ga * m.DN(Na) - gb * m.DN(Nb);
    r.return_type = right ? ReturnType::RightEdge : ReturnType::LeftEdge;
    // (d) apex when the edge point falls beyond it (never for phi = 0: Tresca has no apex)
    if (!(s(0) >= s(2)) && std::isfinite(apex_p_)) r.return_type = ReturnType::Apex;
  }

  Vec3 dep;  // principal plastic strain increment
  if (r.return_type == ReturnType::Apex) {
    s.setConstant(apex_p_);
    const Vec3 ds = v - s;  // D^-1 ds = ds/(2G) + (1/(9K) - 1/(6G)) tr(ds) 1
    dep = ds / (2.0 * G_) + Vec3::Constant((1.0 / (9.0 * K_) - 1.0 / (6.0 * G_)) * ds.sum());
    r.volumetric_plastic_strain_increment = (trial.trace() / 3.0 - apex_p_) / K_;
    r.plastic_multiplier = sin_psi_ > 0.0 ? r.volumetric_plastic_strain_increment / (2.0 * sin_psi_)
                                          : (v(0) - v(2)) / (4.0 * G_);
    r.plastic_multipliers = {r.plastic_multiplier, 0.0};
  } else {
    dep = ga * Na + gb * Nb;
    r.plastic_multipliers = {ga, gb};
    r.plastic_multiplier = ga + gb;
    r.volumetric_plastic_strain_increment = 2.0 * sin_psi_ * (ga + gb);
  }
  const Vec3 dev = dep - Vec3::Constant(dep.sum() / 3.0);
  r.equivalent_plastic_strain_increment = std::sqrt(2.0 / 3.0 * dev.squaredNorm());
  r.stress = r.return_type == ReturnType::Apex ? Matrix3d(apex_p_ * Matrix3d::Identity())  // exact
                                                : from_principal(s, pr.vectors);
  r.plastic_strain_increment = from_principal(dep, pr.vectors);
  return r;
}

MohrCoulomb::Result MohrCoulomb::update(const Matrix3d& sigma_n, const Matrix3d& strain_increment,
                                        const Matrix3d& spin_increment) const noexcept {
  const Matrix3d trial =
      DruckerPrager::jaumann_rotate(sigma_n, spin_increment) + elastic_increment(strain_increment);
  return return_map(trial);
}

}  // namespace geosph::soil
