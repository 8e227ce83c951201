// Modified Cam Clay triaxial references; model, sources and conventions in the header.
#include "analytical/cam_clay_triaxial.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_roots.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace geosph::reference {

namespace {

[[noreturn]] void reject(const std::string& what, double value) {
  std::ostringstream msg;
  msg.precision(10);
  msg << "cam_clay_triaxial: " << what << ", got " << value;
  throw std::invalid_argument(msg.str());
}

void check_soil(const CamClaySoil& s) {
  if (!(s.kappa > 0) || !std::isfinite(s.kappa)) reject("kappa must be > 0", s.kappa);
  if (!(s.lambda > s.kappa) || !std::isfinite(s.lambda)) reject("lambda must be > kappa", s.lambda);
  if (!(s.M > 0) || !std::isfinite(s.M)) reject("M must be > 0", s.M);
  if (!(s.poisson > -1 && s.poisson < 0.5)) reject("poisson must be in (-1, 0.5)", s.poisson);
  if (!(s.specific_volume > 1) || !std::isfinite(s.specific_volume)) reject("specific_volume must be > 1", s.specific_volume);
}

void check_spec(const CamClayTriaxialSpec& sp) {
  check_soil(sp.soil);
  if (!(sp.p0 > 0) || !std::isfinite(sp.p0)) reject("p0 must be > 0", sp.p0);
  if (!(sp.ocr >= 1) || !std::isfinite(sp.ocr)) reject("ocr must be >= 1", sp.ocr);
}

// G/K for a constant Poisson ratio: 3(1 - 2nu)/(2(1 + nu))
double shear_ratio(double nu) { return 3.0 * (1.0 - 2.0 * nu) / (2.0 * (1.0 + nu)); }

// 1/(3 G(p)) = kappa / (3 r v p)
double inv_3G(const CamClaySoil& s, double p) { return s.kappa / (3.0 * shear_ratio(s.poisson) * s.specific_volume * p); }

// GSL's default error handler aborts; the functions below check every status themselves.
class QuietGsl {
 public:
  QuietGsl() : old_(gsl_set_error_handler_off()) {}
  ~QuietGsl() { gsl_set_error_handler(old_); }
  QuietGsl(const QuietGsl&) = delete;
  QuietGsl& operator=(const QuietGsl&) = delete;

