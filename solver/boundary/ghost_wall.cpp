#include "boundary/ghost_wall.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "boundary/body_fields.hpp"
#include "boundary/wall_surface.hpp"
#include "coupling/seepage_fields.hpp"
#include "core/kernels.hpp"

namespace geosph {

void update_ghost_walls(const Scene& scene, const std::vector<TaitEos>& eos, Particles& P, const CellList& cells,
                        const std::array<double, 3>& g, double* wvx, double* wvy, double* wvz,
                        std::vector<std::uint8_t>& unmirrored, PointList& mirrors) {
  unmirrored.assign(P.size(), 0);
  const int dim = scene.dim;
  const double h = scene.h(), inv_h = 1.0 / h;
  const double volume = std::pow(scene.dx, dim);
  const double* depth = P.find(WallSurfaceFields::depth);
  const double* nx = P.find(BodyFields::wall_nx);
  const double* ny = P.find(BodyFields::wall_ny);
  const double* nz = P.find(BodyFields::wall_nz);
  const std::int32_t* slip = P.find_int(BodyFields::wall_free_slip);  // per container, if they differ
  const double* normal[3] = {nx, ny, nz};
  double* por = scene.two_phase() ? P.field(SeepageFields::porosity).data() : nullptr;  // pore water, its walls
  update_mirror_list(P, cells, Kind::Fluid, depth, normal, [&](std::size_t w) { return P.kind[w] == Kind::DummyWall; }, mirrors);
  std::visit(
      [&](const auto& kernel) {
        const std::size_t n = P.size();
#pragma omp parallel
        {
          std::vector<MirrorNeighbour> nb;
#pragma omp for schedule(dynamic, 256)
          for (std::size_t w = 0; w < n; ++w) {
            if (P.kind[w] != Kind::DummyWall) continue;
            const double xw[3] = {P.x[w], P.y[w], P.z[w]}, nw[3] = {nx[w], ny[w], nz[w]};
            const auto xm = ghost_mirror_point(xw, depth[w], nw);
            nb.clear();
            double wmax = -1;
            std::uint16_t mat = 0;
            cells.for_each_near_point(P, mirrors, w, xm[0], xm[1], xm[2], [&](std::uint32_t f, double dx, double dy, double dz, double r2) {
              if (P.kind[f] != Kind::Fluid) return;
              const double W = kernel.W(std::sqrt(r2));
              // d = x_m - x_f, so b = (x_f - x_m) / h = -d / h
              nb.push_back({f, W * P.m[f] / P.rho[f], {-dx * inv_h, -dy * inv_h, -dz * inv_h}});
              if (W > wmax) { wmax = W; mat = P.material[f]; }
            });
            double sv = 0;
            for (const auto& q : nb) sv += q.wv;
            if (!(sv > 0)) {  // no fluid near the mirror point: the dummy walls' value at w
              unmirrored[w] = 1;
              continue;
            }
            const TaitEos& e = eos[mat];
            double fit[6];  // p, the intrinsic density rho / n, v and the porosity n at the mirror point
            bounded_mls<6>(nb, dim, sv, [&](std::uint32_t f, double v[6]) {
              const double nf = por ? por[f] : 1.0;
              v[0] = P.p[f]; v[1] = P.rho[f] / nf; v[2] = P.vx[f]; v[3] = P.vy[f]; v[4] = P.vz[f]; v[5] = nf;
            }, fit);
            const double pm = fit[0], rm = fit[1], vm[3] = {fit[2], fit[3], fit[4]};
            P.p[w] = pm + rm * (g[0] * (xw[0] - xm[0]) + g[1] * (xw[1] - xm[1]) + g[2] * (xw[2] - xm[2]));
            P.rho[w] = e.density(P.p[w]);
            if (por) {  // pore water: the partial density n rho_w, as the dummy walls take it
              por[w] = fit[5];
              P.rho[w] *= por[w];
            }
            P.m[w] = P.rho[w] * volume;
            if (wvx && !(slip && slip[w])) {
              wvx[w] = 2.0 * P.vx[w] - vm[0];
              wvy[w] = 2.0 * P.vy[w] - vm[1];
              wvz[w] = 2.0 * P.vz[w] - vm[2];
            }
          }
        }
      },
      make_kernel(scene.kernel, scene.dim, scene.h()));
}

}  // namespace geosph
