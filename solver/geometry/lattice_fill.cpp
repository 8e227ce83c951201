#include "geometry/lattice_fill.hpp"

#include <algorithm>
#include <cmath>

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
  visit_lattice_points(s.dim(), dx, s.bounds(), [&](const Point& p) {
    if (s.contains(p, dx) && (shell <= 0 || s.distance(p) > -shell)) out.push_back(p);
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
