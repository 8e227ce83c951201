// Reading a scene's bodies (bodies[k]): material, box, initial state, surcharge, velocity, fixed, and
// for structures their interface and prescribed motion; a material model may read body fields of its
// own (materials/solid_model.hpp: read_body). The fields are declared for the scene reference.
#pragma once
#include "io/json_fields.hpp"
#include "io/scene.hpp"

namespace geosph {

// bodies[k], after the scene's materials are known.
BodySpec parse_body(const JsonFields& b, const Scene& s);

}  // namespace geosph
