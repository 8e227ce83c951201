#include "harness/element_test.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace geosph::verify {

namespace {

using Matrix3d = Eigen::Matrix3d;

Matrix3d diag(double xx, double yy, double zz) { return Eigen::Vector3d(xx, yy, zz).asDiagonal(); }

void record(TriaxialPath& run, const soil::ModifiedCamClay::Result& r, double ea, double ev, int k, int every) {
  run.converged = run.converged && r.converged;
  run.max_iterations = std::max(run.max_iterations, r.iterations);
  if (r.plastic) ++run.plastic_steps;
  if (k % every != 0) return;
  run.eps_a.push_back(ea);
  run.eps_v.push_back(ev);
  run.p.push_back(soil::ModifiedCamClay::mean_effective_stress(r.stress));
  run.q.push_back(soil::ModifiedCamClay::deviator_stress(r.stress));
  run.plastic.push_back(r.plastic);
}

}  // namespace

TriaxialPath mcc_drained_triaxial_run(const soil::ModifiedCamClay& model, double p0, double ocr, double d,
                                      double eps_end, double out_every) {
  Matrix3d s = -p0 * Matrix3d::Identity();
  double pc = ocr * p0;
  const double target = -p0;
  double ea = 0, ev = 0, er_guess = model.params().poisson * d;  // elastic guess: d eps_r = -nu d eps_a
  TriaxialPath run;
  const int n = static_cast<int>(std::lround(eps_end / d));
  const int every = std::max(1, static_cast<int>(std::lround(out_every / d)));
  for (int k = 1; k <= n; ++k) {
    auto step = [&](double er) { return model.update(s, pc, diag(-d, er, er), Matrix3d::Zero()); };
    double er = er_guess;
    auto r = step(er);
    for (int it = 0; it < 60 && std::abs(r.stress(1, 1) - target) > 1e-11 * p0; ++it) {
      const double h = 1e-6 * d;
      const double slope = (step(er + h).stress(1, 1) - r.stress(1, 1)) / h;
      er -= (r.stress(1, 1) - target) / slope;
      r = step(er);
    }
    run.max_lateral_residual = std::max({run.max_lateral_residual, std::abs(r.stress(1, 1) - target) / p0,
                                         std::abs(r.stress(2, 2) - target) / p0});
    s = r.stress;
    pc = r.preconsolidation;
    er_guess = er;
    ea += d;
    ev += d - 2 * er;
    const double q = -s(0, 0) + s(1, 1), p = soil::ModifiedCamClay::mean_effective_stress(s);
    if (q > 1e-3 * p0) run.max_slope_dev = std::max(run.max_slope_dev, std::abs(q - 3 * (p - p0)) / q);
    record(run, r, ea, ev, k, every);
  }
  return run;
}

TriaxialPath mcc_undrained_triaxial_run(const soil::ModifiedCamClay& model, double p0, double ocr, double d,
                                        double eps_end, double out_every) {
  Matrix3d s = -p0 * Matrix3d::Identity();
  double pc = ocr * p0, ea = 0;
  TriaxialPath run;
  const int n = static_cast<int>(std::lround(eps_end / d));
  const int every = std::max(1, static_cast<int>(std::lround(out_every / d)));
  const Matrix3d de = diag(-d, 0.5 * d, 0.5 * d);  // isochoric
  for (int k = 1; k <= n; ++k) {
    const auto r = model.update(s, pc, de, Matrix3d::Zero());
    s = r.stress;
    pc = r.preconsolidation;
    ea += d;
    record(run, r, ea, 0.0, k, every);
  }
  return run;
}

}  // namespace geosph::verify
