#include "core/cell_list.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <omp.h>

namespace geosph {

namespace {
// Sorts the first m entries of a (a handful: one per particle kind) ascending by key(entry); std::sort
// on a fixed-size array gives GCC 12 a false -Warray-bounds.
template <class T, std::size_t N, class Key>
void sort_few(std::array<T, N>& a, int m, Key key) {
  for (int q = 1; q < m; ++q)
    for (int t = q; t > 0 && key(a[static_cast<std::size_t>(t)]) < key(a[static_cast<std::size_t>(t - 1)]); --t)
      std::swap(a[static_cast<std::size_t>(t)], a[static_cast<std::size_t>(t - 1)]);
}
}  // namespace

long CellList::build(const Particles& P, const Box& box, double radius, double skin) {
  const bool same = box.dim == dim_ && radius == r_ && skin == skin_ && pair_start_.size() == P.size() + 1 &&
                    [&] {
                      for (int a = 0; a < box.dim; ++a)
                        if (box.lo[a] != lo_[a] || box.length(a) != len_[a] || box.periodic[a] != periodic_[a]) return false;
                      return true;
                    }();
  if (!same) cached_ = false;
  dim_ = box.dim;
  r_ = radius;
  skin_ = skin;
  r2max_ = radius * radius;
  list_r2max_ = (radius + skin) * (radius + skin);
  const double reach = radius + skin;  // the cells are sized for the pair list's reach
  for (int a = 0; a < 3; ++a) {
    if (a >= dim_) { nc_[a] = 1; lo_[a] = 0; inv_cell_[a] = 0; len_[a] = 0; periodic_[a] = false; continue; }
    lo_[a] = box.lo[a];
    len_[a] = box.length(a);
    periodic_[a] = box.periodic[a];
    nc_[a] = std::max(1, static_cast<int>(std::floor(kStencil * len_[a] / reach)));
    if (periodic_[a] && nc_[a] < 2 * kStencil + 1)
      throw std::invalid_argument("periodic axis " + std::to_string(a) + " is shorter than 3 kernel supports");
    inv_cell_[a] = nc_[a] / len_[a];
  }
  any_periodic_ = periodic_[0] || periodic_[1] || periodic_[2];
  for (int code = 0; code < 27; ++code)
    for (int a = 0, c = code; a < 3; ++a, c /= 3) image_shift_[code][a] = (c % 3 - 1) * len_[a];
  const std::size_t n = P.size(), ncell = static_cast<std::size_t>(nc_[0]) * nc_[1] * nc_[2];
  cell_.resize(n);
  // the binning in parallel (the counting sort below is serial); `first_out` is the smallest index
  // outside, whatever the thread count
  long first_out = std::numeric_limits<long>::max();
#pragma omp parallel for schedule(static) reduction(min : first_out)
  for (std::size_t i = 0; i < n; ++i) {
    if (!inside(box, P, i)) {
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
  cached_ = false;
}

IndexRanges CellList::ranges_of(std::initializer_list<Kind> kinds) const {
  IndexRanges out;
  if (!cached_) {  // gather ignores the ranges then
    out.r[0] = {0, std::numeric_limits<std::uint32_t>::max()};
    out.n = 1;
    return out;
  }
  std::array<std::array<std::uint32_t, 2>, 8> r{};
  int m = 0;
  for (const Kind k : kinds) {
    const auto c = static_cast<std::size_t>(k);
    if (kind_lo_[c] < kind_hi_[c]) r[static_cast<std::size_t>(m++)] = {kind_lo_[c], kind_hi_[c]};
  }
  sort_few(r, m, [](const std::array<std::uint32_t, 2>& x) { return x[0]; });  // by lo
  for (int q = 0; q < m; ++q) {  // merge overlapping or touching ranges
    const auto& x = r[static_cast<std::size_t>(q)];
    if (out.n > 0 && x[0] <= out.r[static_cast<std::size_t>(out.n - 1)][1])
      out.r[static_cast<std::size_t>(out.n - 1)][1] = std::max(out.r[static_cast<std::size_t>(out.n - 1)][1], x[1]);
    else
      out.r[static_cast<std::size_t>(out.n++)] = x;
  }
  return out;
}

long CellList::find_outside(const Particles& P, const Box& box) const {
  const std::size_t n = P.size();
  long first_out = std::numeric_limits<long>::max();
#pragma omp parallel for schedule(static) reduction(min : first_out)
  for (std::size_t i = 0; i < n; ++i)
    if (!inside(box, P, i)) first_out = std::min(first_out, static_cast<long>(i));
  return first_out == std::numeric_limits<long>::max() ? -1 : first_out;
}

bool CellList::pairs_current(const Particles& P) const {
  return cached_ && pair_start_.size() == P.size() + 1 && max_displacement2(P) <= 0.25 * skin_ * skin_;
}

double CellList::max_displacement2(const Particles& P) const {
  const std::size_t n = P.size();
  double d2 = 0;
#pragma omp parallel for schedule(static) reduction(max : d2)
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = P.x[i] - x0_[i], dy = P.y[i] - y0_[i], dz = P.z[i] - z0_[i];
    d2 = std::max(d2, dx * dx + dy * dy + dz * dz);  // NaN positions: build() has reported them
  }
  return d2;
}

// Each thread scans a contiguous block of particles into its own list (each particle's sorted by j,
// with its periodic image codes), then copies it to its place in the shared one: the list is the same
// whatever the thread count.
void CellList::rebuild_pairs(const Particles& P) {
  cached_ = false;
  if (!(skin_ > 0)) return;  // no list: queries scan the cells
  const std::size_t n = P.size();
  kind_lo_.fill(std::numeric_limits<std::uint32_t>::max());
  kind_hi_.fill(0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(P.kind[i]);
    kind_lo_[k] = std::min(kind_lo_[k], static_cast<std::uint32_t>(i));
    kind_hi_[k] = static_cast<std::uint32_t>(i + 1);
  }
  // Each kind's particles in one block of indices (a reorder grouped by kind): the scan then meets the
  // blocks interleaved cell by cell, each block's part ascending, and the lists are put in block order
  // first, so that the insertion sort below has little left to do.
  std::array<std::uint32_t, 8> cuts{};  // the blocks' first indices after the first
  int ncut = 0;
  std::size_t covered = 0;
  for (std::size_t k = 0; k < kind_lo_.size(); ++k)
    if (kind_lo_[k] < kind_hi_[k]) {
      covered += kind_hi_[k] - kind_lo_[k];
      if (kind_lo_[k] > 0) cuts[static_cast<std::size_t>(ncut++)] = kind_lo_[k];
    }
  const bool blocks = covered == n && ncut > 0;
  sort_few(cuts, ncut, [](std::uint32_t c) { return c; });
  pair_start_.assign(n + 1, 0);
  thread_pairs_.resize(static_cast<std::size_t>(omp_get_max_threads()));
  thread_images_.resize(thread_pairs_.size());
  const bool images = any_periodic_;
#pragma omp parallel
  {
    const auto t = static_cast<std::size_t>(omp_get_thread_num()), T = static_cast<std::size_t>(omp_get_num_threads());
    const std::size_t b = n * t / T, e = n * (t + 1) / T;
    std::vector<std::uint32_t>& mine = thread_pairs_[t];
    std::vector<std::uint8_t>& my_images = thread_images_[t];
    mine.clear();
    my_images.clear();
    Neighbors nb;
    std::vector<std::uint32_t> tj;
    std::vector<std::uint8_t> ti, key;
    for (std::size_t i = b; i < e; ++i) {
      if (dim_ == 2) gather_scan<2, true>(P, i, nb);
      else gather_scan<3, true>(P, i, nb);
      if (blocks) {  // stable partition by block (a counting sort on the block number)
        tj.resize(nb.n); ti.resize(nb.n); key.resize(nb.n);
        std::array<std::size_t, 9> at{};
        for (std::size_t c = 0; c < nb.n; ++c) {
          std::uint8_t q = 0;
          while (q < ncut && nb.j[c] >= cuts[q]) ++q;
          key[c] = q;
          ++at[q + 1u];
        }
        for (int q = 0; q < ncut; ++q) at[static_cast<std::size_t>(q) + 1] += at[static_cast<std::size_t>(q)];
        for (std::size_t c = 0; c < nb.n; ++c) {
          const std::size_t d = at[key[c]]++;
          tj[d] = nb.j[c];
          ti[d] = nb.image[c];
        }
        std::copy(tj.begin(), tj.end(), nb.j.begin());
        std::copy(ti.begin(), ti.end(), nb.image.begin());
      }
      // insertion sort by j: the scan visits the cells in index order, and the particles are sorted by
      // cell every few steps, so the scan's order is nearly ascending already
      for (std::size_t c = 1; c < nb.n; ++c) {
        const std::uint32_t j = nb.j[c];
        const std::uint8_t im = nb.image[c];
        std::size_t q = c;
        for (; q > 0 && nb.j[q - 1] > j; --q) { nb.j[q] = nb.j[q - 1]; nb.image[q] = nb.image[q - 1]; }
        nb.j[q] = j;
        nb.image[q] = im;
      }
      const auto k = static_cast<std::ptrdiff_t>(nb.n);
      pair_start_[i + 1] = nb.n;
      mine.insert(mine.end(), nb.j.begin(), nb.j.begin() + k);
      if (images) my_images.insert(my_images.end(), nb.image.begin(), nb.image.begin() + k);
    }
#pragma omp barrier
#pragma omp single
    {
      for (std::size_t i = 0; i < n; ++i) pair_start_[i + 1] += pair_start_[i];
      pair_j_.resize(pair_start_[n]);
      pair_image_.resize(images ? pair_start_[n] : 0);
    }
    const auto at = static_cast<std::ptrdiff_t>(pair_start_[b]);
    std::copy(mine.begin(), mine.end(), pair_j_.begin() + at);
    if (images) std::copy(my_images.begin(), my_images.end(), pair_image_.begin() + at);
  }
  x0_ = P.x;
  y0_ = P.y;
  z0_ = P.z;
  cached_ = true;
  ++list_builds_;
}

}  // namespace geosph
