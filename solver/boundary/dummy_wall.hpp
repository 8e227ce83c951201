// Dummy wall particles with extrapolated pressure (Adami, Hu & Adams 2012, J. Comput. Phys. 231,
// eqs. 22-28): each wall particle w takes, from the fluid particles f around it,
//   p_w = ( sum_f p_f W_wf + (g - a_w) . sum_f rho_f r_wf W_wf ) / sum_f W_wf,   r_wf = x_w - x_f,
//   rho_w from the fluid's equation of state and the mass rho_w dx^dim (Adami's momentum equation is
//   written with particle volumes, so the wall enters with its lattice volume), and for no-slip the velocity
//   v_w = 2 v_wall - sum_f v_f W_wf / sum_f W_wf,
// so the wall carries the hydrostatic pressure right up to its surface (no particle deficiency).
// Morris walls (walls.type "morris", boundary/morris_wall.hpp) take p and rho from here and no v_w.
// Ghost walls (walls.type "ghost", boundary/ghost_wall.hpp) fill the same fields from their mirror points.
// Drained sides (boundary/drained_face.hpp) take the prescribed pore pressure instead of the extrapolated one.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "boundary/drained_face.hpp"
#include "core/cell_list.hpp"
#include "core/particles.hpp"
#include "fluid/fluid_forces.hpp"
#include "io/scene.hpp"

namespace geosph {

// The fluid walls' ghost velocity (no slip only); their pressure, density and mass are the walls'
// own p, rho, m (the fluid's sums read them).
struct DummyWallFields {
  static constexpr const char* owner = "fluid_walls";
  static constexpr const char* vx = "wall_vx", *vy = "wall_vy", *vz = "wall_vz";
};

class DummyWalls {
 public:
  DummyWalls(const Scene& scene, const FluidForces& fluid);
  // Allocates the extrapolated-velocity fields when the walls are no-slip.
  void allocate(Particles& P) const;
  void update(Particles& P, const CellList& cells, const std::array<double, 3>& g) const;

 private:
  const Scene& scene_;
  const FluidForces& fluid_;
  bool no_slip_, ghost_;
  std::vector<DrainedFace> drained_;  // containers' drained sides: their water pressure is prescribed
  mutable std::vector<std::uint8_t> unmirrored_;  // ghost walls: the particles left to the dummy treatment
  mutable PointList mirrors_;  // ghost walls: the fluid near each mirror point
};

}  // namespace geosph
