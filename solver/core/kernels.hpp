// SPH smoothing kernels in 2D and 3D. q = r/h; each kernel has compact support kappa*h.
//  - Cubic B-spline: Monaghan (1992), Annu. Rev. Astron. Astrophys. 30, eq. (2.6); kappa = 2.
//  - Wendland C2: Wendland (1995), Adv. Comput. Math. 4; normalisation as in Dehnen & Aly (2012),
//    MNRAS 425, Table 1 (written with support 2h): W = alpha (1 - q/2)^4 (2q + 1); kappa = 2.
//  - Quintic spline: Morris, Fox & Zhu (1997), J. Comput. Phys. 136, eq. (8); kappa = 3.
#pragma once
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <variant>

namespace geosph {

enum class KernelType { CubicSpline, WendlandC2, QuinticSpline };

KernelType kernel_from_name(const std::string& name);  // throws std::invalid_argument
std::string kernel_name(KernelType type);
double default_h_over_dx(KernelType type);
double kernel_support_factor(KernelType type);  // kappa: support radius = kappa * h

struct CubicSpline {
  double h, inv_h, sigma;  // sigma includes 1/h^dim
  static constexpr double kappa = 2.0;
  CubicSpline(int dim, double h_)
      : h(h_), inv_h(1.0 / h_),
        sigma(dim == 2 ? 10.0 / (7.0 * std::numbers::pi * h_ * h_) : 1.0 / (std::numbers::pi * h_ * h_ * h_)) {}
  double W(double r) const {
    const double q = r * inv_h;
    if (q < 1.0) return sigma * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
    if (q < 2.0) { const double t = 2.0 - q; return sigma * 0.25 * t * t * t; }
    return 0.0;
  }
  double dWdr(double r) const {
    const double q = r * inv_h;
    if (q < 1.0) return sigma * inv_h * (-3.0 * q + 2.25 * q * q);
    if (q < 2.0) { const double t = 2.0 - q; return -sigma * inv_h * 0.75 * t * t; }
    return 0.0;
  }
  // dW/dr / r without a division (grad_i W_ij = gradW_over_r * r_ij); finite at r = 0
  double gradW_over_r(double r) const {
    const double q = r * inv_h;
    if (q < 1.0) return sigma * inv_h * inv_h * (-3.0 + 2.25 * q);
    if (q < 2.0) { const double t = 2.0 - q; return -sigma * inv_h * 0.75 * t * t / r; }
    return 0.0;
  }  double W_inside(double r) const { return W(r); }  // piecewise: no branch-free form
  double gradW_over_r_inside(double r) const { return gradW_over_r(r); }
};

struct WendlandC2 {
  double h, inv_h, sigma;
  static constexpr double kappa = 2.0;
  WendlandC2(int dim, double h_)
      : h(h_), inv_h(1.0 / h_),
        sigma(dim == 2 ? 7.0 / (4.0 * std::numbers::pi * h_ * h_) : 21.0 / (16.0 * std::numbers::pi * h_ * h_ * h_)) {}
  double W(double r) const {
    const double q = r * inv_h;
    if (q >= 2.0) return 0.0;
    return W_inside(r);
  }
  double dWdr(double r) const {  // d/dq [(1-q/2)^4 (2q+1)] = -5 q (1-q/2)^3
    const double q = r * inv_h;
    if (q >= 2.0) return 0.0;
    const double t = 1.0 - 0.5 * q;
    return -5.0 * sigma * inv_h * q * t * t * t;
  }
  double gradW_over_r(double r) const {
    const double q = r * inv_h;
    if (q >= 2.0) return 0.0;
    return gradW_over_r_inside(r);
  }
  // W and gradW_over_r for r inside the support (a gathered neighbour): the same values without the
  // support test, so that a pair loop over gathered neighbours vectorises
  double W_inside(double r) const {
    const double q = r * inv_h;
    const double t = 1.0 - 0.5 * q, t2 = t * t;
    return sigma * t2 * t2 * (2.0 * q + 1.0);
  }
  double gradW_over_r_inside(double r) const {
    const double q = r * inv_h;
    const double t = 1.0 - 0.5 * q;
    return -5.0 * sigma * inv_h * inv_h * t * t * t;
  }
};

struct QuinticSpline {
  double h, inv_h, sigma;
  static constexpr double kappa = 3.0;
  QuinticSpline(int dim, double h_)
      : h(h_), inv_h(1.0 / h_),
        sigma(dim == 2 ? 7.0 / (478.0 * std::numbers::pi * h_ * h_) : 1.0 / (120.0 * std::numbers::pi * h_ * h_ * h_)) {}
  static double p5(double t) { const double t2 = t * t; return t2 * t2 * t; }
  static double p4(double t) { const double t2 = t * t; return t2 * t2; }
  double W(double r) const {
    const double q = r * inv_h;
    if (q >= 3.0) return 0.0;
    double w = p5(3.0 - q);
    if (q < 2.0) w -= 6.0 * p5(2.0 - q);
    if (q < 1.0) w += 15.0 * p5(1.0 - q);
    return sigma * w;
  }
  double dWdr(double r) const {
    const double q = r * inv_h;
    if (q >= 3.0) return 0.0;
    double d = -5.0 * p4(3.0 - q);
    if (q < 2.0) d += 30.0 * p4(2.0 - q);
    if (q < 1.0) d -= 75.0 * p4(1.0 - q);
    return sigma * inv_h * d;
  }
  double gradW_over_r(double r) const { return r > 0 ? dWdr(r) / r : 0.0; }
  double W_inside(double r) const { return W(r); }  // piecewise: no branch-free form
  double gradW_over_r_inside(double r) const { return gradW_over_r(r); }
};

using AnyKernel = std::variant<CubicSpline, WendlandC2, QuinticSpline>;

AnyKernel make_kernel(KernelType type, int dim, double h);

}  // namespace geosph
