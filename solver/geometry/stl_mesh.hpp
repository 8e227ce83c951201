// A closed triangulated surface read from an STL file (ASCII or binary) as a 3D shape. CGAL does the
// geometry (Debian libcgal-dev): the triangles are merged into a mesh (shared vertices by their exact
// coordinates), which must be closed; the inside test is CGAL::Side_of_triangle_mesh and the distance
// comes from an AABB tree of the faces (CGAL 5.5 manual, "3D Fast Intersection and Distance
// Computation" and Polygon Mesh Processing), both logarithmic in the number of triangles.
#pragma once
#include <filesystem>

#include "geometry/polygon.hpp"  // ShapeError
#include "geometry/shape.hpp"

namespace geosph::geometry {

// Throws ShapeError naming the file for an unreadable or malformed STL, one without triangles, or a
// surface that is not closed (a border edge) or not a 2-manifold.
ShapePtr make_stl(const std::filesystem::path& file);

}  // namespace geosph::geometry
