// Per-particle fields the particle builder (boundary/geometry.cpp) writes from the scene's bodies and
// walls; created only when a body or wall declares them.
#pragma once

namespace geosph {

struct BodyFields {
  static constexpr const char* owner = "geometry";
  static constexpr const char* fixed = "fixed";                    // int flag: held in place (velocity zero)
  static constexpr const char* structure_body = "structure_body";  // int: body index + 1 of a structure particle
  static constexpr const char* wall_block = "wall_block";          // int: walls.blocks index + 1 of a block particle
  static constexpr const char* wall_free_slip = "wall_free_slip";  // int flag: the wall's container is free-slip
                                                                    // (only where containers differ in slip)
  // outward unit normal of a walls.boundaries surface at its wall particles (zero at container walls,
  // but for Morris and ghost walls: the normal of the nearest container or block face, boundary/wall_surface.hpp)
  static constexpr const char* wall_nx = "wall_nx", *wall_ny = "wall_ny", *wall_nz = "wall_nz";
  // int bit mask at container and block walls of soil scenes: bit a set where the particle's mirror
  // across the wall reverses axis a (a container particle beyond its inner box on axis a; a block
  // particle's nearest face normal to a); two or three bits at an edge or corner (the double mirror)
  static constexpr const char* wall_mirror_axes = "wall_mirror_axes";
  static constexpr const char* surcharge = "surcharge";            // [Pa] on a soil body's top row
  static constexpr const char* surcharge_ramp = "surcharge_ramp";  // [s]
};

}  // namespace geosph
