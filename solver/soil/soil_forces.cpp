#include "soil/soil_forces.hpp"
#include "core/artificial_viscosity.hpp"
#include "core/kernel_columns.hpp"
#include "core/pair_columns.hpp"
#include "soil/soil_mirror_images.hpp"
#include "soil/viscosity_switch.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <numbers>

#include "boundary/soil_wall.hpp"
#include "sim/stability.hpp"

namespace geosph {

namespace {

// Stress fields as raw pointers; xz and yz exist only in 3D.
struct StressView {
  double *xx, *yy, *zz, *xy, *xz, *yz;
  explicit StressView(Particles& P)
      : xx(P.field(SoilFields::xx).data()), yy(P.field(SoilFields::yy).data()), zz(P.field(SoilFields::zz).data()),
        xy(P.field(SoilFields::xy).data()), xz(P.dim == 3 ? P.field(SoilFields::xz).data() : nullptr),
        yz(P.dim == 3 ? P.field(SoilFields::yz).data() : nullptr) {}
  Eigen::Matrix3d get(std::size_t i) const {
    Eigen::Matrix3d s;
    const double sxz = xz ? xz[i] : 0.0, syz = yz ? yz[i] : 0.0;
    s << xx[i], xy[i], sxz, xy[i], yy[i], syz, sxz, syz, zz[i];
    return s;
  }
  void set(std::size_t i, const Eigen::Matrix3d& s) const {
    xx[i] = s(0, 0); yy[i] = s(1, 1); zz[i] = s(2, 2); xy[i] = s(0, 1);
    if (xz) { xz[i] = s(0, 2); yz[i] = s(1, 2); }
  }
};

// Pairs that share one SPH continuum: soil with soil and with dummy walls (which carry its ghost
// stress), a deformable structure with its own particles. Soil and structures meet only through
// contact forces (coupling/soil_structure_contact.hpp), rigid structures only through contact.
inline bool continuum_pair(Kind ki, Kind kj) {
  return ki == Kind::Soil ? (kj == Kind::Soil || kj == Kind::DummyWall) : kj == Kind::Structure;
}

constexpr int kMomentumColumns = 32;  // momentum_with's PairColumns

}  // namespace

SoilForces::SoilForces(const Scene& scene) : scene_(scene) {
  if (scene.walls.type == "mirror") mirror_ = std::make_shared<const MirrorWalls>(scene);
  for (std::size_t k = 0; k < scene.soils.size(); ++k)
    if (scene.corrects_stress_divergence(k)) stress_correction_ = true;
  for (const auto& m : scene.soils) {
    total_lagrangian_.push_back(m.total_lagrangian ? 1 : 0);
    wave_speed_.push_back(m.wave_speed());
    if (m.pressure_dependent()) has_pressure_dependent_ = true;
    else max_wave_speed_ = std::max(max_wave_speed_, m.wave_speed());
    if (m.artificial_viscosity_balsara) has_viscosity_switch_ = true;
    std::visit([&](const auto& model) {
      for (const char* f : model.state_fields) state_fields_.insert(f);
      if constexpr (requires { model.elastic; }) hooke_.push_back(materials::LinearElastic::with(model.elastic));
      else hooke_.emplace_back();
    }, m.model);
  }
}

void SoilForces::allocate(Particles& P) const {
  for (const char* f : {SoilFields::xx, SoilFields::yy, SoilFields::zz, SoilFields::xy, SoilFields::plastic_strain})
    P.add_field(f, SoilFields::owner);
  if (P.dim == 3) { P.add_field(SoilFields::xz, SoilFields::owner); P.add_field(SoilFields::yz, SoilFields::owner); }
  for (const auto& f : state_fields_) P.add_field(f, SoilFields::owner);
  if (stress_correction_)
    for (const char* f : SoilFields::correction) P.add_field(f, SoilFields::owner);
  if (has_pressure_dependent_) {
    P.add_field(SoilFields::wave_speed, SoilFields::owner);
    update_wave_speeds(P);
  }
  // a restart or a construction stage keeps the values already there (for the snapshots: the stress
  // update recomputes f before each momentum pass reads it)
  if (has_viscosity_switch_ && !P.has_field(SoilFields::viscosity_switch)) {
    auto& f = P.add_field(SoilFields::viscosity_switch, SoilFields::owner);
    std::fill(f.begin(), f.end(), 1.0);
  }
}

std::vector<materials::SolidState> SoilForces::bind_states(Particles& P) const {
  std::vector<materials::SolidState> states(scene_.soils.size());
  for (std::size_t k = 0; k < scene_.soils.size(); ++k) states[k] = scene_.soils[k].bind_state(P);
  return states;
}

void SoilForces::update_wave_speeds(Particles& P) const {
  double* c = P.field(SoilFields::wave_speed).data();
  double cmax = 0;
  const std::size_t n = P.size();
#pragma omp parallel for schedule(static) reduction(max : cmax)
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_solid(P.kind[i])) continue;
    const SoilMaterial& m = scene_.soils[P.material[i]];
    c[i] = std::visit([&](const auto& model) { return model.wave_speed(P.p[i], m.density); }, m.model);
    cmax = std::max(cmax, c[i]);
  }
  for (const auto& m : scene_.soils)
    if (!m.pressure_dependent()) cmax = std::max(cmax, m.wave_speed());
  max_wave_speed_ = cmax;
}

