#include "core/cell_list.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace geosph {

long CellList::build(const Particles& P, const Box& box, double radius) {
  dim_ = box.dim;
  r_ = radius;
  r2max_ = radius * radius;
  for (int a = 0; a < 3; ++a) {
    if (a >= dim_) { nc_[a] = 1; lo_[a] = 0; inv_cell_[a] = 0; len_[a] = 0; periodic_[a] = false; continue; }
    lo_[a] = box.lo[a];
    len_[a] = box.length(a);
    periodic_[a] = box.periodic[a];
    nc_[a] = std::max(1, static_cast<int>(std::floor(kStencil * len_[a] / radius)));
    if (periodic_[a] && nc_[a] < 2 * kStencil + 1)
      throw std::invalid_argument("periodic axis " + std::to_string(a) + " is shorter than 3 kernel supports");
    inv_cell_[a] = nc_[a] / len_[a];
  }
  const std::size_t n = P.size(), ncell = static_cast<std::size_t>(nc_[0]) * nc_[1] * nc_[2];
  cell_.resize(n);
  // the binning in parallel (the counting sort below is serial); `first_out` is the smallest index
  // outside, whatever the thread count
  long first_out = std::numeric_limits<long>::max();
#pragma omp parallel for schedule(static) reduction(min : first_out)
  for (std::size_t i = 0; i < n; ++i) {
    if (!box.contains(P.x[i], P.y[i], P.z[i]) || !std::isfinite(P.x[i] + P.y[i] + P.z[i])) {
      first_out = std::min(first_out, static_cast<long>(i));
      cell_[i] = 0;
      continue;
    }
    const int ci = cell_coord(P.x[i], 0), cj = cell_coord(P.y[i], 1), ck = dim_ == 3 ? cell_coord(P.z[i], 2) : 0;
    cell_[i] = static_cast<std::uint32_t>((static_cast<std::size_t>(ck) * nc_[1] + cj) * nc_[0] + ci);
  }
  const long outside = first_out == std::numeric_limits<long>::max() ? -1 : first_out;
  start_.assign(ncell + 1, 0);
  for (std::size_t i = 0; i < n; ++i) ++start_[cell_[i] + 1];
  std::uint32_t fullest = 0;
  for (std::size_t c = 0; c < ncell; ++c) {
    fullest = std::max(fullest, start_[c + 1]);
    start_[c + 1] += start_[c];
  }
  const std::size_t stencil_cells = dim_ == 3 ? (2 * kStencil + 1) * (2 * kStencil + 1) * (2 * kStencil + 1)
                                              : (2 * kStencil + 1) * (2 * kStencil + 1);
  max_candidates_ = fullest * stencil_cells;
  sorted_.resize(n);
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) sorted_[fill[cell_[i]]++] = static_cast<std::uint32_t>(i);
  identity_ = false;
  return outside;
}

void CellList::mark_permuted() {
  for (std::size_t k = 0; k < sorted_.size(); ++k) sorted_[k] = static_cast<std::uint32_t>(k);
  identity_ = true;
}

}  // namespace geosph
