// Cell-linked list: particles binned into cells of edge >= half the search reach (kernel support plus
// the pair list's skin) and sorted by cell with a counting sort, O(N). Neighbour queries read the
// Verlet pair list when one is kept, else visit the 5^dim surrounding cells (rows along x as
// contiguous ranges); both return minimum-image distances along periodic axes.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <span>
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

// The neighbours of one particle as arrays (CellList::gather), so that a pair loop runs over contiguous
// data with no call per pair. Reused across particles (keep one per thread): the arrays only grow.
struct Neighbors {
  std::vector<std::uint32_t> j;
  std::vector<double> dx, dy, dz, r2;
  std::vector<std::uint8_t> image;  // CellList::rebuild_pairs only: the periodic image of j (CellList::image_code)
  std::size_t n = 0;
  std::size_t size() const { return n; }
  void reserve(std::size_t cap) {
    if (j.size() >= cap) return;
    j.resize(cap); dx.resize(cap); dy.resize(cap); dz.resize(cap); r2.resize(cap); image.resize(cap);
  }
};

// Particle index ranges [lo, hi) that hold every particle of some kinds (CellList::ranges_of), ascending
// and disjoint: a query restricted to them reads only the part of a particle's list it needs. They bound
// the kinds wherever their particles lie; they are tight when each kind's particles are contiguous, as
// after a reorder grouped by kind (Simulation::neighbour_search).
struct IndexRanges {
  std::array<std::array<std::uint32_t, 2>, 6> r{};
  int n = 0;
};

// What a neighbour query reads and writes, as raw pointers: the positions, and the arrays of a
// Neighbors reserved for `cap` entries.
struct GatherPointers {
  const double *px, *py, *pz;
  std::uint32_t* oj;
  double *ox, *oy, *oz, *orr;
  std::uint8_t* oi;
  GatherPointers(const Particles& P, Neighbors& out, std::size_t cap) : px(P.x.data()), py(P.y.data()), pz(P.z.data()) {
    out.reserve(cap);
    oj = out.j.data(); ox = out.dx.data(); oy = out.dy.data(); oz = out.dz.data(); orr = out.r2.data();
    oi = out.image.data();
  }
};

// A Verlet list for query points that are not particles (ghost walls' mirror points), built by
// CellList::list_near_points: point q's candidates are j[start[q] .. start[q+1]), in the order the
// cell scan visits them, with their periodic images. Valid for the pair list build it was made in
// (`build`), provided each point moves with a particle (a mirror point with its wall particle).
struct PointList {
  std::vector<std::size_t> start;
  std::vector<std::uint32_t> j;
  std::vector<std::uint8_t> image;  // periodic scenes only
  long build = -1;
};

// Buffers for neighbour queries nested inside another's pair function (a few levels).
class NeighborStack {
 public:
  // One level for the lifetime of a query (released also when the pair function throws).
  struct Level {
    NeighborStack& stack;
    Neighbors& buffer;
    explicit Level(NeighborStack& s) : stack(s), buffer(s.push()) {}
    ~Level() { --stack.depth_; }
    Level(const Level&) = delete;
    Level& operator=(const Level&) = delete;
  };

 private:
  Neighbors& push() {
    if (depth_ == kDepth) throw std::logic_error("neighbour queries nested deeper than 4");
    return level_[depth_++];
  }
  static constexpr int kDepth = 4;
  Neighbors level_[kDepth];
  int depth_ = 0;
};

class CellList {
 public:
  // Bins all particles, in cells wide enough for neighbours within radius + skin (the pair list's
  // reach; queries return those within radius). Returns the index of the first particle outside the
  // box, or -1. Keeps the pair list (rebuild_pairs) unless the box, radius or skin changed.
  long build(const Particles& P, const Box& box, double radius, double skin = 0);

  // Particle indices in cell order; cell c holds sorted()[cell_start(c) .. cell_start(c+1)).
  const std::vector<std::uint32_t>& sorted() const { return sorted_; }
  // After Particles::permute(sorted()), call this so the list refers to the new order.
  void mark_permuted();

  std::array<int, 3> cells() const { return nc_; }
  double radius() const { return r_; }

