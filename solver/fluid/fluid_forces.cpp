#include "fluid/fluid_forces.hpp"

#include "boundary/body_fields.hpp"
#include "boundary/dummy_wall.hpp"
#include "coupling/seepage_fields.hpp"

#include <algorithm>
#include <cmath>

namespace geosph {

FluidForces::FluidForces(const Scene& scene) : scene_(scene), mats_(scene.materials) {
  for (const auto& m : mats_) eos_.emplace_back(m);
  free_slip_walls_ = scene.walls.slip == "free_slip";
  const double c0 = max_sound_speed();
  repulsive_D_ = scene.walls.repulsive_strength > 0 ? scene.walls.repulsive_strength : 0.05 * c0 * c0;
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

void FluidForces::continuity(Particles& P, const CellList& cells, const std::array<double, 3>& g) const {
  std::visit([&](const auto& k) { continuity_with(k, P, cells, g); }, make_kernel(scene_.kernel, scene_.dim, scene_.h()));
}

void FluidForces::momentum(Particles& P, const CellList& cells, const std::array<double, 3>& g) const {
  // walls whose slip differs per container read a per-particle flag; the common case keeps the pair
  // loop free of it (the flag lookup per wall pair cost 10% of a dam-break step)
  const bool mixed = P.find_int(BodyFields::wall_free_slip) != nullptr;
  std::visit([&](const auto& k) {
    if (mixed) momentum_with<true>(k, P, cells, g);
    else momentum_with<false>(k, P, cells, g);
  }, make_kernel(scene_.kernel, scene_.dim, scene_.h()));
}

template <class K>
void FluidForces::continuity_with(const K& kernel, Particles& P, const CellList& cells,
                                  const std::array<double, 3>& g) const {
  const std::size_t n = P.size();
  const double h = scene_.h(), eta2 = 0.01 * h * h;
  const double* por = porosity(P);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    if (P.kind[i] != Kind::Fluid) continue;
    const FluidMaterial& mi = mats_[P.material[i]];
    const double rhoi = P.rho[i], vxi = P.vx[i], vyi = P.vy[i], vzi = P.vz[i];
    const double delta_hc = mi.density_diffusion * h * mi.sound_speed;
    const double ni = por ? por[i] : 1.0;
    const TaitEos& eos = eos_[P.material[i]];
    const bool hydrostatic = mi.density_diffusion_hydrostatic;
    double drho = 0;
    cells.for_each_neighbor(P, i, [&](std::uint32_t j, double dx, double dy, double dz, double r2) {
      const Kind kj = P.kind[j];
      if (kj != Kind::Fluid && kj != Kind::DummyWall) return;  // the skeleton acts through coupling/seepage
      const double fw = kernel.gradW_over_r(std::sqrt(r2));  // grad_i W_ij = fw * r_ij
      const double mj = P.m[j];
      // walls enter with their own (prescribed) velocity, zero for fixed walls
      drho += mj * fw * ((vxi - P.vx[j]) * dx + (vyi - P.vy[j]) * dy + (vzi - P.vz[j]) * dz);
      // pore water: the diffusion acts on the intrinsic density (rho/n), scaled back by n_i
      if (kj == Kind::Fluid && delta_hc > 0) {
        double d = rhoi - (por ? ni * P.rho[j] / por[j] : P.rho[j]);
        // hydrostatic pair difference rho^H_i - rho^H_j from p_i - p_j = rho0 g . r_ij through the Tait
        // equation (Fourtakas et al. 2019, eq. 17)
        if (hydrostatic) d -= ni * eos.hydrostatic_density_difference(g[0] * dx + g[1] * dy + g[2] * dz);
        drho += delta_hc * 2.0 * d * fw * r2 / (r2 + eta2) * mj / P.rho[j];
      }
    });
    P.drho[i] = drho;
  }
}

template <bool MixedSlip, class K>
void FluidForces::momentum_with(const K& kernel, Particles& P, const CellList& cells,
                                const std::array<double, 3>& g) const {
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
  const double D = repulsive_D_, r0 = repulsive_r0_;
  const auto bf = scene_.body_force;
  // p/rho^2 once per particle (fluid and extrapolated walls) instead of once per pair
  pressure_over_rho2_.resize(n);
  double* pr2 = pressure_over_rho2_.data();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) pr2[i] = P.p[i] / (P.rho[i] * P.rho[i]);
  const double* por = porosity(P);

#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    if (P.kind[i] != Kind::Fluid) continue;
    const FluidMaterial& mi = mats_[P.material[i]];
    const double rhoi = P.rho[i], pi_r2 = pr2[i];
    const double vxi = P.vx[i], vyi = P.vy[i], vzi = P.vz[i];
    const double alpha_c = mi.artificial_viscosity * mi.sound_speed;
    const double mu_i = rhoi * mi.kinematic_viscosity;
    const double ni = por ? por[i] : 1.0;  // pore water: -n grad p / (n rho_w)
    double ax = 0, ay = 0, az = 0;
    cells.for_each_neighbor(P, i, [&](std::uint32_t j, double dx, double dy, double dz, double r2) {
      const Kind kj = P.kind[j];
      if (kj != Kind::Fluid && kj != Kind::DummyWall && kj != Kind::RepulsiveWall) return;
      if (kj == Kind::RepulsiveWall) {
        if (r2 < r0 * r0 && r2 > 0) {
          const double s2 = r0 * r0 / r2, s4 = s2 * s2, s12 = s4 * s4 * s4;
          const double f = D * (s12 - s4) / r2;
          ax += f * dx; ay += f * dy; az += f * dz;
        }
        return;
      }
      const double fw = kernel.gradW_over_r(std::sqrt(r2));  // grad_i W_ij = fw * r_ij
      const double gx = fw * dx, gy = fw * dy, gz = fw * dz;
      const double mj = P.m[j], rhoj = P.rho[j];
      const double ux = vxi - P.vx[j], uy = vyi - P.vy[j], uz = vzi - P.vz[j];
      // pore water: its partial density n rho_w jumps where the porosity does (0.4 -> 1 at a soil surface
      // under free water); (p_i + p_j)/(rho_i rho_j) estimates grad p / rho_i without a rho-gradient error
      // (Colagrossi & Landrini 2003, J. Comput. Phys. 191, 448-475, for density jumps)
      double coef = por ? ni * mj * (P.p[i] + P.p[j]) / (rhoi * rhoj) : mj * (pi_r2 + pr2[j]);
      const bool wall = kj == Kind::DummyWall;
      if (!(wall && (MixedSlip ? slip[j] != 0 : free_slip_walls_))) {  // free slip: no viscous interaction with the wall (Adami et al. 2012)
        double vx = ux, vy = uy, vz = uz;
        if (wall && wvx) { vx = vxi - wvx[j]; vy = vyi - wvy[j]; vz = vzi - wvz[j]; }
        const double vr = vx * dx + vy * dy + vz * dz;
        if (alpha_c > 0 && vr < 0) coef += mj * (-alpha_c * h * vr / (r2 + eta2)) / (0.5 * (rhoi + rhoj));  // m_j Pi_ij
        if (mu_i > 0) {
          const double mu_j = wall ? mu_i : rhoj * mats_[P.material[j]].kinematic_viscosity;
          const double lam = mj * (mu_i + mu_j) * (fw * r2) / (rhoi * rhoj * (r2 + eta2_lam));
          ax += lam * vx; ay += lam * vy; az += lam * vz;
        }
      }
      ax -= coef * gx; ay -= coef * gy; az -= coef * gz;
    });
    P.ax[i] = ax + g[0] + bf[0];
    P.ay[i] = ay + g[1] + bf[1];
    P.az[i] = az + g[2] + bf[2];
  }
}

}  // namespace geosph
