// 3D axisymmetric granular column collapse: a cylinder of sand (radius r0, height H0 = a r0) released
// on a rough floor, against the scaling laws of Lube et al. (2004, J. Fluid Mech. 508) and Lajeunesse
// et al. (2004, Phys. Fluids 16). One quarter of the cylinder is simulated: the planes x = 0 and y = 0
// are free-slip walls (mirror symmetry), the floor a no-slip wall block. Each run goes on until the
// soil has stopped (its rms speed below a fraction of sqrt(g H0), the front still); the run-out (r_inf - r0)/r0 and the final height H_inf are measured on the deposit.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "harness/case_record.hpp"
#include "harness/deposit.hpp"
#include "harness/driver_registry.hpp"
#include "harness/run_stats.hpp"
#include "soil/soil_fields.hpp"

namespace geosph::verify {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// the reference's piecewise power laws (harness/deposit.hpp)
double law(const nlohmann::json& entries, double a) { return scaling_law(entries, a); }

// Radius of the deposit's edge on the floor (soil within 2 dx of it), at the particle's edge.
double radial_front(const Particles& P, double dx) {
  double r = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::Soil && P.z[i] < 2 * dx) r = std::max(r, std::hypot(P.x[i], P.y[i]));
  return r + 0.5 * dx;
}

// Surface height over the radius: the highest soil particle's top in radial bins of width dx.
Series radial_profile(const Particles& P, double dx, const std::string& name) {
  std::map<long, double> top;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Soil) continue;
    const long b = std::lround(std::floor(std::hypot(P.x[i], P.y[i]) / dx));
    auto [it, fresh] = top.try_emplace(b, P.z[i]);
    if (!fresh) it->second = std::max(it->second, P.z[i]);
  }
  Series s{name, "simulation", "profile", "r [m]", "height [m]", {}, {}};
  for (const auto& [b, z] : top) {
    s.x.push_back((b + 0.5) * dx);
    s.y.push_back(z + 0.5 * dx);
  }
  return s;
}

