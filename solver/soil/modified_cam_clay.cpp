// Modified Cam Clay point model; equations, sources and conventions in the header.
#include "soil/modified_cam_clay.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "soil/parameter_error.hpp"

namespace geosph::soil {

namespace {

constexpr int kMaxIterations = 50;
constexpr double kYieldTolerance = 1e-12;   // |f| <= tol * p_c,n+1^2
constexpr double kAcceptTolerance = 1e-10;  // accepted when the bracket has collapsed first
constexpr int kMaxInnerIterations = 200;

// Exact solution of dp = max(p, a) dy from p(0) = pn (y = v eps_v^e / kappa, compression
// positive): p = pn e^y while p >= a, linear with slope a below a. Continuous with a continuous
// derivative; strictly increasing in y.
class ElasticPressure {
 public:
  ElasticPressure(double pn, double a) : pn_(pn), a_(a), above_(pn >= a) {
    ya_ = above_ ? std::log(a / pn) : (a - pn) / a;  // y at which p = a (<= 0 above, > 0 below)
  }
  double p(double y, double* dpdy) const {
    double p;
    if (above_) {
      if (y >= ya_) {
        p = pn_ * std::exp(y);
        *dpdy = p;
      } else {
        p = a_ * (1.0 + (y - ya_));
        *dpdy = a_;
      }
    } else if (y <= ya_) {
      p = pn_ + a_ * y;
      *dpdy = a_;
    } else {
      p = a_ * std::exp(y - ya_);
      *dpdy = p;
    }
    return p;
  }
  // y with p(y) = target
  double inverse(double target) const {
    if (above_) return target >= a_ ? std::log(target / pn_) : ya_ + target / a_ - 1.0;
    return target <= a_ ? (target - pn_) / a_ : ya_ + std::log(target / a_);
  }

