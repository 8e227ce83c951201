#include "coupling/seepage.hpp"

#include "boundary/body_fields.hpp"
#include "boundary/soil_wall.hpp"
#include "core/kernel_columns.hpp"
#include "core/pair_columns.hpp"

#include <algorithm>
#include <cmath>

#include "fluid/equation_of_state.hpp"

namespace geosph {

namespace {
// Water at 20 C: dynamic viscosity 1.002e-3 Pa s (CRC Handbook of Chemistry and Physics, "Viscosity of
// water"), used with grain_size when the fluid declares no kinematic viscosity.
constexpr double kWaterViscosity20C = 1.002e-3;
constexpr double kMinPorosity = 0.05;  // floor on the water's porosity (its intrinsic density is rho / n)
constexpr double kImmovable = 1e30;    // partner density standing for a held (fixed) skeleton
// where the pore-pressure force takes out its constant-pressure part (Seepage::apply_with): the water
// around the skeleton particle has a full kernel support (sum V W >= kFullSupport) and its porosity
// differs from the particle's by more than kJumpFrom (ramped to full at kJumpFull)
constexpr double kFullSupport = 0.95, kJumpFrom = 0.02, kJumpFull = 0.1;
}  // namespace

Seepage::Seepage(const Scene& scene) : scene_(scene) {
  const FluidMaterial& w = scene.materials.front();
  rho_w_ = w.density;
  // Hydraulic conductivity is defined with the unit weight of water; scenes without gravity (e.g. the
  // excess pore pressure of consolidation) use standard gravity 9.80665 m/s^2.
  const double g = std::sqrt(scene.gravity[0] * scene.gravity[0] + scene.gravity[1] * scene.gravity[1] +
                             scene.gravity[2] * scene.gravity[2]);
  gamma_w_ = rho_w_ * (g > 0 ? g : 9.80665);
  mu_w_ = w.kinematic_viscosity > 0 ? w.kinematic_viscosity * w.density : kWaterViscosity20C;
}

double Seepage::conductivity(std::size_t mat, double n) const {
  const SoilMaterial& m = scene_.soils[mat];
  n = std::clamp(n, 1e-3, 0.999);
  if (m.hydraulic_conductivity > 0) return m.hydraulic_conductivity * kozeny_carman(n) / kozeny_carman(m.porosity);
  return gamma_w_ / mu_w_ * m.grain_size * m.grain_size / 180.0 * kozeny_carman(n);
}

double Seepage::undrained_wave_speed(double soil_wave_speed) const {
  const double Kw = rho_w_ * scene_.materials.front().sound_speed * scene_.materials.front().sound_speed;
  double c2 = 0;
  for (const auto& m : scene_.soils) {
    if (!m.saturated()) continue;
    const double M = soil_wave_speed * soil_wave_speed * m.density;  // K + 4G/3 of the skeleton
    c2 = std::max(c2, (Kw / m.porosity + M) / (m.density + m.porosity * rho_w_));
  }
  return std::sqrt(c2);
}

void Seepage::allocate(Particles& P) const {
  P.add_field(SeepageFields::porosity, "seepage");
  P.add_field(SeepageFields::conductivity, "seepage");
  P.add_field(SeepageFields::drag_c, "seepage");
  P.add_field(SeepageFields::porosity_rate, "seepage");
  P.add_field(SeepageFields::other_phase_sum, "seepage");
  P.add_field(SeepageFields::skeleton_sum, "seepage");
  P.add_field(SeepageFields::gx, "seepage"); P.add_field(SeepageFields::gy, "seepage"); P.add_field(SeepageFields::gz, "seepage");
  P.add_field(SeepageFields::nx, "seepage"); P.add_field(SeepageFields::ny, "seepage"); P.add_field(SeepageFields::nz, "seepage");
  for (const char* f : {SeepageFields::partner_vx, SeepageFields::partner_vy, SeepageFields::partner_vz,
                        SeepageFields::partner_ax, SeepageFields::partner_ay, SeepageFields::partner_az,
                        SeepageFields::partner_rho})
    P.add_field(f, "seepage");
}

void Seepage::initialise(Particles& P, const CellList& cells) const {
  update_porosity(P, cells);
  std::visit([&](const auto& k) { interpolate_water_porosity(k, P, cells); },
             make_kernel(scene_.kernel, scene_.dim, scene_.h()));
  const double* n = P.field(SeepageFields::porosity).data();
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Fluid) continue;
    const double vol = P.m[i] / P.rho[i];  // built at the intrinsic density on the lattice
    P.rho[i] *= n[i];
    P.m[i] = P.rho[i] * vol;
  }
}