double SoilForces::max_wave_speed() const { return max_wave_speed_; }

void SoilForces::update_stress(Particles& P, const CellList& cells, double dt, long step, double time) const {
  std::visit([&](const auto& k) {
    if (scene_.dim == 2) update_stress_with<2>(k, P, cells, dt, step, time);
    else update_stress_with<3>(k, P, cells, dt, step, time);
  }, make_kernel(scene_.kernel, scene_.dim, scene_.h()));
}

void SoilForces::momentum(Particles& P, const CellList& cells, const std::array<double, 3>& g) const {
  std::visit([&](const auto& k) {
    if (scene_.dim == 2) momentum_with<2>(k, P, cells, g);
    else momentum_with<3>(k, P, cells, g);
  }, make_kernel(scene_.kernel, scene_.dim, scene_.h()));
}

// Dim: the dimension; in 2D the out-of-plane rows of L and B are zero and are not summed.
template <int Dim, class K>
void SoilForces::update_stress_with(const K& kernel, Particles& P, const CellList& cells, double dt, long step,
                                    double time) const {
  const std::size_t n = P.size();
  const StressView sv(P);
  double* eps_p = P.field(SoilFields::plastic_strain).data();
  gather_soil_view(P);
  const double* mass = mass_.data();
  const double* vol = volume_.data();
  std::vector<materials::SolidState> states = bind_states(P);
  for (auto& st : states) st.dt = dt;
  long bad = -1, unconverged = -1;
  double* bt[9] = {};  // B^-T - I for the stress divergence (stress_correction_)
  if (stress_correction_)
    for (int c = 0; c < 9; ++c) bt[c] = P.field(SoilFields::correction[c]).data();
  const Kind* kind = P.kind.data();
  const double *vx = P.vx.data(), *vy = P.vy.data(), *vz = P.vz.data();
  const double *gvx = ghost_vx_.data(), *gvy = ghost_vy_.data(), *gvz = ghost_vz_.data();
  const bool two_phase = scene_.two_phase();  // skip the pore water's part of the lists (continuum_pair)
  const IndexRanges skeleton_and_walls = cells.ranges_of({Kind::Soil, Kind::DummyWall});
  double* sw = has_viscosity_switch_ ? P.field(SoilFields::viscosity_switch).data() : nullptr;
  const double* cw_now = has_pressure_dependent_ ? P.field(SoilFields::wave_speed).data() : nullptr;
  const double h = scene_.h();
#pragma omp parallel
  {
  Neighbors nb;
  MirrorSet images;
  PairColumns cols;
#pragma omp for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    const Kind ki = kind[i];
    if (!is_solid(ki) || total_lagrangian_[P.material[i]]) continue;  // structure/total_lagrangian.hpp
    const bool correct = scene_.corrects_velocity_gradient(P.material[i]);
    const bool correct_stress = scene_.corrects_stress_divergence(P.material[i]);
    const double vxi = vx[i], vyi = vy[i], vzi = vz[i];
    double L[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, B[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    double drho = 0;
    if (two_phase && ki == Kind::Soil) cells.gather<Dim>(P, i, nb, skeleton_and_walls);
    else cells.gather<Dim>(P, i, nb);
    const std::size_t nn = nb.size();
    // the kernel gradients first, in a loop that vectorises (core/kernel_columns.hpp); the sums below are
    // cheap per pair and stay scalar (as columns they were slower: their gathering cost more than it saved)
    cols.reserve(nn, 1);
    double* fws = cols.col(0);
    kernel_gradients(kernel, nb.r2.data(), nn, fws);
    for (std::size_t k = 0; k < nn; ++k) {
      const std::uint32_t j = nb.j[k];
      const Kind kj = kind[j];
      if (!continuum_pair(ki, kj)) continue;
      const double dx = nb.dx[k], dy = nb.dy[k], dz = Dim == 3 ? nb.dz[k] : 0.0;
      const double fw = fws[k];
      const double grad[3] = {fw * dx, fw * dy, fw * dz};
      const double mj = mass[j], Vj = vol[j];
      // continuity with the wall's own (prescribed) velocity
      drho += mj * ((vxi - vx[j]) * grad[0] + (vyi - vy[j]) * grad[1] + (vzi - vz[j]) * grad[2]);
      // the velocity gradient with the walls' ghost velocity (boundary/soil_wall.cpp)
      const double dv[3] = {gvx[j] - vxi, gvy[j] - vyi, Dim == 3 ? gvz[j] - vzi : 0.0};
      for (int a = 0; a < Dim; ++a)
        for (int b = 0; b < Dim; ++b) L[a][b] += Vj * dv[a] * grad[b];
      if (correct) {
        const double rji[3] = {-dx, -dy, -dz};  // x_j - x_i
        for (int a = 0; a < Dim; ++a)
          for (int b = 0; b < Dim; ++b) B[a][b] += Vj * rji[a] * grad[b];
      }
    }
    if (mirror_ && ki == Kind::Soil)  // mirror walls: the same sums with the soil's images
      for_each_soil_image(*mirror_, images, P, cells, i, 0.5 * scene_.dx, [&](const MirrorImage& M, std::uint32_t j, const std::array<double, 3>& r,
                                                              const std::array<double, 3>&) {
        const double fw = kernel.gradW_over_r(std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]));
        const double grad[3] = {fw * r[0], fw * r[1], fw * r[2]};
        const auto vj = mirror_velocity(M, P, j);
        const double dv[3] = {vj[0] - vxi, vj[1] - vyi, Dim == 3 ? vj[2] - vzi : 0.0};
        // continuity with the mirrored velocity R v_j whatever the slip: the wall is impermeable, and a
        // no-slip wall's shear has no divergence (the reversed tangential velocity of a sliding front's
        // images behind it, with none ahead, read as an expansion that tore the toe of a collapse apart)
        const double vjm[3] = {P.vx[j], P.vy[j], P.vz[j]};
        const auto vm = M.rotate(vjm);
        const double cv[3] = {vm[0] - vxi, vm[1] - vyi, Dim == 3 ? vm[2] - vzi : 0.0};
        drho -= mass[j] * (cv[0] * grad[0] + cv[1] * grad[1] + cv[2] * grad[2]);
        for (int a = 0; a < Dim; ++a)
          for (int b = 0; b < Dim; ++b) {
            L[a][b] += vol[j] * dv[a] * grad[b];
            if (correct) B[a][b] -= vol[j] * r[a] * grad[b];
          }
      });
    if (correct) {
      // L <- L B^-1 on the in-plane block (B is the identity for a full, regular support)
      Eigen::Matrix3d Bm = Eigen::Matrix3d::Identity(), Lm = Eigen::Matrix3d::Zero();
      for (int a = 0; a < Dim; ++a)
        for (int b = 0; b < Dim; ++b) { Bm(a, b) = B[a][b]; Lm(a, b) = L[a][b]; }
      bool invertible = false;
      Eigen::Matrix3d Binv = Eigen::Matrix3d::Identity();  // set by the check where B is invertible
      double det = 0;
      Bm.computeInverseAndDetWithCheck(Binv, det, invertible, 1e-3);
      if (bt[0])
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b)
            bt[3 * a + b][i] = invertible && correct_stress ? Binv(b, a) - (a == b ? 1.0 : 0.0) : 0.0;
      if (invertible) {
        const Eigen::Matrix3d Lc = Lm * Binv;
        for (int a = 0; a < Dim; ++a)
          for (int b = 0; b < Dim; ++b) L[a][b] = Lc(a, b);
      }
    }
    P.drho[i] = drho;
    if (sw) {  // Balsara's switch from this velocity gradient
      if (scene_.soils[P.material[i]].artificial_viscosity_balsara)
        sw[i] = balsara_switch(L, cw_now ? cw_now[i] : wave_speed_[P.material[i]], h);
      else
        sw[i] = 1.0;
    }
    Eigen::Matrix3d de, dw;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        de(a, b) = 0.5 * dt * (L[a][b] + L[b][a]);
        dw(a, b) = 0.5 * dt * (L[a][b] - L[b][a]);
      }
    const auto mat = P.material[i];
    const materials::SolidUpdate r =
        elastic_only_ && hooke_[mat]  // the elastic mode: Hooke with the model's own E, nu
            ? hooke_[mat]->update(sv.get(i), de, dw, states[mat], i)
            : std::visit([&](const auto& model) { return model.update(sv.get(i), de, dw, states[mat], i); },
                         scene_.soils[mat].model);
    if (!r.converged) {
#pragma omp critical
      if (unconverged < 0 || static_cast<long>(i) < unconverged) unconverged = static_cast<long>(i);
      continue;
    }
    const Eigen::Matrix3d& stress = r.stress;
    const double eq_plastic = r.eq_plastic;
    if (!stress.allFinite()) {
#pragma omp critical
      if (bad < 0 || static_cast<long>(i) < bad) bad = static_cast<long>(i);
      continue;
    }
    sv.set(i, stress);
    eps_p[i] += eq_plastic;
    P.p[i] = -stress.trace() / 3.0;
  }
  }
  const auto diagnose = [&](long which, const std::string& what) {
    const auto i = static_cast<std::size_t>(which);
    Diagnosis d;
    d.step = step; d.time = time; d.particle_id = P.id[i];
    d.x = P.x[i]; d.y = P.y[i]; d.z = P.z[i];
    d.quantity = what;
    throw InstabilityError(d);
  };
  if (bad >= 0) diagnose(bad, "soil stress is not finite after the Jaumann update and return mapping");
  if (unconverged >= 0) {
    const auto i = static_cast<std::size_t>(unconverged);
    const SoilMaterial& m = scene_.soils[P.material[i]];
    diagnose(unconverged, std::visit([&](const auto& model) {
      return model.describe_failure(sv.get(i), states[P.material[i]], i);
    }, m.model));
  }
  if (has_pressure_dependent_) update_wave_speeds(P);
}

