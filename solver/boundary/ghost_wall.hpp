// Ghost walls (walls.type "ghost"): fixed ghost particles (Marrone, Antuono, Colagrossi, Colicchio,
// Le Touze & Graziani 2011, Comput. Methods Appl. Mech. Engrg. 200, 1526-1542, Sec. 3.1). Each wall
// particle w, at depth d behind the wall surface with unit normal n into the fluid
// (boundary/wall_surface.hpp), is the mirror image of the point x_m = x_w + 2 d n inside the fluid; at a
// box corner n is the corner's diagonal and x_m the point reflected through the corner (the double
// mirror). Its values are the fluid's at x_m by first-order moving least squares,
//   phi(x_m) = sum_f (c . b_f) W_mf V_f phi_f,   A c = e_1,   A = sum_f b_f b_f^T W_mf V_f,
//   b_f = (1, (x_f - x_m) / h),  V_f = m_f / rho_f,
// which reproduces linear fields exactly (Shepard's sum_f W_mf V_f phi_f / sum_f W_mf V_f where A is near
// singular: too few fluid neighbours to span the dimension), and then
//   p_w = p(x_m) + rho(x_m) g . (x_w - x_m)     the hydrostatic step across the wall (fixed walls),
//   no slip: v_w = 2 v_wall - v(x_m)            the opposite velocity, zero on the surface;
// free slip has no viscous wall interaction, as with dummy walls. A wall particle whose mirror point
// has no fluid within the support (the wall above the fluid; the far side of a wall thinner than
// two supports, where the nearest surface is not the one facing the fluid) takes the dummy value. Dummy walls (Adami et al. 2012) average
// the fluid around the wall particle itself, a one-sided average whose wall velocity is first order;
// the mirror reproduces a linear velocity profile through the wall. Pore water (two-phase scenes): the
// fit is of p, the intrinsic density rho / n, v and the porosity n, the hydrostatic step takes the
// intrinsic density and the wall the partial density n rho(p_w) and porosity n(x_m), as the dummy
// walls do with the averages around the particle. The soil's ghost values are boundary/soil_wall.hpp's.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "boundary/mirror_mls.hpp"  // ghost_mirror_point
#include "core/cell_list.hpp"
#include "core/particles.hpp"
#include "fluid/equation_of_state.hpp"
#include "io/scene.hpp"

namespace geosph {

// Writes p, rho, m of every dummy-kind wall particle whose mirror point has fluid within the kernel
// support and, for no slip (wvx non-null), its ghost velocity into wvx, wvy, wvz; sets unmirrored[w] = 1
// for the others (size P.size()), which take the dummy walls' values at the particle itself
// (DummyWalls::update): the far side of a wall thinner than two supports, whose nearest surface is not
// the one facing the fluid, and the wall above the fluid. `mirrors` keeps the fluid near each mirror
// point between pair list builds (update_mirror_list, boundary/mirror_mls.hpp).
void update_ghost_walls(const Scene& scene, const std::vector<TaitEos>& eos, Particles& P, const CellList& cells,
                        const std::array<double, 3>& g, double* wvx, double* wvy, double* wvz,
                        std::vector<std::uint8_t>& unmirrored, PointList& mirrors);

}  // namespace geosph
