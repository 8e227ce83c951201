#include "geometry/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace geosph::geometry {

namespace {

using P2 = std::array<double, 2>;

double cross(const P2& o, const P2& a, const P2& b) { return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]); }

std::string show(const P2& p) {
  std::ostringstream s;
  s.precision(6);
  s << "(" << p[0] << ", " << p[1] << ")";
  return s.str();
}

// Distance from q to the segment ab.
double segment_distance(const P2& a, const P2& b, double qx, double qy) {
  const double ex = b[0] - a[0], ey = b[1] - a[1], len2 = ex * ex + ey * ey;
  double t = len2 > 0 ? ((qx - a[0]) * ex + (qy - a[1]) * ey) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const double dx = qx - a[0] - t * ex, dy = qy - a[1] - t * ey;
  return std::sqrt(dx * dx + dy * dy);
}

// Segments ab and cd share a point (within tol, a length).
bool segments_meet(const P2& a, const P2& b, const P2& c, const P2& d, double tol) {
  const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  return segment_distance(c, d, a[0], a[1]) <= tol || segment_distance(c, d, b[0], b[1]) <= tol ||
         segment_distance(a, b, c[0], c[1]) <= tol || segment_distance(a, b, d[0], d[1]) <= tol;
}

double ring_distance(const Ring& r, double qx, double qy) {
  double d = 1e300;
  for (std::size_t i = 0, n = r.size(); i < n; ++i) d = std::min(d, segment_distance(r[i], r[(i + 1) % n], qx, qy));
  return d;
}

// One ring: at least 3 vertices, no repeated vertex, non-zero area, no two edges meeting except
// neighbours at their shared vertex (and those not folding back onto each other).
void check_ring(const Ring& r, const std::string& name, double tol) {
  const std::size_t n = r.size();
  if (n < 3) throw ShapeError(name + " needs at least 3 vertices, got " + std::to_string(n));
  for (const auto& p : r)
    if (!std::isfinite(p[0]) || !std::isfinite(p[1])) throw ShapeError(name + " has a vertex that is not a finite number");
  for (std::size_t i = 0; i < n; ++i) {
    const P2 &a = r[i], &b = r[(i + 1) % n];
    if (std::hypot(b[0] - a[0], b[1] - a[1]) <= tol)
      throw ShapeError(name + ": vertices " + std::to_string(i) + " and " + std::to_string((i + 1) % n) +
                       " coincide at " + show(a) + " (a zero-length edge)");
  }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool neighbours = j == i + 1 || (i == 0 && j == n - 1);
      const P2 &a = r[i], &b = r[(i + 1) % n], &c = r[j], &d = r[(j + 1) % n];
      if (neighbours) {
        // the far end of one edge may not lie on the other (the outline folds back on itself)
        const P2& shared = j == i + 1 ? b : a;
        const P2& far_i = j == i + 1 ? a : b;
        const P2& far_j = j == i + 1 ? d : c;
        if (segment_distance(shared, far_j, far_i[0], far_i[1]) <= tol ||
            segment_distance(shared, far_i, far_j[0], far_j[1]) <= tol)
          throw ShapeError(name + ": edges " + std::to_string(i) + " and " + std::to_string(j) +
                           " fold back onto each other at " + show(shared));
        continue;
      }
      if (segments_meet(a, b, c, d, tol))
        throw ShapeError(name + " intersects itself: edges " + std::to_string(i) + " (" + show(a) + "-" + show(b) +
                         ") and " + std::to_string(j) + " (" + show(c) + "-" + show(d) + ") meet");
    }
  if (std::abs(signed_area(r)) <= tol * tol) throw ShapeError(name + " encloses no area");
}

double length_scale(const Ring& r) {
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (const auto& p : r)
    for (int a = 0; a < 2; ++a) { lo[a] = std::min(lo[a], p[a]); hi[a] = std::max(hi[a], p[a]); }
  return std::max(hi[0] - lo[0], hi[1] - lo[1]);
}

