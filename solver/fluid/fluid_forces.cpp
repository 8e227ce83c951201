#include "fluid/fluid_forces.hpp"

#include "boundary/body_fields.hpp"
#include "boundary/dummy_wall.hpp"
#include "boundary/drained_face.hpp"
#include "boundary/morris_wall.hpp"
#include "coupling/seepage_fields.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace geosph {

FluidForces::FluidForces(const Scene& scene) : scene_(scene), mats_(scene.materials) {
  for (const auto& m : mats_) eos_.emplace_back(m);
  free_slip_walls_ = scene.walls.slip == "free_slip";
  morris_walls_ = scene.walls.type == "morris";
  if (scene.walls.type == "mirror") mirror_ = std::make_shared<const MirrorWalls>(scene);
  const double c0 = max_sound_speed();
  repulsive_D_ = scene.walls.repulsive_strength > 0 ? scene.walls.repulsive_strength : 0.05 * c0 * c0;
  // r0: the fluid's initial distance from the wall line (Monaghan 1994), dx (boundary/geometry.cpp)
  repulsive_r0_ = scene.dx;
}

double FluidForces::max_sound_speed() const {
  double c = 0;
  for (const auto& m : mats_) c = std::max(c, m.sound_speed);
  return c;
}

double FluidForces::max_kinematic_viscosity() const {
  double nu = 0;
  for (const auto& m : mats_) nu = std::max(nu, m.kinematic_viscosity);
  return nu;
}

// Pore water (coupling/seepage.hpp): rho is the partial density n rho_w; the pressure follows the
// intrinsic density rho / n.
void FluidForces::update_pressure(Particles& P) const {
  const std::size_t n = P.size();
  const double* por = porosity(P);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i)
    if (P.kind[i] == Kind::Fluid) P.p[i] = eos_[P.material[i]].pressure(por ? P.rho[i] / por[i] : P.rho[i]);
}

const double* FluidForces::porosity(const Particles& P) const {
  if (!scene_.two_phase()) return nullptr;
  return P.field(SeepageFields::porosity).data();
}

void FluidForces::rates(Particles& P, const CellList& cells, const std::array<double, 3>& g, double dt_predicted) const {
  // walls whose slip differs per container read a per-particle flag; the common case keeps the pair
  // loop free of it (the flag lookup per wall pair cost 10% of a dam-break step)
  const bool mixed = P.find_int(BodyFields::wall_free_slip) != nullptr;
  const bool porous = porosity(P) != nullptr;
  const auto run = [&]<int Dim>(const auto& k) {
    if (morris_walls_) rates_with<Dim, false, false, true>(k, P, cells, g);  // no-slip, fluid-only scenes
    else if (mixed) porous ? rates_with<Dim, true, true, false>(k, P, cells, g) : rates_with<Dim, true, false, false>(k, P, cells, g);
    else porous ? rates_with<Dim, false, true, false>(k, P, cells, g) : rates_with<Dim, false, false, false>(k, P, cells, g);
  };
  std::visit([&](const auto& k) {
    if (scene_.dim == 2) run.template operator()<2>(k);
    else run.template operator()<3>(k);
  }, make_kernel(scene_.kernel, scene_.dim, scene_.h()));
  if (mirror_) add_mirror_images(P, cells, g);
  correct_density(P, dt_predicted);
}

// The step predicted rho with the last rate (integrate hook: rho~ = rho^n + dt drho^{n-1}); with the new
// rate the density is rho^n + dt drho^n, i.e. rho~ + dt (drho^n - drho^{n-1}). A separate pass: the pair
// loop reads its neighbours' densities.
void FluidForces::correct_density(Particles& P, double dt_predicted) const {
  const std::size_t n = P.size();
  const double* fresh = drho_new_.data();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (P.kind[i] != Kind::Fluid) continue;
    P.rho[i] += dt_predicted * (fresh[i] - P.drho[i]);
    P.drho[i] = fresh[i];
  }
}