// V = m / rho of every particle, once per pass rather than once per pair (the same bits).
const double* Seepage::volumes(const Particles& P) const {
  const std::size_t n = P.size();
  volume_.resize(n);
  double* v = volume_.data();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) v[i] = P.m[i] / P.rho[i];
  return v;
}

void Seepage::update_porosity(Particles& P, const CellList& cells) const {
  std::visit([&](const auto& k) { porosity_with(k, P, cells); }, make_kernel(scene_.kernel, scene_.dim, scene_.h()));
}

template <class K>
void Seepage::porosity_with(const K& kernel, Particles& P, const CellList& cells) const {
  const std::size_t n = P.size();
  const bool flat = cells.dim() == 2;  // 2D: nb.dz is not written
  double* por = P.field(SeepageFields::porosity).data();
  double* cond = P.field(SeepageFields::conductivity).data();
  // skeleton: n = 1 - rho / rho_s
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (P.kind[i] != Kind::Soil) continue;
    const SoilMaterial& m = scene_.soils[P.material[i]];
    if (!m.saturated()) { por[i] = 0; cond[i] = 0; continue; }
    por[i] = std::clamp(1.0 - P.rho[i] / m.grain_density(), 0.0, 1.0);
    cond[i] = conductivity(P.material[i], por[i]);
  }
  // kernel sums of the other phase, sum_j V_j W_ij (the drag's pair normalisation)
  // and, at water particles, the skeleton's kernel-gradient sum G = sum_s V_s grad W (the pore-pressure force)
  double* S = P.field(SeepageFields::other_phase_sum).data();
  double* Sg = P.field(SeepageFields::skeleton_sum).data();
  double* G[3] = {P.field(SeepageFields::gx).data(), P.field(SeepageFields::gy).data(), P.field(SeepageFields::gz).data()};
  double* GN[3] = {P.field(SeepageFields::nx).data(), P.field(SeepageFields::ny).data(), P.field(SeepageFields::nz).data()};
  // walls bounding the skeleton count with the soil's ghost volume (boundary/soil_wall.hpp)
  const double* swm = P.find(SoilWallFields::m);
  const double* swrho = P.find(SoilWallFields::rho);
  const double* vol = volumes(P);
  // (the skeleton's own sum is taken in its pressure-force pass, apply_with, which reads the same
  // neighbours: a pass fewer)
  const IndexRanges for_water = cells.ranges_of({Kind::Fluid, Kind::Soil, Kind::DummyWall});
#pragma omp parallel
  {
  Neighbors nb;
  PairColumns cols;  // the kernel's values of each particle's neighbours (core/kernel_columns.hpp)
#pragma omp for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    if (P.kind[i] != Kind::Fluid) continue;
    double sum = 0, sg = 0, g[3] = {0, 0, 0}, gn[3] = {0, 0, 0};
    cells.gather_any_dim(P, i, nb, for_water);
    cols.reserve(nb.n, 2);
    double *Wq = cols.col(0), *fwq = cols.col(1);
    kernel_values_and_gradients(kernel, nb.r2.data(), nb.n, Wq, fwq);
    for (std::size_t q = 0; q < nb.n; ++q) {
      const std::uint32_t j = nb.j[q];
      const double dx = nb.dx[q], dy = nb.dy[q], dz = flat ? 0.0 : nb.dz[q];
      const Kind kj = P.kind[j];
      if (kj == Kind::Fluid) {  // the water's porosity gradient (as in porosity_rate_with)
        const double c = vol[j] * (por[j] - por[i]) * fwq[q];
        gn[0] += c * dx; gn[1] += c * dy; gn[2] += c * dz;
        continue;
      }
      const bool wall = kj == Kind::DummyWall;  // walls bound the skeleton too
      if (kj != Kind::Soil && !wall) continue;
      const double Vj = wall && swm ? swm[j] / swrho[j] : vol[j];
      const double fw = fwq[q], W = Wq[q];
      if (!wall) sum += Vj * W;
      sg += Vj * W; g[0] += Vj * fw * dx; g[1] += Vj * fw * dy; g[2] += Vj * fw * dz;
    }
    S[i] = sum;
    Sg[i] = sg;
    for (int a = 0; a < 3; ++a) { G[a][i] = g[a]; GN[a][i] = gn[a]; }
  }
  }
}

