// Hard case (stability table): a saturated sand layer under free water, at rest under gravity. The
// porosity jumps from n0 to 1 at the sand's surface, where the pore water's partial density n rho_w and
// the skeleton's pore-pressure force must stay consistent: the water must stay hydrostatic, the skeleton
// carry its buoyant weight, and nothing move.

#include <algorithm>
#include <cmath>

#include "analytical/hydrostatic_tait.hpp"
#include "harness/case_record.hpp"
#include "harness/driver_registry.hpp"
#include "harness/metrics.hpp"
#include "harness/run_stats.hpp"
#include "soil/soil_fields.hpp"

namespace geosph::verify {

namespace {

Record run_at(const CaseConfig& cfg, const CaseContext& ctx, double spacing) {
  const Scene scene = cfg.scene(spacing);
  const FluidMaterial& w = scene.materials.front();
  const SoilMaterial& s = scene.soils.front();
  const BodySpec& water = scene.bodies[0];
  const BodySpec& sand = scene.bodies[1];
  const double g = -scene.gravity[1], Hw = water.hi[1], Hs = sand.hi[1];
  const double gamma_b = (s.density - (1.0 - s.porosity) * w.density) * g;  // buoyant: (1-n)(rho_s - rho_w) g, density = (1-n) rho_s
  const reference::HydrostaticTait hydro(w.density, w.sound_speed, w.gamma, g, Hw);

  Simulation sim(scene);
  Record rec = start_record(cfg, ctx);
  Series vmax{"SPH", "simulation", "speed_history", "t [s]", "max speed / sqrt(g H)", {}, {}};
  double next = 0;
  const double vref = std::sqrt(g * Hw);
  auto max_speed = [](const Particles& P) {
    double v = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.kind[i] == Kind::Fluid || P.kind[i] == Kind::Soil) v = std::max(v, std::hypot(P.vx[i], P.vy[i]));
    return v;
  };
  const bool ok = run_timed(sim, rec, [&](const Simulation& sm) {
    if (sm.time() < next) return;
    next += scene.t_end / 100;
    vmax.x.push_back(sm.time());
    vmax.y.push_back(max_speed(sm.particles()) / vref);
  }, ctx.progress);
  rec.series.push_back(vmax);

  const Particles& P = sim.particles();
  const auto& syy = P.extra_fields().at(SoilFields::yy);
  std::vector<double> sv, sv_ref, pw, pw_ref;
  Series s_sph{"SPH sigma'_v", "simulation", "stress_profile", "stress [kPa]", "y [m]", {}, {}};
  Series p_sph{"SPH pore pressure", "simulation", "stress_profile", s_sph.xlabel, s_sph.ylabel, {}, {}};
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] == Kind::Soil) {
      sv.push_back(-syy[i]);
      sv_ref.push_back(gamma_b * (Hs - P.y[i]));
      s_sph.x.push_back(-syy[i] / 1e3); s_sph.y.push_back(P.y[i]);
    } else if (P.kind[i] == Kind::Fluid) {
      pw.push_back(P.p[i]);
      pw_ref.push_back(hydro.pressure_at_depth(std::max(0.0, Hw - P.y[i])));
      p_sph.x.push_back(P.p[i] / 1e3); p_sph.y.push_back(P.y[i]);
    }
  }
  rec.series.push_back(s_sph);
  rec.series.push_back(p_sph);
  rec.series.push_back({"gamma' depth (buoyant weight)", "analytical", "stress_profile", s_sph.xlabel, s_sph.ylabel,
                        {0.0, gamma_b * Hs / 1e3}, {Hs, 0.0}});
  rec.series.push_back({"hydrostatic (Tait)", "analytical", "stress_profile", s_sph.xlabel, s_sph.ylabel,
                        {0.0, hydro.pressure_at_depth(Hw) / 1e3}, {Hw, 0.0}});
  add_case_metric(rec, cfg, "effective_stress_rel_l2", relative_l2(sv, sv_ref), ok);
  add_case_metric(rec, cfg, "pore_pressure_rel_l2", relative_l2(pw, pw_ref), ok);
  add_case_metric(rec, cfg, "final_max_speed_over_sqrt_gH", vmax.y.empty() ? NAN : max_speed(P) / vref, ok);
  rec.snapshot = field_snapshot(sim, SoilFields::yy, "Pa");
  return rec;
}

}  // namespace

std::vector<Record> run_soil_under_free_water(const CaseContext& ctx, const std::string& case_name) {
  return run_each_spacing(ctx, case_name, run_at);
}

GEOSPH_CASE_DRIVER(soil_under_free_water, run_soil_under_free_water);

}  // namespace geosph::verify
