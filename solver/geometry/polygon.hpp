// A simple polygon with holes (2D) and its extrusion along z (3D). The inside test is the winding
// number by signed edge crossings (Sunday's rule; Hormann & Agathos 2001, "The point in polygon
// problem for arbitrary polygons", Comput. Geom. 20), exact in sign for points off the boundary; a
// point on an edge is decided by Shape::contains. Construction rejects what has no inside: fewer than 3 vertices, zero area, repeated
// vertices, edges that cross or touch, holes that leave the outline or meet each other.
#pragma once
#include <stdexcept>

#include "geometry/shape.hpp"

namespace geosph::geometry {

using Ring = std::vector<std::array<double, 2>>;

// Thrown by the constructors with what is wrong (e.g. "edges 1 and 3 cross at (0.5, 0.5)"); the scene
// reader prefixes the file and field.
struct ShapeError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

ShapePtr make_polygon(Ring outline, std::vector<Ring> holes);
// The polygon extruded over z in [z_min, z_max].
ShapePtr make_extrusion(Ring outline, std::vector<Ring> holes, double z_min, double z_max);

// Signed area (shoelace formula): positive for counter-clockwise vertices.
double signed_area(const Ring& r);
// Winding number of the closed ring about q (0 outside).
int winding_number(const Ring& r, double qx, double qy);

}  // namespace geosph::geometry
