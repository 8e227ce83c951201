#include "boundary/ghost_wall.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "boundary/body_fields.hpp"
#include "boundary/mirror_mls.hpp"
#include "boundary/wall_surface.hpp"
#include "core/kernels.hpp"

namespace geosph {

void update_ghost_walls(const Scene& scene, const std::vector<TaitEos>& eos, Particles& P, const CellList& cells,
                        const std::array<double, 3>& g, double* wvx, double* wvy, double* wvz,
                        std::vector<std::uint8_t>& unmirrored) {
  unmirrored.assign(P.size(), 0);
  const int dim = scene.dim;
  const double h = scene.h(), inv_h = 1.0 / h;
  const double volume = std::pow(scene.dx, dim);
  const double* depth = P.find(WallSurfaceFields::depth);
  const double* nx = P.find(BodyFields::wall_nx);
  const double* ny = P.find(BodyFields::wall_ny);
  const double* nz = P.find(BodyFields::wall_nz);
  const std::int32_t* slip = P.find_int(BodyFields::wall_free_slip);  // per container, if they differ
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
            cells.for_each_near_point(P, xm[0], xm[1], xm[2], [&](std::uint32_t f, double dx, double dy, double dz, double r2) {
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
            double c[4] = {0, 0, 0, 0};
            if (!mls_coefficients(nb, dim, c)) c[0] = 1.0 / sv;  // Shepard
            double pm = 0, rm = 0, vm[3] = {0, 0, 0};
            double lo[5] = {INFINITY, INFINITY, INFINITY, INFINITY, INFINITY}, hi[5] = {-INFINITY, -INFINITY, -INFINITY, -INFINITY, -INFINITY};
            for (const auto& q : nb) {
              const double phi = (c[0] + c[1] * q.b[0] + c[2] * q.b[1] + c[3] * q.b[2]) * q.wv;
              const double v[5] = {P.p[q.f], P.rho[q.f], P.vx[q.f], P.vy[q.f], P.vz[q.f]};
              pm += phi * v[0];
              rm += phi * v[1];
              vm[0] += phi * v[2]; vm[1] += phi * v[3]; vm[2] += phi * v[4];
              for (int k = 0; k < 5; ++k) { lo[k] = std::min(lo[k], v[k]); hi[k] = std::max(hi[k], v[k]); }
            }
            // bounded by the neighbours' values: a mirror point beyond the fluid (a splash, the free
            // surface) would otherwise extrapolate the fit
            pm = std::clamp(pm, lo[0], hi[0]);
            rm = std::clamp(rm, lo[1], hi[1]);
            for (int k = 0; k < 3; ++k) vm[k] = std::clamp(vm[k], lo[2 + k], hi[2 + k]);
            P.p[w] = pm + rm * (g[0] * (xw[0] - xm[0]) + g[1] * (xw[1] - xm[1]) + g[2] * (xw[2] - xm[2]));
            P.rho[w] = e.density(P.p[w]);
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