// t = 0 only: n_i = 1 - sum_s (1-n_s) V_s W_is / sum_w V_w W_iw (the water's own kernel sum, so that
// free water above soil has n -> 1 and wall/free-surface deficiencies cancel). Later the water's
// porosity follows its rate (porosity_rate): the interpolation itself ripples by ~0.5% as water moves
// across the skeleton's particle lattice, which the stiff pore pressure would turn into kPa of noise.
template <class K>
void Seepage::interpolate_water_porosity(const K& kernel, Particles& P, const CellList& cells) const {
  double* por = P.field(SeepageFields::porosity).data();
  const double W0 = kernel.W(0.0);
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Fluid) continue;
    double solid = 0, water = P.m[i] / P.rho[i] * W0;
    cells.for_each_neighbor(P, i, [&](std::uint32_t j, double, double, double, double r2) {
      const Kind kj = P.kind[j];
      if (kj == Kind::Fluid) water += P.m[j] / P.rho[j] * kernel.W(std::sqrt(r2));
      else if (kj == Kind::Soil) solid += (1.0 - por[j]) * P.m[j] / P.rho[j] * kernel.W(std::sqrt(r2));
    });
    por[i] = std::clamp(1.0 - solid / water, kMinPorosity, 1.0);
  }
}

void Seepage::porosity_rate(Particles& P, const CellList& cells) const {
  std::visit([&](const auto& k) { porosity_rate_with(k, P, cells); }, make_kernel(scene_.kernel, scene_.dim, scene_.h()));
}

// Following the water, n = 1 - phi changes as the skeleton deforms and as the water moves through a
// porosity gradient:  D^w n/Dt = (1 - n) div v_s + (v_w - v_s) . grad n   (from the skeleton's mass balance
// D^s n/Dt = (1 - n) div v_s with incompressible grains). div v_s = sum_s V_s (v_s - v~_s) . grad W and
// v~_s the Shepard-averaged skeleton velocity at the water particle; grad n = sum_w V_w (n_w - n_i) grad W
// over the water's own porosities (free water carries n = 1). Both vanish for uniform fields: no ripple.
template <class K>
void Seepage::porosity_rate_with(const K& kernel, Particles& P, const CellList& cells) const {
  const std::size_t n = P.size();
  const bool flat = cells.dim() == 2;  // 2D: nb.dz is not written
  const double* por = P.field(SeepageFields::porosity).data();
  double* dn = P.field(SeepageFields::porosity_rate).data();
  const double* vol = volumes(P);
#pragma omp parallel
  {
  Neighbors nb;
  PairColumns cols;  // the kernel's values of each particle's neighbours (core/kernel_columns.hpp)
#pragma omp for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    if (P.kind[i] != Kind::Fluid) continue;
    double sW = 0, sv[3] = {0, 0, 0}, dv[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, g[3] = {0, 0, 0};
    double gn[3] = {0, 0, 0};
    cells.gather_any_dim(P, i, nb);
    cols.reserve(nb.n, 2);
    double *Wq = cols.col(0), *fwq = cols.col(1);
    kernel_values_and_gradients(kernel, nb.r2.data(), nb.n, Wq, fwq);
    for (std::size_t q = 0; q < nb.n; ++q) {
      const std::uint32_t j = nb.j[q];
      const double dx = nb.dx[q], dy = nb.dy[q], dz = flat ? 0.0 : nb.dz[q];
      const Kind kj = P.kind[j];
      if (kj != Kind::Soil && kj != Kind::Fluid && kj != Kind::DummyWall) continue;  // walls: skeleton at rest
      const double Vj = vol[j], fw = fwq[q];
      const double gr[3] = {fw * dx, fw * dy, fw * dz};
      if (kj == Kind::Fluid) {
        for (int a = 0; a < 3; ++a) gn[a] += Vj * (por[j] - por[i]) * gr[a];
        continue;
      }
      const double W = Wq[q], v[3] = {P.vx[j], P.vy[j], P.vz[j]};
      sW += Vj * W;
      for (int a = 0; a < 3; ++a) {
        sv[a] += Vj * v[a] * W;
        g[a] += Vj * gr[a];
        for (int b = 0; b < 3; ++b) dv[a][b] += Vj * v[a] * gr[b];
      }
    }
    if (sW <= 0) { dn[i] = 0; continue; }
    const double vs[3] = {sv[0] / sW, sv[1] / sW, sv[2] / sW};
    const double div_vs = (dv[0][0] - vs[0] * g[0]) + (dv[1][1] - vs[1] * g[1]) + (dv[2][2] - vs[2] * g[2]);
    const double w[3] = {P.vx[i] - vs[0], P.vy[i] - vs[1], P.vz[i] - vs[2]};
    dn[i] = (1.0 - por[i]) * div_vs + w[0] * gn[0] + w[1] * gn[1] + w[2] * gn[2];
  }
  }
}

