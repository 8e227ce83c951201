// 2D collapse of a column of aluminium bars (Bui, Fukagawa, Sako & Ohno 2008): a 0.2 m x 0.1 m
// column of cohesionless Drucker-Prager material released from rest against the back wall. At the
// end the free-surface profile, the run-out and the failure line (boundary of the static wedge, in
// the initial configuration) are compared with the experiment.

#include <gsl/gsl_fit.h>

#include <algorithm>
#include <filesystem>
#include <cmath>
#include <numbers>

#include "harness/case_record.hpp"
#include "harness/driver_registry.hpp"
#include "harness/deposit.hpp"
#include "harness/metrics.hpp"
#include "harness/run_stats.hpp"
#include "soil/soil_fields.hpp"

namespace geosph::verify {

namespace {

// Failure line in the initial configuration: for each initial column of particles (x bins of width
// dx), the top of the static wedge = highest initial y among particles displaced less than
// `still`; a least-squares line (GSL) through the wedge tops that lie strictly inside the column
// gives the failure angle to the horizontal.
double failure_angle_deg(const Particles& P, const std::vector<double>& x0, const std::vector<double>& y0,
                         double col_lo, double col_hi, double height, double dx, double still, Series& line) {
  const auto nb = static_cast<std::size_t>(std::lround((col_hi - col_lo) / dx));
  std::vector<double> top(nb, -1.0);
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Soil) continue;
    const auto id = static_cast<std::size_t>(P.id[i]);
    const double d = std::hypot(P.x[i] - x0[id], P.y[i] - y0[id]);
    if (d >= still) continue;
    const auto b = std::min(nb - 1, static_cast<std::size_t>((x0[id] - col_lo) / dx));
    top[b] = std::max(top[b], y0[id] + 0.5 * dx);
  }
  std::vector<double> xs, ys;
  for (std::size_t b = 0; b < nb; ++b)
    if (top[b] > 0 && top[b] < height - 1.5 * dx) {
      xs.push_back(col_lo + (b + 0.5) * dx);
      ys.push_back(top[b]);
    }
  line.x = xs;
  line.y = ys;
  if (xs.size() < 3) return NAN;
  double c0, c1, c00, c01, c11, ss;
  gsl_fit_linear(xs.data(), 1, ys.data(), 1, xs.size(), &c0, &c1, &c00, &c01, &c11, &ss);
  return std::atan(std::abs(c1)) * 180.0 / std::numbers::pi;
}

}  // namespace

