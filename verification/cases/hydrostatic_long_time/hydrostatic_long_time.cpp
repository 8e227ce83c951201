// Resting water over a long time with the default density diffusion: a column of depth d (case.json
// variants) at d/dx = 25 and 50 (levels), started in its hydrostatic state, must keep it for 10 s.
// The particle pressures averaged over the last second are compared with the hydrostatic profile of
// the same Tait fluid (reference/analytical/hydrostatic_tait.hpp): over the whole column and in the row
// next to the floor, where plain delta-SPH's drift shows first. One study run with the plain form
// (density_diffusion_hydrostatic: false) is recorded unscored beside them.

#include <cmath>
#include <string>

#include "analytical/hydrostatic_tait.hpp"
#include "harness/case_record.hpp"
#include "harness/driver_registry.hpp"
#include "harness/hydrostatic_profile.hpp"
#include "harness/metrics.hpp"
#include "harness/run_stats.hpp"

namespace geosph::verify {

namespace {

// The case's scene for a column of depth d at d/dx = resolution, with c0 = 10 sqrt(g d).
CaseConfig column_config(const CaseConfig& base, double depth, double end, bool plain) {
  CaseConfig cfg = base;
  auto& s = cfg.scene_json;
  const double g = -s["gravity"][1].get<double>();
  s["time"]["end"] = end;
  s["materials"]["water"]["sound_speed"] = 10.0 * std::sqrt(g * depth);
  if (plain) s["materials"]["water"]["density_diffusion_hydrostatic"] = false;
  s["bodies"][0]["max"][1] = depth;
  s["walls"]["containers"][0]["max"][1] = 1.1 * depth;
  s["domain"]["max"][1] = 1.1 * depth + 0.3;
  return cfg;
}

Record run_column(const CaseConfig& base, const CaseContext& ctx, const std::string& variant, double resolution,
                  bool plain) {
  const double depth = base.spec.at("variants").at(variant).at("depth").get<double>();
  const double end = base.level_number("duration_s");
  const CaseConfig cfg = column_config(base, depth, end, plain);
  const Scene scene = cfg.scene(depth / resolution);
  Simulation sim(scene);
  Record rec = start_record(cfg, ctx);
  rec.variant = plain ? variant + "_plain_diffusion" : variant;
  rec.scored = !plain;
  rec.extra["depth_m"] = depth;
  rec.extra["depth_over_dx"] = resolution;

  // The hydrostatic start places the particles on the lattice with rho(depth) m = rho V: the column
  // holds more water than rho0 d. The reference takes the column's own mass, as the height it would
  // fill at rho0.
  const auto& water = scene.materials.front();
  const double g = -scene.gravity[1];
  const auto& box = scene.bodies.front();
  double mass = 0;
  for (std::size_t i = 0; i < sim.particles().size(); ++i)
    if (sim.particles().kind[i] == Kind::Fluid) mass += sim.particles().m[i];
  const double filled = mass / (water.density * (box.hi[0] - box.lo[0]));
  const reference::HydrostaticTait ref(water.density, water.sound_speed, water.gamma, g, filled);
  rec.extra["settled_surface_height_m"] = ref.surface_height();
  const double t_avg = end - 1.0;
  const std::size_t n = sim.particles().size();
  std::vector<double> psum(n, 0), ysum(n, 0);
  long samples = 0;
  Series base_hist{"SPH, floor row", "simulation", "base_pressure", "t [s]", "p / p_Tait", {}, {}};
  double next_sample = 0;
  const bool ok = run_timed(sim, rec, [&](const Simulation& s) {
    const auto& P = s.particles();
    if (s.time() >= next_sample) {  // the floor row's pressure every 0.1 s, for the plot
      double pr = 0;
      int k = 0;
      for (std::size_t i = 0; i < P.size(); ++i)
        if (P.kind[i] == Kind::Fluid && P.y[i] < scene.dx) { pr += P.p[i] / ref.pressure(P.y[i]); ++k; }
      base_hist.x.push_back(s.time());
      base_hist.y.push_back(k > 0 ? pr / k : NAN);
      next_sample += 0.1;
    }
    if (s.time() < t_avg) return;
    ++samples;
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (P.kind[i] != Kind::Fluid) continue;
      psum[P.id[i]] += P.p[i];
      ysum[P.id[i]] += P.y[i];
    }
  }, ctx.progress);

  if (ok && samples > 0) {
    HydrostaticProfile profile(ref, scene.dx);
    double floor_sim = 0, floor_ref = 0;
    for (std::size_t k = 0; k < n; ++k) {
      if (psum[k] == 0 && ysum[k] == 0) continue;
      const double p = psum[k] / samples, y = ysum[k] / samples;
      profile.add(p, y);
      if (y < scene.dx) { floor_sim += p; floor_ref += ref.pressure(y); }
    }
    add_case_metric(rec, cfg, "pressure_rel_l2", relative_l2(profile.simulated(), profile.reference()));
    add_case_metric(rec, cfg, "base_pressure_error", std::abs(floor_sim / floor_ref - 1.0), floor_ref > 0);
    rec.series = profile.series();
    rec.series.push_back(base_hist);
  } else {
    add_case_metric(rec, cfg, "pressure_rel_l2", 0.0, false);
    add_case_metric(rec, cfg, "base_pressure_error", 0.0, false);
  }
  rec.snapshot = pressure_snapshot(sim);
  return rec;
}

std::vector<Record> run_hydrostatic_long_time(const CaseContext& ctx, const std::string& case_name) {
  const CaseConfig cfg = load_case(ctx, case_name);
  std::vector<Record> out;
  for (const auto& v : cfg.spec.at("variants").items())
    for (double resolution : cfg.level_numbers("depth_over_dx")) out.push_back(run_column(cfg, ctx, v.key(), resolution, false));
  const auto& study = cfg.spec.at("study");
  out.push_back(run_column(cfg, ctx, study.at("variant").get<std::string>(), study.at("depth_over_dx").get<double>(), true));
  return out;
}

}  // namespace

GEOSPH_CASE_DRIVER(hydrostatic_long_time, run_hydrostatic_long_time);

}  // namespace geosph::verify