void Seepage::advance_porosity(Particles& P, double dt) const {
  double* por = P.field(SeepageFields::porosity).data();
  const double* dn = P.field(SeepageFields::porosity_rate).data();
  const std::size_t n = P.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i)
    if (P.kind[i] == Kind::Fluid) por[i] = std::clamp(por[i] + dt * dn[i], kMinPorosity, 1.0);
}

void Seepage::apply(Particles& P, const CellList& cells) const {
  std::visit([&](const auto& k) { apply_with(k, P, cells); }, make_kernel(scene_.kernel, scene_.dim, scene_.h()));
}

template <class K>
void Seepage::apply_with(const K& kernel, Particles& P, const CellList& cells) const {
  const std::size_t n = P.size();
  const bool flat = cells.dim() == 2;  // 2D: nb.dz is not written
  const double* por = P.field(SeepageFields::porosity).data();
  const double* cond = P.field(SeepageFields::conductivity).data();
  double* S = P.field(SeepageFields::other_phase_sum).data();  // the skeleton's are written here
  const double* G[3] = {P.field(SeepageFields::gx).data(), P.field(SeepageFields::gy).data(),
                        P.field(SeepageFields::gz).data()};
  const double* Sg = P.field(SeepageFields::skeleton_sum).data();
  const double* GN[3] = {P.field(SeepageFields::nx).data(), P.field(SeepageFields::ny).data(),
                         P.field(SeepageFields::nz).data()};
  double* C = P.field(SeepageFields::drag_c).data();
  double* pv[3] = {P.field(SeepageFields::partner_vx).data(), P.field(SeepageFields::partner_vy).data(),
                   P.field(SeepageFields::partner_vz).data()};
  double* pa[3] = {P.field(SeepageFields::partner_ax).data(), P.field(SeepageFields::partner_ay).data(),
                   P.field(SeepageFields::partner_az).data()};
  double* prho = P.field(SeepageFields::partner_rho).data();
  const double gw = gamma_w_;
  const std::int32_t* fixed = P.find_int(BodyFields::fixed);
  auto saturated = [&](std::size_t i) { return P.kind[i] == Kind::Soil && scene_.soils[P.material[i]].saturated(); };
  auto beta = [&](std::size_t s) { return por[s] * por[s] * gw / cond[s]; };  // n^2 gamma_w / k
  const double* vol = volumes(P);
  // 1. pore-pressure force on the skeleton: the adjoint of the water's porosity rate (1 - n) div v_s
  //    (porosity_rate_with), so that the pressure work on the skeleton equals the water's compression
  //    energy: F_i = -V_i sum_j V_j (1 - n_j) p_j (grad_i W_ij + W_ij G_j / S_j), G_j = sum_s V_s grad_j W_js,
  //    S_j = sum_s V_s W_js (walls bound the skeleton). In a uniform porosity this is -(1 - n) grad p;
  //    the simpler -(1 - n) grad p estimate with a Shepard-averaged p is not adjoint and let a loaded
  //    column's oscillation grow (measured on the consolidation column).
  //    That part alone is -grad((1 - n) p) = -(1 - n) grad p + p grad n: where the porosity changes (the
  //    soil surface under free water, n: 0.4 -> 1) it pulled the top of the skeleton up. The rate's
  //    advective term -v~_s . grad n, adjoint likewise, removes it: F_i += -V_i sum_j V_j p_j grad n_j W_ij / S_j
  //    (grad n_j over the water, update_porosity), so the total is -(1 - n) grad p (Biot's interphase force).
  //    A constant pressure must exert no force. In uniform soil the sums above ensure it (their geometric
  //    factor K_i = sum_j V_j [(1 - n_j)(grad W + W G_j/S_j) + W grad n_j / S_j] is a lattice ripple, the
  //    adjoint of the porosity rate's), but where the porosity jumps under free water their large terms,
  //    of order (1 - n) p, cancel in total and not row by row: under 0.5 m of water the top sand row
  //    carried 4.4 times its buoyant weight and the second 0.62 times (soil_under_free_water; the error
  //    grows with the water depth). There the force is taken relative to the Shepard-averaged pressure,
  //    F_i = -V_i (sum_j p_j B_ij - p~_i K_i), which leaves only the pressure's variation over the kernel:
  //    top row 1.10 times, second 0.95. It is applied only (a) where the water's porosity around i differs
  //    from n_i (the jump; in uniform soil the ripple must stay consistent with the porosity rate: with the
  //    correction everywhere the Terzaghi isochrone error rose from 0.013 to 0.068 at H/dx = 20) and
  //    (b) where the water has a full support (at a water free surface the missing neighbours stand for
  //    the drained p = 0, which the plain sums already express).
  //
  // 2. drag: each particle's rate C_i = sum_j c_ij and its partner phase's c-weighted velocity,
  //    acceleration (without drag) and partial density, for the implicit update in Simulation::kick.
  //    c_ij = beta V_j W_ij 2/(S_i + S_j) / rho_i, beta of the soil particle of the pair.
  //    beta of every particle once (0: not a saturated skeleton particle), not per pair: the pair loop
  //    was a quarter of the coupled step's time with the material lookup and division inside it.
  // The skeleton's drag sums share its pressure-force pass (their partners, the water, get no force in
  // it); the water's follow, as they read the skeleton's acceleration with the pressure force.
  beta_.resize(n);
  double* bs = beta_.data();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) bs[i] = saturated(i) ? beta(i) : 0.0;
  // the drag sums of particle i from its neighbour q with kernel value W, partner beta b
  struct DragSums {
    double c = 0, sv[3] = {0, 0, 0}, sa[3] = {0, 0, 0}, sr = 0;
  };
  const auto add_drag = [&](DragSums& d, std::uint32_t j, double b, double W, double Si, double rhoi) {
    const double cij = b * vol[j] * W * 2.0 / ((Si + S[j]) * rhoi);
    d.c += cij;
    d.sv[0] += cij * P.vx[j]; d.sv[1] += cij * P.vy[j]; d.sv[2] += cij * P.vz[j];
    if (fixed && fixed[j] > 0) {  // a held skeleton (a porous plate): an immovable partner
      d.sr += cij * kImmovable;
      return;
    }
    d.sa[0] += cij * P.ax[j]; d.sa[1] += cij * P.ay[j]; d.sa[2] += cij * P.az[j];
    d.sr += cij * P.rho[j];
  };
  const auto store_drag = [&](std::size_t i, const DragSums& d) {
    C[i] = d.c;
    if (d.c <= 0) return;
    for (int a = 0; a < 3; ++a) { pv[a][i] = d.sv[a] / d.c; pa[a][i] = d.sa[a] / d.c; }
    prho[i] = d.sr / d.c;
  };
  const IndexRanges water_and_walls = cells.ranges_of({Kind::Fluid, Kind::DummyWall});
  const IndexRanges skeleton = cells.ranges_of({Kind::Soil});
