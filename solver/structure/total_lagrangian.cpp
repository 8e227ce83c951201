#include "structure/total_lagrangian.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "boundary/body_fields.hpp"
#include "core/artificial_viscosity.hpp"
#include "core/kernels.hpp"
#include "io/json_fields.hpp"
#include "materials/linear_elastic.hpp"
#include "sim/stability.hpp"
#include "soil/soil_fields.hpp"

namespace geosph {

namespace {
using Mat = Eigen::Matrix3d;

std::array<double, 9> pack(const Mat& m) {
  return {m(0, 0), m(0, 1), m(0, 2), m(1, 0), m(1, 1), m(1, 2), m(2, 0), m(2, 1), m(2, 2)};
}
}  // namespace

bool TotalLagrangianSolids::wanted(const Scene& scene) {
  return std::any_of(scene.soils.begin(), scene.soils.end(), [](const SoilMaterial& m) { return m.total_lagrangian; });
}

TotalLagrangianSolids::TotalLagrangianSolids(const Scene& scene) : scene_(scene) {
  for (const SoilMaterial& m : scene.soils) {
    tl_.push_back(m.total_lagrangian ? 1 : 0);
    double lambda = 0, mu = 0;
    if (m.total_lagrangian) {
      const std::string where = scene.file + ": field 'materials." + m.name + ".formulation': total_lagrangian ";
      if (!m.is<materials::LinearElastic>())
        throw InputError(where + "is for the linear_elastic model (this material is " + m.model_name() + ")");
      if (m.artificial_stress > 0)
        throw InputError(where + "has no tensile instability: remove materials." + m.name + ".artificial_stress");
      if (m.kernel_gradient_correction)
        throw InputError(where + "always corrects the kernel gradient: remove materials." + m.name +
                         ".kernel_gradient_correction");
      if (m.artificial_viscosity_balsara)
        throw InputError(where + "has no artificial_viscosity_switch (remove it)");
      const auto& e = m.as<materials::LinearElastic>().elastic;
      mu = e.young / (2.0 * (1.0 + e.poisson));
      lambda = e.young * e.poisson / ((1.0 + e.poisson) * (1.0 - 2.0 * e.poisson));
    }
    lambda_.push_back(lambda);
    mu_.push_back(mu);
    c_.push_back(m.wave_speed());
  }
  for (int a = 0; a < scene.dim; ++a)
    if (scene.domain.periodic[a])
      throw InputError(scene.file + ": field 'domain.periodic': a total_lagrangian structure needs a domain "
                                    "without periodic axes (its bonds use plain distances)");
  bool updated = false, total = false;
  for (const auto& b : scene.bodies) {
    const auto it = std::find_if(scene.soils.begin(), scene.soils.end(),
                                 [&](const SoilMaterial& m) { return m.name == b.material; });
    if (it == scene.soils.end()) continue;
    if (!it->total_lagrangian) {
      if (b.structure && !b.motion.active) updated = true;
      continue;
    }
    if (!b.structure || b.motion.active)
      throw InputError(scene.file + ": field 'bodies' (material \"" + b.material +
                       "\"): a total_lagrangian material is for deformable structure bodies (\"structure\": true, "
                       "no prescribed motion)");
    total = true;
  }
  if (updated && total)
    throw InputError(scene.file + ": field 'materials': deformable structures are either all total_lagrangian or "
                                  "none (the two formulations do not share a continuum)");
}

void TotalLagrangianSolids::allocate(Particles& P) const {
  for (const char* f : TotalLagrangianFields::reference) P.add_field(f, TotalLagrangianFields::owner);
  P.add_int_field(TotalLagrangianFields::has_reference, TotalLagrangianFields::owner);
}

void TotalLagrangianSolids::build_bonds(Particles& P) const {
  const std::size_t n = P.size();
  double* X[3];
  for (int a = 0; a < 3; ++a) X[a] = P.field(TotalLagrangianFields::reference[a]).data();
  std::int32_t* has = P.int_field(TotalLagrangianFields::has_reference).data();
  list_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    if (P.kind[i] != Kind::Structure || !tl_[P.material[i]]) continue;
    if (!has[i]) {  // the start, or a body placed since: its reference configuration is where it is now
      X[0][i] = P.x[i]; X[1][i] = P.y[i]; X[2][i] = P.z[i];
      has[i] = 1;
    }
    list_.push_back(static_cast<std::uint32_t>(i));
  }
  ids_.assign(P.id.begin(), P.id.end());
  const std::size_t m = list_.size();
  const int dim = scene_.dim;
  const double support = scene_.support();
  // bin the reference positions in cells of the support: a bond's partner is in the 3^d cells around
  struct Cell { std::int64_t key; std::uint32_t k; };
  std::vector<Cell> cells(m);
  const auto coord = [&](double v) { return static_cast<std::int64_t>(std::floor(v / support)); };
  const auto key_of = [](std::int64_t cx, std::int64_t cy, std::int64_t cz) {
    return ((cx + (1 << 20)) << 42) | ((cy + (1 << 20)) << 21) | (cz + (1 << 20));
  };
  for (std::size_t k = 0; k < m; ++k) {
    const std::uint32_t i = list_[k];
    cells[k] = {key_of(coord(X[0][i]), coord(X[1][i]), dim == 3 ? coord(X[2][i]) : 0), static_cast<std::uint32_t>(k)};
  }
  std::sort(cells.begin(), cells.end(), [](const Cell& a, const Cell& b) { return a.key < b.key || (a.key == b.key && a.k < b.k); });
  const AnyKernel kernel = make_kernel(scene_.kernel, dim, scene_.h());
  const double h = scene_.h();
  start_.assign(m + 1, 0);
  bond_j_.clear();
  bond_c_.clear();
  bond_fw_.clear();
  V0_.resize(m);
  for (std::size_t k = 0; k < m; ++k) V0_[k] = P.m[list_[k]] / scene_.soils[P.material[list_[k]]].density;
  P_.resize(m);
  const int nq = dim == 2 ? 5 : 9;  // the quadratic basis' size
  const auto basis = [&](const double r[3], double* p) {  // p(X_j - X_i) / h: linear, then quadratic terms
    const double u = r[0] / h, w = r[1] / h, z = r[2] / h;
    if (dim == 2) { p[0] = u; p[1] = w; p[2] = u * u; p[3] = u * w; p[4] = w * w; }
    else { p[0] = u; p[1] = w; p[2] = z; p[3] = u * u; p[4] = w * w; p[5] = z * z; p[6] = u * w; p[7] = u * z; p[8] = w * z; }
  };
  for (std::size_t k = 0; k < m; ++k) {
    const std::uint32_t i = list_[k];
    const std::int64_t c[3] = {coord(X[0][i]), coord(X[1][i]), dim == 3 ? coord(X[2][i]) : 0};
    std::vector<std::uint32_t> partners;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = (dim == 3 ? -1 : 0); dz <= (dim == 3 ? 1 : 0); ++dz) {
          const std::int64_t key = key_of(c[0] + dx, c[1] + dy, c[2] + dz);
          auto it = std::lower_bound(cells.begin(), cells.end(), key, [](const Cell& a, std::int64_t v) { return a.key < v; });
          for (; it != cells.end() && it->key == key; ++it)
            if (it->k != k) partners.push_back(it->k);
        }
    std::sort(partners.begin(), partners.end());  // a fixed order: the sums do not depend on the binning
    // the bonds (X_j - X_i, weight V0_j W) and the two moment matrices: A (Bonet & Lok) and M (quadratic)
    struct Bond { std::uint32_t kj; double r[3]; double w, fw; };
    std::vector<Bond> bonds;
    Mat A = Mat::Zero();
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(nq, nq);
    double p[9];
    for (const std::uint32_t kj : partners) {
      const std::uint32_t j = list_[kj];
      Bond b{kj, {X[0][j] - X[0][i], X[1][j] - X[1][i], dim == 3 ? X[2][j] - X[2][i] : 0.0}, 0, 0};
      const double r0 = std::sqrt(b.r[0] * b.r[0] + b.r[1] * b.r[1] + b.r[2] * b.r[2]);
      if (r0 >= support) continue;
      std::visit([&](const auto& K) { b.w = V0_[kj] * K.W(r0); b.fw = K.gradW_over_r(r0); }, kernel);
      for (int a = 0; a < dim; ++a)  // (X_j - X_i) (x) grad0 W_ij, grad0 W_ij = fw (X_i - X_j)
        for (int e = 0; e < dim; ++e) A(a, e) -= V0_[kj] * b.r[a] * b.fw * b.r[e];
      basis(b.r, p);
      for (int a = 0; a < nq; ++a)
        for (int e = 0; e < nq; ++e) M(a, e) += b.w * p[a] * p[e];
      bonds.push_back(b);
    }
    // the gradient weights c_ij (F_i = sum_j (x_j - x_i) (x) c_ij): the quadratic fit's linear part where
    // the neighbourhood determines a quadratic, Bonet & Lok's first-order correction where it does not
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const auto& sv = svd.singularValues();
    const bool quadratic = sv(nq - 1) > 1e-8 * sv(0);
    Eigen::MatrixXd Minv;
    if (quadratic) Minv = svd.solve(Eigen::MatrixXd::Identity(nq, nq));
    for (int a = dim; a < 3; ++a) A(a, a) = 1.0;
    Mat Ainv;
    bool invertible = false;
    double det = 0;
    A.computeInverseAndDetWithCheck(Ainv, det, invertible, 1e-3);
    if (!quadratic && !invertible)
      throw InputError(scene_.file + ": field 'bodies': total_lagrangian structure particle " + std::to_string(P.id[i]) +
                       " at (" + std::to_string(P.x[i]) + ", " + std::to_string(P.y[i]) + ", " + std::to_string(P.z[i]) +
                       ") has too few bonds to span the plane or space (a member needs at least two particles across)");
    for (const Bond& b : bonds) {
      std::array<double, 3> cw{0, 0, 0};
      if (quadratic) {
        basis(b.r, p);
        for (int a = 0; a < dim; ++a) {
          double s = 0;
          for (int e = 0; e < nq; ++e) s += Minv(a, e) * p[e];
          cw[a] = b.w * s / h;
        }
      } else {
        const double gr[3] = {-b.fw * b.r[0], -b.fw * b.r[1], -b.fw * b.r[2]};
        for (int a = 0; a < dim; ++a)
          for (int e = 0; e < dim; ++e) cw[a] += V0_[b.kj] * Ainv(e, a) * gr[e];  // A^-T grad0 W
      }
      bond_j_.push_back(b.kj);
      bond_c_.push_back(cw);
      bond_fw_.push_back(b.fw);
    }
    start_[k + 1] = static_cast<std::uint32_t>(bond_j_.size());
  }
  // each bond's reverse (the bonds are symmetric: the same reference distance both ways)
  bond_rev_.assign(bond_j_.size(), 0);
  for (std::size_t k = 0; k < m; ++k)
    for (std::uint32_t b = start_[k]; b < start_[k + 1]; ++b) {
      const std::uint32_t kj = bond_j_[b];
      const auto first = bond_j_.begin() + start_[kj], last = bond_j_.begin() + start_[kj + 1];
      const auto it = std::lower_bound(first, last, static_cast<std::uint32_t>(k));
      bond_rev_[b] = static_cast<std::uint32_t>(it - bond_j_.begin());
    }
}

