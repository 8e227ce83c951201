// Mohr–Coulomb elastic–perfectly-plastic soil model with the true hexagonal-pyramid yield surface:
// a pure, SPH-independent material-point model (stress in, stress out). Sign convention: TENSION
// POSITIVE, as in soil/drucker_prager.hpp; stresses and strains are full 3x3 symmetric tensors (in
// plane strain the caller passes zero zz/xz/yz strain increments and sigma_zz is carried).
//
// Source: de Souza Neto, Peric & Owen (2008), "Computational Methods for Plasticity", Wiley,
// Sec. 8.2 (cited as dSN), return mapping in principal stresses, Boxes 8.4–8.5, here with no
// hardening (c constant). dSN write the model tension positive too, so no sign change is needed;
// the coefficients a, b below were re-derived here as N_phi.D.N_psi of the planes involved (with
// D N = (K - 2G/3) tr(N) 1 + 2 G N), which reproduces dSN's expressions. Principal stresses are ordered sigma_1 >= sigma_2 >= sigma_3; s_phi = sin(phi),
// c_phi = cos(phi), s_psi = sin(psi).
//
//   main plane      Phi_a = (sigma_1 - sigma_3) + (sigma_1 + sigma_3) s_phi - 2 c c_phi
//   potential       Psi_a = (sigma_1 - sigma_3) + (sigma_1 + sigma_3) s_psi   (psi <= phi)
//   yield(sigma) = Phi_a of the ordered principal stresses = max of the six planes' Phi.
//   Mohr's circle form: t = c c_phi - p s_phi, t = (sigma_1 - sigma_3)/2, p = (sigma_1 + sigma_3)/2.
//   Elasticity in principal space: D N = (K - 2G/3) tr(N) 1 + 2 G N.
//
// Return (dSN Boxes 8.4–8.5, perfectly plastic); sigma^tr ordered:
//   (a) Phi_a(sigma^tr) <= 0: elastic, sigma = sigma^tr (no eigen-decomposition).
//   (b) main plane: sigma = sigma^tr - dgamma D N_a, N_a = dPsi_a/dsigma = (1 + s_psi, 0, -1 + s_psi),
//       dgamma = Phi_a^tr / a,  a = N_phi.D.N_psi = 4G (1 + s_phi s_psi / 3) + 4K s_phi s_psi.
//       Valid if the ordering survives: sigma_1 >= sigma_2 >= sigma_3.
//   (c) otherwise an edge, chosen by dSN's sign test (the test's linear form is unchanged by the
//       main-plane return, so its sign tells which ordering the main-plane return broke):
//         (1 - s_psi) sigma_1^tr - 2 sigma_2^tr + (1 + s_psi) sigma_3^tr > 0  -> RIGHT edge
//       RIGHT edge sigma_2 = sigma_3 (triaxial EXTENSION, tension positive), second plane
//         Phi_b = (sigma_1 - sigma_2) + (sigma_1 + sigma_2) s_phi - 2 c c_phi,  N_b = (1+s_psi, -1+s_psi, 0),
//         b = 2G (1 + s_phi + s_psi - s_phi s_psi / 3) + 4K s_phi s_psi;
//       LEFT edge sigma_1 = sigma_2 (triaxial COMPRESSION), second plane
//         Phi_b = (sigma_2 - sigma_3) + (sigma_2 + sigma_3) s_phi - 2 c c_phi,  N_b = (0, 1+s_psi, -1+s_psi),
//         b = 2G (1 - s_phi - s_psi - s_phi s_psi / 3) + 4K s_phi s_psi;
//       the 2x2 system [a b; b a] (dgamma_a, dgamma_b) = (Phi_a^tr, Phi_b^tr) has the closed form
//         dgamma_a = (a Phi_a - b Phi_b)/(a^2 - b^2),  dgamma_b = (a Phi_b - b Phi_a)/(a^2 - b^2),
//       (a - b = 2G (1 - s_phi)(1 - s_psi) right, 2G (1 + s_phi)(1 + s_psi) left: > 0),
//       sigma = sigma^tr - dgamma_a D N_a - dgamma_b D N_b.
//       Valid if sigma_1 >= sigma_3 (the edge point is on the pyramid side of the apex); the unit
//       tests check that dgamma_a, dgamma_b >= 0 then, and (associated flow) the closest-point
//       variational inequality, i.e. that this selection picks the right region.
//   (d) otherwise the apex (phi > 0 only): sigma = c cot(phi) I (set exactly), the model's tension
//       cut-off; the plastic volume change is eps_v^p = (p^tr - c cot phi)/K, p = tr(sigma)/3. For
//       psi > 0 the plastic strain is then a non-negative combination of the six planes' N_psi
//       (checked in the unit tests); for psi = 0 its volume change is the crack opening of the
//       cut-off, which the flow rule alone could not give. With phi = 0 (Tresca, psi = 0) there is no
//       apex: the returns are purely deviatoric and the edge return is always valid.
//   The stress tensor is rebuilt with the trial's eigenvectors, so the return is coaxial.
//
// Plastic strain reported (Result): plastic_strain_increment = D^-1 : (sigma^tr - sigma_{n+1}); on
//   a plane/edge it is sum dgamma_i N_i in the principal frame, trace 2 s_psi (dgamma_a + dgamma_b).
//   equivalent_plastic_strain_increment = sqrt(2/3 dev(de_p):dev(de_p)), as in DruckerPrager.
//   At the apex the multipliers of the six planes are not unique: plastic_multiplier is then
//   eps_v^p / (2 s_psi) (the total that the flow rule needs for the volume change) for psi > 0 and
//   (sigma_1^tr - sigma_3^tr)/(4G) (the main-plane multiplier of the deviatoric part) for psi = 0.
//
// update() does (a) the Jaumann rotation of DruckerPrager::update (DruckerPrager::jaumann_rotate),
// (b) the elastic predictor and (c) the return. It allocates nothing (fixed-size Eigen types),
// never throws (a non-finite input gives a non-finite stress) and is safe to call concurrently on a
// const MohrCoulomb.
#pragma once

