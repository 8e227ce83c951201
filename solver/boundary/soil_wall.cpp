#include "boundary/soil_wall.hpp"

#include "boundary/body_fields.hpp"
#include "boundary/mirror_mls.hpp"
#include "boundary/wall_surface.hpp"
#include "coupling/seepage_fields.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>

#include <Eigen/Core>

#include "soil/soil_forces.hpp"

namespace geosph {

namespace {

// A mirror point whose Shepard sum sum_k W_mk V_k (1 in a full support) is below this lies at the free
// surface or in a tail a particle or two thick; the wall particle keeps its dummy value there.
constexpr double kMinMirrorSupport = 0.5;

// Ghost walls (walls.type "ghost"): the soil's values at the mirror point x_m = x_w + 2 d n of wall
// particle w (boundary/ghost_wall.hpp), by first-order MLS over the soil there, each bounded by the
// neighbours' values, written to w's stress s and ghost velocity wv:
//   free slip: sigma_w = R sigma(x_m) R^T - rho' g.(x_w - x_m) I,   v_w = v_wall + R (v(x_m) - v_wall),
//   no slip:   sigma_w = sigma(x_m)       - rho' g.(x_w - x_m) I,   v_w = 2 v_wall - v(x_m),
// R the reflection (boundary/mirror_mls.hpp). At a face with normal along axis a, R sigma R^T reverses
// the shear components sigma_ab (b != a) and keeps the normal stresses and the tangential shear
// sigma_bc (b, c != a); through a 2D corner (R = -I) nothing changes sign, at a 3D edge only the two
// shears with the edge's axis keep theirs. No slip keeps every shear, so the wall shears the soil as the
// dummy walls do. The isotropic hydrostatic step is the dummy walls' (Adami eq. 27 on the mean stress),
// taken over the distance x_w - x_m; rho' the soil density the dummy sums use (buoyant when saturated).
// A clamping block's particles keep their own velocity. False when the soil fills less than half
// the support at x_m (kMinMirrorSupport).
template <class Kernel, class EffectiveDensity>
bool mirror_ghost(const Particles& P, const CellList& cells, const Kernel& kernel, std::size_t w, double depth,
                  const double n[3], bool corner, bool no_slip, bool clamp, const std::array<double, 3>& g, int ncomp,
                  double* const* s, double* const* wv, const EffectiveDensity& rho_eff, double inv_h,
                  const PointList& mirrors, std::vector<MirrorNeighbour>& nb) {
  const double xw[3] = {P.x[w], P.y[w], P.z[w]};
  const auto xm = ghost_mirror_point(xw, depth, n);
  nb.clear();
  double sv = 0;
  cells.for_each_near_point(P, mirrors, w, xm[0], xm[1], xm[2], [&](std::uint32_t k, double dx, double dy, double dz, double r2) {
    if (P.kind[k] != Kind::Soil) return;
    const double W = kernel.W(std::sqrt(r2));
    nb.push_back({k, W * P.m[k] / P.rho[k], {-dx * inv_h, -dy * inv_h, -dz * inv_h}});  // b = (x_k - x_m) / h
    sv += nb.back().wv;
  });
  if (!(sv >= kMinMirrorSupport)) return false;
  // the values: stress components, velocity, density
  double val[10];
  bounded_mls<10>(nb, P.dim, sv, [&](std::uint32_t k, double v[10]) {
    for (int comp = 0; comp < 6; ++comp) v[comp] = comp < ncomp ? s[comp][k] : 0.0;
    v[6] = P.vx[k]; v[7] = P.vy[k]; v[8] = P.vz[k];
    v[9] = rho_eff(k);
  }, val);
  const double xz = ncomp == 6 ? val[4] : 0.0, yz = ncomp == 6 ? val[5] : 0.0;
  Eigen::Matrix3d t;
  t << val[0], val[3], xz, val[3], val[1], yz, xz, yz, val[2];
  const Eigen::Matrix3d R = mirror_reflection(n, corner);
  if (!no_slip) t = R * t * R.transpose();
  const double hydro = val[9] * (g[0] * (xw[0] - xm[0]) + g[1] * (xw[1] - xm[1]) + g[2] * (xw[2] - xm[2]));
  s[0][w] = t(0, 0) - hydro; s[1][w] = t(1, 1) - hydro; s[2][w] = t(2, 2) - hydro;
  s[3][w] = t(0, 1);
  if (ncomp == 6) { s[4][w] = t(0, 2); s[5][w] = t(1, 2); }
  const Eigen::Vector3d vwall(P.vx[w], P.vy[w], P.vz[w]), vm(val[6], val[7], val[8]);
  const Eigen::Vector3d u = clamp ? vwall : no_slip ? Eigen::Vector3d(2.0 * vwall - vm) : Eigen::Vector3d(vwall + R * (vm - vwall));
  for (int a = 0; a < 3; ++a) wv[a][w] = u[a];
  return true;
}

}  // namespace

SoilWalls::SoilWalls(const Scene& scene)
    : scene_(scene), no_slip_(scene.walls.slip == "no_slip"), ghost_(scene.walls.type == "ghost") {}

void SoilWalls::allocate(Particles& P) const {
  for (const char* f : {SoilWallFields::vx, SoilWallFields::vy, SoilWallFields::vz}) P.add_field(f, SoilWallFields::owner);
  // until the first update the soil sees the walls as built (boundary/geometry.cpp)
  P.add_field(SoilWallFields::rho, SoilWallFields::owner) = P.rho;
  P.add_field(SoilWallFields::m, SoilWallFields::owner) = P.m;
}

void SoilWalls::mark_read_walls(const Particles& P, const CellList& cells) const {
  const std::size_t n = P.size();
  const Kind* kind = P.kind.data();
  if (cells.pairs_cached()) {
    // from the pair list, once per list build: a wall none of whose listed candidates is another kind's
    // particle is in no support until the next build (the list is symmetric)
    if (marked_build_ == cells.pair_list_builds() && read_.size() == n) return;
    read_.assign(n, 0);
#pragma omp parallel for schedule(static)
    for (std::size_t w = 0; w < n; ++w) {
      if (kind[w] != Kind::DummyWall) continue;
      for (const std::uint32_t j : cells.listed(w))
        if (kind[j] != Kind::DummyWall) { read_[w] = 1; break; }
    }
    marked_build_ = cells.pair_list_builds();
    return;
  }
  marked_build_ = -1;
  read_.assign(n, 0);
  std::uint8_t* read = read_.data();
#pragma omp parallel
  {
  Neighbors nb;
#pragma omp for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    if (kind[i] == Kind::DummyWall) continue;
    cells.gather_any_dim(P, i, nb);
    for (std::size_t k = 0; k < nb.n; ++k) {
      const std::uint32_t j = nb.j[k];
      if (kind[j] == Kind::DummyWall) std::atomic_ref<std::uint8_t>(read[j]).store(1, std::memory_order_relaxed);
    }
  }
  }
}