  // The neighbours of particle i (as for_each_neighbor) into `out`. Branch-free: every candidate is
  // written and the count advances only for a neighbour (the r < radius test is a coin flip for half
  // the candidates, and a mispredicted branch each time cost more than the stores).
  // Dim 2: dz is 0 and out.dz is not written.
  template <int Dim = 3>
  void gather(const Particles& P, std::size_t i, Neighbors& out) const {
    if (cached_) gather_cached<Dim>(P, i, out);
    else gather_scan<Dim>(P, i, out);
  }
  // gather in the list's dimension (2D: out.dz is not written, read it as 0)
  void gather_any_dim(const Particles& P, std::size_t i, Neighbors& out) const {
    if (dim_ == 2) gather<2>(P, i, out);
    else gather<3>(P, i, out);
  }
  // The same neighbours restricted to the index ranges `only` (ranges_of: the kinds a pair loop reads),
  // in the same ascending order: a loop that skips the other kinds sums the same terms in the same order.
  // Without a pair list it gathers them all.
  template <int Dim = 3>
  void gather(const Particles& P, std::size_t i, Neighbors& out, const IndexRanges& only) const {
    if (!cached_) { gather_scan<Dim>(P, i, out); return; }
    if (any_periodic_) gather_cached_with<Dim, true>(P, i, out, &only);
    else gather_cached_with<Dim, false>(P, i, out, &only);
  }
  void gather_any_dim(const Particles& P, std::size_t i, Neighbors& out, const IndexRanges& only) const {
    if (dim_ == 2) gather<2>(P, i, out, only);
    else gather<3>(P, i, out, only);
  }
  // Index ranges holding every particle of the given kinds, as of the last rebuild_pairs (kinds do not
  // change between builds); the whole index range without a pair list.
  IndexRanges ranges_of(std::initializer_list<Kind> kinds) const;
  int dim() const { return dim_; }

  // A Verlet pair list (Verlet 1967, Phys. Rev. 159, 98; with a skin as in Allen & Tildesley 1987,
  // "Computer Simulation of Liquids", sec. 5.3.1): each particle's neighbours within radius + skin,
  // and valid until a particle has moved more than skin/2 since its build (no pair can then have come
  // within radius unseen) or the particles are permuted. Queries read the list and
  // keep the pairs within radius: a scan of the cells visits about twice the candidates it keeps.
  // Each particle's list is in ascending j, so a query's neighbours and their order do not depend on
  // when the list was built (a restarted run gives the same bits), nor on the thread count.
  // rebuild_pairs builds the list from the current cells (call after build); with no skin it keeps none.
  void rebuild_pairs(const Particles& P);
  // Whether the list holds every pair within radius now (no particle moved half the skin since its
  // build); while it does, a step needs no new cells, only find_outside.
  bool pairs_current(const Particles& P) const;
  // The index of the first particle outside the box (or not finite), as build() reports it, or -1.
  long find_outside(const Particles& P, const Box& box) const;
  bool pairs_cached() const { return cached_; }
  long pair_list_builds() const { return list_builds_; }
  // The listed candidates of i (within radius + skin at the list's build, ascending); pairs_cached() only.
  // The list is symmetric: j is listed for i exactly when i is listed for j.
  std::span<const std::uint32_t> listed(std::size_t i) const {
    return {pair_j_.data() + pair_start_[i], pair_start_[i + 1] - pair_start_[i]};
  }

  // f(j, dx, dy, dz, r2) for every j != i with r2 < radius^2; d = x_i - x_j (minimum image).
  // The neighbours are gathered first into a per-thread buffer, so that f has a single call site
  // and is inlined into the pair loop (called per pair from the cell scan, it was not).
  // A pair loop with accumulators of its own should call gather_any_dim and loop over the arrays itself:
  // through f's references the compiler keeps the accumulators in memory, not in registers.
  template <class F>
  void for_each_neighbor(const Particles& P, std::size_t i, F&& f) const {
    thread_local NeighborStack stack;
    const NeighborStack::Level level(stack);
    Neighbors& nb = level.buffer;
    gather_any_dim(P, i, nb);
    const bool flat = dim_ == 2;
    for (std::size_t k = 0; k < nb.n; ++k) f(nb.j[k], nb.dx[k], nb.dy[k], flat ? 0.0 : nb.dz[k], nb.r2[k]);
  }

