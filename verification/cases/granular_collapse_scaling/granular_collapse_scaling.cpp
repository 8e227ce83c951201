// 2D granular column collapse over a range of aspect ratios a = H0/L0 against the experimental
// scaling laws of Lube, Huppert, Sparks & Freundt (2005) and Lajeunesse, Monnier & Homsy (2005):
// normalised run-out (L_inf - L0)/L0 ~ a (small a) and ~ a^(2/3) (large a), final height
// H_inf/L0 ~ a^(2/5) (Lube) or a^(1/3) (Lajeunesse) at large a. One SPH collapse per a (the
// sand column of each of the case's sand models, released against the back wall, run until it has
// stopped); the exponents of the two regimes, fitted in log-log by least squares (GSL), are scored
// for the scored model and shown beside it for the others; the prefactors, which depend on the
// material, are recorded per a as unscored studies.

#include <gsl/gsl_fit.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "harness/case_record.hpp"
#include "harness/driver_registry.hpp"
#include "harness/deposit.hpp"
#include "harness/run_stats.hpp"
#include "soil/soil_fields.hpp"

namespace geosph::verify {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// the reference's piecewise power laws (harness/deposit.hpp)
double law(const nlohmann::json& entries, double a) { return scaling_law(entries, a); }

// Least-squares exponent and prefactor of y = c a^p over the points with a in [lo, hi).
struct PowerFit {
  double exponent = kNaN, prefactor = kNaN;
  std::size_t points = 0;
};
PowerFit fit_power(const std::vector<double>& a, const std::vector<double>& y, double lo, double hi) {
  std::vector<double> la, ly;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (a[k] >= lo && a[k] < hi && y[k] > 0 && std::isfinite(y[k])) {
      la.push_back(std::log(a[k]));
      ly.push_back(std::log(y[k]));
    }
  PowerFit f;
  f.points = la.size();
  if (la.size() < 2) return f;
  double c0, c1, c00, c01, c11, ss;
  gsl_fit_linear(la.data(), 1, ly.data(), 1, la.size(), &c0, &c1, &c00, &c01, &c11, &ss);
  f.exponent = c1;
  f.prefactor = std::exp(c0);
  return f;
}

struct Collapse {
  double runout = kNaN, height = kNaN;  // (L_inf - L0)/L0 and H_inf/L0
  bool stopped = false, stable = false, inside = false;
  Record rec;
};

// One column of aspect ratio a: scene built from the case's template, run in chunks until the soil
// has stopped moving.
Collapse collapse(const CaseConfig& cfg, const CaseContext& ctx, const SandModel& model, double a, double dx) {
  const double L0 = cfg.spec.at("column_length_m"), H0 = a * L0, g = 9.81;
  const double t_ref = std::sqrt(H0 / g);
  // floor long enough for twice the larger of the two experimental run-outs, plus a margin
  const double lube = std::max(1.2 * a, 1.9 * std::pow(a, 2.0 / 3.0));
  const double floor_len = L0 * (1.0 + 2.0 * std::max(lube, 1.8 * a)) + 0.1;
  const double margin = 8 * dx;
  nlohmann::json j = cfg.scene_json;
  j["dx"] = dx;
  j["materials"]["sand"] = model.material;
  j["bodies"][0]["min"] = {0.0, 0.0};
  j["bodies"][0]["max"] = {L0, H0};
  j["walls"]["containers"][0]["min"] = {0.0, 0.0};
  j["walls"]["containers"][0]["max"] = {floor_len, 1.1 * H0};
  j["domain"]["min"] = {-margin, -margin};
  j["domain"]["max"] = {floor_len + margin, 1.1 * H0 + margin};
  j["time"]["end"] = cfg.spec.at("max_time_factor").get<double>() * t_ref;
  const Scene scene = parse_scene(j, (cfg.dir / "scene.json").string());

  Collapse c;
  Simulation sim(scene);
  c.rec = start_record(cfg, ctx);
  char variant[32];
  std::snprintf(variant, sizeof variant, " a=%g", a);
  c.rec.variant = model.name + variant;
  c.rec.scored = false;
  c.rec.extra["aspect_ratio"] = a;
  c.rec.extra["sand_model"] = model.describe();

  Series front{"SPH run-out", "simulation", "runout_history", "t [s]", "(L - L0)/L0", {}, {}};
  const double v_stop = cfg.spec.at("stop_speed_fraction").get<double>() * std::sqrt(g * H0);
  const double t_min = cfg.spec.at("min_time_factor").get<double>() * t_ref;
  const double chunk = 0.05 * t_ref;
  c.stable = true;
  while (sim.time() < scene.t_end - 1e-12) {
    c.stable = run_timed(sim, c.rec, {}, ctx.progress, std::min(scene.t_end, sim.time() + chunk));
    if (!c.stable) break;
    front.x.push_back(sim.time());
    front.y.push_back((runout_front(sim.particles(), 0.0, dx) - L0) / L0);
    if (sim.time() >= t_min && max_soil_speed(sim.particles()) < v_stop) { c.stopped = true; break; }
  }
  c.rec.series.push_back(front);
  const Particles& P = sim.particles();
  const Profile pr = surface_profile(P, 0.0, 0.0, dx);
  c.rec.series.push_back({"SPH", "simulation", "profile", "x [m]", "height [m]", pr.x, pr.h});
  const double front_x = runout_front(P, 0.0, dx);
  c.inside = front_x < floor_len - 2 * dx;
  if (c.stable) {
    c.runout = (front_x - L0) / L0;
    c.height = *std::max_element(pr.h.begin(), pr.h.end()) / L0;
  }
  c.rec.extra["runout_normalised"] = c.runout;
  c.rec.extra["height_normalised"] = c.height;
  c.rec.extra["stopped"] = c.stopped;
  c.rec.extra["end_time_s"] = sim.time();
  c.rec.extra["deposit_inside_floor"] = c.inside;
  c.rec.snapshot = field_snapshot(sim, SoilFields::plastic_strain, "-");
  return c;
}

}  // namespace

