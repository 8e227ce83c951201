#include "geometry/shape.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace geosph::geometry {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Distance of a box-like intersection of slabs: the per-axis excesses e_a (positive outside the slab)
// give min(max e, 0) + |max(e, 0)| (the exact box distance).
double slab_distance(const double* e, int n) {
  double inside = -1e300, out2 = 0;
  for (int a = 0; a < n; ++a) {
    inside = std::max(inside, e[a]);
    if (e[a] > 0) out2 += e[a] * e[a];
  }
  return std::min(inside, 0.0) + std::sqrt(out2);
}

double point_distance(const Point& a, const Point& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// The planes of `all` whose point lies on the surface of `s` (within 1e-9 reach), appended to out.
void keep_on_surface(const Shape& s, const std::vector<TangentPlane>& all, double reach, std::vector<TangentPlane>& out) {
  for (const auto& t : all)
    if (std::abs(s.distance(t.point)) <= 1e-9 * reach) out.push_back(t);
}

class Box final : public Shape {
 public:
  Box(int dim, Point lo, Point hi) : Shape(dim), lo_(lo), hi_(hi) {}
  double distance(const Point& p) const override {
    double e[3];
    for (int a = 0; a < dim(); ++a) e[a] = std::abs(p[a] - 0.5 * (lo_[a] + hi_[a])) - 0.5 * (hi_[a] - lo_[a]);
    return slab_distance(e, dim());
  }
  Bounds bounds() const override { return {lo_, hi_}; }
  // each face: its plane at the face point nearest to p
  void tangent_planes(const Point& p, double reach, std::vector<TangentPlane>& out) const override {
    for (int a = 0; a < dim(); ++a)
      for (const bool upper : {false, true}) {
        TangentPlane t;
        for (int b = 0; b < dim(); ++b) t.point[b] = std::clamp(p[b], lo_[b], hi_[b]);
        t.point[a] = upper ? hi_[a] : lo_[a];
        t.normal[a] = upper ? 1.0 : -1.0;
        if (point_distance(p, t.point) < reach) out.push_back(t);
      }
  }
  double exact_measure() const override {
    double v = 1;
    for (int a = 0; a < dim(); ++a) v *= hi_[a] - lo_[a];
    return v;
  }
  std::string describe() const override { return "box"; }

 private:
  Point lo_, hi_;
};

class Ball final : public Shape {
 public:
  Ball(int dim, Point c, double r) : Shape(dim), c_(c), r_(r) {}
  double distance(const Point& p) const override {
    double d2 = 0;
    for (int a = 0; a < dim(); ++a) d2 += (p[a] - c_[a]) * (p[a] - c_[a]);
    return std::sqrt(d2) - r_;
  }
  Bounds bounds() const override {
    Bounds b{c_, c_};
    for (int a = 0; a < dim(); ++a) { b.lo[a] -= r_; b.hi[a] += r_; }
    return b;
  }
  double exact_measure() const override { return dim() == 2 ? kPi * r_ * r_ : 4.0 / 3.0 * kPi * r_ * r_ * r_; }
  std::string describe() const override { return dim() == 2 ? "circle" : "sphere"; }

 private:
  Point c_;
  double r_;
};

class Cylinder final : public Shape {
 public:
  Cylinder(Point c, int axis, double r, double len) : Shape(3), c_(c), axis_(axis), r_(r), len_(len) {}
  double distance(const Point& p) const override {
    double rad2 = 0;
    for (int a = 0; a < 3; ++a)
      if (a != axis_) rad2 += (p[a] - c_[a]) * (p[a] - c_[a]);
    const double e[2] = {std::sqrt(rad2) - r_, std::abs(p[axis_] - c_[axis_]) - 0.5 * len_};
    return slab_distance(e, 2);
  }
  Bounds bounds() const override {
    Bounds b{c_, c_};
    for (int a = 0; a < 3; ++a) {
      const double half = a == axis_ ? 0.5 * len_ : r_;
      b.lo[a] -= half; b.hi[a] += half;
    }
    return b;
  }
  // the mantle (the radial plane at the nearest mantle point) and the two caps
  void tangent_planes(const Point& p, double reach, std::vector<TangentPlane>& out) const override {
    double rad[3] = {0, 0, 0}, rlen = 0;
    for (int a = 0; a < 3; ++a)
      if (a != axis_) { rad[a] = p[a] - c_[a]; rlen += rad[a] * rad[a]; }
    rlen = std::sqrt(rlen);
    const double half = 0.5 * len_;
    const double along = std::clamp(p[axis_] - c_[axis_], -half, half);
    if (rlen > 0) {
      TangentPlane t;
      for (int a = 0; a < 3; ++a)
        if (a != axis_) { t.normal[a] = rad[a] / rlen; t.point[a] = c_[a] + r_ * t.normal[a]; }
      t.point[axis_] = c_[axis_] + along;
      if (point_distance(p, t.point) < reach) out.push_back(t);
    }
    const double shrink = rlen > r_ ? r_ / rlen : 1.0;  // the nearest cap point: p's radial offset within r
    for (const double side : {-1.0, 1.0}) {
      TangentPlane t;
      for (int a = 0; a < 3; ++a)
        if (a != axis_) t.point[a] = c_[a] + shrink * rad[a];
      t.point[axis_] = c_[axis_] + side * half;
      t.normal[axis_] = side;
      if (point_distance(p, t.point) < reach) out.push_back(t);
    }
  }
  double exact_measure() const override { return kPi * r_ * r_ * len_; }
  std::string describe() const override { return "cylinder"; }

 private:
  Point c_;
  int axis_;
  double r_, len_;
};

class Union final : public Shape {
 public:
  Union(int dim, std::vector<ShapePtr> parts) : Shape(dim), parts_(std::move(parts)) {}
  double distance(const Point& p) const override {
    double d = 1e300;
    for (const auto& s : parts_) d = std::min(d, s->distance(p));
    return d;
  }
  Bounds bounds() const override {
    Bounds b = parts_.front()->bounds();
    for (const auto& s : parts_) {
      const Bounds o = s->bounds();
      for (int a = 0; a < 3; ++a) { b.lo[a] = std::min(b.lo[a], o.lo[a]); b.hi[a] = std::max(b.hi[a], o.hi[a]); }
    }
    return b;
  }
  // the parts' tangent planes whose point lies on the union's surface (not inside another part)
  void tangent_planes(const Point& p, double reach, std::vector<TangentPlane>& out) const override {
    std::vector<TangentPlane> all;
    for (const auto& s : parts_) s->tangent_planes(p, reach, all);
    keep_on_surface(*this, all, reach, out);
  }
  double exact_measure() const override { return -1; }
  std::string describe() const override { return "union of " + std::to_string(parts_.size()) + " shapes"; }

 private:
  std::vector<ShapePtr> parts_;
};

class Difference final : public Shape {
 public:
  Difference(int dim, std::vector<ShapePtr> parts) : Shape(dim), parts_(std::move(parts)) {}
  double distance(const Point& p) const override {
    double d = parts_.front()->distance(p);
    for (std::size_t k = 1; k < parts_.size(); ++k) d = std::max(d, -parts_[k]->distance(p));
    return d;
  }
  Bounds bounds() const override { return parts_.front()->bounds(); }
  // the first part's tangent planes and the others' turned inside out (their outward normal points into
  // the hole), those whose point lies on the difference's surface
  void tangent_planes(const Point& p, double reach, std::vector<TangentPlane>& out) const override {
    std::vector<TangentPlane> all;
    for (std::size_t k = 0; k < parts_.size(); ++k) {
      const std::size_t first = all.size();
      parts_[k]->tangent_planes(p, reach, all);
      if (k > 0)
        for (std::size_t m = first; m < all.size(); ++m)
          for (auto& c : all[m].normal) c = -c;
    }
    keep_on_surface(*this, all, reach, out);
  }
  double exact_measure() const override { return -1; }
  std::string describe() const override {
    return parts_.front()->describe() + " less " + std::to_string(parts_.size() - 1) + " shape(s)";
  }

 private:
  std::vector<ShapePtr> parts_;
};

// Measure of the cell [lo, lo + h]^dim: whole if the distance at its centre proves it inside, none if
// outside, otherwise the sum over its 2^dim halves; at the last level the centre decides.
double cell_measure(const Shape& s, const Point& lo, double h, int levels) {
  const int d = s.dim();
  Point c = lo;
  for (int a = 0; a < d; ++a) c[a] += 0.5 * h;
  const double dist = s.distance(c), half_diag = 0.5 * h * std::sqrt(static_cast<double>(d));
  const double full = std::pow(h, d);
  if (dist <= -half_diag) return full;
  if (dist >= half_diag) return 0.0;
  if (levels == 0) return dist < 0 ? full : (dist == 0 ? 0.5 * full : 0.0);
  double sum = 0;
  for (int k = 0; k < (1 << d); ++k) {
    Point q = lo;
    for (int a = 0; a < d; ++a)
      if (k >> a & 1) q[a] += 0.5 * h;
    sum += cell_measure(s, q, 0.5 * h, levels - 1);
  }
  return sum;
}

}  // namespace