  // f(j, dx, dy, dz, r2) for every particle j within radius of the point (x, y, z), which need not be a
  // particle's (a ghost wall's mirror point); d = point - x_j (minimum image), 2D: dz = 0. Reads the
  // current positions through the cells of the last build(): a particle moves less than the skin
  // between builds and the cells cover radius + skin.
  template <class F>
  void for_each_near_point(const Particles& P, double x, double y, double z, F&& f) const {
    const bool flat = dim_ == 2;
    for_each_range_at(x, y, z, [&](std::uint32_t s0, std::uint32_t s1, double sx, double sy, double sz) {
      for (std::uint32_t s = s0; s < s1; ++s) {
        const std::uint32_t j = identity_ ? s : sorted_[s];
        const double dx = x - (P.x[j] + sx), dy = y - (P.y[j] + sy), dz = flat ? 0.0 : z - (P.z[j] + sz);
        const double r2 = dx * dx + dy * dy + dz * dz;
        if (r2 < r2max_) f(j, dx, dy, dz, r2);
      }
    });
  }

  // Lists, for each of nq query points, the particles j with keep(j) within radius + skin of it at the
  // pair list's current build: point(q, xyz) writes point q's position and returns false where q has
  // no query. Two passes (count, fill), each a parallel loop: the list does not depend on the thread
  // count. Requires pairs_cached().
  template <class Point, class Keep>
  void list_near_points(const Particles& P, std::size_t nq, const Point& point, const Keep& keep, PointList& out) const {
    if (!cached_) throw std::logic_error("CellList::list_near_points needs the pair list");
    out.start.assign(nq + 1, 0);
    const auto scan = [&](std::size_t q, auto&& take) {
      double xq[3] = {0, 0, 0};
      if (!point(q, xq)) return;
      const bool flat = dim_ == 2;
      for_each_range_at(xq[0], xq[1], xq[2], [&](std::uint32_t s0, std::uint32_t s1, double sx, double sy, double sz) {
        for (std::uint32_t s = s0; s < s1; ++s) {
          const std::uint32_t j = identity_ ? s : sorted_[s];
          const double dx = xq[0] - (P.x[j] + sx), dy = xq[1] - (P.y[j] + sy), dz = flat ? 0.0 : xq[2] - (P.z[j] + sz);
          if (dx * dx + dy * dy + dz * dz < list_r2max_ && keep(j)) take(j, image_code(sx, sy, sz));
        }
      });
    };
#pragma omp parallel for schedule(dynamic, 256)
    for (std::size_t q = 0; q < nq; ++q) {
      std::size_t c = 0;
      scan(q, [&](std::uint32_t, std::uint8_t) { ++c; });
      out.start[q + 1] = c;
    }
    for (std::size_t q = 0; q < nq; ++q) out.start[q + 1] += out.start[q];
    out.j.resize(out.start[nq]);
    out.image.resize(any_periodic_ ? out.start[nq] : 0);
#pragma omp parallel for schedule(dynamic, 256)
    for (std::size_t q = 0; q < nq; ++q) {
      std::size_t c = out.start[q];
      scan(q, [&](std::uint32_t j, std::uint8_t im) {
        out.j[c] = j;
        if (any_periodic_) out.image[c] = im;
        ++c;
      });
    }
    out.build = list_builds_;
  }
  // Whether `list` was built for the pair list as it stands.
  bool point_list_current(const PointList& list) const { return cached_ && list.build == list_builds_; }

  // for_each_near_point at query point q of `list` (at x, y, z now), from its listed candidates where
  // the list is current: the same particles in the same order as the scan (each moved under half the
  // skin since the build), filtered by the list's keep.
  template <class F>
  void for_each_near_point(const Particles& P, const PointList& list, std::size_t q, double x, double y, double z, F&& f) const {
    if (!point_list_current(list)) {
      for_each_near_point(P, x, y, z, f);
      return;
    }
    const bool flat = dim_ == 2;
    for (std::size_t k = list.start[q]; k < list.start[q + 1]; ++k) {
      const std::uint32_t j = list.j[k];
      const double* s = any_periodic_ ? image_shift_[list.image[k]].data() : image_shift_[13].data();
      const double dx = x - (P.x[j] + s[0]), dy = y - (P.y[j] + s[1]), dz = flat ? 0.0 : z - (P.z[j] + s[2]);
      const double r2 = dx * dx + dy * dy + dz * dz;
      if (r2 < r2max_) f(j, dx, dy, dz, r2);
    }
  }