void SoilForces::gather_soil_view(const Particles& P) const {
  const std::size_t n = P.size();
  mass_.resize(n);
  rho_.resize(n);
  volume_.resize(n);
  ghost_vx_.resize(n);
  ghost_vy_.resize(n);
  ghost_vz_.resize(n);
  const double* wm = P.find(SoilWallFields::m);
  const double* wrho = P.find(SoilWallFields::rho);
  const double* wvx = P.find(SoilWallFields::vx);
  const double* wvy = P.find(SoilWallFields::vy);
  const double* wvz = P.find(SoilWallFields::vz);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const bool wall = P.kind[i] == Kind::DummyWall;
    const bool ghost = wm && wall, ghost_v = wvx && wall;
    mass_[i] = ghost ? wm[i] : P.m[i];
    rho_[i] = ghost ? wrho[i] : P.rho[i];
    volume_[i] = mass_[i] / rho_[i];
    ghost_vx_[i] = ghost_v ? wvx[i] : P.vx[i];
    ghost_vy_[i] = ghost_v ? wvy[i] : P.vy[i];
    ghost_vz_[i] = ghost_v ? wvz[i] : P.vz[i];
  }
}

void SoilForces::prepare_pair_terms(Particles& P) const {
  const std::size_t n = P.size();
  S_.resize(n);
  R_.resize(n);
  tension_.assign(n, 0);
  const StressView sv(P);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_solid(P.kind[i]) && P.kind[i] != Kind::DummyWall) continue;
    const Eigen::Matrix3d s = sv.get(i);
    const double inv_r2 = 1.0 / (rho_[i] * rho_[i]);
    S_[i] = {s(0, 0) * inv_r2, s(1, 1) * inv_r2, s(2, 2) * inv_r2, s(0, 1) * inv_r2, s(0, 2) * inv_r2, s(1, 2) * inv_r2};
    // Artificial stress (Gray, Monaghan & Swift 2001, eqs. 3.2-3.5): in the principal frame,
    // R'_a = -eps sigma'_a / rho^2 where sigma'_a > 0 (tension), else 0; rotated back.
    const std::size_t mat = is_solid(P.kind[i]) ? P.material[i] : 0;
    const double eps = scene_.soils[mat].artificial_stress;
    R_[i] = {0, 0, 0, 0, 0, 0};
    if (eps <= 0) continue;
    // no tension if every Gershgorin disc lies below zero (most of a soil body in compression): skip the
    // eigen-decomposition; the margin keeps a round-off-sized positive eigenvalue on the decomposition's side
    const double scale = std::abs(s(0, 0)) + std::abs(s(1, 1)) + std::abs(s(2, 2));
    const double margin = 1e-12 * scale;
    if (s(0, 0) + std::abs(s(0, 1)) + std::abs(s(0, 2)) < -margin &&
        s(1, 1) + std::abs(s(0, 1)) + std::abs(s(1, 2)) < -margin &&
        s(2, 2) + std::abs(s(0, 2)) + std::abs(s(1, 2)) < -margin)
      continue;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
    es.computeDirect(s);
    Eigen::Vector3d rp = Eigen::Vector3d::Zero();
    bool any = false;
    for (int a = 0; a < 3; ++a)
      if (es.eigenvalues()(a) > 0) { rp(a) = -eps * es.eigenvalues()(a) * inv_r2; any = true; }
    if (!any) continue;
    const Eigen::Matrix3d R = es.eigenvectors() * rp.asDiagonal() * es.eigenvectors().transpose();
    R_[i] = {R(0, 0), R(1, 1), R(2, 2), R(0, 1), R(0, 2), R(1, 2)};
    tension_[i] = 1;
  }
}

