#include "analytical/sheet_pile_seepage.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <gsl/gsl_sf_ellint.h>

namespace geosph::reference {

namespace {

double modulus(double s_over_T) {
  if (!(s_over_T > 0 && s_over_T < 1)) throw std::invalid_argument("sheet pile: s/T must lie in (0, 1)");
  return std::sin(M_PI * s_over_T / 2.0);
}

double K(double k) { return gsl_sf_ellint_Kcomp(k, GSL_PREC_DOUBLE); }

// n = value / step as a whole number, or an error naming what is off the grid
int whole(double value, double step, const char* what) {
  const double n = value / step;
  if (std::abs(n - std::round(n)) > 1e-9 * std::max(1.0, n))
    throw std::invalid_argument(std::string("sheet pile Laplace solver: ") + what + " is not a whole number of grid cells");
  return static_cast<int>(std::lround(n));
}

}  // namespace

double ThinSheetPile::discharge_over_kH() const {
  const double k = modulus(s_over_T), kp = std::sqrt(1.0 - k * k);
  return K(kp) / (2.0 * K(k));
}

double ThinSheetPile::exit_gradient_at_face_times_T_over_H() const {
  const double k = modulus(s_over_T);
  return M_PI / (4.0 * k * K(k));
}

double ThinSheetPile::downstream_face_head(double depth_over_T) const {
  const double k = modulus(s_over_T);
  if (depth_over_T <= 0) return 0.0;
  const double sphi = std::min(1.0, std::sin(M_PI * depth_over_T / 2.0) / k);
  return gsl_sf_ellint_F(std::asin(sphi), k, GSL_PREC_DOUBLE) / (2.0 * K(k));
}

double ThinSheetPile::exit_gradient_times_T_over_H(double x_over_T) const {
  const double k = modulus(s_over_T);
  return M_PI / (2.0 * std::sqrt(2.0) * K(k) * std::sqrt(std::cosh(M_PI * x_over_T) - std::cos(M_PI * s_over_T)));
}

bool SheetPileLaplace::in_pile(int i, int j) const {
  const double x = -g_.W + (i + 0.5) * g_.grid, y = -g_.T + (j + 0.5) * g_.grid;
  return std::abs(x) < 0.5 * g_.t && y > -g_.s;
}

SheetPileLaplace::SheetPileLaplace(const SheetPileGeometry& g) : g_(g) {
  if (!(g.grid > 0 && g.T > 0 && g.W > 0.5 * g.t && g.s > 0 && g.s < g.T && g.t >= 0))
    throw std::invalid_argument("sheet pile Laplace solver: need 0 < s < T, 0 <= t < 2W, grid > 0");
  nx_ = 2 * whole(g.W, g.grid, "W");
  ny_ = whole(g.T, g.grid, "T");
  whole(g.s, g.grid, "s");
  whole(0.5 * g.t, g.grid, "t/2");
  const int n = nx_ * ny_;
  std::vector<int> idx(n, -1);
  int unknowns = 0;
  for (int j = 0; j < ny_; ++j)
    for (int i = 0; i < nx_; ++i)
      if (!in_pile(i, j)) idx[j * nx_ + i] = unknowns++;
  // a zero-thickness pile is a no-flow face on x = 0 above the toe
  const int mid = nx_ / 2;
  auto blocked = [&](int i0, int i1, int j) {
    return g.t == 0 && std::min(i0, i1) == mid - 1 && std::max(i0, i1) == mid && -g.T + (j + 0.5) * g.grid > -g.s;
  };
  std::vector<Eigen::Triplet<double>> a;
  Eigen::VectorXd b = Eigen::VectorXd::Zero(unknowns);
  for (int j = 0; j < ny_; ++j)
    for (int i = 0; i < nx_; ++i) {
      const int r = idx[j * nx_ + i];
      if (r < 0) continue;
      double diag = 0;
      auto link = [&](int i2, int j2) {  // unit conductance between neighbouring soil cells
        if (i2 < 0 || i2 >= nx_ || j2 < 0 || j2 >= ny_) return;
        const int c = idx[j2 * nx_ + i2];
        if (c < 0 || (j2 == j && blocked(i, i2, j))) return;
        diag += 1.0;
        a.emplace_back(r, c, -1.0);
      };
      link(i - 1, j); link(i + 1, j); link(i, j - 1); link(i, j + 1);
      if (j == ny_ - 1) {  // the ground surface, half a cell above: head H upstream, 0 downstream
        diag += 2.0;
        if (-g.W + (i + 0.5) * g.grid < 0) b[r] += 2.0;
      }
      a.emplace_back(r, r, diag);
    }
  Eigen::SparseMatrix<double> A(unknowns, unknowns);
  A.setFromTriplets(a.begin(), a.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
  if (solver.info() != Eigen::Success) throw std::runtime_error("sheet pile Laplace solver: factorisation failed");
  const Eigen::VectorXd h = solver.solve(b);
  h_.assign(n, NAN);
  for (int c = 0; c < n; ++c)
    if (idx[c] >= 0) h_[c] = h[idx[c]];
  for (int i = 0; i < nx_; ++i)  // outflow through the downstream surface (head 0 there)
    if (-g.W + (i + 0.5) * g.grid > 0 && idx[(ny_ - 1) * nx_ + i] >= 0) q_ += 2.0 * cell(i, ny_ - 1);
}

double SheetPileLaplace::head(double x, double y) const {
  const double fx = (x + g_.W) / g_.grid - 0.5, fy = (y + g_.T) / g_.grid - 0.5;
  const int i0 = static_cast<int>(std::floor(fx)), j0 = static_cast<int>(std::floor(fy));
  double sw = 0, sh = 0;
  for (int dj = 0; dj < 2; ++dj)
    for (int di = 0; di < 2; ++di) {
      const int i = std::clamp(i0 + di, 0, nx_ - 1), j = std::clamp(j0 + dj, 0, ny_ - 1);
      const double v = cell(i, j);
      if (std::isnan(v)) continue;  // inside the pile
      // never across a zero-thickness pile: only the cells on the point's side above the toe
      const double xc = -g_.W + (i + 0.5) * g_.grid, yc = -g_.T + (j + 0.5) * g_.grid;
      if (g_.t == 0 && yc > -g_.s && (xc < 0) != (x < 0)) continue;
      const double wx = di ? fx - i0 : 1.0 - (fx - i0), wy = dj ? fy - j0 : 1.0 - (fy - j0);
      const double w = std::clamp(wx, 0.0, 1.0) * std::clamp(wy, 0.0, 1.0) + 1e-12;
      sw += w;
      sh += w * v;
    }
  if (sw > 0) return sh / sw;
  // a point inside the pile's cells (an SPH particle a fraction of a spacing into the wall block):
  // the nearest soil cell on the point's side
  double best = 1e300, value = NAN;
  for (int j = 0; j < ny_; ++j)
    for (int i = 0; i < nx_; ++i) {
      const double v = cell(i, j), xc = -g_.W + (i + 0.5) * g_.grid, yc = -g_.T + (j + 0.5) * g_.grid;
      if (std::isnan(v) || (xc < 0) != (x < 0)) continue;
      const double d = (xc - x) * (xc - x) + (yc - y) * (yc - y);
      if (d < best) { best = d; value = v; }
    }
  return value;
}

}  // namespace geosph::reference
