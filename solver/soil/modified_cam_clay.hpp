// Modified Cam Clay (MCC) elasto-plastic soil model: a pure, SPH-independent material-point model
// (stress and preconsolidation pressure in, stress and preconsolidation pressure out), in EFFECTIVE
// stresses. Sign convention at the interface: TENSION POSITIVE, as in the Drucker–Prager model
// (soil/drucker_prager.hpp); internally the model works with the usual soil-mechanics invariants,
// which are COMPRESSION POSITIVE:
//   p' = -tr(sigma)/3,  s = sigma + p' I,  q = sqrt(3 J2) = sqrt(3/2 s:s),
//   d eps_v = -tr(d eps)  (compression positive),  d e = dev(d eps),  d eps_q = sqrt(2/3 d e : d e).
// Stresses and strains are full 3x3 symmetric tensors; in plane strain the caller passes zero
// zz/xz/yz strain increments and the zz stress is carried (as in the Drucker–Prager model).
//
// Model (Roscoe & Burland 1968, "On the generalised stress-strain behaviour of 'wet' clay", in
// Engineering Plasticity, Cambridge UP, pp. 535–609; notation of Wood 1990, "Soil Behaviour and
// Critical State Soil Mechanics", Cambridge UP, Ch. 4 (elasticity and the yield locus) and Ch. 5
// (hardening, the elastic–plastic rate equations)):
//   yield function  f = q^2/M^2 + p'(p' - p_c)        (ellipse through the origin and (p_c, 0))
//   associated flow d eps^p = d gamma df/dsigma = d gamma (-(2p' - p_c)/3 I + 3 s/M^2), i.e.
//                   d eps_v^p = d gamma (2p' - p_c)  (compression positive),  d eps_q^p = d gamma 2q/M^2
//   hardening       d p_c / p_c = theta d eps_v^p,  theta = v/(lambda - kappa)
//   elasticity      K = v max(p', p'_min)/kappa,  G = 3K(1 - 2 nu)/(2(1 + nu))  (constant Poisson ratio)
// v = 1 + e is held CONSTANT (ModifiedCamClayParams::specific_volume): this is the usual
// small-strain form of the model; the consequences of a changing v are second order in the strain.
// Critical state: q = M p', p_c = 2 p'. Isotropic normal compression line (q = 0, p' = p_c):
// d eps_v = lambda/v d ln p'. Unloading–reloading lines: d eps_v = kappa/v d ln p'.
//
// Stress update over one step (ModifiedCamClay::update, strain-driven, from (sigma_n, p_c,n)):
//   (a) Jaumann rotation of sigma_n (forward Euler), DruckerPrager::jaumann_rotate: it leaves p'
//       unchanged exactly and q to O(|W|^2).
//   (b) elastic predictor, integrated over the step:
//         p'_trial = P(p'_n, d eps_v): the exact solution of dp' = v max(p', p'_min)/kappa d eps_v^e,
//           = p'_n exp(v d eps_v/kappa) while p' >= p'_min (secant/log form, Borja 1991), linear with
//           slope v p'_min/kappa below p'_min (so a stress-free particle, p'_n = 0, does stiffen);
//         s_trial = dev(sigma_n) + 2 G_n dev(d eps),  G_n = G(p'_n)  -- CHOICE: the shear modulus is
//           evaluated at the start of the step (explicit in G; first-order accurate in the step like
//           the return itself, and it keeps the return radial in the deviatoric plane).
//   (c) if p'_trial < 0: tension cut-off, the point goes to the apex p' = 0, q = 0 (no tension,
//       cohesionless), p_c unchanged (the volumetric strain beyond p' = 0 is reported as plastic
//       opening, like the tension crack of the Drucker–Prager model, and is not Cam-clay dilation).
//       Else if f(p'_trial, q_trial, p_c,n) <= 0: elastic.
//   (d) else implicit closest-point (backward-Euler) return in the invariants (Borja & Lee 1990,
//       "Cam-Clay plasticity, Part I: implicit integration of elasto-plastic constitutive relations",
//       Comput. Methods Appl. Mech. Eng. 78:49–72; Borja 1991, "Cam-Clay plasticity, Part II:
//       implicit integration of constitutive equation based on a nonlinear elastic stress
//       predictor", CMAME 88:225–240), unknowns Delta_gamma, p'_{n+1}, p_c,n+1:
//         x = Delta eps_v^p = Delta_gamma (2p' - p_c)                    (evaluated at n+1)
//         p'   = P(p'_n, d eps_v - x)                                      (exact log elasticity)
//         p_c  = p_c,n exp(theta x)                                        (exact hardening)
//         q    = q_trial - 3 G_n Delta eps_q^p = q_trial / (1 + 6 G_n Delta_gamma/M^2)
//         s    = (q/q_trial) s_trial        (radial: n = s_trial/|s_trial| is preserved)
//         f(p', q, p_c) = 0.
//       Solution: for a given Delta_gamma >= 0 the first three equations have a unique x (the
//       residual x - Delta_gamma (2p'(x) - p_c(x)) is strictly increasing in x); it is found by
//       Newton's method safeguarded by bisection inside a bracket that does not depend on
//       Delta_gamma. The outer scalar equation F(Delta_gamma) = f(...) = 0 has F(0) = f_trial > 0
//       and F -> -p'^2 < 0 as Delta_gamma -> infinity, so a root always exists; it is found by
//       Newton's method (analytic derivative) safeguarded by bisection / bracket expansion, which
//       converges for large steps on the wet (hardening) and dry (softening) sides alike.
//       Tolerance |f| <= 1e-12 p_c,n+1^2 (accepted at 1e-10 if the bracket collapses first at the
//       round-off level), at most 50 outer iterations.
//   update() never throws (it runs inside OpenMP loops): a failed return sets converged = false
//   and returns the last iterate; invalid inputs (p_c,n <= 0 or non-finite) return the elastic
//   trial state with converged = false.
//
// Reported plastic strains (Result): volumetric_plastic_strain_increment = tr(Delta eps^p), TENSION
// POSITIVE like the Drucker–Prager model (= -x: negative for compaction on the wet side, positive
// for dilation on the dry side and for the opening at the apex);
// equivalent_plastic_strain_increment = sqrt(2/3 dev(Delta eps^p):dev(Delta eps^p)) = 2 Delta_gamma q/M^2
// (= q_trial/(3 G_n) at the apex).
//
// update() allocates nothing (fixed-size Eigen types only) and is safe to call concurrently on a
// const ModifiedCamClay.
#pragma once