 private:
  template <int Dim, bool RecordImage = false>
  void gather_scan(const Particles& P, std::size_t i, Neighbors& out) const {
    const double xi = P.x[i], yi = P.y[i], zi = P.z[i];
    const auto [px, py, pz, oj, ox, oy, oz, orr, oi] = GatherPointers(P, out, max_candidates_);
    std::size_t n = 0;
    for_each_range(P, i, [&](std::uint32_t s0, std::uint32_t s1, double sx, double sy, double sz) {
      const double r2max = RecordImage ? list_r2max_ : r2max_;  // the pair list reaches radius + skin
      const std::uint8_t code = RecordImage ? image_code(sx, sy, sz) : 0;
      std::size_t c = n;
      for (std::uint32_t s = s0; s < s1; ++s) {
        const std::uint32_t j = identity_ ? s : sorted_[s];
        const double dx = xi - px[j] - sx, dy = yi - py[j] - sy, dz = Dim == 3 ? zi - pz[j] - sz : 0.0;
        const double r2 = Dim == 3 ? dx * dx + dy * dy + dz * dz : dx * dx + dy * dy;
        oj[c] = j; ox[c] = dx; oy[c] = dy; orr[c] = r2;
        if constexpr (Dim == 3) oz[c] = dz;
        if constexpr (RecordImage) oi[c] = code;
        c += static_cast<std::size_t>((r2 < r2max) & (j != i));
      }
      n = c;
    });
    out.n = n;
  }

  // The listed neighbours of i within radius, their distances from the current positions: x_i - x_j
  // minus the shift of j's periodic image (the scan's arithmetic); branch-free as gather_scan.
  template <int Dim>
  void gather_cached(const Particles& P, std::size_t i, Neighbors& out) const {
    if (any_periodic_) gather_cached_with<Dim, true>(P, i, out);
    else gather_cached_with<Dim, false>(P, i, out);
  }
  template <int Dim, bool Periodic>
  void gather_cached_with(const Particles& P, std::size_t i, Neighbors& out, const IndexRanges* only = nullptr) const {
    const std::size_t k0 = pair_start_[i], n = pair_start_[i + 1] - k0;
    const GatherPointers ptr(P, out, n);
    const std::uint32_t* list = pair_j_.data() + k0;
    if (!only) { out.n = gather_listed<Dim, Periodic>(P, i, ptr, 0, n, 0); return; }
    std::size_t c = 0;
    for (int q = 0; q < only->n; ++q) {  // each range's part of the ascending list
      const std::size_t a = static_cast<std::size_t>(std::lower_bound(list, list + n, only->r[q][0]) - list);
      const std::size_t b = static_cast<std::size_t>(std::lower_bound(list + a, list + n, only->r[q][1]) - list);
      c = gather_listed<Dim, Periodic>(P, i, ptr, a, b, c);
    }
    out.n = c;
  }
  // Entries [a, b) of i's list into the gather arrays from position c on; returns the new count.
  template <int Dim, bool Periodic>
  std::size_t gather_listed(const Particles& P, std::size_t i, const GatherPointers& ptr, std::size_t a, std::size_t b,
                            std::size_t c) const {
    const double xi = P.x[i], yi = P.y[i], zi = P.z[i];
    const std::size_t k0 = pair_start_[i];
    const double r2max = r2max_;
    [[maybe_unused]] const auto [px, py, pz, oj, ox, oy, oz, orr, oi] = ptr;
    const std::uint32_t* __restrict list = pair_j_.data() + k0;
    const std::uint8_t* __restrict img = Periodic ? pair_image_.data() + k0 : nullptr;
    for (std::size_t k = a; k < b; ++k) {
      const std::uint32_t j = list[k];
      double dx = xi - px[j], dy = yi - py[j], dz = Dim == 3 ? zi - pz[j] : 0.0;
      if constexpr (Periodic) {
        const double* s = image_shift_[img[k]].data();
        dx = dx - s[0];
        dy = dy - s[1];
        if constexpr (Dim == 3) dz = dz - s[2];
      }
      const double r2 = Dim == 3 ? dx * dx + dy * dy + dz * dz : dx * dx + dy * dy;
      oj[c] = j; ox[c] = dx; oy[c] = dy; orr[c] = r2;
      if constexpr (Dim == 3) oz[c] = dz;
      c += static_cast<std::size_t>(r2 < r2max);
    }
    return c;
  }
  // A periodic image as one number, 0..26: the sign of its shift along each axis, (sx, sy, sz) =
  // image_shift_[code] (the values wrap() gives: 0 or +-len_, exactly).
  static std::uint8_t image_code(double sx, double sy, double sz) {
    const auto sign = [](double s) { return static_cast<int>(s > 0) - static_cast<int>(s < 0) + 1; };
    return static_cast<std::uint8_t>(sign(sx) + 3 * sign(sy) + 9 * sign(sz));
  }