 private:
  gsl_error_handler_t* old_;
};

template <class F>
double trampoline(double x, void* params) {
  return (*static_cast<F*>(params))(x);
}

// Integral of f over [a, b] (a <= b) with GSL QAGS (adaptive, with extrapolation: integrable
// end-point singularities are allowed).
template <class F>
double integrate(F f, double a, double b, double rel_tol) {
  if (!(b > a)) return 0.0;
  QuietGsl quiet;
  constexpr std::size_t kLimit = 2000;
  gsl_integration_workspace* w = gsl_integration_workspace_alloc(kLimit);
  if (!w) throw std::runtime_error("cam_clay_triaxial: cannot allocate the GSL integration workspace");
  gsl_function gf{&trampoline<F>, &f};
  double result = 0, abserr = 0;
  const int status = gsl_integration_qags(&gf, a, b, 0.0, rel_tol, kLimit, w, &result, &abserr);
  gsl_integration_workspace_free(w);
  // GSL reports round-off limits (EROUND) when the requested tolerance is below what double
  // precision allows; such results are accepted when the error estimate is still small.
  if (status != GSL_SUCCESS && !(abserr <= 1e-9 * std::abs(result)))
    throw std::runtime_error("cam_clay_triaxial: GSL quadrature failed (" + std::string(gsl_strerror(status)) + ")");
  return result;
}

// Root of f in [lo, hi] (f(lo), f(hi) of opposite signs) with GSL's Brent solver.
template <class F>
double brent(F f, double lo, double hi, double rel_tol) {
  QuietGsl quiet;
  gsl_function gf{&trampoline<F>, &f};
  gsl_root_fsolver* s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  if (!s) throw std::runtime_error("cam_clay_triaxial: cannot allocate the GSL root solver");
  int status = gsl_root_fsolver_set(s, &gf, lo, hi);
  double root = 0.5 * (lo + hi);
  for (int it = 0; status == GSL_SUCCESS && it < 500; ++it) {
    status = gsl_root_fsolver_iterate(s);
    if (status != GSL_SUCCESS) break;
    root = gsl_root_fsolver_root(s);
    const double a = gsl_root_fsolver_x_lower(s), b = gsl_root_fsolver_x_upper(s);
    if (gsl_root_test_interval(a, b, 0.0, rel_tol) == GSL_SUCCESS) break;
  }
  gsl_root_fsolver_free(s);
  if (status != GSL_SUCCESS)
    throw std::runtime_error("cam_clay_triaxial: GSL root solver failed (" + std::string(gsl_strerror(status)) + ")");
  return root;
}

// ---- drained: p' = p'_0 + q/3 ----

void check_drained(const CamClayTriaxialSpec& sp) {
  check_spec(sp);
  if (!(sp.soil.M < 3.0)) reject("drained path dq/dp' = 3 needs M < 3 to reach the critical state", sp.soil.M);
  const double ocr_max = 6.0 / (3.0 - sp.soil.M);  // p_c0/2 < p'_cs: yield on the wet side
  if (!(sp.ocr < ocr_max)) reject("drained reference supports wet-side yielding only, ocr < 6/(3 - M)", sp.ocr);
}

// d ln p_c / dq on the locus p_c = p' + q^2/(M^2 p'), p' = p'_0 + q/3:
// dp_c/dq = 1/3 + 2 q/(M^2 p') - q^2/(3 M^2 p'^2)
double drained_dlnpc_dq(const CamClayTriaxialSpec& sp, double q) {
  const double M2 = sp.soil.M * sp.soil.M, p = sp.p0 + q / 3.0;
  const double pc = p + q * q / (M2 * p);
  return (1.0 / 3.0 + 2.0 * q / (M2 * p) - q * q / (3.0 * M2 * p * p)) / pc;
}

}  // namespace

double mcc_drained_critical_p(const CamClayTriaxialSpec& spec) {
  check_drained(spec);
  return 3.0 * spec.p0 / (3.0 - spec.soil.M);
}

double mcc_drained_yield_q(const CamClayTriaxialSpec& spec) {
  check_drained(spec);
  // q^2/M^2 + (p0 + q/3)(p0 + q/3 - pc0) = 0:  a q^2 + b q + c = 0
  const double M2 = spec.soil.M * spec.soil.M, pc0 = spec.ocr * spec.p0;
  const double a = 1.0 / M2 + 1.0 / 9.0, b = (2.0 * spec.p0 - pc0) / 3.0, c = spec.p0 * (spec.p0 - pc0);
  const double disc = std::sqrt(b * b - 4.0 * a * c);
  // positive root, written without cancellation for either sign of b (c <= 0)
  return b > 0 ? -2.0 * c / (b + disc) : (-b + disc) / (2.0 * a);
}