#include <Eigen/Core>

#include "soil/drucker_prager.hpp"  // Matrix3d, DruckerPrager::jaumann_rotate

namespace geosph::soil {

// Material constants (dimensionless, except min_pressure in Pa).
struct ModifiedCamClayParams {
  double lambda;           // slope of the normal compression line in v - ln p' (> kappa)
  double kappa;            // slope of the unloading-reloading lines in v - ln p' (> 0)
  double M;                // critical state line slope in q - p' (> 0)
  double poisson;          // constant Poisson ratio nu in (-1, 0.5): G = 3K(1 - 2nu)/(2(1 + nu))
  double specific_volume;  // v = 1 + e (> 1), held constant (small-strain form): K = v p'/kappa,
                           // theta = v/(lambda - kappa)
  double min_pressure;     // p'_min > 0 [Pa]: floor on p' in the elastic moduli (stress-free surfaces)
};

// Throws std::invalid_argument naming the offending field and its allowed range (NaN is rejected).
void validate(const ModifiedCamClayParams& params);

struct ModifiedCamClayResult {
  Matrix3d stress;                             // sigma_{n+1}, tension positive
  double preconsolidation;                     // p_c,n+1 [Pa] (> 0)
  double volumetric_plastic_strain_increment;  // tr(Delta eps^p), TENSION positive (= -Delta eps_v^p)
  double equivalent_plastic_strain_increment;  // sqrt(2/3 dev(Delta eps^p):dev(Delta eps^p))
  int iterations;                              // outer Newton iterations (0 if elastic or apex)
  bool converged;                              // false if the local Newton did not converge
  bool plastic;                                // plastic return (smooth surface or apex)
};

class ModifiedCamClay {
 public:
  using Result = ModifiedCamClayResult;

  explicit ModifiedCamClay(const ModifiedCamClayParams& params);  // validates (std::invalid_argument)

  const ModifiedCamClayParams& params() const { return params_; }
  double theta() const { return theta_; }  // v/(lambda - kappa)

  static double mean_effective_stress(const Matrix3d& sigma);  // p' = -tr(sigma)/3
  static double deviator_stress(const Matrix3d& sigma);        // q = sqrt(3 J2)

  // f = q^2/M^2 + p'(p' - p_c)
  double yield(const Matrix3d& sigma, double pc) const;
  double bulk_modulus(double p) const;   // K = v max(p', p'_min)/kappa
  double shear_modulus(double p) const;  // G = 3 K(p') (1 - 2 nu)/(2 (1 + nu))

  // sigma + sigma W^T + W sigma: the Drucker–Prager model's rotation (same function).
  static Matrix3d jaumann_rotate(const Matrix3d& sigma, const Matrix3d& spin_increment) {
    return DruckerPrager::jaumann_rotate(sigma, spin_increment);
  }

  // Steps (b)-(d) of the header from an already rotated sigma_n.
  Result return_map(const Matrix3d& sigma_n, double pc_n, const Matrix3d& strain_increment) const;

  // One step: strain_increment = dt * (grad v + grad v^T)/2 (symmetric),
  // spin_increment = dt * omega, omega_ab = (dv_a/dx_b - dv_b/dx_a)/2 (antisymmetric).
  Result update(const Matrix3d& sigma_n, double pc_n, const Matrix3d& strain_increment,
                const Matrix3d& spin_increment) const;

  // Initialisation helper: p_c of the yield surface through (p', q), times the overconsolidation
  // ratio: p_c = OCR (p' + q^2/(M^2 p')). Throws std::invalid_argument unless p' > 0, q >= 0,
  // M > 0 and OCR >= 1 (all finite); the caller floors p' (e.g. with min_pressure) at a free surface.
  static double preconsolidation_for(double p, double q, double M, double ocr);

 private:
  ModifiedCamClayParams params_;
  double theta_;        // v/(lambda - kappa)
  double c_;            // v/kappa
  double shear_ratio_;  // G/K = 3(1 - 2 nu)/(2(1 + nu))
};

}  // namespace geosph::soil
