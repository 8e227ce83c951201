// Drucker–Prager elastic–perfectly-plastic point model; sources and conventions in the header.
#include "soil/drucker_prager.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "soil/parameter_error.hpp"

namespace geosph::soil {

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

}  // namespace

void validate(const DruckerPragerParams& p) {
  // Comparisons are written so that NaN fails them.
  if (!(p.young > 0.0) || !std::isfinite(p.young)) reject_parameter("young", "> 0 (Young's modulus, Pa)", p.young);
  if (!(p.poisson > -1.0 && p.poisson < 0.5)) reject_parameter("poisson", "in (-1, 0.5) (Poisson's ratio)", p.poisson);
  if (!(p.cohesion >= 0.0) || !std::isfinite(p.cohesion)) reject_parameter("cohesion", ">= 0 (Pa)", p.cohesion);
  if (!(p.friction_angle >= 0.0 && p.friction_angle < 0.5 * std::numbers::pi))
    reject_parameter("friction_angle", "in [0, 90) degrees", p.friction_angle, true);
  if (!(p.dilatancy_angle >= 0.0 && p.dilatancy_angle <= p.friction_angle)) {
    std::ostringstream range;
    range.precision(10);
    range << "in [0, friction_angle] = [0, " << p.friction_angle * kDeg << "] degrees";
    reject_parameter("dilatancy_angle", range.str(), p.dilatancy_angle, true);
  }
}

double dp_alpha(double angle) {
  const double t = std::tan(angle);
  return t / std::sqrt(9.0 + 12.0 * t * t);
}

double dp_kc(double cohesion, double friction_angle) {
  const double t = std::tan(friction_angle);
  return 3.0 * cohesion / std::sqrt(9.0 + 12.0 * t * t);
}

DruckerPrager::DruckerPrager(const DruckerPragerParams& params) : params_(params) {
  validate(params_);
  K_ = params_.young / (3.0 * (1.0 - 2.0 * params_.poisson));
  G_ = params_.young / (2.0 * (1.0 + params_.poisson));
  alpha_phi_ = dp_alpha(params_.friction_angle);
  alpha_psi_ = dp_alpha(params_.dilatancy_angle);
  k_c_ = dp_kc(params_.cohesion, params_.friction_angle);
  apex_I1_ = alpha_phi_ > 0.0 ? k_c_ / alpha_phi_ : std::numeric_limits<double>::infinity();
}

namespace {

// sqrt(J2) of a deviator s: J2 = s:s/2.
inline double sqrt_J2(const Matrix3d& s) { return std::sqrt(0.5 * s.squaredNorm()); }

}  // namespace

double DruckerPrager::yield(const Matrix3d& sigma) const {
  const double I1 = sigma.trace();
  const Matrix3d s = sigma - (I1 / 3.0) * Matrix3d::Identity();
  return alpha_phi_ * I1 + sqrt_J2(s) - k_c_;
}

double DruckerPrager::potential(const Matrix3d& sigma) const {
  const double I1 = sigma.trace();
  const Matrix3d s = sigma - (I1 / 3.0) * Matrix3d::Identity();
  return alpha_psi_ * I1 + sqrt_J2(s);
}

Matrix3d DruckerPrager::hooke_increment(double K, double G, const Matrix3d& de) {
  const double tr = de.trace();
  Matrix3d d = (2.0 * G) * de;
  d.diagonal().array() += (K - 2.0 * G / 3.0) * tr;
  return d;
}

Matrix3d DruckerPrager::jaumann_rotate(const Matrix3d& sigma, const Matrix3d& W) {
  const Matrix3d Ws = W * sigma;
  return sigma + Ws + Ws.transpose();  // sigma W^T = (W sigma)^T for symmetric sigma
}

DruckerPrager::Result DruckerPrager::return_map(const Matrix3d& sigma_trial) const {
  Result r;
  r.plastic_multiplier = 0.0;
  r.volumetric_plastic_strain_increment = 0.0;
  r.equivalent_plastic_strain_increment = 0.0;

  const double I1 = sigma_trial.trace();
  const Matrix3d s = sigma_trial - (I1 / 3.0) * Matrix3d::Identity();
  const double q = sqrt_J2(s);  // sqrt(J2_trial)
  const double f = alpha_phi_ * I1 + q - k_c_;
  if (!(f > 0.0)) {
    r.stress = sigma_trial;
    r.plastic_strain_increment.setZero();
    r.return_type = ReturnType::Elastic;
    return r;
  }

  // The cone return passes the apex iff G dlambda > q with dlambda = f/(G + 9 K a_phi a_psi);
  // with f = a_phi (I1 - I1_apex) + q this is 9 K a_psi q < G (I1 - I1_apex) (for a_phi > 0),
  // evaluated without dividing by the (possibly zero) a_psi.
  if (alpha_phi_ > 0.0 && 9.0 * K_ * alpha_psi_ * q < G_ * (I1 - apex_I1_)) {
    // Apex return (also the tension cut-off, see header).
    r.return_type = ReturnType::Apex;
    r.stress = (apex_I1_ / 3.0) * Matrix3d::Identity();
    const double dev_vol = (I1 - apex_I1_) / (3.0 * K_);  // plastic volumetric strain, > 0
    r.plastic_strain_increment = s / (2.0 * G_);
    r.plastic_strain_increment.diagonal().array() += dev_vol / 3.0;
    r.volumetric_plastic_strain_increment = dev_vol;
    r.plastic_multiplier = alpha_psi_ > 0.0 ? dev_vol / (3.0 * alpha_psi_) : q / G_;
    r.equivalent_plastic_strain_increment = q / (std::sqrt(3.0) * G_);
    return r;
  }

  // Smooth-cone return (q > 0 here: q = 0 with f > 0 needs a_phi > 0 and I1 > I1_apex, i.e. apex).
  const double dl = f / (G_ + 9.0 * K_ * alpha_phi_ * alpha_psi_);
  const double I1_new = I1 - 9.0 * K_ * alpha_psi_ * dl;
  const double q_new = q - G_ * dl;  // >= 0
  r.return_type = ReturnType::Cone;
  r.stress = (q_new / q) * s;
  r.stress.diagonal().array() += I1_new / 3.0;
  r.plastic_multiplier = dl;
  r.plastic_strain_increment = (dl / (2.0 * q)) * s;  // dl * s/(2 sqrt(J2)), deviatoric part
  // s = trial - I1/3 I carries a trace of order eps |I1|; remove it so that the deviatoric part is
  // traceless to round-off relative to itself (tr = 0 up to ~1e-16 |de_p| for psi = 0).
  r.plastic_strain_increment.diagonal().array() -= r.plastic_strain_increment.trace() / 3.0;
  r.plastic_strain_increment.diagonal().array() += alpha_psi_ * dl;
  r.volumetric_plastic_strain_increment = 3.0 * alpha_psi_ * dl;
  r.equivalent_plastic_strain_increment = dl / std::sqrt(3.0);
  return r;
}

DruckerPrager::Result DruckerPrager::update(const Matrix3d& sigma_n, const Matrix3d& strain_increment,
                                            const Matrix3d& spin_increment) const {
  const Matrix3d trial = jaumann_rotate(sigma_n, spin_increment) + elastic_increment(strain_increment);
  return return_map(trial);
}

}  // namespace geosph::soil
