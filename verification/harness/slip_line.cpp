#include "harness/slip_line.hpp"

#include <gsl/gsl_fit.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace geosph::verify {

namespace {

constexpr int kStrips = 10;

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

double wedge_angle_deg(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<double> xs, ys;
  // the strips centred at 0.15-0.85 H; the window's edges lie between strip centres so that rounding
  // of a centre cannot move a strip in or out
  for (std::size_t k = 0; k < x.size(); ++k)
    if (y[k] > 0.1 && y[k] < 0.9) { xs.push_back(x[k]); ys.push_back(y[k]); }
  if (xs.size() < 3) return NAN;
  double c0, c1, c00, c01, c11, ss;
  gsl_fit_linear(xs.data(), 1, ys.data(), 1, xs.size(), &c0, &c1, &c00, &c01, &c11, &ss);
  return std::atan(std::abs(c1)) * 180.0 / std::numbers::pi;
}

SlipLine slip_line(const std::vector<double>& x0, const std::vector<double>& y0, const std::vector<double>& ux,
                   double H, double Lb, double bin, double travel) {
  SlipLine line;
  const double half = 0.5 * std::abs(travel), sign = travel < 0 ? -1.0 : 1.0;
  const int nb = static_cast<int>(std::ceil(Lb / bin));
  for (int k = 0; k < kStrips; ++k) {
    const double ylo = k * H / kStrips, yhi = (k + 1) * H / kStrips;
    std::vector<std::vector<double>> in_bin(nb);
    std::size_t count = 0;
    for (std::size_t i = 0; i < x0.size(); ++i) {
      if (y0[i] < ylo || y0[i] >= yhi || x0[i] < 0) continue;
      const int b = static_cast<int>(x0[i] / bin);
      if (b < nb) { in_bin[b].push_back(sign * ux[i]); ++count; }
    }
    if (count < 10) continue;
    std::vector<double> med(nb), sm(nb);
    for (int b = 0; b < nb; ++b) med[b] = median(in_bin[b]);
    for (int b = 0; b < nb; ++b) {
      std::vector<double> around;
      for (int c = std::max(0, b - 1); c <= std::min(nb - 1, b + 1); ++c)
        if (!std::isnan(med[c])) around.push_back(med[c]);
      sm[b] = median(around);
    }
    for (int b = 0; b < nb; ++b) {
      if (std::isnan(sm[b]) || sm[b] >= half) continue;
      double xs = 0.0;
      if (b > 0) {  // linear interpolation between the bin centres
        const double x1 = (b - 0.5) * bin, x2 = (b + 0.5) * bin;
        xs = sm[b - 1] != sm[b] ? x1 + (sm[b - 1] - half) / (sm[b - 1] - sm[b]) * (x2 - x1) : x2;
      }
      line.x.push_back(xs / H);
      line.y.push_back(0.5 * (ylo + yhi) / H);
      break;
    }
  }
  line.angle_deg = wedge_angle_deg(line.x, line.y);
  return line;
}

}  // namespace geosph::verify