void SoilWalls::update(Particles& P, const CellList& cells, const std::array<double, 3>& g) const {
  std::visit(
      [&](const auto& kernel) {
        const std::size_t n = P.size();
        double* wv[3] = {P.field(SoilWallFields::vx).data(), P.field(SoilWallFields::vy).data(), P.field(SoilWallFields::vz).data()};
        double* wrho = P.field(SoilWallFields::rho).data();
        double* wm = P.field(SoilWallFields::m).data();
        double* s[6] = {P.field(SoilFields::xx).data(), P.field(SoilFields::yy).data(), P.field(SoilFields::zz).data(),
                        P.field(SoilFields::xy).data(), P.dim == 3 ? P.field(SoilFields::xz).data() : nullptr,
                        P.dim == 3 ? P.field(SoilFields::yz).data() : nullptr};
        const int ncomp = P.dim == 3 ? 6 : 4;
        const double volume = std::pow(scene_.dx, scene_.dim);
        const std::int32_t* slip = P.find_int(BodyFields::wall_free_slip);  // per container, if they differ
        const std::int32_t* block = P.find_int(BodyFields::wall_block);
        const std::int32_t* mirror_axes = P.find_int(BodyFields::wall_mirror_axes);
        const double* wn[3] = {P.find(BodyFields::wall_nx), P.find(BodyFields::wall_ny), P.find(BodyFields::wall_nz)};
        // saturated soil: the effective stress grows with the buoyant weight rho - (1 - n) rho_w
        const double* por = scene_.two_phase() ? P.field(SeepageFields::porosity).data() : nullptr;
        const double rho_w = scene_.two_phase() ? scene_.materials.front().density : 0.0;
        mark_read_walls(P, cells);
        const double rho0_far = scene_.soils.front().density;
        const double* depth = ghost_ ? P.find(WallSurfaceFields::depth) : nullptr;
        if (depth)  // the walls mirror_ghost queries: the read ones
          update_mirror_list(P, cells, Kind::Soil, depth, wn, [&](std::size_t w) { return P.kind[w] == Kind::DummyWall && read_[w]; },
                             mirrors_);
        const std::int32_t* corner = P.find_int(WallSurfaceFields::corner);
        const double inv_h = 1.0 / scene_.h();
        const auto effective_density = [&](std::size_t k) { return por ? P.rho[k] - (1.0 - por[k]) * rho_w : P.rho[k]; };
#pragma omp parallel
        {
        std::vector<MirrorNeighbour> nb;
#pragma omp for schedule(dynamic, 256)
        for (std::size_t w = 0; w < n; ++w) {
          if (P.kind[w] != Kind::DummyWall) continue;
          const auto far_wall = [&] {  // in no particle's support: the values of a wall without soil around
            for (int c = 0; c < ncomp; ++c) s[c][w] = 0;
            for (int a = 0; a < 3; ++a) wv[a][w] = 0;
            wrho[w] = rho0_far;
            wm[w] = rho0_far * volume;
          };
          if (!read_[w]) { far_wall(); continue; }
          const bool no_slip = slip ? slip[w] == 0 : no_slip_;
          // free slip at a container or block face: R sigma R^T with R = diag(-1 on the mirror axes), so
          // shear ab reverses where exactly one of a, b is mirrored (at a face normal to x: xy and xz, not
          // yz; at a 2D corner none); no slip keeps every shear
          const auto shear_sign = [&](std::size_t k, int c) {
            if (no_slip) return 1.0;
            if (!mirror_axes || mirror_axes[k] == 0) return -1.0;  // no face known: every shear reverses
            static constexpr int kAxes[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
            const bool ma = (mirror_axes[k] >> kAxes[c][0]) & 1, mb = (mirror_axes[k] >> kAxes[c][1]) & 1;
            return ma != mb ? -1.0 : 1.0;
          };
          double sw = 0, ss[6] = {0, 0, 0, 0, 0, 0}, sr[3] = {0, 0, 0}, sv[3] = {0, 0, 0}, sd[3] = {0, 0, 0}, wmax = -1;
          std::uint16_t mat = 0;
          bool covered = false;  // the centre lies inside a structure particle's cell: the structure is there
          bool in_support = false;  // another kind's particle within the support (and so this wall in its)
          // lattice neighbours ((1.01 dx)^2): a soil particle among them, and the offsets to structure ones
          const double adjacent2 = 1.0201 * scene_.dx * scene_.dx;
          bool soil_adjacent = false;
          int n_adjacent = 0;
          double adjacent[6][3];
          cells.for_each_neighbor(P, w, [&](std::uint32_t k, double dx, double dy, double dz, double r2) {
            in_support = in_support || P.kind[k] != Kind::DummyWall;
            if (is_structure(P.kind[k])) {
              covered = covered || std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) < 0.5 * scene_.dx;
              if (r2 <= adjacent2 && n_adjacent < 6) {
                adjacent[n_adjacent][0] = dx; adjacent[n_adjacent][1] = dy; adjacent[n_adjacent][2] = dz;
                ++n_adjacent;
              }
              return;
            }
            if (P.kind[k] != Kind::Soil) return;
            soil_adjacent = soil_adjacent || r2 <= adjacent2;
            const double W = kernel.W(std::sqrt(r2));
            sw += W;
            for (int c = 0; c < ncomp; ++c) ss[c] += s[c][k] * W;
            const double rw = effective_density(k) * W;
            sr[0] += rw * dx; sr[1] += rw * dy; sr[2] += rw * dz;
            sv[0] += P.vx[k] * W; sv[1] += P.vy[k] * W; sv[2] += P.vz[k] * W;
            sd[0] += W * dx; sd[1] += W * dy; sd[2] += W * dz;
            if (W > wmax) { wmax = W; mat = P.material[k]; }
          });
          if (!in_support) { far_wall(); continue; }  // a listed candidate, not (yet) within the support
          // a wall particle in a structure's shadow (a structure particle adjacent on the soil's side, i.e.
          // towards the kernel-weighted mean of the soil neighbours, and no soil particle adjacent: the
          // floor under a retaining wall that stands on it) is the structure's support, not the soil's:
          // left in the soil's sums it carries the soil's extrapolated stress beneath the structure and
          // props the soil at the structure's foot (a retaining wall standing on the floor lost a quarter
          // of its active thrust). A structure on the far side (a wall reaching into the floor, seen from
          // the floor beside it) leaves it the soil's.
          for (int a = 0; a < n_adjacent && !soil_adjacent && !covered; ++a)
            covered = adjacent[a][0] * sd[0] + adjacent[a][1] * sd[1] + adjacent[a][2] * sd[2] > 0;
          const double rho0 = scene_.soils[mat].density;
          wrho[w] = rho0;
          wm[w] = covered ? 0.0 : rho0 * volume;  // a covered ghost leaves the soil's sums
          if (sw <= 0 || covered) {
            for (int c = 0; c < ncomp; ++c) s[c][w] = 0;
            for (int a = 0; a < 3; ++a) wv[a][w] = 0;
            continue;
          }
          const double vw[3] = {P.vx[w], P.vy[w], P.vz[w]};
          const bool clamp = block && block[w] > 0 && no_slip;  // the embedded material does not move
          const bool shaped = wn[0] && (wn[0][w] != 0 || wn[1][w] != 0 || wn[2][w] != 0);
          const double nw[3] = {shaped ? wn[0][w] : 0.0, shaped ? wn[1][w] : 0.0, shaped ? wn[2][w] : 0.0};
          const bool at_corner = corner && corner[w];
          if (depth && mirror_ghost(P, cells, kernel, w, depth[w], nw, at_corner, no_slip, clamp, g, ncomp, s, wv,
                                    effective_density, inv_h, mirrors_, nb))
            continue;  // the ghost values at the mirror point; else the dummy values below
          const double hydro = (g[0] * sr[0] + g[1] * sr[1] + g[2] * sr[2]) / sw;  // fixed walls: a_w = 0
          if (shaped && !no_slip && !at_corner) {
            // a wall of any shape (walls.boundaries, and the faces of a ghost-wall scene's containers,
            // which carry their normals): the extrapolated stress mirrored across the wall's tangent plane,
            // H sigma H with H = I - 2 n n^T, which reverses the normal-tangential shear and keeps the
            // rest, so the mean of soil and ghost stress has no shear traction on the wall
            const Eigen::Matrix3d H = mirror_reflection(nw, false);
            Eigen::Matrix3d t;
            t << ss[0], ss[3], ncomp == 6 ? ss[4] : 0.0, ss[3], ss[1], ncomp == 6 ? ss[5] : 0.0,
                ncomp == 6 ? ss[4] : 0.0, ncomp == 6 ? ss[5] : 0.0, ss[2];
            const Eigen::Matrix3d m = H * (t / sw) * H;
            s[0][w] = m(0, 0) - hydro; s[1][w] = m(1, 1) - hydro; s[2][w] = m(2, 2) - hydro;
            s[3][w] = m(0, 1);
            if (ncomp == 6) { s[4][w] = m(0, 2); s[5][w] = m(1, 2); }
          } else {
            for (int c = 0; c < 3; ++c) s[c][w] = ss[c] / sw - hydro;
            for (int c = 3; c < ncomp; ++c) s[c][w] = shear_sign(w, c) * ss[c] / sw;
          }
          const double vs[3] = {sv[0] / sw, sv[1] / sw, sv[2] / sw};  // Shepard average of the soil velocity
          if (clamp) {
            for (int a = 0; a < 3; ++a) wv[a][w] = vw[a];
          } else if (no_slip) {
            for (int a = 0; a < 3; ++a) wv[a][w] = 2.0 * vw[a] - vs[a];
          } else if (!(shaped && !at_corner) && mirror_axes && mirror_axes[w] != 0) {
            // free slip at a container or block face: the velocity mirrored as the stress is,
            // u = v_wall + R (v_s - v_wall) with R = diag(-1 on the mirror axes): the normal velocity
            // reverses about the wall's, the tangential one is the soil's (a corner reverses both). The
            // kernel-weighted mean offset to the soil, the normal used before, tilts wherever the soil
            // fills the support on one side only (the free surface beside a wall, a corner): the wall
            // then mirrored part of the soil's tangential velocity and held a settling column's top rows
            // as a rough wall would (sigma_v 3 kPa, 3-6%, above rho g d; issue 17, item 3)
            for (int a = 0; a < 3; ++a) wv[a][w] = (mirror_axes[w] >> a) & 1 ? 2.0 * vw[a] - vs[a] : vs[a];
          } else {
            // free slip at a wall of any shape: the soil's tangential velocity, its normal velocity
            // mirrored about the wall's, u = v_s + 2 ((v_w - v_s).n) n, n the wall's surface normal into
            // the soil, or where a particle has none, minus the kernel-weighted mean offset to the soil
            // neighbours; the stress divergence then resists the soil moving into the wall without
            // shearing it
            const double len = std::sqrt(sd[0] * sd[0] + sd[1] * sd[1] + sd[2] * sd[2]);
            double nrm[3] = {0, 0, 0}, vn = 0;
            if (shaped && !at_corner)
              for (int a = 0; a < 3; ++a) { nrm[a] = wn[a][w]; vn += (vw[a] - vs[a]) * nrm[a]; }
            else if (len > 0)
              for (int a = 0; a < 3; ++a) { nrm[a] = -sd[a] / len; vn += (vw[a] - vs[a]) * nrm[a]; }
            for (int a = 0; a < 3; ++a) wv[a][w] = vs[a] + 2.0 * vn * nrm[a];
          }
        }
        }
      },
      make_kernel(scene_.kernel, scene_.dim, scene_.h()));
}

}  // namespace geosph
