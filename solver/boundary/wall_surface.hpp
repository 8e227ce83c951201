// Where a wall particle sits relative to the wall surface, for the treatments that need it (Morris
// walls, boundary/morris_wall.hpp; ghost walls, boundary/ghost_wall.hpp): its depth behind the surface
// and the unit normal of the surface nearest it, pointing into the fluid (BodyFields::wall_nx..nz).
// Containers: the nearest point of the inner box (a corner particle's normal is the corner's
// diagonal, and it carries the corner flag); blocks: the nearest face; walls.boundaries: the shape's signed distance and normal.
#pragma once

namespace geosph {

struct WallSurfaceFields {
  static constexpr const char* owner = "wall_surface";
  static constexpr const char* depth = "wall_depth";  // [m] distance of the wall particle behind the surface
  // int flag: a container's corner (or 3D edge) particle, behind more than one face, whose mirror is
  // through the corner (boundary/mirror_mls.hpp mirror_reflection)
  static constexpr const char* corner = "wall_corner";
};

}  // namespace geosph
