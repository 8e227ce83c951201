#include "boundary/mirror_relaxation.hpp"

#include <algorithm>
#include <cmath>

#include "boundary/geometry.hpp"
#include "boundary/mirror_wall.hpp"
#include "core/cell_list.hpp"
#include "core/kernels.hpp"
#include "fluid/equation_of_state.hpp"

namespace geosph {

namespace {

constexpr int kIterations = 300;
constexpr double kBeta = 0.1;         // x += -beta h^2 sum V grad W per iteration
constexpr double kMaxMove = 0.05;     // at most this many dx per iteration

// Mirror walls on the body's own surface: the solid is everything outside the body (a box around it
// less the body), so the images fill the outside and a particle that leaves the body bounces back in.
MirrorWalls body_surface_walls(const Scene& s, const BodySpec& b) {
  Scene w = s;
  w.walls = WallSpec{};
  w.walls.type = "mirror";
  geometry::Point lo = b.lo, hi = b.hi;
  const double margin = 4 * s.support();
  for (int a = 0; a < s.dim; ++a) { lo[a] -= margin; hi[a] += margin; }
  BoundarySpec outside;
  outside.shape = geometry::make_difference(s.dim, {geometry::make_box(s.dim, lo, hi), b.shape});
  outside.slip = "no_slip";
  w.walls.boundaries.push_back(outside);
  return MirrorWalls(w);
}

template <int Dim, class K>
double packing_step(const K& kernel, const MirrorWalls& walls, const Particles& Q, const CellList& cells, double volume,
                    std::vector<double>& gx, std::vector<double>& gy, std::vector<double>& gz) {
  const std::size_t n = Q.size();
  double worst = 0;
#pragma omp parallel reduction(max : worst)
  {
  Neighbors nb;
  MirrorSet set;
#pragma omp for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    double G[3] = {0, 0, 0};
    cells.gather<Dim>(Q, i, nb);
    for (std::size_t k = 0; k < nb.size(); ++k) {
      const double fw = kernel.gradW_over_r(std::sqrt(nb.r2[k]));
      G[0] += volume * fw * nb.dx[k]; G[1] += volume * fw * nb.dy[k];
      if constexpr (Dim == 3) G[2] += volume * fw * nb.dz[k];
    }
    const double xi[3] = {Q.x[i], Q.y[i], Dim == 3 ? Q.z[i] : 0.0};
    walls.images(xi, set);
    for (const MirrorImage& T : set.images) {
      const auto q = T.apply(xi);
      cells.for_each_near_point(Q, q[0], q[1], q[2], [&](std::uint32_t, double dx, double dy, double dz, double r2) {
        const double d[3] = {dx, dy, dz};
        const auto r = T.rotate(d);  // x_i - x_j'
        const double y[3] = {xi[0] - r[0], xi[1] - r[1], xi[2] - r[2]};
        if (!set.keep(T, y)) return;
        const double fw = kernel.gradW_over_r(std::sqrt(r2));
        for (int a = 0; a < Dim; ++a) G[a] += volume * fw * r[a];
      });
    }
    gx[i] = G[0]; gy[i] = G[1]; gz[i] = G[2];
    worst = std::max(worst, std::sqrt(G[0] * G[0] + G[1] * G[1] + G[2] * G[2]));
  }
  }
  return worst;
}

}  // namespace

RelaxationResult relax_body_against_mirror_walls(const Scene& s, const BodySpec& b, Particles& P, std::size_t first,
                                                 std::size_t count) {
  RelaxationResult res;
  if (count == 0) return res;
  const MirrorWalls walls = body_surface_walls(s, b);
  Particles Q;  // the body's particles alone
  Q.dim = s.dim;
  for (std::size_t i = first; i < first + count; ++i) Q.add(P.x[i], P.y[i], P.z[i], P.m[i], P.rho[i], Kind::Fluid, 0);
  const double h = s.h(), dx = s.dx, volume = std::pow(dx, s.dim);
  std::vector<double> gx(count), gy(count), gz(count);
  CellList cells;
  std::visit([&](const auto& kernel) {
    for (int it = 0; it < kIterations; ++it) {
      cells.build(Q, s.domain, s.support());
      const double worst = s.dim == 2 ? packing_step<2>(kernel, walls, Q, cells, volume, gx, gy, gz)
                                      : packing_step<3>(kernel, walls, Q, cells, volume, gx, gy, gz);
      double mean = 0;
      for (std::size_t i = 0; i < count; ++i) mean += std::sqrt(gx[i] * gx[i] + gy[i] * gy[i] + gz[i] * gz[i]);
      mean *= h / static_cast<double>(count);
      if (it == 0) { res.initial_residual = h * worst; res.initial_mean = mean; }
      res.final_residual = h * worst;
      res.final_mean = mean;
      res.iterations = it + 1;
      for (std::size_t i = 0; i < count; ++i) {
        double d[3] = {-kBeta * h * h * gx[i], -kBeta * h * h * gy[i], -kBeta * h * h * gz[i]};
        const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        const double f = len > kMaxMove * dx ? kMaxMove * dx / len : 1.0;
        Q.x[i] += f * d[0]; Q.y[i] += f * d[1];
        if (s.dim == 3) Q.z[i] += f * d[2];
      }
      walls.reflect_crossings(Q);
    }
  }, make_kernel(s.kernel, s.dim, h));
  // the body's initial state at the new positions (its mass stays: the lattice's rho dx^dim)
  const TaitEos eos(s.materials[P.material[first]]);
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = first + k;
    P.x[i] = Q.x[k]; P.y[i] = Q.y[k]; P.z[i] = Q.z[k];
    P.rho[i] = fluid_initial_density(s, b, P.x[i], P.y[i], P.z[i]);
    P.p[i] = eos.pressure(P.rho[i]);
  }
  return res;
}

}  // namespace geosph