CamClayTriaxialPoint mcc_drained_triaxial_at_q(const CamClayTriaxialSpec& spec, double q, double rel_tol) {
  const double p_cs = mcc_drained_critical_p(spec);
  const double q_cs = spec.soil.M * p_cs;
  if (!(q >= 0 && q < q_cs)) reject("drained: q must be in [0, M p'_cs)", q);
  const CamClaySoil& s = spec.soil;
  const double v = s.specific_volume, M2 = s.M * s.M;
  const double q_y = mcc_drained_yield_q(spec);
  const double p = spec.p0 + q / 3.0;

  // elastic rates over [0, q]: d eps_v^e/dq = kappa/(v p) dp/dq, d eps_q^e/dq = 1/(3 G(p))
  const double ev_e = integrate([&](double x) { return s.kappa / (v * (spec.p0 + x / 3.0)) / 3.0; }, 0.0, q, rel_tol);
  const double eq_e = integrate([&](double x) { return inv_3G(s, spec.p0 + x / 3.0); }, 0.0, q, rel_tol);
  // plastic rates over [q_y, q]: d eps_v^p = (lambda - kappa)/v d ln p_c,
  // d eps_q^p = 2 eta/(M^2 - eta^2) d eps_v^p. The second is singular like 1/(q_cs - q) at the
  // critical state; with q = q_cs (1 - e^-u), dq = (q_cs - q) du, and
  // (q_cs - q)/(M - eta) = p'/(1 - M/3) (from p' = p'_0 + q/3, q_cs = M p'_0/(1 - M/3)), the
  // integrand in u is smooth and bounded and is evaluated without cancellation.
  double ev_p = 0, eq_p = 0;
  if (q > q_y) {
    ev_p = integrate([&](double x) { return (s.lambda - s.kappa) / v * drained_dlnpc_dq(spec, x); }, q_y, q, rel_tol);
    const double u_y = -std::log1p(-q_y / q_cs), u_q = -std::log1p(-q / q_cs);
    eq_p = integrate(
        [&](double u) {
          const double x = -q_cs * std::expm1(-u);
          const double px = spec.p0 + x / 3.0, eta = x / px;
          return 2.0 * eta / (s.M + eta) * px / (1.0 - s.M / 3.0) * (s.lambda - s.kappa) / v *
                 drained_dlnpc_dq(spec, x);
        },
        u_y, u_q, rel_tol);
  }
  CamClayTriaxialPoint pt;
  pt.q = q;
  pt.p = p;
  pt.volumetric_strain = ev_e + ev_p;
  pt.deviatoric_strain = eq_e + eq_p;
  pt.axial_strain = pt.deviatoric_strain + pt.volumetric_strain / 3.0;
  pt.plastic = q >= q_y;
  pt.preconsolidation = q > q_y ? p + q * q / (M2 * p) : spec.ocr * spec.p0;
  return pt;
}

CamClayTriaxialPoint mcc_drained_triaxial_at_axial_strain(const CamClayTriaxialSpec& spec, double eps_a) {
  if (!(eps_a >= 0) || !std::isfinite(eps_a)) reject("drained: axial strain must be >= 0", eps_a);
  const double q_cs = spec.soil.M * mcc_drained_critical_p(spec);
  if (eps_a == 0.0) return mcc_drained_triaxial_at_q(spec, 0.0);
  auto residual = [&](double q) { return mcc_drained_triaxial_at_q(spec, q).axial_strain - eps_a; };
  double gap = 1e-2;  // q_hi = q_cs (1 - gap)
  while (residual(q_cs * (1.0 - gap)) < 0.0) {
    gap *= 0.01;
    if (gap < 1e-14) reject("drained: axial strain too large to resolve the approach to the critical state", eps_a);
  }
  const double q = brent(residual, 0.0, q_cs * (1.0 - gap), 1e-14);
  return mcc_drained_triaxial_at_q(spec, q);
}

std::vector<CamClayTriaxialPoint> mcc_drained_triaxial_curve(const CamClayTriaxialSpec& spec, int n, double q_fraction) {
  if (n < 1) reject("drained curve: n must be >= 1", n);
  if (!(q_fraction > 0 && q_fraction < 1)) reject("drained curve: q_fraction must be in (0, 1)", q_fraction);
  const double q_end = q_fraction * spec.soil.M * mcc_drained_critical_p(spec);
  std::vector<CamClayTriaxialPoint> out;
  out.reserve(static_cast<std::size_t>(n) + 1);
  for (int k = 0; k <= n; ++k) out.push_back(mcc_drained_triaxial_at_q(spec, q_end * k / n));
  return out;
}

// ---- undrained ----

double mcc_undrained_yield_q(const CamClayTriaxialSpec& spec) {
  check_spec(spec);
  return spec.soil.M * std::sqrt(spec.p0 * (spec.ocr * spec.p0 - spec.p0));
}