#pragma omp parallel
  {
  Neighbors nb;
  PairColumns cols;  // the kernel's values of each particle's neighbours (core/kernel_columns.hpp)
#pragma omp for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    C[i] = 0;
    if (P.kind[i] == Kind::Soil) S[i] = 0;
    if (!saturated(i)) continue;
    double fp[3] = {0, 0, 0}, k[3] = {0, 0, 0}, sp = 0, sw = 0, jump = 0;
    const double rhoi = P.rho[i], bi = bs[i];
    DragSums drag;
    cells.gather_any_dim(P, i, nb, water_and_walls);
    cols.reserve(nb.n, 2);
    double *Wq = cols.col(0), *fwq = cols.col(1);
    kernel_values_and_gradients(kernel, nb.r2.data(), nb.n, Wq, fwq);
    double Si = 0;  // the skeleton's kernel sum of the water (the drag's pair normalisation)
    for (std::size_t q = 0; q < nb.n; ++q)
      if (P.kind[nb.j[q]] == Kind::Fluid) Si += vol[nb.j[q]] * Wq[q];
    S[i] = Si;
    for (std::size_t q = 0; q < nb.n; ++q) {
      const std::uint32_t j = nb.j[q];
      const double dx = nb.dx[q], dy = nb.dy[q], dz = flat ? 0.0 : nb.dz[q];
      const Kind kj = P.kind[j];
      if (kj != Kind::Fluid && kj != Kind::DummyWall) continue;
      const double Vj = vol[j], W = Wq[q], fw = fwq[q];
      const double w_over_s = kj == Kind::Fluid && Sg[j] > 0 ? W / Sg[j] : 0.0;  // walls: no porosity rate
      const double phi = Vj * (1.0 - por[j]), vn = kj == Kind::Fluid ? Vj * w_over_s : 0.0;
      const double b[3] = {phi * (fw * dx + w_over_s * G[0][j]) + vn * GN[0][j],
                           phi * (fw * dy + w_over_s * G[1][j]) + vn * GN[1][j],
                           phi * (fw * dz + w_over_s * G[2][j]) + vn * GN[2][j]};
      for (int a = 0; a < 3; ++a) { fp[a] += P.p[j] * b[a]; k[a] += b[a]; }
      sp += Vj * W * P.p[j];
      sw += Vj * W;
      if (kj == Kind::Fluid) {
        jump = std::max(jump, std::abs(por[j] - por[i]));
        if (bi > 0) add_drag(drag, j, bi, W, Si, rhoi);
      }
    }
    const double gauge = std::clamp((jump - kJumpFrom) / (kJumpFull - kJumpFrom), 0.0, 1.0);
    const double p_ref = sw >= kFullSupport ? gauge * sp / sw : 0.0;
    P.ax[i] -= (fp[0] - p_ref * k[0]) / P.rho[i];
    P.ay[i] -= (fp[1] - p_ref * k[1]) / P.rho[i];
    P.az[i] -= (fp[2] - p_ref * k[2]) / P.rho[i];
    store_drag(i, drag);
  }
  }
