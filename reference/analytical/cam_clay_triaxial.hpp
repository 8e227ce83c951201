// Element-test references for the Modified Cam Clay (MCC) model in triaxial space, written from the
// continuum rate equations of the model and sharing no code with the solver's return mapping
// (solver/soil/modified_cam_clay.*). Compression positive throughout (soil mechanics convention):
// p' mean effective stress, q = sigma_a - sigma_r deviator stress, eps_v = eps_a + 2 eps_r,
// eps_q = 2/3 (eps_a - eps_r), hence eps_a = eps_q + eps_v/3.
//
// Model (Roscoe & Burland 1968, "On the generalised stress-strain behaviour of 'wet' clay", in
// Engineering Plasticity, Cambridge UP, 535–609; notation and rate equations of Wood 1990, "Soil
// Behaviour and Critical State Soil Mechanics", Cambridge UP, the chapters on the elastic–plastic
// (Cam clay) model and on critical states), with constant specific volume v (small-strain form, as
// in the solver):
//   yield locus       q^2 = M^2 p'(p_c - p'),  i.e. p_c = p'(1 + eta^2/M^2), eta = q/p'
//   elastic           d eps_v^e = kappa/v dp'/p',  d eps_q^e = dq/(3 G(p')),
//                     G = 3K(1 - 2nu)/(2(1 + nu)), K = v p'/kappa  (constant Poisson ratio)
//   plastic (yielding) d eps_v^p = (lambda - kappa)/v dp_c/p_c,
//                     d eps_q^p / d eps_v^p = 2 eta/(M^2 - eta^2)   (associated flow)
//   critical state    eta = M, p_c = 2 p'.
//
// 1. Drained conventional triaxial compression (sigma_r' constant, dq/dp' = 3) from an isotropic
//    state p'_0 with p_c0 = OCR p'_0 (Wood 1990, the worked drained and undrained triaxial
//    predictions of the Cam clay model; Borja & Lee 1990, CMAME 78:49–72, drained and undrained
//    triaxial examples of the same model): elastic until the path
//    p' = p'_0 + q/3 meets the initial locus, then on the expanding locus. Strains are integrated
//    over q with GSL adaptive quadrature (QAGS) of the rate equations above; the path tends to the
//    critical state q -> M p'_cs with p'_cs = 3 p'_0/(3 - M) (the strains grow without bound,
//    logarithmically in M p'_cs - q). Only wet-side yielding is supported (hardening, q monotone):
//    OCR < 6/(3 - M) and M < 3.
// 2. Undrained triaxial compression (eps_v = 0) from the same state (Wood 1990, the undrained
//    triaxial prediction and the undrained strength of Cam clay):
//    elastic phase at p' = p'_0 (vertical in p'–q) up to q_y = M sqrt(p'_0 (p_c0 - p'_0)); then
//    plastic with no volume change, kappa ln(p'/p'_0) + (lambda - kappa) ln(p_c/p_c0) = 0, so
//      p_c(p') = p_c0 (p'_0/p')^(kappa/(lambda - kappa)),  q(p') = M sqrt(p'(p_c(p') - p')),
//    ending at the critical state p_c = 2 p':
//      p'_f = p'_0 (OCR/2)^Lambda,  Lambda = (lambda - kappa)/lambda,  q_f = M p'_f
//    (Wood 1990's undrained strength ratio c_u/p'_0 = (M/2)(OCR/2)^Lambda). p' decreases towards
//    p'_f for OCR < 2 (wet side) and increases for OCR > 2 (dry side). The axial strain (= eps_q)
//    is integrated over p' with GSL QAGS.
// 3. One-dimensional (K0) normal compression: the stress ratio eta_K0 at which proportional loading
//    on the yield locus (p_c proportional to p') produces no lateral strain, d eps_q/d eps_v = 2/3:
//      [kappa eta/(3 r) + (lambda - kappa) 2 eta/(M^2 - eta^2)] / lambda = 2/3,
//      r = G/K = 3(1 - 2nu)/(2(1 + nu))  (elastic part: d eps_q^e/d eps_v^e = 2(1 + nu) eta/(9(1 - 2nu)))
//    solved with GSL's Brent bracketing solver on (0, M); K0_nc = sigma_r/sigma_a = (3 - eta)/(3 + 2 eta)
//    (the K0 prediction of Cam clay in Wood 1990; the ratio K0_nc(eta) is statics only).
// The chapter and section numbers of the books could not be checked here (no copy in the stored
// corpora), so none are given; every formula above is re-derived in the .cpp comments.
//
// All functions throw std::invalid_argument on invalid input and std::runtime_error if GSL fails.
#pragma once