// The renormalised gradient of the water's intrinsic density rho/n at each fluid particle (Antuono,
// Colagrossi, Marrone & Molteni 2010, Comput. Phys. Commun. 181, eq. 7; Randles & Libersky 1996):
// grad rho_i = (sum_j V_j (x_j - x_i) (x) grad W_ij)^-1 sum_j V_j (rho_j - rho_i) grad W_ij, over water.
template <int Dim, class K>
void FluidForces::density_gradients(const K& kernel, const Particles& P, const CellList& cells, const double* por,
                                    const double* vol) const {
  const std::size_t n = P.size();
  for (auto& a : grad_rho_) a.assign(n, 0.0);
  double *gx = grad_rho_[0].data(), *gy = grad_rho_[1].data(), *gz = grad_rho_[2].data();
  const Kind* kind = P.kind.data();
  const IndexRanges water = cells.ranges_of({Kind::Fluid});
#pragma omp parallel
  {
  Neighbors nb;
#pragma omp for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    if (kind[i] != Kind::Fluid) continue;
    const double ri = por ? P.rho[i] / por[i] : P.rho[i];
    Eigen::Matrix<double, Dim, Dim> M = Eigen::Matrix<double, Dim, Dim>::Zero();
    Eigen::Matrix<double, Dim, 1> G = Eigen::Matrix<double, Dim, 1>::Zero();
    cells.gather<Dim>(P, i, nb, water);
    for (std::size_t k = 0; k < nb.size(); ++k) {
      const std::uint32_t j = nb.j[k];
      if (kind[j] != Kind::Fluid) continue;
      const double fw = kernel.gradW_over_r(std::sqrt(nb.r2[k])), Vj = vol[j];
      const double rj = por ? P.rho[j] / por[j] : P.rho[j];
      const double r[3] = {nb.dx[k], nb.dy[k], Dim == 3 ? nb.dz[k] : 0.0};  // x_i - x_j
      for (int a = 0; a < Dim; ++a) {
        G(a) += Vj * (rj - ri) * fw * r[a];
        for (int b = 0; b < Dim; ++b) M(a, b) -= Vj * r[a] * fw * r[b];
      }
    }
    const Eigen::Matrix<double, Dim, 1> gr = std::abs(M.determinant()) > 1e-3 ? Eigen::Matrix<double, Dim, 1>(M.inverse() * G)
                                                                               : Eigen::Matrix<double, Dim, 1>::Zero();
    gx[i] = gr(0); gy[i] = gr(1);
    if constexpr (Dim == 3) gz[i] = gr(2);
  }
  }
}

// Continuity, delta-SPH and momentum in one neighbour pass: each fluid particle gathers its own sums
// (no scatter, so the result does not depend on the thread count).
template <int Dim, bool MixedSlip, bool Porous, bool Morris, class K>
void FluidForces::rates_with(const K& kernel, Particles& P, const CellList& cells, const std::array<double, 3>& g) const {
  const std::size_t n = P.size();
  const double h = scene_.h(), eta2 = 0.01 * h * h;
  // Laminar term regularisation: Morris et al. (1997) use eta^2 = 0.01 h^2, but with eta/h fixed
  // the factor r^2/(r^2 + eta^2) under-estimates the viscosity by ~1% at every resolution (measured
  // on the Poiseuille case: the error stalls at 1.0-1.4% of v_max). Pairs never come within 0.01 h
  // in WCSPH, so the smaller eta^2 = 1e-4 h^2 only guards against r = 0.
  const double eta2_lam = 1e-4 * h * h;
  const double* wvx = P.find(DummyWallFields::vx);  // no-slip walls only
  const std::int32_t* slip = P.find_int(BodyFields::wall_free_slip);  // per container, if they differ
  const double* wvy = P.find(DummyWallFields::vy);
  const double* wvz = P.find(DummyWallFields::vz);
  // Morris walls: each wall particle's depth behind the surface and the surface normal into the fluid
  const double* mdepth = Morris ? P.find(WallSurfaceFields::depth) : nullptr;
  const double* mnx = Morris ? P.find(BodyFields::wall_nx) : nullptr;
  const double* mny = Morris ? P.find(BodyFields::wall_ny) : nullptr;
  const double* mnz = Morris ? P.find(BodyFields::wall_nz) : nullptr;
  const double beta_max = scene_.walls.morris_beta_max;
  const double D = repulsive_D_, r0 = repulsive_r0_;
  const auto bf = scene_.body_force;
  // p/rho^2 and m/rho once per particle (fluid and extrapolated walls) instead of once per pair
  pressure_over_rho2_.resize(n);
  volume_.resize(n);
  drho_new_.resize(n);
  double* pr2 = pressure_over_rho2_.data();
  double* vol = volume_.data();
  double* drho_out = drho_new_.data();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    pr2[i] = P.p[i] / (P.rho[i] * P.rho[i]);
    vol[i] = P.m[i] / P.rho[i];
  }
  const double* por = Porous ? porosity(P) : nullptr;
  // drained sides (boundary/drained_face.hpp): the pore water crosses them with its own velocity
  const std::int32_t* drained = Porous ? P.find_int(DrainedFields::face) : nullptr;
  // pore water: delta-SPH less the linear part of the density field (Antuono et al. 2010), so that a
  // smooth pore-pressure profile is not diffused: plain or hydrostatic delta-SPH drained a consolidating
  // layer through the water's numerical diffusion, delta h c0, which rivals c_v = k M / gamma_w at low k
  const bool consistent = Porous && std::any_of(mats_.begin(), mats_.end(), [](const auto& m) { return m.density_diffusion > 0; });
  if (consistent) density_gradients<Dim>(kernel, P, cells, por, vol);
  const double *grx = grad_rho_[0].data(), *gry = grad_rho_[1].data(), *grz = grad_rho_[2].data();
  const Kind* kind = P.kind.data();
  const double *m = P.m.data(), *rho = P.rho.data(), *p = P.p.data();
  const double *vx = P.vx.data(), *vy = P.vy.data(), *vz = P.vz.data();

  // a.b in Dim dimensions (2D: the z terms are not computed at all)
  const auto dot = [](double ax, double ay, double az, double bx, double by, double bz) {
    if constexpr (Dim == 3) return ax * bx + ay * by + az * bz;
    else {
      (void)az; (void)bz;
      return ax * bx + ay * by;
    }
  };
  // pore water: the pairs with its skeleton are the coupling's (coupling/seepage.hpp), not read here
  const IndexRanges fluid_and_walls = cells.ranges_of({Kind::Fluid, Kind::DummyWall, Kind::RepulsiveWall});
