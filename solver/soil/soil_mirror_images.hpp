// The mirror walls' share of the soil's pair sums (boundary/mirror_wall.hpp), for a soil particle i:
// the images j' = T(x_j) of the soil particles j within the support of T(x_i) enter the velocity
// gradient, continuity and momentum of soil/soil_forces.hpp as a wall particle would. The image carries
// m_j and V_j, the velocity R v_j (free slip) or -v_j (no slip), and the stress
//   free slip  R sigma_j R^T   (R = I - 2 n n^T: the normal-tangential shears change sign; through a
//              right-angled corner the double mirror),
//   no slip    sigma_j         (copied, as the soil's ghost walls do, boundary/soil_wall.hpp),
// less the isotropic hydrostatic step rho_j g . (x_j' - x_j) of the soil's weight across the wall (the
// dummy and ghost walls' step); the artificial stress R_j turns with the stress.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>

#include "boundary/mirror_wall.hpp"
#include "core/cell_list.hpp"
#include "core/particles.hpp"

namespace geosph {

// A symmetric tensor as xx yy zz xy xz yz, turned by an image map: R A R^T (free slip) or A.
inline std::array<double, 6> mirror_tensor(const MirrorImage& T, const std::array<double, 6>& a) {
  if (!T.free_slip) return a;
  const double A[3][3] = {{a[0], a[3], a[4]}, {a[3], a[1], a[5]}, {a[4], a[5], a[2]}};
  double B[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      double v = 0;
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) v += T.R[3 * r + p] * A[p][q] * T.R[3 * c + q];
      B[r][c] = v;
    }
  return {B[0][0], B[1][1], B[2][2], B[0][1], B[0][2], B[1][2]};
}

// The image velocity of particle j.
inline std::array<double, 3> mirror_velocity(const MirrorImage& T, const Particles& P, std::uint32_t j) {
  const double v[3] = {P.vx[j], P.vy[j], P.vz[j]};
  if (T.free_slip) return T.rotate(v);
  return {-v[0], -v[1], -v[2]};
}

// f(T, j, r, step) for each soil image of particle i kept on its plane's side: r = x_i - x_j',
// step = x_j' - x_j. An image is placed at least half a spacing behind the wall (min_depth = dx/2):
// the mirror image of a particle nearer the wall than that is moved deeper along the wall's inward
// direction, so that the wall holds a soil particle that comes close to it as a dummy wall particle
// dx/2 behind the surface does (the exact mirror's normal force vanishes with the distance: the toe of
// a collapsing column sank to a fifth of a spacing from the floor and tore apart).
template <class F>
void for_each_soil_image(const MirrorWalls& walls, MirrorSet& set, const Particles& P, const CellList& cells,
                         std::size_t i, double min_depth, F&& f) {
  const double xi[3] = {P.x[i], P.y[i], P.dim == 3 ? P.z[i] : 0.0};
  walls.images(xi, set);
  for (const MirrorImage& T : set.images) {
    const auto q = T.apply(xi);
    cells.for_each_near_point(P, q[0], q[1], q[2], [&](std::uint32_t j, double dx, double dy, double dz, double) {
      if (P.kind[j] != Kind::Soil) return;
      const double d[3] = {dx, dy, dz};
      auto r = T.rotate(d);
      std::array<double, 3> y = {xi[0] - r[0], xi[1] - r[1], xi[2] - r[2]};
      if (!set.keep(T, y.data())) return;
      std::array<double, 3> step = {y[0] - (q[0] - dx), y[1] - (q[1] - dy), y[2] - (q[2] - dz)};
      const double depth = 0.5 * std::sqrt(step[0] * step[0] + step[1] * step[1] + step[2] * step[2]);
      if (depth < min_depth) {
        const double deeper = min_depth - depth;
        for (int a = 0; a < 3; ++a) {
          y[a] += deeper * T.into[a];
          step[a] += deeper * T.into[a];
          r[a] -= deeper * T.into[a];
        }
      }
      f(T, j, r, step);
    });
  }
}

}  // namespace geosph