CamClayFailure mcc_undrained_failure(const CamClayTriaxialSpec& spec) {
  check_spec(spec);
  // kappa ln(p/p0) + (lambda - kappa) ln(pc/pc0) = 0 with pc = 2p at the critical state:
  // p^(lambda/(lambda - kappa)) = (pc0/2) p0^(kappa/(lambda - kappa))  =>  p_f = p0 (OCR/2)^Lambda
  const double Lambda = (spec.soil.lambda - spec.soil.kappa) / spec.soil.lambda;
  const double pf = spec.p0 * std::pow(0.5 * spec.ocr, Lambda);
  return {pf, spec.soil.M * pf};
}

namespace {

// p_c on the undrained plastic branch: p_c0 (p'_0/p')^(kappa/(lambda - kappa))
double undrained_pc(const CamClayTriaxialSpec& sp, double p) {
  const double k = sp.soil.kappa / (sp.soil.lambda - sp.soil.kappa);
  return sp.ocr * sp.p0 * std::pow(sp.p0 / p, k);
}

bool between(double x, double a, double b) { return x >= std::min(a, b) && x <= std::max(a, b); }

}  // namespace

double mcc_undrained_q(const CamClayTriaxialSpec& spec, double p) {
  const CamClayFailure f = mcc_undrained_failure(spec);
  if (!between(p, spec.p0, f.p)) reject("undrained: p' must lie between p'_0 and p'_f on the plastic branch", p);
  const double pc = undrained_pc(spec, p);
  return spec.soil.M * std::sqrt(std::max(0.0, p * (pc - p)));
}

CamClayTriaxialPoint mcc_undrained_at_p(const CamClayTriaxialSpec& spec, double p, double rel_tol) {
  const CamClayFailure f = mcc_undrained_failure(spec);
  const bool at_yield = p == spec.p0;
  if (!at_yield && !(between(p, spec.p0, f.p) && p != f.p))
    reject("undrained: p' must lie between p'_0 and p'_f (exclusive of p'_f)", p);
  const CamClaySoil& s = spec.soil;
  const double M2 = s.M * s.M, v = s.specific_volume, k = s.kappa / (s.lambda - s.kappa);
  const double q_y = mcc_undrained_yield_q(spec);
  const double eps_y = q_y * inv_3G(s, spec.p0);  // elastic phase at p'_0: eps_q = q/(3 G0)
  // plastic branch, integrated over p' from p'_0 (eps_v = 0, eps_a = eps_q):
  //   d eps_q = dq/(3 G(p')) + 2 eta/(M^2 - eta^2) d eps_v^p,  d eps_v^p = -d eps_v^e = -kappa/v dp'/p'
  //   dq/dp' = M^2 ((1 - k) p_c - 2 p')/(2 q)  (from q^2 = M^2 (p' p_c - p'^2), p' dp_c/dp' = -k p_c)
  // The second term is singular like 1/(p' - p'_f) at the critical state; with
  // p' = p'_f + (p'_0 - p'_f) e^-u, dp' = -(p' - p'_f) du, and
  // M^2 - eta^2 = M^2 (2 - p_c/p') = -2 M^2 expm1((1 + k) ln(p'_f/p'))  (p_c/p' = 2 (p'_f/p')^(1+k)),
  // the integrand in u is bounded and evaluated without cancellation. (At u = 0 for OCR = 1, q = 0
  // and dq/dp' has an integrable 1/sqrt singularity, handled by QAGS.)
  const double dp0 = spec.p0 - f.p;
  auto rate_u = [&](double u) {
    const double d = dp0 * std::exp(-u), x = f.p + d;  // d = p' - p'_f
    const double pc = undrained_pc(spec, x);
    const double q = s.M * std::sqrt(std::max(0.0, x * (pc - x)));
    const double eta = q / x;
    const double dqdp = M2 * ((1.0 - k) * pc - 2.0 * x) / (2.0 * q);
    const double m2_eta2 = -2.0 * M2 * std::expm1(-(1.0 + k) * std::log1p(d / f.p));
    return -d * (dqdp * inv_3G(s, x) + 2.0 * eta / m2_eta2 * (-s.kappa / (v * x)));
  };
  const double u_end = at_yield ? 0.0 : -std::log((p - f.p) / dp0);
  const double integral = integrate(rate_u, 0.0, u_end, rel_tol);
  CamClayTriaxialPoint pt;
  pt.p = p;
  pt.q = at_yield ? q_y : mcc_undrained_q(spec, p);
  pt.volumetric_strain = 0.0;
  pt.deviatoric_strain = eps_y + integral;
  pt.axial_strain = pt.deviatoric_strain;
  pt.preconsolidation = undrained_pc(spec, p);
  pt.plastic = true;
  return pt;
}

