// Particle positions of a shape: the points lo + (i + 1/2) dx of the lattice that starts at the shape's
// lower bound and covers its bounding box, kept where they lie strictly inside the shape.
#pragma once
#include <vector>

#include "geometry/shape.hpp"

namespace geosph::geometry {

// The lattice points inside s; with shell > 0 only those within shell of its surface (the wall layers
// of a solid wall). Visits the points in lattice order, x fastest.
std::vector<Point> fill_lattice(const Shape& s, double dx, double shell = 0);
// Some lattice point lies inside s (stops at the first).
bool holds_lattice_point(const Shape& s, double dx);
// Some lattice point lies inside both a and b (shapes that only touch share none; symmetric, since
// both are read on the one lattice).
bool shapes_overlap(const Shape& a, const Shape& b, double dx);

}  // namespace geosph::geometry
