// Dummy wall particles for soil that carry the soil's stress, so that a soil particle at the wall
// has a full kernel support (no particle deficiency). The fluid dummy-particle treatment of
// Adami, Hu & Adams (2012, J. Comput. Phys. 231, eq. 27) is applied to the stress tensor, tension
// positive, with its hydrostatic extrapolation acting on the mean stress:
//   sigma_w = ( sum_s sigma_s W_ws - I (g - a_w) . sum_s rho_s r_ws W_ws ) / sum_s W_ws,  r_ws = x_w - x_s
// No slip: the shear components are copied and the velocity is v_w = 2 v_wall - v~ (Adami eq. 23),
// so the wall shears the soil. Free slip: the shear components are mirrored (sigma_w,ab = -sigma~_ab,
// a != b), which gives zero shear traction on the axis-aligned container walls (at a wall of any shape,
// walls.boundaries, the stress is mirrored across its tangent plane, H sigma H with H = I - 2 n n^T
// and n the surface normal the particle carries), and the wall's ghost
// velocity keeps the soil's tangential velocity and mirrors its normal velocity about the wall's,
// v_w = v~ + 2 ((v_wall - v~).n) n, n the wall normal into the soil (the kernel-weighted mean offset
// to the soil neighbours; the free-slip counterpart of Adami eq. 23 applied to the normal component
// only), so the soil cannot move into the wall unresisted (in the velocity gradient and the artificial
// viscosity) while it slides freely along it. With no slip, particles of wall blocks (walls.blocks,
// e.g. a clamp) keep their own velocity: the material embedded in a block is held, as the clamped
// particles of Gray, Monaghan & Swift (2001). Wall density is the soil's reference density and its mass
// rho0 dx^dim, as for the fluid walls. A dummy particle whose centre lies inside a structure particle's
// cell (e.g. the floor under a retaining wall) is the structure's space, not an image of the soil: it gets
// zero mass and stress and leaves the soil's sums, so the soil meets the structure only through the
// contact (coupling/soil_structure_contact.hpp). Before, the floor ghosts under a wall carried the
// extrapolated passive stress and took ~20% of the thrust off the wall in the bottom 0.1 H
// (rankine_passive).
// Ghost walls (walls.type "ghost"): each wall particle takes instead the soil's stress and velocity at its
// mirror point inside the soil, mirrored across the wall for free slip (soil_wall.cpp, mirror_ghost,
// states which components change sign); one whose mirror point has no soil near it keeps the dummy
// value above.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "core/cell_list.hpp"
#include "core/particles.hpp"
#include "io/scene.hpp"

namespace geosph {

// The soil's ghost values at the dummy particles, in fields of their own so that a scene with fluid
// walls too (two-phase) keeps both phases' wall values side by side: velocity, density and mass as the
// soil's sums see them (the ghost stress is in the SoilFields stress fields).
struct SoilWallFields {
  static constexpr const char* owner = "soil_walls";
  static constexpr const char* vx = "soil_wall_vx", *vy = "soil_wall_vy", *vz = "soil_wall_vz";
  static constexpr const char* rho = "soil_wall_density", *m = "soil_wall_mass";
};

class SoilWalls {
 public:
  explicit SoilWalls(const Scene& scene);
  void allocate(Particles& P) const;
  void update(Particles& P, const CellList& cells, const std::array<double, 3>& g) const;

 private:
  // read_[w] = 1 for the dummy particles that may be in the support of another kind's particle (soil,
  // structure, or pore water, which all read the soil's ghost values): with a pair list, those with such
  // a particle among their listed candidates (marked once per list build), else those found in the
  // support by that particle's own neighbour query. The others, most of a large floor or a 3D
  // container, get the values of a wall without soil around without a neighbour loop of their own;
  // update() gives the same values to a marked wall its own neighbour query finds in no support.
  void mark_read_walls(const Particles& P, const CellList& cells) const;
  const Scene& scene_;
  bool no_slip_, ghost_;  // ghost_: walls.type "ghost", the values at each wall particle's mirror point
  mutable std::vector<std::uint8_t> read_;
  mutable PointList mirrors_;  // ghost walls: the soil near each read wall's mirror point
  mutable long marked_build_ = -1;  // the pair list build read_ was marked from, -1 for none
};

}  // namespace geosph
