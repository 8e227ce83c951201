// What ghost walls of every phase share (boundary/ghost_wall.hpp for fluids, boundary/soil_wall.hpp for
// soil): the first-order moving-least-squares weights at a wall particle's mirror point (Marrone et al.
// 2011, Comput. Methods Appl. Mech. Engrg. 200, Sec. 3.1), and the reflection that maps the material's
// tensors and vectors at the mirror point onto the wall particle.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/cell_list.hpp"
#include "core/particles.hpp"

namespace geosph {

// The mirror point of a wall particle at x with depth d behind the surface and unit normal n.
inline std::array<double, 3> ghost_mirror_point(const double x[3], double depth, const double n[3]) {
  return {x[0] + 2 * depth * n[0], x[1] + 2 * depth * n[1], x[2] + 2 * depth * n[2]};
}

// Keeps `list` of the particles of `kind` near the mirror point of each wall particle w with listed(w)
// (n: the wall normal fields, null where a scene has none), built once per pair list build, so that a
// mirror point's query reads its listed candidates instead of scanning 5^dim cells
// (CellList::for_each_near_point with the list). Without a pair list nothing is listed and the queries
// scan. A mirror point moves with its wall particle (x_w + 2 d n, d and n fixed), so the list stays
// valid as long as the pair list does. Query only the walls listed(w) selects.
template <class Listed>
void update_mirror_list(const Particles& P, const CellList& cells, Kind kind, const double* depth, const double* const n[3],
                        const Listed& listed, PointList& list) {
  if (!cells.pairs_cached() || cells.point_list_current(list)) return;
  cells.list_near_points(
      P, P.size(),
      [&](std::size_t w, double xq[3]) {
        if (!listed(w)) return false;
        const double xw[3] = {P.x[w], P.y[w], P.z[w]};
        const double nw[3] = {n[0] ? n[0][w] : 0.0, n[1] ? n[1][w] : 0.0, n[2] ? n[2][w] : 0.0};
        const auto xm = ghost_mirror_point(xw, depth[w], nw);
        for (int a = 0; a < 3; ++a) xq[a] = xm[a];
        return true;
      },
      [&](std::uint32_t j) { return P.kind[j] == kind; }, list);
}

// A neighbour f of the mirror point x_m: its index, W_mf V_f and the basis b_f = (x_f - x_m) / h.
struct MirrorNeighbour {
  std::uint32_t f;
  double wv, b[3];
};

// The coefficients c of phi(x_m) = sum_f (c . (1, b_f)) W_mf V_f phi_f (A c = e_1 with
// A = sum_f (1, b_f)(1, b_f)^T W_mf V_f), which reproduce linear fields; false where A is near singular
// (too few neighbours to span the dimension: take Shepard's c = (1 / sum_f W_mf V_f, 0, ...)).
bool mls_coefficients(const std::vector<MirrorNeighbour>& nb, int dim, double c[4]);

// K values at the mirror point from its neighbours nb (sv = sum_f W_mf V_f > 0; values(f, v) writes
// neighbour f's K values into v): the MLS estimate, Shepard's where the fit is singular, each bounded
// by the neighbours' own values - a mirror point beyond the material (a splash, the free surface) would
// otherwise extrapolate the fit.
template <int K, class Values>
void bounded_mls(const std::vector<MirrorNeighbour>& nb, int dim, double sv, const Values& values, double out[K]) {
  double c[4] = {0, 0, 0, 0};
  if (!mls_coefficients(nb, dim, c)) c[0] = 1.0 / sv;  // Shepard
  double lo[K], hi[K];
  for (int k = 0; k < K; ++k) { out[k] = 0; lo[k] = INFINITY; hi[k] = -INFINITY; }
  for (const auto& q : nb) {
    const double phi = (c[0] + c[1] * q.b[0] + c[2] * q.b[1] + c[3] * q.b[2]) * q.wv;
    double v[K];
    values(q.f, v);
    for (int k = 0; k < K; ++k) {
      out[k] += phi * v[k];
      lo[k] = std::min(lo[k], v[k]);
      hi[k] = std::max(hi[k], v[k]);
    }
  }
  for (int k = 0; k < K; ++k) out[k] = std::clamp(out[k], lo[k], hi[k]);
}

// The reflection R that carries the material at the mirror point onto the wall particle: across the
// tangent plane at a face or a shaped wall, R = I - 2 n n^T (n the unit normal); through the corner or
// edge at a box corner (corner = true; n points from the particle to the corner), the product of the
// face reflections of the axes n has components on, R = diag(-1 where n_a != 0, else 1) - the double
// (or triple) mirror. A vector maps as R v, a tensor as R sigma R^T.
Eigen::Matrix3d mirror_reflection(const double n[3], bool corner);

}  // namespace geosph