void Shape::tangent_planes(const Point& p, double reach, std::vector<TangentPlane>& out) const {
  const double d = distance(p);
  if (!(std::abs(d) < reach)) return;
  TangentPlane t;
  t.normal = outward_normal(*this, p, 1e-4 * reach);
  for (int a = 0; a < dim_; ++a) t.point[a] = p[a] - d * t.normal[a];
  out.push_back(t);
}

bool Shape::contains(const Point& p, double dx) const {
  static constexpr double kTilt[3] = {0.7236, 0.5491, 0.4184};  // a unit vector of no lattice or edge direction
  const double e = 1e-7 * dx;
  return inside({p[0] + e * kTilt[0], p[1] + e * kTilt[1], p[2] + (dim_ == 3 ? e * kTilt[2] : 0.0)});
}

ShapePtr make_box(int dim, Point lo, Point hi) { return std::make_shared<Box>(dim, lo, hi); }
ShapePtr make_ball(int dim, Point centre, double radius) { return std::make_shared<Ball>(dim, centre, radius); }
ShapePtr make_cylinder(Point centre, int axis, double radius, double length) {
  return std::make_shared<Cylinder>(centre, axis, radius, length);
}
ShapePtr make_union(int dim, std::vector<ShapePtr> parts) { return std::make_shared<Union>(dim, std::move(parts)); }
ShapePtr make_difference(int dim, std::vector<ShapePtr> parts) {
  return std::make_shared<Difference>(dim, std::move(parts));
}