namespace {
// All aspect ratios at one spacing: the summary record (scored exponents) first, then one study
// record per aspect ratio.
std::vector<Record> scaling_at(const CaseConfig& cfg, const CaseContext& ctx, const nlohmann::json& laws,
                               const SandModel& model, double dx) {
  const double small_max = cfg.spec.at("small_a_max"), large_min = cfg.spec.at("large_a_min");

  std::vector<Record> out;
  Record summary = start_record(cfg, ctx);
  summary.variant = model.name;
  summary.scored = model.scored;
  summary.extra["sand_model"] = model.describe();
  std::vector<double> as, runouts, heights;
  bool all_ok = true;
  for (double a : cfg.spec.at("aspect_ratios").get<std::vector<double>>()) {
    // the level's dx is L0 / n: n particles across the smaller side of the column (a squat column's
    // height carries its flow, and at H0/dx = 10-20 its run-out was not converged; see the notes)
    const double dx_a = dx * std::min(1.0, a);
    std::fprintf(stderr, "-- %s, a = %g, dx = %g\n", model.name.c_str(), a, dx_a);
    Collapse c = collapse(cfg, ctx, model, a, dx_a);
    const bool ok = c.stable && c.stopped && c.inside;
    all_ok = all_ok && ok;
    as.push_back(a);
    runouts.push_back(ok ? c.runout : kNaN);
    heights.push_back(ok ? c.height : kNaN);
    // per-a prefactor check against each law set (a study: the prefactor depends on the material)
    const double tol = 0.3;
    const std::string why =
        "prefactors are material dependent: the two experiments differ by 50% at small a (1.2 a vs 1.8 a); "
        "reported as a study, not scored";
    const double lube = law(laws.at("runout"), a), laj = law(laws.at("alternative_runout"), a);
    c.rec.extra["runout_lube"] = lube;
    c.rec.extra["runout_lajeunesse"] = laj;
    c.rec.extra["height_lube"] = law(laws.at("height"), a);
    c.rec.extra["height_lajeunesse"] = law(laws.at("alternative_height"), a);
    if (std::isfinite(lube)) c.rec.add_metric("runout_rel_diff_lube", ok ? std::abs(c.runout - lube) / lube : kNaN, tol, why);
    if (std::isfinite(laj)) c.rec.add_metric("runout_rel_diff_lajeunesse", ok ? std::abs(c.runout - laj) / laj : kNaN, tol, why);
    summary.steps += c.rec.steps;
    summary.wall_s += c.rec.wall_s;
    summary.particles = std::max(summary.particles, c.rec.particles);
    summary.wall_particles = std::max(summary.wall_particles, c.rec.wall_particles);
    summary.threads = c.rec.threads;
    summary.options = c.rec.options;
    summary.stable = summary.stable && c.rec.stable;
    if (!c.rec.stable) summary.failure = c.rec.failure;
    out.push_back(std::move(c.rec));
  }

  summary.dx = dx;
  summary.dimension = 2;
  double psteps = 0;  // several particle counts: particle-steps summed over the per-a runs
  for (const auto& r : out) psteps += static_cast<double>(r.particles) * static_cast<double>(r.steps);
  summary.particle_steps_per_s = summary.wall_s > 0 ? psteps / summary.wall_s : 0;
  summary.extra["aspect_ratios"] = as;
  summary.extra["runout_normalised"] = runouts;
  summary.extra["height_normalised"] = heights;
  summary.extra["all_runs_stopped_inside"] = all_ok;

  const PowerFit r_small = fit_power(as, runouts, 0.0, small_max);
  const PowerFit r_large = fit_power(as, runouts, large_min, 1e9);
  const PowerFit h_large = fit_power(as, heights, large_min, 1e9);
  summary.extra["runout_exponent_small_a"] = r_small.exponent;
  summary.extra["runout_prefactor_small_a"] = r_small.prefactor;
  summary.extra["runout_exponent_large_a"] = r_large.exponent;
  summary.extra["runout_prefactor_large_a"] = r_large.prefactor;
  summary.extra["height_exponent_large_a"] = h_large.exponent;
  summary.extra["height_prefactor_large_a"] = h_large.prefactor;
  const auto score = [&](const std::string& name, const PowerFit& f, double expected) {
    add_case_metric(summary, cfg, name, std::abs(f.exponent - expected), all_ok && f.points >= 2);
    summary.extra[name.substr(0, name.size() - 6) + "_expected"] = expected;
  };
  score("runout_exponent_large_a_error", r_large, 2.0 / 3.0);
  score("runout_exponent_small_a_error", r_small, 1.0);
  score("height_exponent_large_a_error", h_large, 0.4);

  // curves: SPH points over the laws (sampled on their ranges of validity)
  summary.series.push_back({"SPH", "simulation", "runout_scaling", "a = H0/L0", "(L_inf - L0)/L0", as, runouts});
  summary.series.push_back({"SPH", "simulation", "height_scaling", "a = H0/L0", "H_inf/L0", as, heights});
  const double a_hi = as.empty() ? 1.0 : *std::max_element(as.begin(), as.end());
  const std::vector<std::tuple<std::string, std::string, std::string>> curves = {
      {"Lube et al. 2005", "runout", "runout_scaling"},
      {"Lajeunesse et al. 2005", "alternative_runout", "runout_scaling"},
      {"Lube et al. 2005", "height", "height_scaling"},
      {"Lajeunesse et al. 2005 (prefactor 1 assumed)", "alternative_height", "height_scaling"}};
  for (const auto& [label, key, plot] : curves) {
    Series s{label, "experiment", plot, "a = H0/L0", plot == "runout_scaling" ? "(L_inf - L0)/L0" : "H_inf/L0", {}, {}};
    for (int k = 0; k <= 100; ++k) {
      const double a = 0.3 + (a_hi - 0.3) * k / 100.0;
      const double v = law(laws.at(key), a);
      if (std::isfinite(v)) { s.x.push_back(a); s.y.push_back(v); }
    }
    summary.series.push_back(s);
  }
  out.insert(out.begin(), std::move(summary));
  return out;
}
}  // namespace

std::vector<Record> run_granular_collapse_scaling(const CaseContext& ctx, const std::string& case_name) {
  const CaseConfig cfg = load_case(ctx, case_name);
  const nlohmann::json laws = read_json_file(cfg.reference_file(ctx, cfg.spec.at("laws")));
  std::vector<Record> out;
  for (const SandModel& model : sand_models(cfg))
    for (double dx : cfg.level_numbers("dx")) {
      auto recs = scaling_at(cfg, ctx, laws, model, dx);
      out.insert(out.end(), std::make_move_iterator(recs.begin()), std::make_move_iterator(recs.end()));
    }
  return out;
}

GEOSPH_CASE_DRIVER(granular_collapse_scaling, run_granular_collapse_scaling);

}  // namespace geosph::verify
