#include "geometry/shape_input.hpp"

#include <filesystem>

#include "geometry/polygon.hpp"
#include "geometry/stl_mesh.hpp"
#include "io/scene_reference.hpp"

namespace geosph {

namespace {

const std::vector<std::string> kTypes2 = {"box", "polygon", "circle", "union", "difference"};
const std::vector<std::string> kTypes3 = {"box", "sphere", "cylinder", "extrusion", "stl", "union", "difference"};

const bool documented = register_section(
    {"shape", "shape (bodies[k].shape, walls.boundaries[k].shape, shape.parts[k])",
     "A body's or wall's shape: a primitive, or the union or difference of shapes. Particles fill the points (i + 1/2) dx "
     "inside it (one lattice anchored at the origin, shared by every shape).",
     {choice_doc("type", {"box", "polygon", "circle", "sphere", "cylinder", "extrusion", "stl", "union", "difference"},
                 "required",
                 "2D: box, polygon, circle; 3D: box, sphere, cylinder, extrusion (a polygon extruded along z), stl (a "
                 "closed triangulated surface); both: union, difference (parts[0] less the other parts)"),
      {"file", FieldType::Text, "an STL file (ASCII or binary), closed", "required (stl)", "-",
       "stl: the surface, relative to the scene file's folder"},
      {"min", FieldType::Vector, "dimension numbers", "required (box)", "m", "box: lower corner"},
      {"max", FieldType::Vector, "dimension numbers, > min", "required (box)", "m", "box: upper corner"},
      {"vertices", FieldType::Points, "points [x, y]; >= 3, a simple polygon", "required (polygon, extrusion)", "m",
       "polygon, extrusion: the outline's vertices in order (either sense), not repeated at the end"},
      {"holes", FieldType::PointLists, "simple polygons strictly inside the outline", "[]", "m",
       "polygon, extrusion: outlines of holes"},
      {"centre", FieldType::Vector, "dimension numbers", "required (circle, sphere, cylinder)", "m",
       "circle, sphere: centre; cylinder: the midpoint of its axis"},
      number_doc("radius", Range::positive(), "required (circle, sphere, cylinder)", "m", "radius"),
      choice_doc("axis", {"x", "y", "z"}, "z", "cylinder: the axis direction"),
      number_doc("length", Range::positive(), "required (cylinder)", "m", "cylinder: length along its axis"),
      number_doc("z_min", Range{}, "required (extrusion)", "m", "extrusion: lower z"),
      number_doc("z_max", Range{}, "required (extrusion)", "m", "extrusion: upper z (> z_min)"),
      {"parts", FieldType::Objects, "shapes (see shape), >= 2", "required (union, difference)", "-",
       "union, difference: the shapes combined"}}});

geometry::Ring ring_of(const std::vector<std::array<double, 3>>& pts) {
  geometry::Ring r;
  for (const auto& p : pts) r.push_back({p[0], p[1]});
  return r;
}

geometry::ShapePtr parse(const JsonFields& f, int dim, int depth) {
  f.section("shape");
  if (depth > 16) f.fail("parts", "nests shapes more than 16 deep");
  const std::string type = f.choice("type", dim == 2 ? kTypes2 : kTypes3);
  geometry::ShapePtr s;
  if (type == "box") {
    const auto lo = f.vector("min", dim), hi = f.vector("max", dim);
    for (int a = 0; a < dim; ++a)
      if (!(hi[a] > lo[a])) f.fail("max", "must be greater than min on every axis");
    s = geometry::make_box(dim, lo, hi);
  } else if (type == "circle" || type == "sphere") {
    s = geometry::make_ball(dim, f.vector("centre", dim), f.number("radius", Range::positive()));
  } else if (type == "cylinder") {
    const std::string axis = f.choice("axis", {"x", "y", "z"}, "z");
    s = geometry::make_cylinder(f.vector("centre", 3), axis[0] - 'x', f.number("radius", Range::positive()),
                                f.number("length", Range::positive()));
  } else if (type == "stl") {
    const std::filesystem::path rel = f.text("file");
    const auto path = rel.is_absolute() ? rel : std::filesystem::path(f.file()).parent_path() / rel;
    try {
      s = geometry::make_stl(path);
    } catch (const geometry::ShapeError& e) {
      f.fail("file", e.what());
    }
  } else if (type == "polygon" || type == "extrusion") {
    const auto outline = ring_of(f.points("vertices", 2));
    std::vector<geometry::Ring> holes;
    for (const auto& h : f.point_lists("holes", 2)) holes.push_back(ring_of(h));
    double z0 = 0, z1 = 0;
    if (type == "extrusion") {
      z0 = f.number("z_min", Range{});
      z1 = f.number("z_max", Range{});
      if (!(z1 > z0)) f.fail("z_max", "must be greater than z_min");
    }
    try {
      s = type == "polygon" ? geometry::make_polygon(outline, holes) : geometry::make_extrusion(outline, holes, z0, z1);
    } catch (const geometry::ShapeError& e) {
      const std::string what = e.what();
      f.fail(what.rfind("hole", 0) == 0 ? "holes" : "vertices", what);
    }
  } else {  // union, difference
    const auto parts = f.array_of_objects("parts");
    if (parts.size() < 2) f.fail("parts", "needs at least 2 shapes, got " + std::to_string(parts.size()));
    std::vector<geometry::ShapePtr> shapes;
    for (const auto& p : parts) shapes.push_back(parse(p, dim, depth + 1));
    s = type == "union" ? geometry::make_union(dim, shapes) : geometry::make_difference(dim, shapes);
  }
  f.reject_unknown();
  return s;
}

}  // namespace

geometry::ShapePtr parse_shape(const JsonFields& f, int dim) { return parse(f, dim, 0); }

}  // namespace geosph