Record collapse(const CaseConfig& cfg, const CaseContext& ctx, const nlohmann::json& laws, const SandModel& model,
                double a, double dx) {
  const double r0 = cfg.spec.at("column_radius_m").get<double>(), H0 = a * r0, g = 9.81;
  const double t_ref = std::sqrt(H0 / g);
  // the floor reaches past twice the larger law's run-out
  const double expected = std::max(law(laws.at("runout"), a), law(laws.at("alternative_runout"), a));
  const double R = r0 * (1.0 + 2.0 * expected) + 4 * dx;
  const double Hc = 1.2 * H0 + 4 * dx;
  nlohmann::json j = cfg.scene_json;
  j["dx"] = dx;
  j["materials"]["sand"] = model.material;
  const int L = 4;  // wall layers covering the Wendland support 2 h = 3.2 dx
  const double m = (L + 2) * dx;
  j["domain"] = {{"min", {-r0 - m, -r0 - m, -m}}, {"max", {R + m, R + m, Hc + m}}};
  j["bodies"][0]["shape"] = {{"type", "difference"},
                             {"parts", {{{"type", "cylinder"}, {"centre", {0, 0, 0.5 * H0}}, {"radius", r0}, {"axis", "z"}, {"length", H0}},
                                        {{"type", "box"}, {"min", {-2 * r0, -2 * r0, -1}}, {"max", {0, 2 * r0, H0 + 1}}},
                                        {{"type", "box"}, {"min", {-2 * r0, -2 * r0, -1}}, {"max", {2 * r0, 0, H0 + 1}}}}}};
  j["walls"]["containers"][0]["min"] = {0, 0, 0};
  j["walls"]["containers"][0]["max"] = {R, R, Hc};
  j["walls"]["blocks"][0]["min"] = {-L * dx, -L * dx, -L * dx};
  j["walls"]["blocks"][0]["max"] = {R + L * dx, R + L * dx, 0};
  j["time"]["end"] = cfg.spec.at("max_time_factor").get<double>() * t_ref;
  const Scene scene = parse_scene(j, (cfg.dir / "scene.json").string());

  Simulation sim(scene);
  Record rec = start_record(cfg, ctx);
  char variant[32];
  std::snprintf(variant, sizeof variant, " a=%g", a);
  rec.variant = model.name + variant;
  rec.scored = model.scored;
  rec.extra["sand_model"] = model.describe();
  rec.extra["aspect_ratio"] = a;
  rec.extra["column_radius_over_dx"] = r0 / dx;
  Series front{"SPH run-out", "simulation", "runout_history", "t [s]", "(r - r0)/r0", {}, {}};
  const double v_stop = cfg.spec.at("stop_speed_fraction").get<double>() * std::sqrt(g * H0);
  const double t_min = cfg.spec.at("min_time_factor").get<double>() * t_ref;
  const double sample = 0.05 * t_ref;  // the run-out history's step
  const auto window = static_cast<std::size_t>(std::lround(t_ref / sample));  // samples in t_ref
  bool stable = true, stopped = false;
  while (sim.time() < scene.t_end - 1e-12) {
    stable = run_timed(sim, rec, {}, ctx.progress, std::min(scene.t_end, sim.time() + sample));
    if (!stable) break;
    front.x.push_back(sim.time());
    front.y.push_back((radial_front(sim.particles(), dx) - r0) / r0);
    // stopped: the soil's kinetic energy as an rms speed below v_stop, and the front still to a
    // quarter dx over the last t_ref; the largest single speed is recorded, not used,
    // since a few particles at the floor's edge with the symmetry planes keep ringing (case notes)
    const std::size_t n = front.y.size();
    const bool front_still = n > window && std::abs(front.y[n - 1] - front.y[n - 1 - window]) * r0 < 0.25 * dx;
    if (sim.time() >= t_min && front_still && rms_solid_speed(sim.particles()) < v_stop) { stopped = true; break; }
  }
  const Particles& P = sim.particles();
  const double r_inf = radial_front(P, dx);
  double h_inf = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::Soil) h_inf = std::max(h_inf, P.z[i] + 0.5 * dx);
  const bool inside = r_inf < R - 2 * dx;
  const bool ok = stable && stopped && inside;
  const double runout = (r_inf - r0) / r0;
  const double lube = law(laws.at("runout"), a), laj = law(laws.at("alternative_runout"), a);
  rec.extra["runout_normalised"] = runout;
  rec.extra["height_normalised"] = h_inf / r0;
  rec.extra["runout_lube"] = lube;
  rec.extra["runout_lajeunesse"] = laj;
  rec.extra["stopped"] = stopped;
  rec.extra["stop_speed_m_per_s"] = v_stop;
  rec.extra["rms_soil_speed_at_end_m_per_s"] = rms_solid_speed(P);
  rec.extra["max_soil_speed_at_end_m_per_s"] = max_soil_speed(P);
  rec.extra["soil_particles_above_stop_speed_at_end"] = soil_particles_faster_than(P, v_stop);
  rec.extra["deposit_inside_floor"] = inside;
  rec.extra["end_time_s"] = sim.time();
  // scored where the two experiments agree on the form (linear run-out below a = 1.7; the top of the
  // column not lowered below a = 0.74); the large-a laws are recorded only
  if (a < 1.7) add_case_metric(rec, cfg, "runout_rel_error_lube", std::abs(runout - lube) / lube, ok);
  if (a < 0.74) add_case_metric(rec, cfg, "final_height_rel_error", std::abs(h_inf / H0 - 1.0), ok);
  if (a >= 1.7) rec.scored = false;  // recorded against the large-a laws only
  rec.series = {front, radial_profile(P, dx, "SPH deposit (t = " + std::to_string(sim.time()).substr(0, 5) + " s)")};
  rec.series.push_back({"initial column", "analytical", "profile", "r [m]", "height [m]", {0.0, r0, r0}, {H0, H0, 0.0}});
  rec.snapshot = field_snapshot(sim, SoilFields::plastic_strain, "-");
  return rec;
}

}  // namespace

std::vector<Record> run_granular_collapse_axisymmetric(const CaseContext& ctx, const std::string& case_name) {
  const CaseConfig cfg = load_case(ctx, case_name);
  const nlohmann::json laws = read_json_file(cfg.reference_file(ctx, cfg.spec.at("laws")));
  std::vector<Record> out;
  for (const SandModel& model : sand_models(cfg))
    for (double dx : cfg.level_numbers("dx"))
      for (double a : cfg.level.at("aspect_ratios").get<std::vector<double>>()) {
        std::fprintf(stderr, "-- %s, a = %g, dx = %g\n", model.name.c_str(), a, dx);
        out.push_back(collapse(cfg, ctx, laws, model, a, dx));
      }
  return out;
}

GEOSPH_CASE_DRIVER(granular_collapse_axisymmetric, run_granular_collapse_axisymmetric);

}  // namespace geosph::verify
