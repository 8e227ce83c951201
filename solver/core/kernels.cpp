#include "core/kernels.hpp"

namespace geosph {

KernelType kernel_from_name(const std::string& name) {
  if (name == "cubic_spline") return KernelType::CubicSpline;
  if (name == "wendland_c2") return KernelType::WendlandC2;
  if (name == "quintic_spline") return KernelType::QuinticSpline;
  throw std::invalid_argument("unknown kernel '" + name + "' (allowed: cubic_spline, wendland_c2, quintic_spline)");
}

std::string kernel_name(KernelType type) {
  switch (type) {
    case KernelType::CubicSpline: return "cubic_spline";
    case KernelType::WendlandC2: return "wendland_c2";
    case KernelType::QuinticSpline: return "quintic_spline";
  }
  return "?";
}

// Smoothing length in units of particle spacing: 2h = 2.6 dx for the cubic spline (Monaghan 1992),
// 2h = 3.2 dx for Wendland C2 (which needs more neighbours, Dehnen & Aly 2012, Sec. 3),
// h = dx for the quintic spline as in Morris et al. (1997).
double default_h_over_dx(KernelType type) {
  switch (type) {
    case KernelType::CubicSpline: return 1.3;
    case KernelType::WendlandC2: return 1.6;
    case KernelType::QuinticSpline: return 1.0;
  }
  return 1.3;
}

double kernel_support_factor(KernelType type) {
  return type == KernelType::QuinticSpline ? QuinticSpline::kappa : 2.0;
}

AnyKernel make_kernel(KernelType type, int dim, double h) {
  if (dim != 2 && dim != 3) throw std::invalid_argument("kernel dimension must be 2 or 3");
  switch (type) {
    case KernelType::CubicSpline: return CubicSpline(dim, h);
    case KernelType::WendlandC2: return WendlandC2(dim, h);
    case KernelType::QuinticSpline: return QuinticSpline(dim, h);
  }
  return CubicSpline(dim, h);
}

}  // namespace geosph
