#include "analytical/terzaghi_consolidation.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace geosph::reference {

namespace {

void check(const TerzaghiSpec& s) {
  if (!(s.height > 0) || !(s.cv > 0) || !(s.B > 0 && s.B <= 1) || !(s.load > 0) || !(s.ramp >= 0))
    throw std::invalid_argument("terzaghi: need height > 0, cv > 0, 0 < B <= 1, load > 0, ramp >= 0");
}

// I_m / (B q0) for decay rate lambda = M^2 c_v / H^2: Duhamel's integral of the cosine ramp,
//   int_0^e q'(tau)/q0 e^{-lambda (t - tau)} dtau,  q'/q0 = (w/2) sin(w tau), w = pi / t_r, e = min(t, t_r),
// in closed form (int sin(w tau) e^{lambda tau} dtau = e^{lambda tau} (lambda sin w tau - w cos w tau) / (lambda^2 + w^2))
double mode_integral(double lambda, double t, double ramp) {
  if (t <= 0) return 0.0;
  if (ramp == 0) return std::exp(-lambda * t);
  const double w = M_PI / ramp, e = std::min(t, ramp);
  return 0.5 * w / (lambda * lambda + w * w) *
         (std::exp(-lambda * (t - e)) * (lambda * std::sin(w * e) - w * std::cos(w * e)) + w * std::exp(-lambda * t));
}

// Bound on the rest of the series from mode M on, |weight| <= 2/M, modes spaced by pi:
//  - during the ramp |I_m| <= q'_max / (q0 lambda) = pi / (2 t_r a M^2), a = c_v / H^2, so the rest is
//    <= (pi / (t_r a)) sum 1/M^3 <= (pi / (t_r a)) (1/(2 pi M^2) + 1/M^3);
//  - after it (or for a step) |I_m| <= exp(-a M^2 dt), dt = t - t_r, a Gaussian tail:
//    <= (2/M) exp(-a M^2 dt) (1 + 1/(2 pi a M dt)).
double tail_bound(double M, double a, double t, double ramp) {
  double b = 1e300;
  const double dt = t - ramp;
  if (dt > 0) b = 2.0 / M * std::exp(-a * M * M * dt) * (1.0 + 1.0 / (2.0 * M_PI * a * M * dt));
  if (ramp > 0) b = std::min(b, M_PI / (ramp * a) * (1.0 / (2.0 * M_PI * M * M) + 1.0 / (M * M * M)));
  return b;
}

// sum over modes of weight(M) I_m / (B q0) until the rest is below 1e-9 (of B q0)
template <class Weight>
double series(const TerzaghiSpec& s, double t, Weight weight) {
  const double a = s.cv / (s.height * s.height);
  double sum = 0;
  for (int m = 0;; ++m) {
    const double M = M_PI * (2 * m + 1) / 2.0;
    if (tail_bound(M, a, t, s.ramp) < 1e-9) return sum;
    if (m == 20000000)
      throw std::runtime_error("terzaghi: series not converged in 2e7 modes (t = " + std::to_string(t) + " s)");
    sum += weight(M) * mode_integral(M * M * a, t, s.ramp);
  }
}

}  // namespace

TerzaghiSpec terzaghi_spec(double height, double conductivity, double unit_weight_water,
                           double constrained_modulus, double porosity, double water_bulk_modulus,
                           double load, double ramp) {
  if (!(conductivity > 0) || !(unit_weight_water > 0) || !(constrained_modulus > 0) || !(porosity > 0 && porosity < 1) ||
      !(water_bulk_modulus >= 0))
    throw std::invalid_argument("terzaghi_spec: need k, gamma_w, E_oed > 0, 0 < n < 1, K_w >= 0");
  const double mv = 1.0 / constrained_modulus;
  const double S = mv + (water_bulk_modulus > 0 ? porosity / water_bulk_modulus : 0.0);
  TerzaghiSpec s{height, conductivity / (unit_weight_water * S), mv / S, load, ramp};
  check(s);
  return s;
}

double terzaghi_load(const TerzaghiSpec& s, double t) {
  check(s);
  if (t <= 0) return 0.0;
  if (s.ramp == 0 || t >= s.ramp) return s.load;
  return s.load * 0.5 * (1.0 - std::cos(M_PI * t / s.ramp));
}

double terzaghi_excess_pressure(const TerzaghiSpec& s, double depth, double t) {
  check(s);
  if (!(depth >= 0 && depth <= s.height)) throw std::invalid_argument("terzaghi: depth outside [0, H]");
  const double z = depth / s.height;
  return s.B * s.load * series(s, t, [&](double M) { return 2.0 / M * std::sin(M * z); });
}

double terzaghi_mean_excess_pressure(const TerzaghiSpec& s, double t) {
  check(s);
  // (1/H) int_0^H sin(M z / H) dz = 1 / M
  return s.B * s.load * series(s, t, [](double M) { return 2.0 / (M * M); });
}

double terzaghi_degree_of_consolidation(const TerzaghiSpec& s, double t) {
  const double q = terzaghi_load(s, t);
  if (q <= 0) return 0.0;
  return 1.0 - terzaghi_mean_excess_pressure(s, t) / q;
}

}  // namespace geosph::reference
