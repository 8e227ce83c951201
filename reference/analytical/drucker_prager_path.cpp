#include "analytical/drucker_prager_path.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace geosph::reference {

namespace {

using T3 = double[3][3];

// Sym3 index of component (a, b)
constexpr int kIdx[3][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}};

void to_tensor(const double* v, T3 m) {
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) m[a][b] = v[kIdx[a][b]];
}

enum class Branch { Elastic, Plastic };

struct System {
  const DruckerPragerPathSpec* spec;
  Branch branch;
  bool unloaded = false;  // set by the plastic branch when df:D:deps/dt <= 0
};

double yield_of(const DruckerPragerPathSpec& p, const double* sv) {
  T3 s;
  to_tensor(sv, s);
  const double I1 = s[0][0] + s[1][1] + s[2][2];
  double j2 = 0;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const double d = s[a][b] - (a == b ? I1 / 3.0 : 0.0);
      j2 += 0.5 * d * d;
    }
  return p.alpha_phi * I1 + std::sqrt(j2) - p.k_c;
}

// C : e at stress S for the strain rate e (elastic tangent, or the elasto-plastic one when
// 'plastic'); *load receives df:D:e (the loading indicator of the plastic branch).
void stress_rate(const DruckerPragerPathSpec& p, const T3 S, const T3 e, bool plastic, T3 out, double* load) {
  const double K = p.bulk, G = p.shear;
  const double tr_e = e[0][0] + e[1][1] + e[2][2];
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) out[a][b] = 2.0 * G * e[a][b] + (a == b ? (K - 2.0 * G / 3.0) * tr_e : 0.0);
  *load = 0.0;
  if (!plastic) return;
  const double I1 = S[0][0] + S[1][1] + S[2][2];
  T3 dev;
  double j2 = 0;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      dev[a][b] = S[a][b] - (a == b ? I1 / 3.0 : 0.0);
      j2 += 0.5 * dev[a][b] * dev[a][b];
    }
  const double q = std::sqrt(j2);
  double n_e = 0;  // n : e with n = s / (2 sqrt(J2))
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) n_e += dev[a][b] / (2.0 * q) * e[a][b];
  *load = 2.0 * G * n_e + 3.0 * K * p.alpha_phi * tr_e;  // df : D : e
  const double lambda_rate = *load / (G + 9.0 * K * p.alpha_phi * p.alpha_psi);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      out[a][b] -= lambda_rate * (2.0 * G * dev[a][b] / (2.0 * q) + (a == b ? 3.0 * K * p.alpha_psi : 0.0));
}

// y = (stress[6], strain[6]); dy/dt.
int rhs(double /*t*/, const double y[], double dydt[], void* params) {
  auto* sys = static_cast<System*>(params);
  const DruckerPragerPathSpec& p = *sys->spec;
  const bool plastic = sys->branch == Branch::Plastic;
  T3 S, e, C_e;
  to_tensor(y, S);
  to_tensor(p.strain_rate.data(), e);
  const double wxy = p.spin_rate[0], wyz = p.spin_rate[1], wxz = p.spin_rate[2];
  const T3 w = {{0, wxy, wxz}, {-wxy, 0, wyz}, {-wxz, -wyz, 0}};
  T3 jaumann;  // sigma omega^T + omega sigma
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      jaumann[a][b] = 0.0;
      for (int c = 0; c < 3; ++c) jaumann[a][b] += S[a][c] * w[b][c] + w[a][c] * S[c][b];
    }
  double load = 0.0;
  if (p.hold_stress_xx) {
    // On a fixed branch d sigma_xx/dt = jaumann_xx + r0_xx + (r1_xx - r0_xx) e_xx (affine in e_xx):
    // solve for d sigma_xx/dt = 0. The loading check below uses the solved e_xx.
    T3 r0, r1;
    e[0][0] = 0.0;
    stress_rate(p, S, e, plastic, r0, &load);
    e[0][0] = 1.0;
    stress_rate(p, S, e, plastic, r1, &load);
    e[0][0] = -(jaumann[0][0] + r0[0][0]) / (r1[0][0] - r0[0][0]);
  }
  stress_rate(p, S, e, plastic, C_e, &load);
  if (plastic && !(load > 0.0)) {
    sys->unloaded = true;
    return GSL_EBADFUNC;
  }
  for (int a = 0; a < 3; ++a)
    for (int b = a; b < 3; ++b) {
      dydt[kIdx[a][b]] = jaumann[a][b] + C_e[a][b];
      dydt[6 + kIdx[a][b]] = e[a][b];
    }
  return GSL_SUCCESS;
}

