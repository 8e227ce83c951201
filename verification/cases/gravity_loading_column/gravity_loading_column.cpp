// An elastic soil column between smooth (free-slip) walls, loaded from rest by the gravity-loading
// stage (sim/gravity_loading.hpp): at the settled state the vertical stress must carry the weight above
// each particle, sigma_v = rho g d (equilibrium, d the depth in the initial lattice), and the lateral
// stress must be the one-dimensional elastic sigma_h = K0 sigma_v with K0 = nu / (1 - nu) (zero lateral
// strain under Hooke's law). Rows within one kernel support of the free surface are left out (their
// support is truncated; issue 17, item 3 asks for the stress "away from the surface rows").

#include <algorithm>
#include <cmath>
#include <map>

#include "harness/case_record.hpp"
#include "harness/driver_registry.hpp"
#include "harness/run_stats.hpp"
#include "soil/soil_fields.hpp"

namespace geosph::verify {

namespace {

Record run_at(const CaseConfig& cfg, const CaseContext& ctx, double spacing) {
  const Scene scene = cfg.scene(spacing);
  const SoilMaterial& soil = scene.soils.front();
  const BodySpec& body = scene.bodies.front();
  const double g = -scene.gravity[1], nu = soil.poisson_ratio();
  const double k0 = nu / (1.0 - nu);
  Simulation sim(scene);
  Record rec = start_record(cfg, ctx);
  // the initial lattice row of every particle (by id): depth below the top in the mass coordinate
  std::vector<long> row(sim.particles().size(), -1);
  for (std::size_t i = 0; i < sim.particles().size(); ++i)
    if (sim.particles().kind[i] == Kind::Soil)
      row[static_cast<std::size_t>(sim.particles().id[i])] = std::lround((body.hi[1] - sim.particles().y[i]) / scene.dx - 0.5);
  const bool ok = run_timed(sim, rec, {}, ctx.progress);
  const GravityLoadingResult& gl = sim.gravity_loading();
  rec.steps += gl.steps;  // the settling steps are the case's work
  rec.particle_steps_per_s = rec.wall_s > 0 ? rec.particles * static_cast<double>(rec.steps) / rec.wall_s : 0;

  const Particles& P = sim.particles();
  const auto& sxx = P.extra_fields().at(SoilFields::xx);
  const auto& syy = P.extra_fields().at(SoilFields::yy);
  struct Sums { double sv = 0, sh = 0; int n = 0; };
  std::map<long, Sums> rows;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Soil) continue;
    Sums& s = rows[row[static_cast<std::size_t>(P.id[i])]];
    s.sv -= syy[i];
    s.sh -= sxx[i];
    ++s.n;
  }
  const double support = scene.h() * 2.0;  // the cubic spline's and Wendland's support radius
  Series s_v{"SPH sigma_v", "simulation", "stress_profile", "stress [kPa]", "depth (initial) [m]", {}, {}};
  Series s_h{"SPH sigma_h", "simulation", "stress_profile", "stress [kPa]", "depth (initial) [m]", {}, {}};
  double sv_err = 0, k0_err = 0;
  int scored = 0;
  for (const auto& [r, s] : rows) {
    const double depth = (static_cast<double>(r) + 0.5) * scene.dx;
    const double sv = s.sv / s.n, sh = s.sh / s.n, sv_ref = soil.density * g * depth;
    s_v.x.push_back(sv / 1e3); s_v.y.push_back(-depth);
    s_h.x.push_back(sh / 1e3); s_h.y.push_back(-depth);
    if (depth < support) continue;  // the surface rows: a truncated support
    sv_err = std::max(sv_err, std::abs(sv - sv_ref) / sv_ref);
    k0_err = std::max(k0_err, std::abs(sh / sv - k0) / k0);
    ++scored;
  }
  const double H = body.hi[1] - body.lo[1], sv_base = soil.density * g * H;
  rec.series.push_back(s_v);
  rec.series.push_back(s_h);
  rec.series.push_back(linear_depth_profile(s_v, "rho g d (equilibrium)", sv_base / 1e3, H));
  rec.series.push_back(linear_depth_profile(s_v, "K0 rho g d, K0 = nu/(1 - nu)", k0 * sv_base / 1e3, H));
  rec.extra["poisson_ratio"] = nu;
  rec.extra["k0_reference"] = k0;
  rec.extra["column_width_m"] = body.hi[0] - body.lo[0];
  rec.extra["scored_rows"] = scored;
  rec.extra["settling_time_s"] = gl.time;
  rec.extra["settling_steps"] = gl.steps;
  rec.extra["settled_kinetic_energy_ratio"] = gl.peak_kinetic_energy > 0 ? gl.final_kinetic_energy / gl.peak_kinetic_energy : 0.0;
  rec.extra["settled_force_ratio"] = gl.final_force_ratio;
  const bool settled = ok && gl.ran && gl.settled && scored > 0;
  add_case_metric(rec, cfg, "vertical_stress_max_rel_error", sv_err, settled);
  add_case_metric(rec, cfg, "k0_max_rel_error", k0_err, settled);
  rec.snapshot = field_snapshot(sim, SoilFields::yy, "Pa");
  return rec;
}

// case.json "variants": the Poisson ratio (so K0) and the column's width.
Record run_variant(const CaseConfig& base, const CaseContext& ctx, const std::string& variant, double spacing) {
  CaseConfig cfg = base;
  const nlohmann::json& v = cfg.spec.at("variants").at(variant);
  cfg.scene_json["materials"]["soil"]["poisson_ratio"] = v.at("poisson_ratio");
  const double width = v.at("width").get<double>();
  cfg.scene_json["bodies"][0]["max"][0] = width;
  cfg.scene_json["walls"]["containers"][0]["max"][0] = width;
  cfg.scene_json["domain"]["max"][0] = width + 0.5;
  Record rec = run_at(cfg, ctx, spacing);
  rec.variant = variant;
  return rec;
}

}  // namespace

std::vector<Record> run_gravity_loading_column(const CaseContext& ctx, const std::string& case_name) {
  return run_each_variant(ctx, case_name, run_variant);
}

GEOSPH_CASE_DRIVER(gravity_loading_column, run_gravity_loading_column);

}  // namespace geosph::verify
