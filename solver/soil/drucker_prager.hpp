// Drucker–Prager elastic–perfectly-plastic soil model: a pure, SPH-independent material-point
// model (stress in, stress out). Sign convention: TENSION POSITIVE, as in Bui, Fukagawa, Sako &
// Ohno (2008), "Lagrangian meshfree particles method (SPH) for large deformation and failure flows
// of geomaterial using elastic–plastic soil constitutive model", Int. J. Numer. Anal. Meth.
// Geomech. 32:1537–1570 (cited below as Bui 2008). Stresses and strains are full 3x3 symmetric
// tensors; in plane strain the caller passes zero zz/xz/yz strain increments and the zz stress is
// carried (it is needed for I1 and J2).
//
// Model (Bui 2008, Drucker–Prager model with non-associated flow):
//   yield function    f = alpha_phi I1 + sqrt(J2) - k_c
//   plastic potential g = alpha_psi I1 + sqrt(J2)
//   I1 = tr(sigma), s = sigma - I1/3 I, J2 = s:s/2.
//   Plane-strain matching of the Mohr–Coulomb c, phi (Bui 2008, eq. 13 and the plane-strain
//   matching discussed there):
//     alpha_phi = tan(phi) / sqrt(9 + 12 tan^2 phi),  k_c = 3 c / sqrt(9 + 12 tan^2 phi),
//     alpha_psi = tan(psi) / sqrt(9 + 12 tan^2 psi)   (same matching with the dilatancy angle).
//   With phi = 0: alpha_phi = 0, k_c = c, i.e. sqrt(J2) = c: von Mises matched to Tresca in plane
//   strain (undrained strength c).
//   The cone's apex is at s = 0, I1 = k_c/alpha_phi (in tension; the origin when c = 0).
//
// Stress update over one step (DruckerPrager::update):
//   (a) Jaumann rotation, forward Euler (Bui 2008, eqs. 19 and 25: d sigma/dt = sigma.omega^T +
//       omega.sigma + ...):  sigma_rot = sigma_n + sigma_n W^T + W sigma_n,  W = dt * omega,
//       omega_ab = (dv_a/dx_b - dv_b/dx_a)/2; a rigid rotation R ~ I + W rotates the stress to first
//       order (R sigma R^T = sigma_rot + W sigma W^T). The rotation leaves I1 unchanged (exactly in
//       exact arithmetic, tr(W sigma + sigma W^T) = 0).
//   (b) elastic predictor: sigma_trial = sigma_rot + 2 G dev(de) + K tr(de) I.
//   (c) return mapping: closest-point (backward-Euler) return for Drucker–Prager with non-associated
//       flow, de Souza Neto, Peric & Owen (2008), "Computational Methods for Plasticity", Wiley,
//       Sec. 8.3.2, with their eta = 3 alpha_phi, eta_bar = 3 alpha_psi, xi c = k_c
//       and no hardening:
//         cone:  Delta_lambda = f_trial / (G + 9 K alpha_phi alpha_psi)   (closed form),
//                s = (1 - G Delta_lambda / sqrt(J2_trial)) s_trial,
//                I1 = I1_trial - 9 K alpha_psi Delta_lambda;
//         apex:  used when the cone return would pass the apex, i.e. when
//                G Delta_lambda > sqrt(J2_trial)  <=>  9 K alpha_psi sqrt(J2_trial) < G (I1_trial - k_c/alpha_phi);
//                sigma = k_c/(3 alpha_phi) I.
//       The apex return is also the tension cut-off: any trial state in tension beyond the apex
//       (I1_trial > k_c/alpha_phi) goes to the apex, which is what the tension-cracking treatment
//       of Bui 2008 (shift I1 back to k_c/alpha_phi, then scale s by
//       (k_c - alpha_phi I1)/sqrt(J2) = 0 at the apex) produces. With psi = 0 every trial state beyond the apex
//       is returned this way (the cone return passes the apex exactly when I1_trial > k_c/alpha_phi).
//
// Plastic strain reported (Result): plastic_strain_increment = D^-1 : (sigma_trial - sigma_new).
//   On the cone this is Delta_lambda dg/dsigma = Delta_lambda (alpha_psi I + s/(2 sqrt(J2))), with
//   trace 3 alpha_psi Delta_lambda (0 for psi = 0, dilation > 0 for psi > 0, tension positive).
//   At the apex with psi > 0 it is Delta_lambda (alpha_psi I + d), d in the subdifferential of
//   sqrt(J2) at s = 0, and Delta_lambda = (I1_trial - I1_apex)/(9 K alpha_psi) (de Souza Neto's
//   Delta eps_v^p / eta_bar), so again tr = 3 alpha_psi Delta_lambda. At the apex with psi = 0 the
//   flow rule cannot produce volume change: the volumetric part (I1_trial - I1_apex)/(3K) > 0 is the
//   tension-crack opening of the cut-off, and Delta_lambda is reported as sqrt(J2_trial)/G (the
//   multiplier of the deviatoric part alone).
//   equivalent_plastic_strain_increment = sqrt(2/3 dev(de_p):dev(de_p)) (equivalent DEVIATORIC
//   plastic strain, von Mises style; = Delta_lambda/sqrt(3) on the cone,
//   sqrt(J2_trial)/(sqrt(3) G) at the apex).
//
// update() allocates nothing (fixed-size Eigen types only) and is safe to call concurrently on a
// const DruckerPrager.
#pragma once