#include <array>

#include <Eigen/Core>

#include "soil/drucker_prager.hpp"  // Matrix3d, DruckerPrager::jaumann_rotate

namespace geosph::soil {

// Material constants, SI units (Pa, radians).
struct MohrCoulombParams {
  double young;            // E > 0
  double poisson;          // nu in (-1, 0.5)
  double cohesion;         // c >= 0 (c = 0 needs phi > 0)
  double friction_angle;   // phi in [0, 90) degrees, given in radians
  double dilatancy_angle;  // psi in [0, phi], given in radians
};

// Throws std::invalid_argument naming the offending field and its allowed range (NaN is rejected;
// c = 0 with phi = 0 is rejected: no strength).
void validate(const MohrCoulombParams& params);

enum class MohrCoulombReturnType { Elastic, Plane, LeftEdge, RightEdge, Apex };

struct MohrCoulombResult {
  Matrix3d stress;                             // sigma_{n+1}
  Matrix3d plastic_strain_increment;           // D^-1 : (sigma_trial - sigma_{n+1})
  std::array<double, 2> plastic_multipliers;   // (dgamma_a, dgamma_b); dgamma_b = 0 on the plane
  double plastic_multiplier;                   // dgamma_a + dgamma_b (apex: see header)
  double volumetric_plastic_strain_increment;  // 2 s_psi (dgamma_a + dgamma_b); apex (p^tr - p_apex)/K
  double equivalent_plastic_strain_increment;  // sqrt(2/3 dev(de_p):dev(de_p))
  MohrCoulombReturnType return_type;
};

class MohrCoulomb {
 public:
  using Result = MohrCoulombResult;
  using ReturnType = MohrCoulombReturnType;

  explicit MohrCoulomb(const MohrCoulombParams& params);  // validates (std::invalid_argument)

  const MohrCoulombParams& params() const { return params_; }
  double bulk_modulus() const { return K_; }   // K = E / (3 (1 - 2 nu))
  double shear_modulus() const { return G_; }  // G = E / (2 (1 + nu))
  // Mean stress of the apex, c cot(phi); +infinity for phi = 0 (Tresca prism, no apex).
  double apex_mean_stress() const { return apex_p_; }

  // Phi_a of the ordered principal stresses, = max over the six planes (units of stress: 2 x shear).
  double yield(const Matrix3d& sigma) const;
  // D : de = 2 G dev(de) + K tr(de) I
  Matrix3d elastic_increment(const Matrix3d& strain_increment) const;
  // Return of a trial stress (step (c) alone). Never throws.
  Result return_map(const Matrix3d& sigma_trial) const noexcept;
  // One step: strain_increment = dt * sym(grad v), spin_increment = dt * skew(grad v). Never throws.
  Result update(const Matrix3d& sigma_n, const Matrix3d& strain_increment,
                const Matrix3d& spin_increment) const noexcept;

 private:
  MohrCoulombParams params_;
  double K_, G_, sin_phi_, sin_psi_, two_c_cos_phi_, apex_p_;
  double a_, b_right_, b_left_;  // N_phi.D.N_psi of the plane and of the two edges (header)
};

}  // namespace geosph::soil
