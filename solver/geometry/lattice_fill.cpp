#include "geometry/lattice_fill.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace geosph::geometry {

namespace {

// The points (i + 1/2) dx of the lattice anchored at the origin that lie in the window (a box), in
// lattice order, until f returns false; returns whether it stopped early.
template <class F>
bool visit_lattice_points(int d, double dx, const Bounds& window, F&& f) {
  std::array<long, 3> i0{0, 0, 0}, i1{1, 1, 1};
  for (int a = 0; a < d; ++a) {
    i0[a] = static_cast<long>(std::floor(window.lo[a] / dx - 0.5));
    i1[a] = static_cast<long>(std::ceil(window.hi[a] / dx - 0.5)) + 1;
  }
  for (long k = i0[2]; k < i1[2]; ++k)
    for (long j = i0[1]; j < i1[1]; ++j)
      for (long i = i0[0]; i < i1[0]; ++i)
        if (!f(Point{(i + 0.5) * dx, (j + 0.5) * dx, d == 3 ? (k + 0.5) * dx : 0.0})) return true;
  return false;
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
  const Bounds window = s.bounds();
  std::array<long, 3> i0{0, 0, 0}, i1{1, 1, 1}, nb{1, 1, 1};
  for (int a = 0; a < d; ++a) {
    i0[a] = static_cast<long>(std::floor(window.lo[a] / dx - 0.5));
    i1[a] = static_cast<long>(std::ceil(window.hi[a] / dx - 0.5)) + 1;
    nb[a] = (i1[a] - i0[a] + kBlock - 1) / kBlock;
  }
  std::vector<char> near(static_cast<std::size_t>(nb[0] * nb[1] * nb[2]), 1);
  for (long bk = 0; bk < nb[2]; ++bk)
    for (long bj = 0; bj < nb[1]; ++bj)
      for (long bi = 0; bi < nb[0]; ++bi) {
        const long b[3] = {bi, bj, bk};
        Point c{0, 0, 0};
        double half2 = 0;
        for (int a = 0; a < d; ++a) {
          const long lo = i0[a] + b[a] * kBlock, hi = std::min(i1[a], lo + kBlock) - 1;
          c[a] = (0.5 * static_cast<double>(lo + hi) + 0.5) * dx;
          const double half = 0.5 * static_cast<double>(hi - lo) * dx;
          half2 += half * half;
        }
        near[static_cast<std::size_t>((bk * nb[1] + bj) * nb[0] + bi)] = std::abs(s.distance(c)) <= shell + std::sqrt(half2);
      }
  for (long k = i0[2]; k < i1[2]; ++k)
    for (long j = i0[1]; j < i1[1]; ++j)
      for (long i = i0[0]; i < i1[0]; ++i) {
        const std::size_t blk = static_cast<std::size_t>((((k - i0[2]) / kBlock) * nb[1] + (j - i0[1]) / kBlock) * nb[0] +
                                                         (i - i0[0]) / kBlock);
        if (!near[blk]) continue;
        const Point p{(i + 0.5) * dx, (j + 0.5) * dx, d == 3 ? (k + 0.5) * dx : 0.0};
        if (s.contains(p, dx) && s.distance(p) > -shell) out.push_back(p);
      }
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