// Outline less holes, with the validation of each ring and of the rings against each other.
class PolygonArea {
 public:
  PolygonArea(Ring outline, std::vector<Ring> holes) : outline_(std::move(outline)), holes_(std::move(holes)) {
    if (outline_.size() >= 1) tol_ = 1e-9 * std::max(1.0, length_scale(outline_));
    check_ring(outline_, "the outline", tol_);
    for (std::size_t h = 0; h < holes_.size(); ++h) {
      const std::string name = "hole " + std::to_string(h);
      check_ring(holes_[h], name, tol_);
      for (std::size_t i = 0; i < holes_[h].size(); ++i) {
        const P2& v = holes_[h][i];
        if (winding_number(outline_, v[0], v[1]) == 0 || ring_distance(outline_, v[0], v[1]) <= tol_)
          throw ShapeError(name + ": vertex " + std::to_string(i) + " " + show(v) + " is not strictly inside the outline");
      }
      if (rings_meet(holes_[h], outline_)) throw ShapeError(name + " crosses the outline");
      for (std::size_t o = 0; o < h; ++o)
        if (rings_meet(holes_[h], holes_[o]) || winding_number(holes_[o], holes_[h][0][0], holes_[h][0][1]) != 0 ||
            winding_number(holes_[h], holes_[o][0][0], holes_[o][0][1]) != 0)
          throw ShapeError(name + " meets or contains hole " + std::to_string(o));
    }
    lo_ = {1e300, 1e300, 0};
    hi_ = {-1e300, -1e300, 0};
    for (const auto& p : outline_)
      for (int a = 0; a < 2; ++a) { lo_[a] = std::min(lo_[a], p[a]); hi_[a] = std::max(hi_[a], p[a]); }
    area_ = std::abs(signed_area(outline_));
    for (const auto& h : holes_) area_ -= std::abs(signed_area(h));
  }
  double distance(double x, double y) const {
    double d = ring_distance(outline_, x, y);
    for (const auto& h : holes_) d = std::min(d, ring_distance(h, x, y));
    bool inside = winding_number(outline_, x, y) != 0;
    for (const auto& h : holes_) inside = inside && winding_number(h, x, y) == 0;
    return inside ? -d : d;
  }
  // Each edge within reach of (x, y): its line at the edge point nearest to (x, y), the normal the
  // edge's perpendicular pointing out of the area (the side where the distance grows).
  void edge_planes(double x, double y, double reach, std::vector<TangentPlane>& out) const {
    const auto ring = [&](const Ring& r) {
      for (std::size_t i = 0, n = r.size(); i < n; ++i) {
        const P2& a = r[i];
        const P2& b = r[(i + 1) % n];
        const double ex = b[0] - a[0], ey = b[1] - a[1], len = std::hypot(ex, ey);
        const double t = std::clamp(((x - a[0]) * ex + (y - a[1]) * ey) / (len * len), 0.0, 1.0);
        TangentPlane tp;
        tp.point = {a[0] + t * ex, a[1] + t * ey, 0.0};
        if (std::hypot(x - tp.point[0], y - tp.point[1]) >= reach) continue;
        tp.normal = {ey / len, -ex / len, 0.0};
        const double probe = 1e-6 * len;  // off the edge's middle, where no other edge is nearer
        const double mx = a[0] + 0.5 * ex, my = a[1] + 0.5 * ey;
        if (distance(mx + probe * tp.normal[0], my + probe * tp.normal[1]) < 0) tp.normal = {-tp.normal[0], -tp.normal[1], 0.0};
        out.push_back(tp);
      }
    };
    ring(outline_);
    for (const auto& h : holes_) ring(h);
  }
  double area() const { return area_; }
  const Point& lo() const { return lo_; }
  const Point& hi() const { return hi_; }
  std::size_t vertices() const { return outline_.size(); }
  std::size_t holes() const { return holes_.size(); }

