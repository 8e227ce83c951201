// Kernel values of a particle's gathered neighbours as columns, in loops that vectorise: the square root
// and the kernel polynomial of each pair, which a pair loop with scattered reads would otherwise evaluate
// one at a time. Built in core/kernel_columns.cpp without -frounding-math and errno for sqrt (see
// solver/CMakeLists.txt), so that callers compiled with them still get the vector loop. The values are
// the kernel's own (W, gradW_over_r) for neighbours inside the support, bit for bit.
#pragma once
#include <cstddef>

namespace geosph {

// fw[k] = gradW_over_r(sqrt(r2[k])) for k < n
template <class K>
void kernel_gradients(const K& kernel, const double* r2, std::size_t n, double* fw);
// w[k] = W(sqrt(r2[k])) and fw[k] = gradW_over_r(sqrt(r2[k])) for k < n
template <class K>
void kernel_values_and_gradients(const K& kernel, const double* r2, std::size_t n, double* w, double* fw);

}  // namespace geosph