class Integrator {
 public:
  Integrator(System& sys, double rel_tol, double stress_scale, double strain_scale, double h0) {
    sys_ = {rhs, nullptr, 12, &sys};
    for (int i = 0; i < 6; ++i) { scale_[i] = stress_scale; scale_[6 + i] = strain_scale; }
    d_ = gsl_odeiv2_driver_alloc_scaled_new(&sys_, gsl_odeiv2_step_rk8pd, h0, rel_tol, rel_tol, 1.0, 0.0, scale_);
    if (!d_) throw std::runtime_error("drucker_prager_path: cannot allocate the GSL ODE driver");
  }
  ~Integrator() { gsl_odeiv2_driver_free(d_); }
  Integrator(const Integrator&) = delete;
  Integrator& operator=(const Integrator&) = delete;

  // Integrates y from t0 to t1 (fresh start, so the result does not depend on earlier calls).
  void run(double t0, double t1, double* y) {
    if (t1 <= t0) return;
    gsl_odeiv2_driver_reset(d_);
    gsl_odeiv2_driver_reset_hstart(d_, std::min(h0_max_, t1 - t0));
    double t = t0;
    const int status = gsl_odeiv2_driver_apply(d_, &t, t1, y);
    if (status != GSL_SUCCESS) {
      const auto* sys = static_cast<const System*>(sys_.params);
      throw std::runtime_error(sys->unloaded ? "drucker_prager_path: the path unloads from the yield surface "
                                               "(only monotonic plastic loading is supported)"
                                             : "drucker_prager_path: GSL ODE driver failed, status " +
                                                   std::to_string(status));
    }
  }
  void set_h0_max(double h) { h0_max_ = h; }

 private:
  gsl_odeiv2_system sys_{};
  gsl_odeiv2_driver* d_ = nullptr;
  double scale_[12]{};
  double h0_max_ = 1e300;
};

}  // namespace

DruckerPragerPath drucker_prager_path(const DruckerPragerPathSpec& spec, int n_intervals, double rel_tol) {
  if (n_intervals < 1) throw std::invalid_argument("drucker_prager_path: n_intervals must be >= 1");
  if (!(spec.duration > 0)) throw std::invalid_argument("drucker_prager_path: duration must be > 0");
  if (!(spec.bulk > 0 && spec.shear > 0)) throw std::invalid_argument("drucker_prager_path: K and G must be > 0");

  double rate = 0, s0 = spec.k_c;
  for (double v : spec.strain_rate) rate = std::max(rate, std::abs(v));
  for (double v : spec.spin_rate) rate = std::max(rate, std::abs(v));
  for (double v : spec.stress0) s0 = std::max(s0, std::abs(v));
  const double strain_scale = std::max(rate * spec.duration, 1e-300);
  const double stress_scale = std::max({s0, (spec.bulk + spec.shear) * strain_scale, 1e-300});

  const double f0 = yield_of(spec, spec.stress0.data());
  if (f0 > 1e-12 * stress_scale)
    throw std::invalid_argument("drucker_prager_path: the initial stress lies outside the yield surface");

  System sys{&spec, f0 < 0 ? Branch::Elastic : Branch::Plastic};
  const double dt_out = spec.duration / n_intervals;
  Integrator ode(sys, rel_tol, stress_scale, strain_scale, dt_out * 1e-3);
  ode.set_h0_max(dt_out * 1e-3);

  DruckerPragerPath path;
  path.yield_time = sys.branch == Branch::Plastic ? 0.0 : -1.0;
  double y[12] = {};
  std::copy(spec.stress0.begin(), spec.stress0.end(), y);
  auto record = [&](double t) {
    DruckerPragerPathPoint pt;
    pt.t = t;
    std::copy(y, y + 6, pt.stress.begin());
    std::copy(y + 6, y + 12, pt.strain.begin());
    pt.plastic = sys.branch == Branch::Plastic;
    path.points.push_back(pt);
  };
  record(0.0);

  double t = 0.0;
  for (int k = 1; k <= n_intervals; ++k) {
    const double t_next = k == n_intervals ? spec.duration : k * dt_out;
    if (sys.branch == Branch::Elastic) {
      double y_end[12];
      std::copy(y, y + 12, y_end);
      ode.run(t, t_next, y_end);
      if (yield_of(spec, y_end) > 0.0) {
        // First contact inside (t, t_next): bisect on the smooth elastic solution.
        double lo = t, hi = t_next;
        for (int it = 0; it < 200 && hi - lo > 4e-16 * spec.duration; ++it) {
          const double mid = 0.5 * (lo + hi);
          double y_mid[12];
          std::copy(y, y + 12, y_mid);
          ode.run(t, mid, y_mid);
          (yield_of(spec, y_mid) > 0.0 ? hi : lo) = mid;
        }
        ode.run(t, lo, y);
        t = lo;
        path.yield_time = lo;
        sys.branch = Branch::Plastic;
        ode.run(t, t_next, y);
      } else {
        std::copy(y_end, y_end + 12, y);
      }
    } else {
      ode.run(t, t_next, y);
    }
    t = t_next;
    record(t);
  }
  return path;
}

}  // namespace geosph::reference
