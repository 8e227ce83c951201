#include "core/kernel_columns.hpp"

#include <cmath>

#include "core/kernels.hpp"

namespace geosph {

template <class K>
void kernel_gradients(const K& kernel, const double* __restrict r2, std::size_t n, double* __restrict fw) {
#pragma omp simd
  for (std::size_t k = 0; k < n; ++k) fw[k] = kernel.gradW_over_r_inside(std::sqrt(r2[k]));
}

template <class K>
void kernel_values_and_gradients(const K& kernel, const double* __restrict r2, std::size_t n, double* __restrict w,
                                 double* __restrict fw) {
#pragma omp simd
  for (std::size_t k = 0; k < n; ++k) {
    const double r = std::sqrt(r2[k]);
    w[k] = kernel.W_inside(r);
    fw[k] = kernel.gradW_over_r_inside(r);
  }
}

#define GEOSPH_KERNEL_COLUMNS(K)                                                                  \
  template void kernel_gradients<K>(const K&, const double*, std::size_t, double*);             \
  template void kernel_values_and_gradients<K>(const K&, const double*, std::size_t, double*, double*);
GEOSPH_KERNEL_COLUMNS(CubicSpline)
GEOSPH_KERNEL_COLUMNS(WendlandC2)
GEOSPH_KERNEL_COLUMNS(QuinticSpline)
#undef GEOSPH_KERNEL_COLUMNS

}  // namespace geosph