#pragma omp parallel
  {
  Neighbors nb;
#pragma omp for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    if (kind[i] != Kind::Fluid) continue;
    const FluidMaterial& mi = mats_[P.material[i]];
    const double rhoi = rho[i], pi_r2 = pr2[i], pi = p[i];
    const double vxi = vx[i], vyi = vy[i], vzi = vz[i];
    const double alpha_c = mi.artificial_viscosity * mi.sound_speed;
    const double mu_i = rhoi * mi.kinematic_viscosity;
    const double delta_hc = mi.density_diffusion * h * mi.sound_speed;
    const double ni = Porous ? por[i] : 1.0;  // pore water: -n grad p / (n rho_w)
    const TaitEos& eos = eos_[P.material[i]];
    const bool hydrostatic = mi.density_diffusion_hydrostatic;
    const bool free_slip = free_slip_walls_;
    double drho = 0, ax = 0, ay = 0, az = 0;
    if constexpr (Porous) cells.gather<Dim>(P, i, nb, fluid_and_walls);
    else cells.gather<Dim>(P, i, nb);
    const std::size_t nn = nb.size();
    const double av_i = alpha_c * h;
    const bool diffusion = delta_hc > 0;
    for (std::size_t k = 0; k < nn; ++k) {
      const std::uint32_t j = nb.j[k];
      const double dx = nb.dx[k], dy = nb.dy[k], dz = Dim == 3 ? nb.dz[k] : 0.0, r2 = nb.r2[k];
      const Kind kj = kind[j];
      if (kj != Kind::Fluid && kj != Kind::DummyWall) {  // the skeleton acts through coupling/seepage
        if (kj == Kind::RepulsiveWall && r2 < r0 * r0 && r2 > 0) {
          const double s2 = r0 * r0 / r2, s4 = s2 * s2, s12 = s4 * s4 * s4;
          const double f = D * (s12 - s4) / r2;
          ax += f * dx; ay += f * dy; if constexpr (Dim == 3) az += f * dz;
        }
        continue;
      }
      // Coin-flip conditions (wall or fluid neighbour, approaching or receding pair) are selects, not
      // branches.
      const double fw = kernel.gradW_over_r(std::sqrt(r2));  // grad_i W_ij = fw * r_ij
      const double mj = m[j], rhoj = rho[j];
      const double ux = vxi - vx[j], uy = vyi - vy[j], uz = Dim == 3 ? vzi - vz[j] : 0.0;
      const bool wall = kj == Kind::DummyWall;
      const bool outlet = Porous && wall && drained && drained[j] > 0;
      const double inv_r2 = 1.0 / (r2 + eta2);
      // continuity (Monaghan 1992, eq. 4.7); walls enter with their own (prescribed) velocity, a drained
      // side with the water's (no term)
      drho += outlet ? 0.0 : mj * fw * dot(ux, uy, uz, dx, dy, dz);
      if (diffusion) {
        // delta-SPH between fluid particles (Molteni & Colagrossi 2009, eq. 14); pore water: on the
        // intrinsic density (rho/n), scaled back by n_i
        double d = rhoi - (Porous ? ni * rhoj / por[j] : rhoj);
        // hydrostatic pair difference rho^H_i - rho^H_j from p_i - p_j = rho0 g . r_ij through the Tait
        // equation (Fourtakas et al. 2019, eq. 17); pore water: the renormalised gradients' linear part,
        // rho_i - rho_j - (grad rho_i + grad rho_j) . r_ij / 2 (Antuono et al. 2010, eq. 6)
        if (consistent) d -= ni * 0.5 * dot(grx[i] + grx[j], gry[i] + gry[j], grz[i] + grz[j], dx, dy, dz);
        else if (hydrostatic) d -= ni * eos.hydrostatic_density_difference(dot(g[0], g[1], g[2], dx, dy, dz));
        const double diff = delta_hc * 2.0 * d * fw * r2 * inv_r2 * vol[j];
        drho += wall ? 0.0 : diff;
      }
      // pore water: its partial density n rho_w jumps where the porosity does (0.4 -> 1 at a soil surface
      // under free water); (p_i + p_j)/(rho_i rho_j) estimates grad p / rho_i without a rho-gradient error
      // (Colagrossi & Landrini 2003, J. Comput. Phys. 191, 448-475, for density jumps)
      double coef = Porous ? ni * mj * (pi + p[j]) / (rhoi * rhoj) : mj * (pi_r2 + pr2[j]);
      // free slip: no viscous interaction with the wall (Adami et al. 2012)
      const bool viscous = !(wall && (MixedSlip ? slip[j] != 0 : free_slip)) && !outlet;
      double wx, wy, wz;
      if constexpr (Morris) {
        // v_ij = beta (v_i - v_wall), beta = min(beta_max, 1 + d_b / d_i) with d_i the fluid particle's
        // distance to the wall particle's tangent plane (Morris, Fox & Zhu 1997)
        const double beta =
            wall ? morris_velocity_factor(dot(mnx[j], mny[j], mnz[j], dx, dy, dz) - mdepth[j], mdepth[j], beta_max)
                 : 1.0;
        wx = beta * ux; wy = beta * uy; wz = beta * uz;
      } else {
        const bool ghost_v = wall && wvx;  // no-slip walls: the extrapolated velocity
        wx = ghost_v ? vxi - wvx[j] : ux; wy = ghost_v ? vyi - wvy[j] : uy;
        wz = Dim == 3 && ghost_v ? vzi - wvz[j] : uz;
      }
      const double vr = std::min(dot(wx, wy, wz, dx, dy, dz), 0.0);  // approaching pairs only
      // m_j Pi_ij, Pi_ij = -alpha c0 h v_ij.r_ij / ((r^2 + eta^2) rho_ij)
      const double av = -mj * av_i * vr * inv_r2 * 2.0 / (rhoi + rhoj);
      coef += viscous ? av : 0.0;
      if (mu_i > 0) {
        const double mu_j = wall ? mu_i : rhoj * mats_[P.material[j]].kinematic_viscosity;
        const double lam = viscous ? mj * (mu_i + mu_j) * (fw * r2) / (rhoi * rhoj * (r2 + eta2_lam)) : 0.0;
        ax += lam * wx; ay += lam * wy; if constexpr (Dim == 3) az += lam * wz;
      }
      ax -= coef * fw * dx; ay -= coef * fw * dy; if constexpr (Dim == 3) az -= coef * fw * dz;
    }
    drho_out[i] = drho;
    P.ax[i] = ax + g[0] + bf[0];
    P.ay[i] = ay + g[1] + bf[1];
    P.az[i] = az + g[2] + bf[2];
  }
  }
}

}  // namespace geosph