#pragma omp parallel
  {
  Neighbors nb;
  PairColumns cols;  // the kernel's values of each particle's neighbours (core/kernel_columns.hpp)
#pragma omp for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    if (P.kind[i] != Kind::Fluid) continue;
    const double rhoi = P.rho[i], Si = S[i];
    DragSums drag;
    cells.gather_any_dim(P, i, nb, skeleton);
    cols.reserve(nb.n, 2);
    double *Wq = cols.col(0), *fwq = cols.col(1);
    kernel_values_and_gradients(kernel, nb.r2.data(), nb.n, Wq, fwq);
    for (std::size_t q = 0; q < nb.n; ++q) {
      const std::uint32_t j = nb.j[q];
      if (!(bs[j] > 0)) continue;  // saturated skeleton partners only
      add_drag(drag, j, bs[j], Wq[q], Si, rhoi);
    }
    store_drag(i, drag);
  }
  }
}

// Backward Euler for the pair (particle, its partner phase) over h: the mixture velocity takes the
// mass-weighted acceleration, the relative velocity w relaxes at lambda = C (1 + rho_i / rho_p):
//   w' = (w + h (a_i - a_p)) / (1 + h lambda),  v_i' = v_m + h a_m + rho_p / (rho_i + rho_p) w'.
// Unconditionally stable in the drag, and for stiff drag (low permeability) the pair moves as one
// body under the sum of its forces (a point-implicit v_i' = (v_i + h a_i + h C v_p)/(1 + h C) would
// lose the applied force's momentum: measured on an undrained column, the load did not reach the base).
void Seepage::kick(Particles& P, double h, const std::int32_t* fixed) const {
  const auto& f = P.extra_fields();
  const double* C = f.at(SeepageFields::drag_c).data();
  const double* prho = f.at(SeepageFields::partner_rho).data();
  const double* pv[3] = {f.at(SeepageFields::partner_vx).data(), f.at(SeepageFields::partner_vy).data(),
                         f.at(SeepageFields::partner_vz).data()};
  const double* pa[3] = {f.at(SeepageFields::partner_ax).data(), f.at(SeepageFields::partner_ay).data(),
                         f.at(SeepageFields::partner_az).data()};
  const std::size_t n = P.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (!(C[i] > 0) || !is_moving(P.kind[i]) || (fixed && fixed[i] > 0)) continue;
    const double rp = prho[i], ri = P.rho[i];
    const double lambda = C[i] * (1.0 + ri / rp), share = rp / (ri + rp);
    double* v[3] = {&P.vx[i], &P.vy[i], &P.vz[i]};
    const double a[3] = {P.ax[i], P.ay[i], P.az[i]};
    for (int d = 0; d < 3; ++d) {
      const double vp = pv[d][i], ap = pa[d][i];
      const double vm = (ri * *v[d] + rp * vp) / (ri + rp), am = (ri * a[d] + rp * ap) / (ri + rp);
      const double w = (*v[d] - vp + h * (a[d] - ap)) / (1.0 + h * lambda);
      *v[d] = vm + h * am + share * w;
    }
  }
}

}  // namespace geosph