CamClayTriaxialPoint mcc_undrained_at_axial_strain(const CamClayTriaxialSpec& spec, double eps_a) {
  if (!(eps_a >= 0) || !std::isfinite(eps_a)) reject("undrained: axial strain must be >= 0", eps_a);
  const CamClayFailure f = mcc_undrained_failure(spec);
  const double q_y = mcc_undrained_yield_q(spec);
  const double G0inv = inv_3G(spec.soil, spec.p0);
  if (eps_a <= q_y * G0inv || f.p == spec.p0) {
    CamClayTriaxialPoint pt;
    pt.p = spec.p0;
    pt.q = std::min(eps_a / G0inv, q_y);  // OCR = 2: yield at the critical state, then no change
    pt.volumetric_strain = 0.0;
    pt.deviatoric_strain = pt.axial_strain = eps_a;
    pt.preconsolidation = spec.ocr * spec.p0;
    pt.plastic = eps_a >= q_y * G0inv;
    return pt;
  }
  auto residual = [&](double p) { return mcc_undrained_at_p(spec, p).axial_strain - eps_a; };
  double gap = 1e-2;  // bracket end p_f + gap (p'_0 - p'_f)
  while (residual(f.p + gap * (spec.p0 - f.p)) < 0.0) {
    gap *= 0.01;
    if (gap < 1e-14) reject("undrained: axial strain too large to resolve the approach to the critical state", eps_a);
  }
  const double a = spec.p0, b = f.p + gap * (spec.p0 - f.p);
  const double p = brent(residual, std::min(a, b), std::max(a, b), 1e-14);
  return mcc_undrained_at_p(spec, p);
}

// ---- K0 ----

double mcc_proportional_strain_ratio(double lambda, double kappa, double M, double nu, double eta) {
  check_soil({lambda, kappa, M, nu, 2.0});
  if (!(eta >= 0 && eta < M)) reject("eta must be in [0, M)", eta);
  // at constant eta on the locus: d ln p_c = d ln p', so
  // d eps_v = lambda/v d ln p',  d eps_q = [kappa eta/(3 r) + (lambda - kappa) 2 eta/(M^2 - eta^2)]/v d ln p'
  const double r = shear_ratio(nu);
  return (kappa * eta / (3.0 * r) + (lambda - kappa) * 2.0 * eta / (M * M - eta * eta)) / lambda;
}

double mcc_k0_stress_ratio(double lambda, double kappa, double M, double nu) {
  check_soil({lambda, kappa, M, nu, 2.0});
  // the ratio rises monotonically from 0 (eta = 0) to infinity (eta -> M)
  auto residual = [&](double eta) { return mcc_proportional_strain_ratio(lambda, kappa, M, nu, eta) - 2.0 / 3.0; };
  double gap = 1e-3;
  while (residual(M * (1.0 - gap)) < 0.0) gap *= 1e-3;
  return brent(residual, 0.0, M * (1.0 - gap), 1e-15);
}

double mcc_k0_normally_consolidated(double lambda, double kappa, double M, double nu) {
  const double eta = mcc_k0_stress_ratio(lambda, kappa, M, nu);
  return (3.0 - eta) / (3.0 + 2.0 * eta);
}

}  // namespace geosph::reference
