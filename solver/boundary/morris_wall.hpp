// Morris no-slip walls (Morris, Fox & Zhu 1997, J. Comput. Phys. 136, 214-226, Sec. 3.3): the wall
// particles carry the pressure and density of the dummy treatment (boundary/dummy_wall.hpp, Adami et
// al. 2012), but their velocity is extrapolated afresh for every fluid particle across the wall's
// tangent plane. A fluid particle a at distance d_a from the wall surface sees the wall particle b
// (at depth d_b behind it) moving with
//   v_b = v_wall - (d_b / d_a) (v_a - v_wall),  i.e. the pair's relative velocity v_ab = beta (v_a - v_wall),
//   beta = min(beta_max, 1 + d_b / d_a),  beta_max = 1.5 (Morris et al. 1997, Sec. 3.3; walls.morris_beta_max),
// which makes the velocity vanish on the surface along the line a-b whatever the fluid's profile;
// the cap keeps a fluid particle that reaches the wall from seeing an unbounded shear. The relative
// velocity enters the laminar and the artificial viscosity; continuity reads the wall's own velocity.
// Each wall particle carries its depth d_b and the unit normal of the surface nearest it
// (boundary/wall_surface.hpp): the tangent plane at a box corner is the plane normal to its diagonal.
#pragma once
#include <algorithm>

#include "boundary/wall_surface.hpp"

namespace geosph {

inline constexpr double kMorrisBetaMax = 1.5;  // walls.morris_beta_max's default

// beta of the pair: 1 + d_b / d_a, capped at beta_max; a fluid particle on or behind the surface
// (d_a <= 0) takes the cap.
inline double morris_velocity_factor(double fluid_distance, double wall_depth, double beta_max = kMorrisBetaMax) {
  if (!(fluid_distance > 0)) return beta_max;
  return std::min(beta_max, 1.0 + wall_depth / fluid_distance);
}

}  // namespace geosph