#include <Eigen/Core>

namespace geosph::soil {

using Matrix3d = Eigen::Matrix3d;

// Material constants, SI units (Pa, radians).
struct DruckerPragerParams {
  double young;            // E > 0
  double poisson;          // nu in (-1, 0.5)
  double cohesion;         // c >= 0
  double friction_angle;   // phi in [0, 90) degrees, given in radians
  double dilatancy_angle;  // psi in [0, phi], given in radians
};

// Throws std::invalid_argument naming the offending field and its allowed range (NaN is rejected).
void validate(const DruckerPragerParams& params);

// Plane-strain matching of Mohr–Coulomb to Drucker–Prager (Bui 2008, eq. 13).
double dp_alpha(double angle);                          // tan(a) / sqrt(9 + 12 tan^2 a)
double dp_kc(double cohesion, double friction_angle);  // 3 c / sqrt(9 + 12 tan^2 phi)

enum class ReturnType { Elastic, Cone, Apex };

struct DruckerPragerResult {
  Matrix3d stress;                            // sigma_{n+1}
  Matrix3d plastic_strain_increment;          // D^-1 : (sigma_trial - sigma_{n+1}), see above
  double plastic_multiplier;                  // Delta_lambda (0 if elastic)
  double volumetric_plastic_strain_increment; // 3 alpha_psi Delta_lambda (exactly 0 for psi = 0 on
                                              // the cone); (I1_tr - I1_apex)/(3K) at the apex
  double equivalent_plastic_strain_increment; // sqrt(2/3 dev(de_p):dev(de_p))
  ReturnType return_type;
};

class DruckerPrager {
 public:
  using Result = DruckerPragerResult;

  explicit DruckerPrager(const DruckerPragerParams& params);  // validates (std::invalid_argument)

  const DruckerPragerParams& params() const { return params_; }
  double bulk_modulus() const { return K_; }   // K = E / (3 (1 - 2 nu))
  double shear_modulus() const { return G_; }  // G = E / (2 (1 + nu))
  double alpha_phi() const { return alpha_phi_; }
  double alpha_psi() const { return alpha_psi_; }
  double k_c() const { return k_c_; }
  // I1 at the apex, k_c/alpha_phi; +infinity when alpha_phi = 0 (von Mises cylinder, no apex).
  double apex_I1() const { return apex_I1_; }

  double yield(const Matrix3d& sigma) const;      // f = alpha_phi I1 + sqrt(J2) - k_c
  double potential(const Matrix3d& sigma) const;  // g = alpha_psi I1 + sqrt(J2)

  // D : de = 2 G dev(de) + K tr(de) I
  Matrix3d elastic_increment(const Matrix3d& strain_increment) const { return hooke_increment(K_, G_, strain_increment); }
  // the same for any bulk and shear modulus (the isotropic elastic predictor the soil models share)
  static Matrix3d hooke_increment(double bulk, double shear, const Matrix3d& strain_increment);
  // sigma + sigma W^T + W sigma (sigma symmetric; the result is symmetric)
  static Matrix3d jaumann_rotate(const Matrix3d& sigma, const Matrix3d& spin_increment);
  // Closest-point return of a trial stress (step (c) alone).
  Result return_map(const Matrix3d& sigma_trial) const;

  // One step: strain_increment = dt * (grad v + grad v^T)/2 (symmetric),
  // spin_increment = dt * omega, omega_ab = (dv_a/dx_b - dv_b/dx_a)/2 (antisymmetric).
  Result update(const Matrix3d& sigma_n, const Matrix3d& strain_increment,
                const Matrix3d& spin_increment) const;

 private:
  DruckerPragerParams params_;
  double K_, G_, alpha_phi_, alpha_psi_, k_c_, apex_I1_;
};

}  // namespace geosph::soil