 private:
  bool rings_meet(const Ring& a, const Ring& b) const {
    for (std::size_t i = 0; i < a.size(); ++i)
      for (std::size_t j = 0; j < b.size(); ++j)
        if (segments_meet(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()], tol_)) return true;
    return false;
  }
  Ring outline_;
  std::vector<Ring> holes_;
  double tol_ = 1e-9, area_ = 0;
  Point lo_{}, hi_{};
};

std::string counted(std::size_t n, const char* what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); }

class Polygon final : public Shape {
 public:
  Polygon(Ring outline, std::vector<Ring> holes) : Shape(2), a_(std::move(outline), std::move(holes)) {}
  double distance(const Point& p) const override { return a_.distance(p[0], p[1]); }
  Bounds bounds() const override { return {a_.lo(), a_.hi()}; }
  double exact_measure() const override { return a_.area(); }
  void tangent_planes(const Point& p, double reach, std::vector<TangentPlane>& out) const override {
    a_.edge_planes(p[0], p[1], reach, out);
  }
  std::string describe() const override {
    return "polygon (" + counted(a_.vertices(), "vertex") + (a_.holes() ? ", " + counted(a_.holes(), "hole") : "") + ")";
  }

 private:
  PolygonArea a_;
};

class Extrusion final : public Shape {
 public:
  Extrusion(Ring outline, std::vector<Ring> holes, double z0, double z1)
      : Shape(3), a_(std::move(outline), std::move(holes)), z0_(z0), z1_(z1) {}
  double distance(const Point& p) const override {
    const double e[2] = {a_.distance(p[0], p[1]), std::abs(p[2] - 0.5 * (z0_ + z1_)) - 0.5 * (z1_ - z0_)};
    const double inside = std::max(e[0], e[1]);
    const double out = std::hypot(std::max(e[0], 0.0), std::max(e[1], 0.0));
    return std::min(inside, 0.0) + out;
  }
  Bounds bounds() const override {
    Bounds b{a_.lo(), a_.hi()};
    b.lo[2] = z0_; b.hi[2] = z1_;
    return b;
  }
  double exact_measure() const override { return a_.area() * (z1_ - z0_); }
  std::string describe() const override { return "extruded polygon (" + counted(a_.vertices(), "vertex") + ")"; }

 private:
  PolygonArea a_;
  double z0_, z1_;
};

}  // namespace

double signed_area(const Ring& r) {
  double s = 0;
  for (std::size_t i = 0, n = r.size(); i < n; ++i) {
    const P2 &a = r[i], &b = r[(i + 1) % n];
    s += a[0] * b[1] - b[0] * a[1];
  }
  return 0.5 * s;
}

int winding_number(const Ring& r, double qx, double qy) {
  // Sunday's crossing rule: an upward edge with q strictly left of it counts +1, a downward edge with q
  // strictly right of it -1; the half-open rule on y counts a vertex at q's height once.
  int w = 0;
  const P2 q{qx, qy};
  for (std::size_t i = 0, n = r.size(); i < n; ++i) {
    const P2 &a = r[i], &b = r[(i + 1) % n];
    if (a[1] <= qy) {
      if (b[1] > qy && cross(a, b, q) > 0) ++w;
    } else if (b[1] <= qy && cross(a, b, q) < 0) {
      --w;
    }
  }
  return w;
}

ShapePtr make_polygon(Ring outline, std::vector<Ring> holes) {
  return std::make_shared<Polygon>(std::move(outline), std::move(holes));
}

ShapePtr make_extrusion(Ring outline, std::vector<Ring> holes, double z_min, double z_max) {
  if (!(z_max > z_min)) throw ShapeError("z_max must be greater than z_min");
  return std::make_shared<Extrusion>(std::move(outline), std::move(holes), z_min, z_max);
}

}  // namespace geosph::geometry
