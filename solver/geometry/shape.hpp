// Shapes of bodies and walls: primitives (box, polygon with holes, circle; sphere, cylinder, extruded
// polygon) and their union and difference (constructive solid geometry). A shape answers one question,
// the signed distance to its surface (negative inside), from which the inside test, the wall normal and
// the wall layers follow. Setup code only: nothing here runs inside the time loop.
#pragma once
#include <array>
#include <memory>
#include <string>
#include <vector>

namespace geosph::geometry {

using Point = std::array<double, 3>;

struct Bounds {
  Point lo{}, hi{};
};

// A tangent plane of a shape's surface: its point on the surface and the unit outward normal there.
struct TangentPlane {
  Point point{}, normal{};
};

class Shape {
 public:
  explicit Shape(int dim) : dim_(dim) {}
  virtual ~Shape() = default;
  // Signed distance to the surface, negative inside. Exact for the primitives; for union and difference
  // the min/max composition, whose magnitude never exceeds the true distance (Hart 1996, "Sphere
  // tracing", sec. 3), so |d| > r still proves that a ball of radius r lies wholly on one side.
  virtual double distance(const Point& p) const = 0;
  virtual Bounds bounds() const = 0;
  // Area (2D) or volume (3D) in closed form; negative where there is none (union, difference).
  virtual double exact_measure() const = 0;
  virtual std::string describe() const = 0;
  // distance(p) < 0; a shape whose inside test is cheaper than its distance overrides it.
  virtual bool inside(const Point& p) const { return distance(p) < 0; }
  // Inside, for a lattice of spacing dx. A point on the surface (a lattice point on a 45-degree edge,
  // or on the face two shapes share) is decided at a fixed offset of 1e-7 dx along a direction that no
  // lattice line shares (simulation of simplicity, Edelsbrunner & Muecke 1990), so of two shapes that
  // share a surface exactly one holds each of its points.
  bool contains(const Point& p, double dx) const;
  // The tangent planes, at their nearest points to p, of the smooth pieces of the surface (faces,
  // edges of a polygon, a cylinder's mantle and caps) that come within `reach` of p, appended to out:
  // the multiple boundary tangents of a point near a corner (boundary/mirror_wall.hpp). This default
  // gives the one tangent at the nearest surface point (the distance's gradient); box, cylinder,
  // polygon, union and difference list each piece.
  virtual void tangent_planes(const Point& p, double reach, std::vector<TangentPlane>& out) const;
  int dim() const { return dim_; }

 private:
  int dim_;
};

using ShapePtr = std::shared_ptr<const Shape>;

ShapePtr make_box(int dim, Point lo, Point hi);
// 2D circle (dim 2) or sphere (dim 3).
ShapePtr make_ball(int dim, Point centre, double radius);
// 3D cylinder of the given radius and length, its axis along x, y or z (axis 0, 1, 2) through centre.
ShapePtr make_cylinder(Point centre, int axis, double radius, double length);
ShapePtr make_union(int dim, std::vector<ShapePtr> parts);
// parts[0] less all the others.
ShapePtr make_difference(int dim, std::vector<ShapePtr> parts);

// Area or volume: the closed form where there is one, otherwise integrated over cells of size dx
// that are split near the surface down to dx / 2^levels (the distance bound decides which cells lie
// wholly inside or outside); levels < 0: 6 in 2D, 3 in 3D (cells of dx/64 and dx/8 at the surface).
double measure(const Shape& s, double dx, int levels = -1);
// Unit outward normal at p: the central-difference gradient of the distance, with step h.
Point outward_normal(const Shape& s, const Point& p, double h);

}  // namespace geosph::geometry
