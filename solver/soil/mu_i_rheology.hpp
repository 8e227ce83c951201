// Elasto-viscoplastic mu(I) granular rheology: a pure material-point model (stress in, stress out),
// TENSION POSITIVE as the other soil models (soil/drucker_prager.hpp).
//
// Rheology (Jop, Forterre & Pouliquen 2006, Nature 441:727, eqs. 1-2): in flow the equivalent shear
// stress is tau = mu(I) p with
//   mu(I) = mu_s + (mu_2 - mu_s) / (I_0 / I + 1),   I = gamma_dot d / sqrt(p / rho_s),
// tau = sqrt(J2) = |dev sigma| / sqrt(2), p = -tr(sigma)/3 and gamma_dot = sqrt(2 D^p:D^p) the
// plastic shear rate (Jop's |gamma_dot| = sqrt(gamma_dot_ij gamma_dot_ij / 2), gamma_dot_ij = 2 D_ij).
// Below mu_s p the material is elastic (Hooke with E, nu); at p <= 0 it is disconnected and carries
// no stress. This is the elasto-viscoplastic form of Dunatunga & Kamrin (2015), J. Fluid Mech.
// 779:483-513, Sec. 3, which keeps the static (elastic) state of the soil models instead of the
// regularised viscosity of a fluid solver.
//
// Stress update over one step of length dt:
//   (a) Jaumann rotation and elastic predictor as Drucker-Prager (soil/drucker_prager.hpp (a), (b)).
//   (b) p = p_trial (no plastic volume change: the flow is deviatoric, D^p = gamma_dot s/(2 tau)).
//   (c) if tau_trial > mu_s p, backward-Euler return along s: tau = tau_trial - G dt gamma_dot with
//       tau = mu(I(gamma_dot)) p. With xi = I_0 sqrt(p / rho_s) / d (the shear rate at I = I_0) this is
//         G dt gamma^2 + (G dt xi + mu_2 p - tau_trial) gamma - (tau_trial - mu_s p) xi = 0,
//       whose one positive root is the plastic shear rate (the product of the roots is negative);
//       s = s_trial tau / tau_trial. As d -> 0 (xi -> infinity) it is the rate-independent
//       return to tau = mu_s p; as dt -> 0 at a set rate it is tau = mu(I) p exactly.
//   equivalent (deviatoric) plastic strain increment = gamma_dot dt / sqrt(3), the Drucker-Prager
//   measure sqrt(2/3 dev(de_p):dev(de_p)).
#pragma once

#include <Eigen/Core>

namespace geosph::soil {

struct MuIParams {
  double young;           // E > 0 [Pa]
  double poisson;         // nu in (-1, 0.5)
  double mu_s;            // static friction coefficient, >= 0
  double mu_2;            // limiting friction coefficient at large I, >= mu_s
  double i0;              // I_0 > 0
  double grain_diameter;  // d > 0 [m]
  double grain_density;   // rho_s > 0 [kg/m^3]
};

// Throws std::invalid_argument naming the offending field and its allowed range (NaN is rejected).
void validate(const MuIParams& params);

struct MuIResult {
  Eigen::Matrix3d stress;
  double shear_rate = 0;           // plastic gamma_dot [1/s] (0 when elastic or disconnected)
  double inertial_number = 0;      // I of the step (0 when elastic or disconnected)
  double equivalent_plastic_strain_increment = 0;
  bool disconnected = false;       // p_trial <= 0: stress-free
};

class MuIRheology {
 public:
  explicit MuIRheology(const MuIParams& params);  // validates (std::invalid_argument)

  const MuIParams& params() const { return params_; }
  double shear_modulus() const { return G_; }
  double bulk_modulus() const { return K_; }
  double friction(double inertial_number) const;  // mu(I)

  // One step: strain_increment = dt D, spin_increment = dt omega (as DruckerPrager::update).
  MuIResult update(const Eigen::Matrix3d& sigma_n, const Eigen::Matrix3d& strain_increment,
                   const Eigen::Matrix3d& spin_increment, double dt) const;

 private:
  MuIParams params_;
  double K_, G_;
};

}  // namespace geosph::soil
