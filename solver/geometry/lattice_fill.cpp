#include "geometry/lattice_fill.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace geosph::geometry {

namespace {

// The index range [i0, i1) per axis of the lattice points (i + 1/2) dx, anchored at the origin, that
// cover the window (a box); axes beyond d have the single index 0.
struct LatticeRange {
  std::array<long, 3> i0{0, 0, 0}, i1{1, 1, 1};
};
LatticeRange lattice_range(int d, double dx, const Bounds& window) {
  LatticeRange r;
  for (int a = 0; a < d; ++a) {
    r.i0[a] = static_cast<long>(std::floor(window.lo[a] / dx - 0.5));
    r.i1[a] = static_cast<long>(std::ceil(window.hi[a] / dx - 0.5)) + 1;
  }
  return r;
}

// The points of the range in lattice order (x fastest), f(point, index), until f returns false;
// returns whether it stopped early.
template <class F>
bool visit_lattice_range(int d, double dx, const LatticeRange& r, F&& f) {
  for (long k = r.i0[2]; k < r.i1[2]; ++k)
    for (long j = r.i0[1]; j < r.i1[1]; ++j)
      for (long i = r.i0[0]; i < r.i1[0]; ++i)
        if (!f(Point{(i + 0.5) * dx, (j + 0.5) * dx, d == 3 ? (k + 0.5) * dx : 0.0}, std::array<long, 3>{i, j, k}))
          return true;
  return false;
}

// The lattice points that lie in the window, in lattice order, until f(point) returns false.
template <class F>
bool visit_lattice_points(int d, double dx, const Bounds& window, F&& f) {
  return visit_lattice_range(d, dx, lattice_range(d, dx, window),
                             [&](const Point& p, const std::array<long, 3>&) { return f(p); });
}

}  // namespace

std::vector<Point> fill_lattice(const Shape& s, double dx, double shell) {
  std::vector<Point> out;
  if (shell <= 0) {
    visit_lattice_points(s.dim(), dx, s.bounds(), [&](const Point& p) {
      if (s.contains(p, dx)) out.push_back(p);
      return true;
    });
    return out;
  }
  // A wall shell: blocks of kBlock^d lattice points whose centre lies farther than shell + the
  // block's half-diagonal from the surface hold no shell point (|distance| never exceeds the true
  // distance, shape.hpp), so they are skipped with one distance query instead of one per point; deep
  // inside a large STL body the AABB tree's closest-point search is the slow query.
  constexpr long kBlock = 8;
  const int d = s.dim();
  const LatticeRange r = lattice_range(d, dx, s.bounds());
  std::array<long, 3> nb{1, 1, 1};
  for (int a = 0; a < d; ++a) nb[a] = (r.i1[a] - r.i0[a] + kBlock - 1) / kBlock;
  const auto block_of = [&](const std::array<long, 3>& idx) {
    return static_cast<std::size_t>((((idx[2] - r.i0[2]) / kBlock) * nb[1] + (idx[1] - r.i0[1]) / kBlock) * nb[0] +
                                    (idx[0] - r.i0[0]) / kBlock);
  };
  std::vector<char> near(static_cast<std::size_t>(nb[0] * nb[1] * nb[2]), 1);
  for (long bk = 0; bk < nb[2]; ++bk)
    for (long bj = 0; bj < nb[1]; ++bj)
      for (long bi = 0; bi < nb[0]; ++bi) {
        const long b[3] = {bi, bj, bk};
        Point c{0, 0, 0};
        double half2 = 0;
        for (int a = 0; a < d; ++a) {
          const long lo = r.i0[a] + b[a] * kBlock, hi = std::min(r.i1[a], lo + kBlock) - 1;
          c[a] = (0.5 * static_cast<double>(lo + hi) + 0.5) * dx;
          const double half = 0.5 * static_cast<double>(hi - lo) * dx;
          half2 += half * half;
        }
        near[static_cast<std::size_t>((bk * nb[1] + bj) * nb[0] + bi)] = std::abs(s.distance(c)) <= shell + std::sqrt(half2);
      }
  visit_lattice_range(d, dx, r, [&](const Point& p, const std::array<long, 3>& idx) {
    if (near[block_of(idx)] && s.contains(p, dx) && s.distance(p) > -shell) out.push_back(p);
    return true;
  });
  return out;
}

bool holds_lattice_point(const Shape& s, double dx) {
  return visit_lattice_points(s.dim(), dx, s.bounds(), [&](const Point& p) { return !s.contains(p, dx); });
}

bool shapes_overlap(const Shape& a, const Shape& b, double dx) {
  const Bounds ba = a.bounds(), bb = b.bounds();
  Bounds w;
  for (int k = 0; k < 3; ++k) {
    w.lo[k] = std::max(ba.lo[k], bb.lo[k]);
    w.hi[k] = std::min(ba.hi[k], bb.hi[k]);
    if (k < a.dim() && w.hi[k] <= w.lo[k]) return false;
  }
  return visit_lattice_points(a.dim(), dx, w, [&](const Point& p) { return !(a.contains(p, dx) && b.contains(p, dx)); });
}

}  // namespace geosph::geometry
