// Modified Cam Clay soil column consolidating under its own weight, drained and one-dimensional
// (free-slip side walls): from the geostatic state at a fraction of gravity with K0 = 1, gravity is
// ramped slowly to g. At the end the vertical stress must carry the weight above each particle, and
// the horizontal-to-vertical ratio must be the model's K0 of normal compression
// (reference/analytical/cam_clay_triaxial.hpp).

#include <algorithm>
#include <cmath>

#include "analytical/cam_clay_triaxial.hpp"
#include "harness/case_record.hpp"
#include "harness/driver_registry.hpp"
#include "harness/metrics.hpp"
#include "harness/run_stats.hpp"
#include "soil/soil_fields.hpp"

namespace geosph::verify {

namespace {

Record run_at(const CaseConfig& cfg, const CaseContext& ctx, double spacing) {
  const Scene scene = cfg.scene(spacing);
  const SoilMaterial& soil = scene.soils.front();
  const auto& m = soil.as<materials::ModifiedCamClay>();
  const BodySpec& body = scene.bodies.front();
  const double H0 = body.hi[1] - body.lo[1], g = -scene.gravity[1];
  const double k0_ref = reference::mcc_k0_normally_consolidated(m.lambda, m.kappa, m.critical_state_slope, m.poisson);
  Simulation sim(scene);
  Record rec = start_record(cfg, ctx);
  std::vector<double> y0(sim.particles().size());
  for (std::size_t i = 0; i < sim.particles().size(); ++i) y0[static_cast<std::size_t>(sim.particles().id[i])] = sim.particles().y[i];

  Series top{"SPH", "simulation", "settlement_history", "t [s]", "settlement of the top [m]", {}, {}};
  double next = 0;
  const auto top_y = [&](const Particles& P) {
    double y = -1e300;
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.kind[i] == Kind::Soil) y = std::max(y, P.y[i]);
    return y + 0.5 * scene.dx;
  };
  const double top0 = top_y(sim.particles());
  const bool ok = run_timed(sim, rec, [&](const Simulation& s) {
    if (s.time() < next) return;
    next += 0.02;
    top.x.push_back(s.time());
    top.y.push_back(top0 - top_y(s.particles()));
  }, ctx.progress);
  rec.series.push_back(top);

  const Particles& P = sim.particles();
  const auto& sxx = P.extra_fields().at(SoilFields::xx);
  const auto& syy = P.extra_fields().at(SoilFields::yy);
  // profiles against the initial (mass) coordinate: depth below the initial top
  struct Row { double depth, sv, sh, sv_ref; };
  std::vector<Row> rows;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Soil) continue;
    const double depth = body.hi[1] - y0[static_cast<std::size_t>(P.id[i])];
    rows.push_back({depth, -syy[i], -sxx[i], soil.density * g * depth});
  }
  std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.depth < b.depth; });
  std::vector<double> sv, sv_ref;
  double k0_sum = 0;
  int k0_n = 0;
  const double min_depth = cfg.spec.at("k0_min_depth_fraction").get<double>() * H0;
  Series s_v{"SPH sigma_v'", "simulation", "stress_profile", "sigma' [kPa]", "depth (initial) [m]", {}, {}};
  Series s_h{"SPH sigma_h'", "simulation", "stress_profile", "sigma' [kPa]", "depth (initial) [m]", {}, {}};
  for (const auto& r : rows) {
    sv.push_back(r.sv);
    sv_ref.push_back(r.sv_ref);
    s_v.x.push_back(r.sv / 1e3); s_v.y.push_back(-r.depth);
    s_h.x.push_back(r.sh / 1e3); s_h.y.push_back(-r.depth);
    if (r.depth >= min_depth) { k0_sum += r.sh / r.sv; ++k0_n; }
  }
  const double k0_sph = k0_n > 0 ? k0_sum / k0_n : NAN;
  rec.series.push_back(s_v);
  rec.series.push_back(s_h);
  const double sv_base = soil.density * g * H0;
  rec.series.push_back(linear_depth_profile(s_v, "rho g z (equilibrium)", sv_base / 1e3, H0));
  rec.series.push_back(linear_depth_profile(s_v, "K0_nc rho g z (Modified Cam Clay)", k0_ref * sv_base / 1e3, H0));
  rec.extra["k0_sph"] = k0_sph;
  rec.extra["k0_reference"] = k0_ref;
  rec.extra["k0_particles"] = k0_n;
  rec.extra["settlement_m"] = top.y.empty() ? NAN : top.y.back();
  add_case_metric(rec, cfg, "vertical_stress_rel_l2", relative_l2(sv, sv_ref), ok);
  add_case_metric(rec, cfg, "k0_rel_error", std::abs(k0_sph - k0_ref) / k0_ref, ok);
  rec.snapshot = field_snapshot(sim, SoilFields::preconsolidation, "Pa");
  return rec;
}

}  // namespace

std::vector<Record> run_cam_clay_k0_column(const CaseContext& ctx, const std::string& case_name) { return run_each_spacing(ctx, case_name, run_at); }

GEOSPH_CASE_DRIVER(cam_clay_k0_column, run_cam_clay_k0_column);

}  // namespace geosph::verify
