// Elasto-viscoplastic mu(I) point model; sources and the return in the header.
#include "soil/mu_i_rheology.hpp"

#include <cmath>

#include "soil/drucker_prager.hpp"
#include "soil/parameter_error.hpp"

namespace geosph::soil {

void validate(const MuIParams& p) {
  // Comparisons are written so that NaN fails them.
  if (!(p.young > 0.0) || !std::isfinite(p.young)) reject_parameter("young", "> 0 (Young's modulus, Pa)", p.young);
  if (!(p.poisson > -1.0 && p.poisson < 0.5)) reject_parameter("poisson", "in (-1, 0.5) (Poisson's ratio)", p.poisson);
  if (!(p.mu_s >= 0.0) || !std::isfinite(p.mu_s)) reject_parameter("mu_s", ">= 0", p.mu_s);
  if (!(p.mu_2 >= p.mu_s) || !std::isfinite(p.mu_2)) reject_parameter("mu_2", ">= mu_s", p.mu_2);
  if (!(p.i0 > 0.0) || !std::isfinite(p.i0)) reject_parameter("i0", "> 0", p.i0);
  if (!(p.grain_diameter > 0.0) || !std::isfinite(p.grain_diameter)) reject_parameter("grain_diameter", "> 0 (m)", p.grain_diameter);
  if (!(p.grain_density > 0.0) || !std::isfinite(p.grain_density)) reject_parameter("grain_density", "> 0 (kg/m^3)", p.grain_density);
}

MuIRheology::MuIRheology(const MuIParams& params) : params_(params) {
  validate(params_);
  K_ = params_.young / (3.0 * (1.0 - 2.0 * params_.poisson));
  G_ = params_.young / (2.0 * (1.0 + params_.poisson));
}

double MuIRheology::friction(double I) const {
  return I > 0 ? params_.mu_s + (params_.mu_2 - params_.mu_s) * I / (params_.i0 + I) : params_.mu_s;
}

MuIResult MuIRheology::update(const Eigen::Matrix3d& sigma_n, const Eigen::Matrix3d& de, const Eigen::Matrix3d& dw,
                              double dt) const {
  const Eigen::Matrix3d I3 = Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d trial = DruckerPrager::jaumann_rotate(sigma_n, dw) + DruckerPrager::hooke_increment(K_, G_, de);
  MuIResult r;
  const double p = -trial.trace() / 3.0;
  const Eigen::Matrix3d s = trial + p * I3;
  const double tau_trial = std::sqrt(0.5 * (s.array() * s.array()).sum());
  if (!(p > 0.0)) {  // disconnected: no contact stress
    r.stress.setZero();
    r.disconnected = true;
    r.equivalent_plastic_strain_increment = tau_trial / (std::sqrt(3.0) * G_);
    return r;
  }
  if (tau_trial <= params_.mu_s * p || !(dt > 0.0)) {
    r.stress = trial;
    return r;
  }
  const double xi = params_.i0 * std::sqrt(p / params_.grain_density) / params_.grain_diameter;
  const double a = G_ * dt;
  const double b = a * xi + params_.mu_2 * p - tau_trial;
  const double c = -(tau_trial - params_.mu_s * p) * xi;  // < 0
  const double disc = std::sqrt(b * b - 4.0 * a * c);
  // the positive root, in the form that does not cancel
  const double rate = b >= 0.0 ? -2.0 * c / (b + disc) : (-b + disc) / (2.0 * a);
  const double tau = tau_trial - a * rate;
  r.stress = -p * I3 + (tau / tau_trial) * s;
  r.shear_rate = rate;
  r.inertial_number = rate / xi * params_.i0;
  r.equivalent_plastic_strain_increment = rate * dt / std::sqrt(3.0);
  return r;
}

}  // namespace geosph::soil
