// 2D dam break: a water column of width a and height 2a collapses in a tank of length 4a. The
// surge-front position Z = x/a against T = t sqrt(2g/a) is compared with the experiments of
// Martin & Moyce (1952) and Koshizuka & Oka (1996) up to the impact on the far wall; the scored
// metric is the surge-front speed (see below), the Z(T) errors and release lag are recorded.

#include <algorithm>
#include <cmath>

#include <gsl/gsl_fit.h>

#include "harness/case_record.hpp"
#include "harness/driver_registry.hpp"
#include "harness/metrics.hpp"
#include "harness/run_stats.hpp"

namespace geosph::verify {

namespace {
// Front = largest x of the fluid particles within 2 dx of the floor (ignores isolated spray),
// plus dx/2: a particle centre sits half a spacing behind the edge of the volume it represents.
double front_position(const Particles& P, double floor_y, double dx) {
  double xmax = -1e300;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::Fluid && P.y[i] < floor_y + 2 * dx) xmax = std::max(xmax, P.x[i]);
  return xmax + 0.5 * dx;
}

// Least-squares slope dZ/dT of the points with z_lo <= Z <= z_hi (GSL linear fit).
double surge_speed(const std::vector<double>& T, const std::vector<double>& Z, double z_lo, double z_hi) {
  std::vector<double> t, z;
  for (std::size_t k = 0; k < T.size(); ++k)
    if (Z[k] >= z_lo && Z[k] <= z_hi) { t.push_back(T[k]); z.push_back(Z[k]); }
  if (t.size() < 3) return NAN;
  double c0, c1, cov00, cov01, cov11, sumsq;
  gsl_fit_linear(t.data(), 1, z.data(), 1, t.size(), &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
  return c1;
}

// The time lag dT (0 <= dT <= 0.5, steps of 0.005) minimising sum (Z_sim(T - dT) - Z_exp)^2.
double best_time_lag(const std::vector<double>& Ts, const std::vector<double>& Zs, const std::vector<double>& Te,
                     const std::vector<double>& Ze) {
  double best = 0, best_err = 1e300;
  for (int k = 0; k <= 100; ++k) {
    const double lag = 0.005 * k;
    double err = 0;
    for (std::size_t i = 0; i < Te.size(); ++i) {
      const double d = interpolate(Ts, Zs, Te[i] - lag) - Ze[i];
      err += d * d;
    }
    if (err < best_err) { best_err = err; best = lag; }
  }
  return best;
}
}  // namespace

namespace {
Record run_at(const CaseConfig& cfg, const CaseContext& ctx, double spacing) {
  Scene scene = cfg.scene(spacing);
  Simulation sim(scene);
  Record rec = start_record(cfg, ctx);
  const auto& col = scene.bodies.front();
  const double a = col.hi[0] - col.lo[0], g = -scene.gravity[1];
  const double t_scale = std::sqrt(2 * g / a);

  Series front{"SPH", "simulation", "front", "T = t sqrt(2g/a)", "Z = x/a", {0.0}, {1.0}};
  double next_sample = 0.0;
  const double sample_dt = 0.002;
  const bool ok = run_timed(sim, rec, [&](const Simulation& s) {
    if (s.time() < next_sample) return;
    next_sample += sample_dt;
    front.x.push_back(s.time() * t_scale);
    front.y.push_back((front_position(s.particles(), col.lo[1], scene.dx) - col.lo[0]) / a);
  }, ctx.progress);
  rec.series.push_back(front);

  // Metric: the surge-front speed dZ/dT of the developed surge (1.8 <= Z <= 3.9, before the far
  // wall), least-squares slopes (GSL) of the simulation and of each data set over that range.
  // The speed, not Z(T) itself, is compared because the experiments release the column by
  // lifting a gate: the finite release time delays the measured front by a near-constant
  // dT ~ 0.2 that an ideal-release simulation cannot have. The uncorrected Z(T) error and the
  // time lag that best aligns the curves are recorded next to it for transparency.
  const double T_end = scene.t_end * t_scale;
  const double z_lo = cfg.spec.at("surge_range").at(0), z_hi = cfg.spec.at("surge_range").at(1);
  const double sph_speed = ok ? surge_speed(front.x, front.y, z_lo, z_hi) : NAN;
  rec.extra["surge_speed_sph"] = sph_speed;
  for (const auto& [key, file, label, scored] :
       {std::tuple{"martin_moyce", "experimental/dam_break_martin_moyce_1952.csv", "Martin & Moyce 1952", true},
        std::tuple{"koshizuka_oka", "experimental/dam_break_koshizuka_oka_1996.csv", "Koshizuka & Oka 1996", false}}) {
    const Csv data = read_csv(cfg.reference_file(ctx, file).string());
    const auto &T = data.column("T"), &Z = data.column("Z");
    Series exp{label, "experiment", "front", front.xlabel, front.ylabel, T, Z};
    rec.series.push_back(exp);
    const double ref_speed = surge_speed(T, Z, z_lo, z_hi);
    rec.extra["surge_speed_" + std::string(key)] = ref_speed;
    std::vector<double> zs, ze, ts;
    for (std::size_t k = 0; k < T.size(); ++k)
      if (T[k] > 0 && T[k] <= T_end && Z[k] < 4.0) { ts.push_back(T[k]); ze.push_back(Z[k]); }
    if (ok && !ts.empty()) {
      for (double t : ts) zs.push_back(interpolate(front.x, front.y, t));
      rec.extra["front_rel_l2_uncorrected_" + std::string(key)] = relative_l2(zs, ze);
      rec.extra["release_lag_T_" + std::string(key)] = best_time_lag(front.x, front.y, ts, ze);
    }
    if (scored)
      add_case_metric(rec, cfg, "surge_speed_rel_error_" + std::string(key), std::abs(sph_speed - ref_speed) / ref_speed, ok);
  }
  rec.snapshot = pressure_snapshot(sim);
  return rec;
}
}  // namespace

std::vector<Record> run_dam_break_2d(const CaseContext& ctx, const std::string& case_name) { return run_each_spacing(ctx, case_name, run_at); }

GEOSPH_CASE_DRIVER(dam_break_2d, run_dam_break_2d);

}  // namespace geosph::verify
