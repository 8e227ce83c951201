// Reading a scene's walls: the wall treatment, slip, layers, containers (boxes whose faces are walls)
// and blocks (solid boxes of wall particles). The fields are declared for the scene reference.
#pragma once
#include "io/json_fields.hpp"
#include "io/scene.hpp"

namespace geosph {

WallSpec parse_walls(const JsonFields& w, int dim);

// The wall treatments walls.type accepts.
const std::vector<std::string>& wall_types();

}  // namespace geosph