template <int Dim, class K>
void SoilForces::momentum_with(const K& kernel, Particles& P, const CellList& cells,
                               const std::array<double, 3>& g) const {
  const std::size_t n = P.size();
  const double h = scene_.h(), eta2 = 0.01 * h * h;
  const double w_dx = kernel.W(scene_.dx);
  gather_soil_view(P);
  prepare_pair_terms(P);
  const double* mass = mass_.data();
  const double* dens = rho_.data();
  const double* cw = has_pressure_dependent_ ? P.field(SoilFields::wave_speed).data() : nullptr;
  const Kind* kind = P.kind.data();
  const double *gvx = ghost_vx_.data(), *gvy = ghost_vy_.data(), *gvz = ghost_vz_.data();
  const auto* S = S_.data();
  const auto* R = R_.data();
  const std::uint8_t* tension = tension_.data();
  // numerics.kernel_gradient_correction_stress (or a material's kernel_gradient_correction): each side's
  // stress with its own corrected gradient (B^-T - I zero on the sides that are not corrected)
  const double* bt[9] = {};
  if (stress_correction_)
    for (int c = 0; c < 9; ++c) bt[c] = P.field(SoilFields::correction[c]).data();
  const bool two_phase = scene_.two_phase();  // skip the pore water's part of the lists (continuum_pair)
  const IndexRanges skeleton_and_walls = cells.ranges_of({Kind::Soil, Kind::DummyWall});
  const double* sw = has_viscosity_switch_ ? P.field(SoilFields::viscosity_switch).data() : nullptr;
#pragma omp parallel
  {
  Neighbors nb;
  MirrorSet images;
  PairColumns cols;
  std::vector<double> ones;
#pragma omp for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    const Kind ki = kind[i];
    if (!is_solid(ki) || total_lagrangian_[P.material[i]]) continue;  // structure/total_lagrangian.hpp
    const SoilMaterial& mi = scene_.soils[P.material[i]];
    const double rhoi = P.rho[i], vxi = P.vx[i], vyi = P.vy[i], vzi = P.vz[i];
    const double ci = cw ? cw[i] : wave_speed_[P.material[i]];
    const double alpha = mi.artificial_viscosity, beta = mi.artificial_viscosity_beta;
    const double n_as = mi.artificial_stress_exponent;
    const bool n_is_4 = n_as == 4.0;
    const bool use_as = mi.artificial_stress > 0;
    const std::uint8_t tension_i = tension[i];
    const auto& Si = S[i];
    const auto& Ri = R[i];
    double ax = 0, ay = 0, az = 0;
    if (two_phase && ki == Kind::Soil) cells.gather<Dim>(P, i, nb, skeleton_and_walls);
    else cells.gather<Dim>(P, i, nb);
    const std::size_t nn = nb.size();
    cols.reserve(nn, kMomentumColumns);
    // 1. the neighbours' values into columns (the scattered reads, once); a pair outside the continuum
    //    gets zero mass, stress and velocity, so that its term below is zero
    double* __restrict m = cols.col(0);
    double* __restrict rho = cols.col(1);
    double* __restrict sj[6] = {cols.col(2), cols.col(3), cols.col(4), cols.col(5), cols.col(6), cols.col(7)};
    double* __restrict u[3] = {cols.col(8), cols.col(9), cols.col(10)};
    double* __restrict cij = cols.col(11);
    double* __restrict swij = cols.col(12);
    double* __restrict rsum[6] = {cols.col(13), cols.col(14), cols.col(15), cols.col(16), cols.col(17), cols.col(18)};
    double* __restrict fas = cols.col(19);
    double* __restrict bj[9] = {cols.col(20), cols.col(21), cols.col(22), cols.col(23), cols.col(24),
                                cols.col(25), cols.col(26), cols.col(27), cols.col(28)};
    double* __restrict out[3] = {cols.col(29), cols.col(30), cols.col(31)};
    const double swi = sw ? sw[i] : 1.0;
    for (std::size_t k = 0; k < nn; ++k) {
      const std::uint32_t j = nb.j[k];
      const bool keep = continuum_pair(ki, kind[j]);
      m[k] = keep ? mass[j] : 0.0;
      rho[k] = keep ? dens[j] : rhoi;
      const auto& Sj = S[j];
      sj[0][k] = keep ? Sj[0] : 0.0; sj[1][k] = keep ? Sj[1] : 0.0; sj[3][k] = keep ? Sj[3] : 0.0;
      if constexpr (Dim == 3) { sj[2][k] = keep ? Sj[2] : 0.0; sj[4][k] = keep ? Sj[4] : 0.0; sj[5][k] = keep ? Sj[5] : 0.0; }
      u[0][k] = keep ? vxi - gvx[j] : 0.0;  // walls with the soil's ghost velocity
      u[1][k] = keep ? vyi - gvy[j] : 0.0;
      if constexpr (Dim == 3) u[2][k] = keep ? vzi - gvz[j] : 0.0;
    }
    // the optional terms' columns; without them the pair terms read ones (an exact factor 1)
    if (ones.size() < nn) ones.resize(nn, 1.0);
    const double* cc = ones.data();
    double cs = ci;  // c_ij = cs * cc[k]
    if (cw) {
      for (std::size_t k = 0; k < nn; ++k) {
        const std::uint32_t j = nb.j[k];
        const Kind kj = kind[j];
        cij[k] = continuum_pair(ki, kj) && kj != Kind::DummyWall ? 0.5 * (ci + cw[j]) : ci;
      }
      cc = cij;
      cs = 1.0;
    }
    const double* swp = ones.data();
    if (sw) {
      for (std::size_t k = 0; k < nn; ++k) {
        const std::uint32_t j = nb.j[k];
        const Kind kj = kind[j];  // a wall pair: i's own switch
        swij[k] = 0.5 * (swi + (kj == Kind::DummyWall || !continuum_pair(ki, kj) ? swi : sw[j]));
      }
      swp = swij;
    }
    if (use_as)
      for (std::size_t k = 0; k < nn; ++k) {  // R_i + R_j = 0 for a pair with neither in tension
        const std::uint32_t j = nb.j[k];
        const bool t = continuum_pair(ki, kind[j]) && (tension_i | tension[j]);
        for (int c = 0; c < 6; ++c) rsum[c][k] = t ? Ri[c] + R[j][c] : 0.0;
        if (!n_is_4) fas[k] = std::pow(kernel.W(std::sqrt(nb.r2[k])) / w_dx, n_as);
      }
    if (bt[0])
      for (std::size_t k = 0; k < nn; ++k) {
        const std::uint32_t j = nb.j[k];
        const bool keep = continuum_pair(ki, kind[j]);
        for (int c = 0; c < 9; ++c) bj[c][k] = keep ? bt[c][j] : 0.0;
      }
    // 2. the pair terms over the columns
    const auto pair_terms = [&]<bool AS, bool Corr>() {
      const double* __restrict ndx = nb.dx.data();
      const double* __restrict ndy = nb.dy.data();
      const double* __restrict ndz = Dim == 3 ? nb.dz.data() : nb.dx.data();
      const double* __restrict nr2 = nb.r2.data();
      double bti[9] = {};  // B_i^-T - I
      if constexpr (Corr)
        for (int c = 0; c < 9; ++c) bti[c] = bt[c][i];
      const double Ixx = Si[0], Iyy = Si[1], Izz = Si[2], Ixy = Si[3], Ixz = Si[4], Iyz = Si[5];
#pragma omp simd
      for (std::size_t k = 0; k < nn; ++k) {
        const double dx = ndx[k], dy = ndy[k], dz = Dim == 3 ? ndz[k] : 0.0, r2 = nr2[k];
        const double r = std::sqrt(r2);
        const double fw = kernel.gradW_over_r_inside(r);
        const double gx = fw * dx, gy = fw * dy, gz = fw * dz;
        const double mj = m[k];
        const double Jxx = sj[0][k], Jyy = sj[1][k], Jxy = sj[3][k];
        const double Jzz = Dim == 3 ? sj[2][k] : 0.0, Jxz = Dim == 3 ? sj[4][k] : 0.0, Jyz = Dim == 3 ? sj[5][k] : 0.0;
        // T = S_i + S_j (+ artificial stress) - Pi I
        double Txx = Ixx + Jxx, Tyy = Iyy + Jyy, Txy = Ixy + Jxy, Tzz = 0, Txz = 0, Tyz = 0;
        if constexpr (Dim == 3) { Tzz = Izz + Jzz; Txz = Ixz + Jxz; Tyz = Iyz + Jyz; }
        if constexpr (AS) {
          double f;
          if (n_is_4) {
            const double ratio = kernel.W_inside(r) / w_dx;
            f = (ratio * ratio) * (ratio * ratio);
          } else {
            f = fas[k];
          }
          Txx += f * rsum[0][k]; Tyy += f * rsum[1][k]; Txy += f * rsum[3][k];
          if constexpr (Dim == 3) { Tzz += f * rsum[2][k]; Txz += f * rsum[4][k]; Tyz += f * rsum[5][k]; }
        }
        // Monaghan's artificial viscosity for approaching pairs (core/artificial_viscosity.hpp)
        const double ux = u[0][k], uy = u[1][k], uz = Dim == 3 ? u[2][k] : 0.0;
        const double vr = std::min(Dim == 3 ? ux * dx + uy * dy + uz * dz : ux * dx + uy * dy, 0.0);
        const double d = r2 + eta2, hvr = h * vr;
        const double c = cs * cc[k];
        double Pi = monaghan_viscosity(hvr, d, c, alpha, beta, rhoi, rho[k]);
        Pi *= swp[k];
        Txx -= Pi; Tyy -= Pi;
        if constexpr (Dim == 3) Tzz -= Pi;
        if constexpr (Corr) {
          // (S_i B_i^-T + S_j B_j^-T) . grad W: the stresses with the corrected gradients (Bonet & Lok 1999,
          // eq. 22, on each side; antisymmetric in the pair, so linear momentum is kept); viscosity and
          // artificial stress with the plain gradient
          const double g0[3] = {gx, gy, gz};
          double gi[3], gj[3];
          for (int a = 0; a < 3; ++a) {
            gi[a] = g0[a];
            gj[a] = g0[a];
            for (int b = 0; b < Dim; ++b) {
              gi[a] += bti[3 * a + b] * g0[b];
              gj[a] += bj[3 * a + b][k] * g0[b];
            }
          }
          const double rxx = Txx - Ixx - Jxx, ryy = Tyy - Iyy - Jyy, rxy = Txy - Ixy - Jxy;  // the rest of T
          if constexpr (Dim == 3) {
            const double rzz = Tzz - Izz - Jzz, rxz = Txz - Ixz - Jxz, ryz = Tyz - Iyz - Jyz;
            out[0][k] = mj * (Ixx * gi[0] + Ixy * gi[1] + Ixz * gi[2] + Jxx * gj[0] + Jxy * gj[1] + Jxz * gj[2] +
                              rxx * gx + rxy * gy + rxz * gz);
            out[1][k] = mj * (Ixy * gi[0] + Iyy * gi[1] + Iyz * gi[2] + Jxy * gj[0] + Jyy * gj[1] + Jyz * gj[2] +
                              rxy * gx + ryy * gy + ryz * gz);
            out[2][k] = mj * (Ixz * gi[0] + Iyz * gi[1] + Izz * gi[2] + Jxz * gj[0] + Jyz * gj[1] + Jzz * gj[2] +
                              rxz * gx + ryz * gy + rzz * gz);
          } else {
            out[0][k] = mj * (Ixx * gi[0] + Ixy * gi[1] + Jxx * gj[0] + Jxy * gj[1] + rxx * gx + rxy * gy);
            out[1][k] = mj * (Ixy * gi[0] + Iyy * gi[1] + Jxy * gj[0] + Jyy * gj[1] + rxy * gx + ryy * gy);
          }
        } else if constexpr (Dim == 3) {  // (T . grad W)_a with T symmetric
          out[0][k] = mj * (Txx * gx + Txy * gy + Txz * gz);
          out[1][k] = mj * (Txy * gx + Tyy * gy + Tyz * gz);
          out[2][k] = mj * (Txz * gx + Tyz * gy + Tzz * gz);
        } else {
          out[0][k] = mj * (Txx * gx + Txy * gy);
          out[1][k] = mj * (Txy * gx + Tyy * gy);
        }
      }
    };
    if (use_as && bt[0]) pair_terms.template operator()<true, true>();
    else if (use_as) pair_terms.template operator()<true, false>();
    else if (bt[0]) pair_terms.template operator()<false, true>();
    else pair_terms.template operator()<false, false>();
    // 3. the sums, in neighbour order
    for (std::size_t k = 0; k < nn; ++k) {
      ax += out[0][k];
      ay += out[1][k];
      if constexpr (Dim == 3) az += out[2][k];
    }
    if (mirror_ && ki == Kind::Soil)  // mirror walls: the images' stress, artificial stress and viscosity
      for_each_soil_image(*mirror_, images, P, cells, i, 0.5 * scene_.dx, [&](const MirrorImage& M, std::uint32_t j, const std::array<double, 3>& r,
                                                              const std::array<double, 3>& step) {
        const double rr = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
        const double fw = kernel.gradW_over_r(rr);
        const double grad[3] = {fw * r[0], fw * r[1], fw * r[2]};
        const double mj = mass[j], rhoj = dens[j];
        auto Sj = mirror_tensor(M, S[j]);
        // the hydrostatic step: sigma' = sigma - rho g . (x_j' - x_j) I
        const double ds = rhoj * (g[0] * step[0] + g[1] * step[1] + g[2] * step[2]) / (rhoj * rhoj);
        Sj[0] -= ds; Sj[1] -= ds; Sj[2] -= ds;
        std::array<double, 6> Tm;
        for (int c = 0; c < 6; ++c) Tm[c] = Si[c] + Sj[c];
        if (use_as && (tension_i | tension[j])) {
          const double f = std::pow(kernel.W(rr) / w_dx, n_as);
          const auto Rj = mirror_tensor(M, R[j]);
          for (int c = 0; c < 6; ++c) Tm[c] += f * (Ri[c] + Rj[c]);
        }
        const auto vj = mirror_velocity(M, P, j);
        const double u[3] = {vxi - vj[0], vyi - vj[1], Dim == 3 ? vzi - vj[2] : 0.0};
        const double vr = std::min(u[0] * r[0] + u[1] * r[1] + u[2] * r[2], 0.0);
        const double d = rr * rr + eta2, hvr = h * vr;
        const double cij = cw ? 0.5 * (ci + cw[j]) : ci;
        double Pi = monaghan_viscosity(hvr, d, cij, alpha, beta, rhoi, rhoj);
        if (sw) Pi *= 0.5 * (sw[i] + sw[j]);
        Tm[0] -= Pi; Tm[1] -= Pi; Tm[2] -= Pi;
        ax += mj * (Tm[0] * grad[0] + Tm[3] * grad[1] + Tm[4] * grad[2]);
        ay += mj * (Tm[3] * grad[0] + Tm[1] * grad[1] + Tm[5] * grad[2]);
        if constexpr (Dim == 3) az += mj * (Tm[4] * grad[0] + Tm[5] * grad[1] + Tm[2] * grad[2]);
      });
    P.ax[i] = ax + g[0] + scene_.body_force[0];
    P.ay[i] = ay + g[1] + scene_.body_force[1];
    P.az[i] = az + g[2] + scene_.body_force[2];
  }
  }
}

}  // namespace geosph
