// Reading a shape object from a scene (bodies[k].shape, walls.boundaries[k].shape and the parts of a
// union or difference): its type and that type's fields, checked for the scene's dimension.
#pragma once
#include "geometry/shape.hpp"
#include "io/json_fields.hpp"

namespace geosph {

geometry::ShapePtr parse_shape(const JsonFields& f, int dim);

}  // namespace geosph