double measure(const Shape& s, double dx, int levels) {
  const double exact = s.exact_measure();
  if (exact >= 0) return exact;
  const Bounds b = s.bounds();
  const int d = s.dim();
  if (levels < 0) levels = d == 2 ? 6 : 3;
  std::array<long, 3> n{1, 1, 1};
  for (int a = 0; a < d; ++a) n[a] = std::max(1L, static_cast<long>(std::ceil((b.hi[a] - b.lo[a]) / dx - 1e-9)));
  double sum = 0;
  for (long k = 0; k < n[2]; ++k)
    for (long j = 0; j < n[1]; ++j)
      for (long i = 0; i < n[0]; ++i) {
        const Point lo{b.lo[0] + i * dx, b.lo[1] + j * dx, d == 3 ? b.lo[2] + k * dx : 0.0};
        sum += cell_measure(s, lo, dx, levels);
      }
  return sum;
}

Point outward_normal(const Shape& s, const Point& p, double h) {
  Point n{0, 0, 0};
  double len2 = 0;
  for (int a = 0; a < s.dim(); ++a) {
    Point q = p, r = p;
    q[a] += h; r[a] -= h;
    n[a] = s.distance(q) - s.distance(r);
    len2 += n[a] * n[a];
  }
  if (len2 > 0)
    for (int a = 0; a < s.dim(); ++a) n[a] /= std::sqrt(len2);
  return n;
}

}  // namespace geosph::geometry
