#include "boundary/dummy_wall.hpp"

#include <cmath>

#include "boundary/body_fields.hpp"
#include "boundary/ghost_wall.hpp"
#include "coupling/seepage_fields.hpp"

namespace geosph {

DummyWalls::DummyWalls(const Scene& scene, const FluidForces& fluid)
    // Morris walls (boundary/morris_wall.hpp) take the dummy pressure, but their velocity per pair
    : scene_(scene), fluid_(fluid), no_slip_(scene.any_no_slip_wall() && scene.walls.type != "morris"),
      ghost_(scene.walls.type == "ghost"), drained_(drained_faces(scene)) {}

void DummyWalls::allocate(Particles& P) const {
  if (!no_slip_) return;
  for (const char* f : {DummyWallFields::vx, DummyWallFields::vy, DummyWallFields::vz}) P.add_field(f, DummyWallFields::owner);
}

void DummyWalls::update(Particles& P, const CellList& cells, const std::array<double, 3>& g) const {
  // ghost walls: the same fields from the fluid at each mirror point, and the dummy values below for the
  // wall particles whose mirror point has no fluid near it
  if (ghost_)
    update_ghost_walls(scene_, fluid_.eos(), P, cells, g, no_slip_ ? P.field(DummyWallFields::vx).data() : nullptr,
                       no_slip_ ? P.field(DummyWallFields::vy).data() : nullptr,
                       no_slip_ ? P.field(DummyWallFields::vz).data() : nullptr, unmirrored_, mirrors_);
  std::visit(
      [&](const auto& kernel) {
        const std::size_t n = P.size();
        double* wvx = no_slip_ ? P.field(DummyWallFields::vx).data() : nullptr;
        double* wvy = no_slip_ ? P.field(DummyWallFields::vy).data() : nullptr;
        double* wvz = no_slip_ ? P.field(DummyWallFields::vz).data() : nullptr;
        const auto& eos = fluid_.eos();
        const double volume = std::pow(scene_.dx, scene_.dim);
        // pore water (two-phase): rho is the partial density n rho_w; the wall takes the porosity of its
        // water neighbours and the intrinsic density in the hydrostatic term
        const std::int32_t* slip = P.find_int(BodyFields::wall_free_slip);  // per container, if they differ
        double* por = scene_.two_phase() ? P.field(SeepageFields::porosity).data() : nullptr;
        const std::int32_t* drained = drained_.empty() ? nullptr : P.find_int(DrainedFields::face);
#pragma omp parallel for schedule(dynamic, 256)
        for (std::size_t w = 0; w < n; ++w) {
          const DrainedFace* face = drained && drained[w] > 0 ? &drained_[static_cast<std::size_t>(drained[w]) - 1] : nullptr;
          if (P.kind[w] != Kind::DummyWall || (ghost_ && !unmirrored_[w] && !face)) continue;
          double sw = 0, sp = 0, srx = 0, sry = 0, srz = 0, svx = 0, svy = 0, svz = 0, sn = 0;
          double wmax = -1;
          std::uint16_t mat = 0;
          cells.for_each_neighbor(P, w, [&](std::uint32_t f, double dx, double dy, double dz, double r2) {
            if (P.kind[f] != Kind::Fluid) return;
            const double W = kernel.W(std::sqrt(r2));
            sw += W;
            sp += P.p[f] * W;
            const double nf = por ? por[f] : 1.0;
            sn += nf * W;
            const double rw = P.rho[f] / nf * W;
            srx += rw * dx; sry += rw * dy; srz += rw * dz;
            svx += P.vx[f] * W; svy += P.vy[f] * W; svz += P.vz[f] * W;
            if (W > wmax) { wmax = W; mat = P.material[f]; }
          });
          const TaitEos& e = eos[mat];
          if (sw > 0) {
            // fixed walls: a_w = 0
            P.p[w] = (sp + g[0] * srx + g[1] * sry + g[2] * srz) / sw;
            if (face) {  // drained: the excess over the face's hydrostatic line p_h, reflected oddly (0 at the face)
              const double xw[3] = {P.x[w], P.y[w], P.z[w]};
              P.p[w] = 2.0 * face->hydrostatic_pressure(xw, e.rho0, g) - P.p[w];
            }
            P.rho[w] = e.density(P.p[w]);
            if (por) {
              por[w] = sn / sw;
              P.rho[w] *= por[w];
            }
            P.m[w] = P.rho[w] * volume;
            if (no_slip_ && !(slip && slip[w])) {
              wvx[w] = 2.0 * P.vx[w] - svx / sw;
              wvy[w] = 2.0 * P.vy[w] - svy / sw;
              wvz[w] = 2.0 * P.vz[w] - svz / sw;
            }
          } else if (face) {
            const double xw[3] = {P.x[w], P.y[w], P.z[w]};
            P.p[w] = face->hydrostatic_pressure(xw, e.rho0, g);
            P.rho[w] = e.density(P.p[w]);
            if (por) {
              por[w] = scene_.soils.front().porosity;
              P.rho[w] *= por[w];
            }
            P.m[w] = P.rho[w] * volume;
          } else {
            P.p[w] = e.p_bg;
            P.rho[w] = e.rho0;
            if (por) por[w] = 1.0;
            P.m[w] = e.rho0 * volume;
            if (no_slip_) { wvx[w] = P.vx[w]; wvy[w] = P.vy[w]; wvz[w] = P.vz[w]; }
          }
        }
      },
      make_kernel(scene_.kernel, scene_.dim, scene_.h()));
}

}  // namespace geosph
