// Cell-linked list: particles binned into cells of edge >= the kernel support radius and sorted by
// cell with a counting sort, O(N). Neighbour queries visit the 3^dim surrounding cells and return
// minimum-image distances along periodic axes.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "core/particles.hpp"

namespace geosph {

struct Box {
  int dim = 2;
  std::array<double, 3> lo{0, 0, 0}, hi{1, 1, 1};
  std::array<bool, 3> periodic{false, false, false};
  double length(int a) const { return hi[a] - lo[a]; }
  bool contains(double x, double y, double z) const {
    return x >= lo[0] && x < hi[0] && y >= lo[1] && y < hi[1] && (dim == 2 || (z >= lo[2] && z < hi[2]));
  }
};

class CellList {
 public:
  // Bins all particles. Returns the index of the first particle outside the box, or -1.
  long build(const Particles& P, const Box& box, double radius);

  // Particle indices in cell order; cell c holds sorted()[cell_start(c) .. cell_start(c+1)).
  const std::vector<std::uint32_t>& sorted() const { return sorted_; }
  // After Particles::permute(sorted()), call this so the list refers to the new order.
  void mark_permuted();

  std::array<int, 3> cells() const { return nc_; }
  double radius() const { return r_; }

  // f(j, dx, dy, dz, r2) for every j != i with r2 < radius^2; d = x_i - x_j (minimum image).
  template <class F>
  void for_each_neighbor(const Particles& P, std::size_t i, F&& f) const {
    const int ci = cell_coord(P.x[i], 0), cj = cell_coord(P.y[i], 1), ck = dim_ == 3 ? cell_coord(P.z[i], 2) : 0;
    const double xi = P.x[i], yi = P.y[i], zi = P.z[i];
    const int kmin = dim_ == 3 ? -1 : 0, kmax = dim_ == 3 ? 1 : 0;
    for (int dk = kmin; dk <= kmax; ++dk) {
      int kk = ck + dk; double sz = 0;
      if (!wrap(kk, 2, sz)) continue;
      for (int dj = -1; dj <= 1; ++dj) {
        int jj = cj + dj; double sy = 0;
        if (!wrap(jj, 1, sy)) continue;
        for (int di = -1; di <= 1; ++di) {
          int ii = ci + di; double sx = 0;
          if (!wrap(ii, 0, sx)) continue;
          const std::size_t c = (static_cast<std::size_t>(kk) * nc_[1] + jj) * nc_[0] + ii;
          for (std::uint32_t s = start_[c]; s < start_[c + 1]; ++s) {
            const std::uint32_t j = identity_ ? s : sorted_[s];
            if (j == i) continue;
            const double dx = xi - P.x[j] - sx, dy = yi - P.y[j] - sy, dz = zi - P.z[j] - sz;
            const double r2 = dx * dx + dy * dy + dz * dz;
            if (r2 < r2max_) f(j, dx, dy, dz, r2);
          }
        }
      }
    }
  }

 private:
  int cell_coord(double v, int a) const {
    int c = static_cast<int>((v - lo_[a]) * inv_cell_[a]);
    return c < 0 ? 0 : (c >= nc_[a] ? nc_[a] - 1 : c);
  }
  // Wraps a neighbour cell index along a periodic axis; the shift is what to add to x_j.
  bool wrap(int& c, int a, double& shift) const {
    if (c >= 0 && c < nc_[a]) return true;
    if (!periodic_[a]) return false;
    if (c < 0) { c += nc_[a]; shift = -len_[a]; } else { c -= nc_[a]; shift = len_[a]; }
    return true;
  }

  int dim_ = 2;
  std::array<int, 3> nc_{1, 1, 1};
  std::array<double, 3> lo_{0, 0, 0}, inv_cell_{1, 1, 1}, len_{0, 0, 0};
  std::array<bool, 3> periodic_{false, false, false};
  double r_ = 0, r2max_ = 0;
  bool identity_ = false;
  std::vector<std::uint32_t> start_, sorted_, cell_;
};

}  // namespace geosph