#include <vector>

namespace geosph::reference {

struct CamClaySoil {
  double lambda = 0, kappa = 0, M = 0, poisson = 0, specific_volume = 0;
};

struct CamClayTriaxialSpec {
  CamClaySoil soil;
  double p0 = 0;   // initial isotropic effective stress p'_0 > 0 [Pa]
  double ocr = 1;  // p_c0 = ocr * p'_0, ocr >= 1
};

struct CamClayTriaxialPoint {
  double axial_strain;       // eps_a (compression positive)
  double q;                  // deviator stress [Pa]
  double p;                  // p' [Pa]
  double volumetric_strain;  // eps_v (compression positive)
  double deviatoric_strain;  // eps_q
  double preconsolidation;   // p_c [Pa] of the current locus
  bool plastic;              // on the (expanding or contracting) yield locus
};

// ---- 1. drained, dq/dp' = 3 ----
double mcc_drained_critical_p(const CamClayTriaxialSpec& spec);  // 3 p'_0/(3 - M)
double mcc_drained_yield_q(const CamClayTriaxialSpec& spec);     // first yield on the path
// State at deviator stress q, 0 <= q < M p'_cs (rel_tol: quadrature tolerance).
CamClayTriaxialPoint mcc_drained_triaxial_at_q(const CamClayTriaxialSpec& spec, double q, double rel_tol = 1e-12);
// State at axial strain eps_a >= 0 (Brent root of eps_a(q) = target, relative tolerance ~1e-13).
CamClayTriaxialPoint mcc_drained_triaxial_at_axial_strain(const CamClayTriaxialSpec& spec, double eps_a);
// n + 1 states sampled uniformly in q from 0 to q_fraction * M p'_cs (q_fraction in (0, 1)).
std::vector<CamClayTriaxialPoint> mcc_drained_triaxial_curve(const CamClayTriaxialSpec& spec, int n,
                                                             double q_fraction);

// ---- 2. undrained ----
struct CamClayFailure {
  double p, q;
};
double mcc_undrained_yield_q(const CamClayTriaxialSpec& spec);          // M sqrt(p'_0 (p_c0 - p'_0))
CamClayFailure mcc_undrained_failure(const CamClayTriaxialSpec& spec);  // p'_0 (OCR/2)^Lambda, M p'_f
// q on the plastic branch at p' between p'_0 and p'_f (inclusive), closed form.
double mcc_undrained_q(const CamClayTriaxialSpec& spec, double p);
// State on the plastic branch at p' strictly between p'_0 and p'_f (or at p'_0: first yield).
CamClayTriaxialPoint mcc_undrained_at_p(const CamClayTriaxialSpec& spec, double p, double rel_tol = 1e-12);
// State at axial strain eps_a >= 0: elastic branch (p' = p'_0, q = 3 G(p'_0) eps_a) or plastic
// branch (Brent root in p').
CamClayTriaxialPoint mcc_undrained_at_axial_strain(const CamClayTriaxialSpec& spec, double eps_a);

// ---- 3. K0 normal compression ----
// d eps_q / d eps_v for proportional loading at stress ratio eta on the yield locus (0 <= eta < M).
double mcc_proportional_strain_ratio(double lambda, double kappa, double M, double nu, double eta);
double mcc_k0_stress_ratio(double lambda, double kappa, double M, double nu);           // eta_K0
double mcc_k0_normally_consolidated(double lambda, double kappa, double M, double nu);  // (3 - eta)/(3 + 2 eta)

}  // namespace geosph::reference