  // g(s0, s1, sx, sy, sz) for each contiguous range sorted()[s0 .. s1) of the cells around particle i,
  // with the shift to add to x_j (periodic images). The cells of a row along x are consecutive in cell
  // order, so a row is one range (unless it wraps around a periodic x boundary).
  template <class G>
  void for_each_range(const Particles& P, std::size_t i, G&& g) const {
    for_each_range_at(P.x[i], P.y[i], P.z[i], g);
  }
  // The same around any point (x, y, z).
  template <class G>
  void for_each_range_at(double x, double y, double z, G&& g) const {
    const int ci = cell_coord(x, 0), cj = cell_coord(y, 1), ck = dim_ == 3 ? cell_coord(z, 2) : 0;
    const int S = kStencil, kmin = dim_ == 3 ? -S : 0, kmax = dim_ == 3 ? S : 0;
    const bool row_wraps = periodic_[0] && (ci < S || ci >= nc_[0] - S);
    for (int dk = kmin; dk <= kmax; ++dk) {
      int kk = ck + dk; double sz = 0;
      if (!wrap(kk, 2, sz)) continue;
      for (int dj = -S; dj <= S; ++dj) {
        int jj = cj + dj; double sy = 0;
        if (!wrap(jj, 1, sy)) continue;
        const std::size_t row = (static_cast<std::size_t>(kk) * nc_[1] + jj) * nc_[0];
        if (!row_wraps) {
          const auto c0 = static_cast<std::size_t>(std::max(ci - S, 0));
          const auto c1 = static_cast<std::size_t>(std::min(ci + S, nc_[0] - 1));
          g(start_[row + c0], start_[row + c1 + 1], 0.0, sy, sz);
        } else {
          for (int di = -S; di <= S; ++di) {
            int ii = ci + di; double sx = 0;
            if (!wrap(ii, 0, sx)) continue;
            g(start_[row + ii], start_[row + ii + 1], sx, sy, sz);
          }
        }
      }
    }
  }

  // Cells are 1/kStencil of the search radius wide and a query visits (2 kStencil + 1)^dim of
  // them: with 2, about 30% fewer candidate pairs than radius-wide cells in 2D.
  static constexpr int kStencil = 2;
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
  static bool inside(const Box& box, const Particles& P, std::size_t i) {
    return box.contains(P.x[i], P.y[i], P.z[i]) && std::isfinite(P.x[i] + P.y[i] + P.z[i]);
  }
  double max_displacement2(const Particles& P) const;  // since the pair list's build, squared

  double r_ = 0, r2max_ = 0, skin_ = 0, list_r2max_ = 0;
  std::size_t max_candidates_ = 0;  // the most particles a query can scan (fullest cell x stencil cells)
  bool identity_ = false;
  std::vector<std::uint32_t> start_, sorted_, cell_;
  // rebuild_pairs: particle i's neighbours are pair_j_[pair_start_[i] .. pair_start_[i+1])
  bool cached_ = false, any_periodic_ = false;
  long list_builds_ = 0;
  std::vector<double> x0_, y0_, z0_;  // positions at the list's build
  std::array<std::array<double, 3>, 27> image_shift_{};
  std::vector<std::size_t> pair_start_;
  std::vector<std::uint32_t> pair_j_;
  std::vector<std::uint8_t> pair_image_;  // periodic scenes only
  // per kind, the lowest index and one past the highest at the list's build (lo >= hi: none)
  std::array<std::uint32_t, 8> kind_lo_{}, kind_hi_{};
  std::vector<std::vector<std::uint32_t>> thread_pairs_;
  std::vector<std::vector<std::uint8_t>> thread_images_;
};

}  // namespace geosph