namespace {
Record run_at(const CaseConfig& cfg, const CaseContext& ctx, double spacing) {
  Scene scene = cfg.scene(spacing);
  Simulation sim(scene);
  Record rec = start_record(cfg, ctx);
  rec.scored = cfg.spec.value("scored", true);  // the Cam Clay variant is a study (no measured parameters)
  const auto& col = scene.bodies.front();
  const double dx = scene.dx, floor_y = col.lo[1], H0 = col.hi[1] - col.lo[1];

  // initial positions by particle id (ids are the original indices)
  const Particles& P0 = sim.particles();
  std::vector<double> x0(P0.size()), y0(P0.size());
  for (std::size_t i = 0; i < P0.size(); ++i) {
    x0[static_cast<std::size_t>(P0.id[i])] = P0.x[i];
    y0[static_cast<std::size_t>(P0.id[i])] = P0.y[i];
  }

  Series front{"SPH run-out", "simulation", "runout_history", "t [s]", "run-out [m]", {}, {}};
  double next = 0;
  const bool ok = run_timed(sim, rec, [&](const Simulation& s) {
    if (s.time() < next) return;
    next += 0.01;
    front.x.push_back(s.time());
    front.y.push_back(runout_front(s.particles(), floor_y, dx));
  }, ctx.progress);
  rec.series.push_back(front);

  const Particles& P = sim.particles();
  const Profile pr = surface_profile(P, col.lo[0], floor_y, dx);
  rec.series.push_back({"SPH", "simulation", "profile", "x [m]", "height [m]", pr.x, pr.h});

  const Csv exp = read_csv(cfg.reference_file(ctx, cfg.spec.at("reference_profile")).string());
  rec.series.push_back({"Bui et al. 2008 (experiment)", "experiment", "profile", "x [m]", "height [m]",
                        exp.column("x"), exp.column("y")});
  const double still = cfg.spec.at("still_displacement_m");
  Series fl{"SPH failure line (static-wedge top)", "simulation", "failure_line", "x [m]", "y [m]", {}, {}};
  const double angle = ok ? failure_angle_deg(P, x0, y0, col.lo[0], col.hi[0], H0, dx, still, fl) : NAN;
  rec.series.push_back(fl);
  const Csv exp_line = read_csv(cfg.reference_file(ctx, "experimental/granular_collapse_bui_2008_failure_line.csv").string());
  rec.series.push_back({"Bui et al. 2008 failure line (experiment)", "experiment", "failure_line", "x [m]", "y [m]",
                        exp_line.column("x"), exp_line.column("y")});
  rec.extra["failure_angle_deg_reference"] = exp.comment_number("failure_angle_deg");

  const double sph_runout = ok ? runout_front(P, floor_y, dx) - col.lo[0] : NAN;
  double sph_height = 0;
  for (double h : pr.h) sph_height = std::max(sph_height, h);
  rec.extra["runout_m"] = sph_runout;
  rec.extra["final_height_m"] = sph_height;
  rec.extra["failure_angle_deg"] = angle;

  // profile: heights at the experiment's x, relative L2 over the heights
  if (cfg.tolerances.count("profile_rel_l2")) {
    std::vector<double> hs, he;
    for (std::size_t k = 0; k < exp.column("x").size(); ++k) {
      const double xq = exp.column("x")[k];
      he.push_back(exp.column("y")[k]);
      hs.push_back(xq > pr.x.back() + 0.5 * dx ? 0.0 : interpolate(pr.x, pr.h, xq));
    }
    add_case_metric(rec, cfg, "profile_rel_l2", relative_l2(hs, he), ok);
  }
  const std::vector<std::tuple<std::string, std::string, double>> scalars = {
      {"runout_rel_error", "runout_m", sph_runout},
      {"final_height_rel_error", "final_height_m", sph_height},
      {"failure_angle_rel_error", "failure_angle_deg", angle}};
  for (const auto& [metric, key, value] : scalars) {
    if (!cfg.tolerances.count(metric)) continue;
    const double ref = exp.comment_number(key);
    rec.extra[key + std::string("_reference")] = ref;
    add_case_metric(rec, cfg, metric, std::abs(value - ref) / ref, ok);
  }
  // DEM reference (LIGGGHTS, reference/dem): overlaid, and its profile and run-out differences are
  // recorded (not scored: the DEM micro-parameters are calibrated on the angle of repose only, see
  // reference/dem/README.md).
  const auto dem_file = cfg.reference_file(ctx, "dem/collapse_a0.5.csv");
  if (std::filesystem::exists(dem_file)) {
    const Csv dem = read_csv(dem_file.string());
    rec.series.push_back({"LIGGGHTS DEM", "dem", "profile", "x [m]", "height [m]", dem.column("x"), dem.column("y")});
    std::vector<double> hs, hd;
    for (std::size_t k = 0; k < dem.column("x").size(); ++k) {
      const double xq = dem.column("x")[k];
      hd.push_back(dem.column("y")[k]);
      hs.push_back(xq > pr.x.back() + 0.5 * dx ? 0.0 : interpolate(pr.x, pr.h, xq));
    }
    const double dem_runout = dem.comment_number("runout_m");
    rec.extra["dem_runout_m"] = dem_runout;
    rec.extra["dem_final_height_m"] = dem.comment_number("final_height_m");
    if (ok) {
      rec.extra["profile_rel_l2_vs_dem"] = relative_l2(hs, hd);
      rec.extra["runout_rel_diff_vs_dem"] = (sph_runout - dem_runout) / dem_runout;
    }
  }
  rec.snapshot = field_snapshot(sim, SoilFields::plastic_strain, "-");
  return rec;
}
}  // namespace

// Also the driver of granular_collapse_cam_clay (the same experiment with the Modified Cam Clay column).
std::vector<Record> run_granular_collapse_bui(const CaseContext& ctx, const std::string& case_name) {
  return run_each_spacing(ctx, case_name, run_at);
}

GEOSPH_CASE_DRIVER(granular_collapse_bui, run_granular_collapse_bui);

}  // namespace geosph::verify