 private:
  double pn_, a_, ya_;
  bool above_;
};

inline Matrix3d deviator(const Matrix3d& m) {
  Matrix3d d = m;
  d.diagonal().array() -= m.trace() / 3.0;
  return d;
}

}  // namespace

void validate(const ModifiedCamClayParams& p) {
  // Comparisons are written so that NaN fails them.
  if (!(p.kappa > 0.0) || !std::isfinite(p.kappa)) reject_parameter("kappa", "> 0 (slope of the unloading-reloading line)", p.kappa);
  if (!(p.lambda > p.kappa) || !std::isfinite(p.lambda)) {
    std::ostringstream range;
    range.precision(10);
    range << "> kappa = " << p.kappa << " (slope of the normal compression line)";
    reject_parameter("lambda", range.str(), p.lambda);
  }
  if (!(p.M > 0.0) || !std::isfinite(p.M)) reject_parameter("M", "> 0 (critical state line slope)", p.M);
  if (!(p.poisson > -1.0 && p.poisson < 0.5)) reject_parameter("poisson", "in (-1, 0.5) (Poisson's ratio)", p.poisson);
  if (!(p.specific_volume > 1.0) || !std::isfinite(p.specific_volume))
    reject_parameter("specific_volume", "> 1 (v = 1 + e)", p.specific_volume);
  if (!(p.min_pressure > 0.0) || !std::isfinite(p.min_pressure))
    reject_parameter("min_pressure", "> 0 (floor on p' in the elastic moduli, Pa)", p.min_pressure);
}

ModifiedCamClay::ModifiedCamClay(const ModifiedCamClayParams& params) : params_(params) {
  validate(params_);
  theta_ = params_.specific_volume / (params_.lambda - params_.kappa);
  c_ = params_.specific_volume / params_.kappa;
  shear_ratio_ = 3.0 * (1.0 - 2.0 * params_.poisson) / (2.0 * (1.0 + params_.poisson));
}

double ModifiedCamClay::mean_effective_stress(const Matrix3d& sigma) { return -sigma.trace() / 3.0; }

double ModifiedCamClay::deviator_stress(const Matrix3d& sigma) {
  return std::sqrt(1.5 * deviator(sigma).squaredNorm());
}

double ModifiedCamClay::yield(const Matrix3d& sigma, double pc) const {
  const double p = mean_effective_stress(sigma);
  const double q = deviator_stress(sigma);
  return q * q / (params_.M * params_.M) + p * (p - pc);
}

double ModifiedCamClay::bulk_modulus(double p) const { return c_ * std::max(p, params_.min_pressure); }

double ModifiedCamClay::shear_modulus(double p) const { return shear_ratio_ * bulk_modulus(p); }

double ModifiedCamClay::preconsolidation_for(double p, double q, double M, double ocr) {
  if (!(p > 0.0) || !std::isfinite(p)) reject_parameter("preconsolidation_for: p", "> 0 (Pa)", p);
  if (!(q >= 0.0) || !std::isfinite(q)) reject_parameter("preconsolidation_for: q", ">= 0 (Pa)", q);
  if (!(M > 0.0) || !std::isfinite(M)) reject_parameter("preconsolidation_for: M", "> 0", M);
  if (!(ocr >= 1.0) || !std::isfinite(ocr)) reject_parameter("preconsolidation_for: ocr", ">= 1", ocr);
  return ocr * (p + q * q / (M * M * p));
}

ModifiedCamClay::Result ModifiedCamClay::return_map(const Matrix3d& sigma_n, double pc_n,
                                                    const Matrix3d& de) const {
  const double M2 = params_.M * params_.M;
  Result r;
  r.preconsolidation = pc_n;
  r.volumetric_plastic_strain_increment = 0.0;
  r.equivalent_plastic_strain_increment = 0.0;
  r.iterations = 0;
  r.converged = true;
  r.plastic = false;

  // (b) elastic predictor
  const double pn = mean_effective_stress(sigma_n);
  const double dev_v = -de.trace();  // compression positive
  const double Gn = shear_modulus(pn);
  Matrix3d s_tr = deviator(sigma_n) + (2.0 * Gn) * deviator(de);
  s_tr.diagonal().array() -= s_tr.trace() / 3.0;  // traceless to round-off relative to itself
  const double q_tr = std::sqrt(1.5 * s_tr.squaredNorm());
  const ElasticPressure law(pn, params_.min_pressure);
  double dP;
  const double p_tr = law.p(c_ * dev_v, &dP);

  if (!(pc_n > 0.0) || !std::isfinite(pc_n) || !std::isfinite(p_tr) || !std::isfinite(q_tr)) {
    r.stress = s_tr;
    r.stress.diagonal().array() -= p_tr;
    r.converged = false;
    return r;
  }

  // (c) tension cut-off: apex p' = 0, q = 0, p_c unchanged
  if (p_tr < 0.0) {
    const double eps_zero = law.inverse(0.0) / c_;  // elastic volumetric strain that brings p' to 0
    r.stress.setZero();
    r.plastic = true;
    r.volumetric_plastic_strain_increment = eps_zero - dev_v;  // > 0: opening (tension positive)
    r.equivalent_plastic_strain_increment = q_tr / (3.0 * Gn);
    return r;
  }
  const double f_tr = q_tr * q_tr / M2 + p_tr * (p_tr - pc_n);
  if (!(f_tr > 0.0)) {
    r.stress = s_tr;
    r.stress.diagonal().array() -= p_tr;
    return r;
  }

  // (d) closest-point return. Unknown g = Delta_gamma * p_c,n (dimensionless, strain-like).
  // Inner problem for a given g: x - g h(x) = 0, h(x) = (2 p'(x) - p_c(x))/p_c,n, x = Delta eps_v^p.
  // Bracket independent of g (see the header): h(0) > 0 -> x in [0, ln(2 p'_tr/p_c,n)/theta];
  // h(0) < 0 -> x in [x_half, 0] with p'(x_half) = p_c,n/2.
  r.plastic = true;
  const double h0 = (2.0 * p_tr - pc_n) / pc_n;
  double x_bound = 0.0;
  if (h0 > 0.0) {
    x_bound = std::log(2.0 * p_tr / pc_n) / theta_;
  } else if (h0 < 0.0) {
    x_bound = dev_v - law.inverse(0.5 * pc_n) / c_;
  }
  const double a6 = 6.0 * Gn / (M2 * pc_n);  // q = q_tr/(1 + a6 g)

  struct Eval {
    double g, x, p, pc, q, F, dF;
  };
  // Solves the inner problem (warm start x_guess) and evaluates F(g) = f and dF/dg.
  auto evaluate = [&](double g, double x_guess) {
    Eval e{};
    double xl = std::min(0.0, std::max(g * h0, x_bound));
    double xh = std::max(0.0, std::min(g * h0, x_bound));
    if (h0 == 0.0) xl = xh = 0.0;
    double x = std::clamp(x_guess, xl, xh);
    double p = 0, dpdx = 0, pc = 0, dpcdx = 0, dG = 1.0;
    auto state_at = [&](double xx) {
      double dPy;
      p = law.p(c_ * (dev_v - xx), &dPy);
      dpdx = -c_ * dPy;
      pc = pc_n * std::exp(theta_ * xx);
      dpcdx = theta_ * pc;
      dG = 1.0 - g * (2.0 * dpdx - dpcdx) / pc_n;  // >= 1
      return xx - g * (2.0 * p - pc) / pc_n;  // residual x - g h(x)
    };
    for (int it = 0; it < kMaxInnerIterations && xh > xl; ++it) {
      const double Gx = state_at(x);
      if (Gx == 0.0) break;
      if (!std::isfinite(Gx) || Gx > 0.0) {
        xh = x;
      } else {
        xl = x;
      }
      double xn = std::isfinite(Gx) && std::isfinite(dG) ? x - Gx / dG : 0.5 * (xl + xh);
      if (!(xn > xl && xn < xh)) xn = 0.5 * (xl + xh);
      const bool done = std::abs(xn - x) <= 1e-15 * std::abs(x) + 1e-22;
      x = xn;
      if (done) break;
    }
    state_at(x);
    const double denom = 1.0 + a6 * g;
    e.g = g;
    e.x = x;
    e.p = p;
    e.pc = pc;
    e.q = q_tr / denom;
    e.F = e.q * e.q / M2 + p * (p - pc);
    const double dxdg = (2.0 * p - pc) / pc_n / dG;
    const double dqdg = -a6 * e.q / denom;
    e.dF = 2.0 * e.q * dqdg / M2 + ((2.0 * p - pc) * dpdx - p * dpcdx) * dxdg;
    return e;
  };

  // Outer safeguarded Newton on g. F(0) = f_tr > 0 and F(infinity) < 0.
  const double g_scale = params_.kappa / params_.specific_volume;  // elastic strain per unit ln p'
  const Eval e0 = evaluate(0.0, 0.0);
  double lo = 0.0, hi = std::numeric_limits<double>::infinity();
  double g = e0.dF < 0.0 ? -e0.F / e0.dF : g_scale;
  Eval e = e0;
  bool converged = false;
  for (int k = 1; k <= kMaxIterations; ++k) {
    if (!(g > lo && g < hi)) g = std::isfinite(hi) ? 0.5 * (lo + hi) : 4.0 * std::max(lo, g_scale);
    e = evaluate(g, e.x);
    r.iterations = k;
    if (std::abs(e.F) <= kYieldTolerance * e.pc * e.pc) {
      converged = true;
      break;
    }
    if (e.F > 0.0) {
      lo = g;
    } else {
      hi = g;
    }
    if (std::isfinite(hi) && hi - lo <= 4.0 * std::numeric_limits<double>::epsilon() * hi) {
      converged = std::abs(e.F) <= kAcceptTolerance * e.pc * e.pc;
      break;
    }
    double gn = g - e.F / e.dF;
    if (!(e.dF < 0.0) || !(gn > lo && gn < hi)) gn = std::isfinite(hi) ? 0.5 * (lo + hi) : 4.0 * g;
    g = gn;
  }

  r.converged = converged;
  r.preconsolidation = e.pc;
  r.stress = q_tr > 0.0 ? Matrix3d((e.q / q_tr) * s_tr) : Matrix3d(Matrix3d::Zero());
  r.stress.diagonal().array() -= e.p;
  r.volumetric_plastic_strain_increment = -e.x;
  r.equivalent_plastic_strain_increment = 2.0 * (e.g / pc_n) * e.q / M2;  // 2 Delta_gamma q/M^2
  return r;
}

ModifiedCamClay::Result ModifiedCamClay::update(const Matrix3d& sigma_n, double pc_n,
                                                const Matrix3d& strain_increment,
                                                const Matrix3d& spin_increment) const {
  return return_map(jaumann_rotate(sigma_n, spin_increment), pc_n, strain_increment);
}

}  // namespace geosph::soil