void TotalLagrangianSolids::forces(Particles& P, const std::array<double, 3>& g, long step, double time) const {
  bool same = ids_.size() == P.size();
  for (std::size_t i = 0; same && i < P.size(); ++i) same = ids_[i] == P.id[i];
  if (!same) build_bonds(P);
  if (scene_.dim == 2) forces_with<2>(P, g, step, time);
  else forces_with<3>(P, g, step, time);
}

template <int Dim>
void TotalLagrangianSolids::forces_with(Particles& P, const std::array<double, 3>& g, long step, double time) const {
  const std::size_t m = list_.size();
  double* sxx = P.field(SoilFields::xx).data();
  double* syy = P.field(SoilFields::yy).data();
  double* szz = P.field(SoilFields::zz).data();
  double* sxy = P.field(SoilFields::xy).data();
  double* sxz = Dim == 3 ? P.field(SoilFields::xz).data() : nullptr;
  double* syz = Dim == 3 ? P.field(SoilFields::yz).data() : nullptr;
  const double* x[3] = {P.x.data(), P.y.data(), P.z.data()};
  const double* v[3] = {P.vx.data(), P.vy.data(), P.vz.data()};
  long bad = -1;
  // 1. deformation gradient, stress, P A^-T
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < m; ++k) {
    const std::uint32_t i = list_[k];
    Mat F = Mat::Zero();
    for (std::uint32_t b = start_[k]; b < start_[k + 1]; ++b) {
      const std::uint32_t j = list_[bond_j_[b]];
      const auto& cw = bond_c_[b];
      for (int a = 0; a < Dim; ++a) {
        const double d = x[a][j] - x[a][i];
        for (int c = 0; c < Dim; ++c) F(a, c) += d * cw[c];
      }
    }
    for (int a = Dim; a < 3; ++a) F(a, a) = 1.0;
    const double J = F.determinant();
    const std::size_t mat = P.material[i];
    const Mat E = 0.5 * (F.transpose() * F - Mat::Identity());
    const Mat S = lambda_[mat] * E.trace() * Mat::Identity() + 2.0 * mu_[mat] * E;
    const Mat Pk = F * S;
    const Mat sigma = Pk * F.transpose() / J;
    if (!(J > 0) || !sigma.allFinite()) {
#pragma omp critical
      if (bad < 0 || static_cast<long>(i) < bad) bad = static_cast<long>(i);
      continue;
    }
    P_[k] = pack(V0_[k] * Pk);  // V0_i P_i
    sxx[i] = sigma(0, 0); syy[i] = sigma(1, 1); szz[i] = sigma(2, 2); sxy[i] = sigma(0, 1);
    if constexpr (Dim == 3) { sxz[i] = sigma(0, 2); syz[i] = sigma(1, 2); }
    P.p[i] = -sigma.trace() / 3.0;
    P.rho[i] = scene_.soils[mat].density / J;
    P.drho[i] = 0.0;
  }
  if (bad >= 0) {
    const auto i = static_cast<std::size_t>(bad);
    Diagnosis d;
    d.step = step; d.time = time; d.particle_id = P.id[i];
    d.x = P.x[i]; d.y = P.y[i]; d.z = P.z[i];
    d.quantity = "total Lagrangian structure: deformation gradient inverted (det F <= 0) or stress not finite";
    throw InstabilityError(d);
  }
  // 2. accelerations: the stress divergence over the reference bonds and the artificial viscosity
  const double h = scene_.h(), eta2 = 0.01 * h * h;
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < m; ++k) {
    const std::uint32_t i = list_[k];
    const std::size_t mat = P.material[i];
    const SoilMaterial& mi = scene_.soils[mat];
    const double alpha = mi.artificial_viscosity, beta = mi.artificial_viscosity_beta;
    const auto& Pi_ = P_[k];
    double f[3] = {0, 0, 0}, visc[3] = {0, 0, 0};
    for (std::uint32_t b = start_[k]; b < start_[k + 1]; ++b) {
      const std::uint32_t kj = bond_j_[b];
      const std::uint32_t j = list_[kj];
      const auto& Pj = P_[kj];
      const auto& ci = bond_c_[b];
      const auto& cj = bond_c_[bond_rev_[b]];
      for (int a = 0; a < Dim; ++a)  // -dE/dx_i: V0_i P_i c_ij - V0_j P_j c_ji
        for (int c = 0; c < Dim; ++c) f[a] += Pi_[3 * a + c] * ci[c] - Pj[3 * a + c] * cj[c];
      double r[3] = {0, 0, 0}, u[3] = {0, 0, 0};
      double vr = 0, r2 = 0;
      for (int a = 0; a < Dim; ++a) {
        r[a] = x[a][i] - x[a][j];
        u[a] = v[a][i] - v[a][j];
        vr += u[a] * r[a];
        r2 += r[a] * r[a];
      }
      if (vr < 0) {  // Monaghan's, core/artificial_viscosity.hpp
        const double cij = 0.5 * (c_[mat] + c_[P.material[j]]);
        const double Pi = monaghan_viscosity(h * vr, r2 + eta2, cij, alpha, beta, P.rho[i], P.rho[j]);
        for (int a = 0; a < Dim; ++a) visc[a] -= P.m[j] * Pi * bond_fw_[b] * r[a];
      }
    }
    const double inv_m = 1.0 / P.m[i];
    P.ax[i] = f[0] * inv_m + visc[0] + g[0] + scene_.body_force[0];
    P.ay[i] = f[1] * inv_m + visc[1] + g[1] + scene_.body_force[1];
    P.az[i] = Dim == 3 ? f[2] * inv_m + visc[2] + g[2] + scene_.body_force[2] : 0.0;
  }
}

}  // namespace geosph
