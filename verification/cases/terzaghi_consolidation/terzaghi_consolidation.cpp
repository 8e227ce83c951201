// Terzaghi one-dimensional consolidation of a saturated elastic layer, two-phase SPH (soil skeleton +
// pore water, coupling/seepage): a surcharge ramped onto the top of the layer is first carried by the
// pore water (B q) and then moves to the skeleton as the water drains through the top. The excess pore
// pressure isochrones and the degree of consolidation (from the settlement) are compared with the
// series solution with compressible water (reference/analytical/terzaghi_consolidation.hpp).

#include <algorithm>
#include <cmath>

#include "analytical/terzaghi_consolidation.hpp"
#include "boundary/drained_face.hpp"
#include "coupling/seepage.hpp"
#include "harness/case_record.hpp"
#include "harness/driver_registry.hpp"
#include "harness/metrics.hpp"
#include "harness/run_stats.hpp"

namespace geosph::verify {

namespace {

Record run_at(const CaseConfig& cfg, const CaseContext& ctx, double spacing) {
  const Scene scene = cfg.scene(spacing);
  const SoilMaterial& m = scene.soils.front();
  const FluidMaterial& w = scene.materials.front();
  const BodySpec* soil = nullptr;
  for (const auto& b : scene.bodies)
    if (b.surcharge.pressure > 0) soil = &b;
  if (!soil) throw std::runtime_error("terzaghi_consolidation: the scene's soil body needs a surcharge");
  const double H = soil->hi[1] - soil->lo[1], top = soil->hi[1], g = -scene.gravity[1];
  // double drainage (the container's bottom drained, boundary/drained_face.hpp): the layer drains to both
  // faces, each half as single drainage over H/2 (symmetric about mid-depth)
  bool bottom_drained = false;
  for (const auto& f : drained_faces(scene)) bottom_drained = bottom_drained || (f.axis == 1 && !f.upper);
  const double H_dr = bottom_drained ? 0.5 * H : H;
  const double gamma_w = Seepage(scene).unit_weight();  // defines k (standard gravity when the scene has none)
  const auto& el = m.as<materials::LinearElastic>().elastic;
  const double E_oed = el.young * (1 - el.poisson) / ((1 + el.poisson) * (1 - 2 * el.poisson));
  const double K_w = w.density * w.sound_speed * w.sound_speed;  // Tait: dp/drho at rho0 times rho0
  const reference::TerzaghiSpec ref = reference::terzaghi_spec(H_dr, m.hydraulic_conductivity, gamma_w, E_oed,
                                                               m.porosity, K_w, soil->surcharge.pressure,
                                                               soil->surcharge.ramp);
  const double Bq = ref.B * ref.load, s_inf = ref.load / E_oed * H;
  std::vector<double> T_iso = cfg.spec.at("isochrone_T").get<std::vector<double>>();
  std::sort(T_iso.begin(), T_iso.end());

  Simulation sim(scene);
  Record rec = start_record(cfg, ctx);
  const Particles& P0 = sim.particles();
  // the skeleton's top row (for the settlement), by particle id
  std::vector<long> top_ids;
  for (std::size_t i = 0; i < P0.size(); ++i)
    if (P0.kind[i] == Kind::Soil && P0.y[i] > top - scene.dx) top_ids.push_back(P0.id[i]);
  auto top_y = [&](const Particles& P) {
    double s = 0;
    int n = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.kind[i] == Kind::Soil && std::binary_search(top_ids.begin(), top_ids.end(), P.id[i])) { s += P.y[i]; ++n; }
    return n ? s / n : NAN;
  };
  std::sort(top_ids.begin(), top_ids.end());
  const double y_top0 = top_y(P0);

  // excess pore pressure of the water in rows of dx below the soil top, against hydrostatic
  const int rows = static_cast<int>(std::lround(H / scene.dx));
  auto excess_profile = [&](const Particles& P) {
    std::vector<double> sum(rows, 0.0);
    std::vector<int> cnt(rows, 0);
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (P.kind[i] != Kind::Fluid) continue;
      const int r = static_cast<int>(std::floor((top - P.y[i]) / scene.dx));
      if (r < 0 || r >= rows) continue;
      sum[r] += P.p[i] - w.density * g * (top - P.y[i]);  // hydrostatic part, if gravity is on
      ++cnt[r];
    }
    for (int r = 0; r < rows; ++r) sum[r] = cnt[r] ? sum[r] / cnt[r] : NAN;
    return sum;
  };

  std::vector<double> err_all;
  Series U_sph{"SPH (settlement)", "simulation", "degree_of_consolidation", "T = c_v t / H_dr^2", "U = s / s_inf", {}, {}};
  Series U_ref{"series solution", "analytical", "degree_of_consolidation", U_sph.xlabel, U_sph.ylabel, {}, {}};
  double next_U = 0, U_err_max = 0;
  std::size_t next_iso = 0;
  const double t_of_T = H_dr * H_dr / ref.cv;
  const bool ok = run_timed(sim, rec, [&](const Simulation& s) {
    const double t = s.time(), T = t / t_of_T;
    if (t >= next_U) {
      next_U += 0.02 * t_of_T;
      const double U = (y_top0 - top_y(s.particles())) / s_inf, Ur = reference::terzaghi_degree_of_consolidation(ref, t);
      U_sph.x.push_back(T); U_sph.y.push_back(U);
      U_ref.x.push_back(T); U_ref.y.push_back(Ur);
      if (t >= ref.ramp) U_err_max = std::max(U_err_max, std::abs(U - Ur));
    }
    if (next_iso < T_iso.size() && T >= T_iso[next_iso] * (1 - 1e-9)) {
      const auto u = excess_profile(s.particles());
      char name[64];
      std::snprintf(name, sizeof name, "T = %.2f", T_iso[next_iso]);
      Series sph{std::string("SPH ") + name, "simulation", "isochrones", "excess pore pressure / (B q)", "depth / H", {}, {}};
      Series an{std::string("series ") + name, "analytical", "isochrones", sph.xlabel, sph.ylabel, {}, {}};
      for (int r = 0; r < rows; ++r) {
        const double z = (r + 0.5) * scene.dx;
        const double ur = reference::terzaghi_excess_pressure(ref, std::min(z, 2 * H_dr - z), t);
        sph.x.push_back(u[r] / Bq); sph.y.push_back(-z / H);
        an.x.push_back(ur / Bq); an.y.push_back(-z / H);
        err_all.push_back(u[r] - ur);
      }
      rec.series.push_back(sph);
      rec.series.push_back(an);
      ++next_iso;
    }
  }, ctx.progress);
  rec.series.push_back(U_sph);
  rec.series.push_back(U_ref);
  const bool all_isochrones = ok && next_iso == T_iso.size();
  // rel. L2 over every row of every isochrone, in units of B q
  double e2 = 0;
  for (double e : err_all) e2 += e * e;
  const double iso_err = err_all.empty() ? NAN : std::sqrt(e2 / err_all.size()) / Bq;
  rec.extra["consolidation_coefficient_m2_s"] = ref.cv;
  rec.extra["pore_pressure_coefficient_B"] = ref.B;
  rec.extra["final_settlement_m"] = s_inf;
  rec.extra["H_over_dx"] = H / scene.dx;
  rec.extra["drainage_path_m"] = H_dr;
  rec.extra["drainage"] = bottom_drained ? "double (top: free water surface; bottom: drained side)" : "single (top)";
  add_case_metric(rec, cfg, "isochrone_rel_l2", iso_err, all_isochrones);
  add_case_metric(rec, cfg, "degree_of_consolidation_max_error", U_err_max, all_isochrones);
  rec.snapshot = pressure_snapshot(sim);
  return rec;
}

}  // namespace

// case.json "variants": the layer's permeability (so c_v) and the run's end, optionally the drained
// sides ("drained") and a scale of every modulus and the load ("stiffness_scale"); a variant's own
// "levels" entry, if any, replaces the case's spacings (the slow low-c_v runs at fewer of them).
std::vector<Record> run_terzaghi_consolidation(const CaseContext& ctx, const std::string& case_name) {
  const CaseConfig base = load_case(ctx, case_name);
  std::vector<Record> out;
  for (const auto& [name, v] : base.spec.at("variants").items()) {
    CaseConfig cfg = base;
    cfg.scene_json["materials"]["clay"]["hydraulic_conductivity"] = v.at("hydraulic_conductivity");
    cfg.scene_json["time"]["end"] = v.at("t_end");
    if (v.contains("drained")) cfg.scene_json["walls"]["containers"][0]["drained"] = v.at("drained");
    if (v.contains("stiffness_scale")) {
      // the same layer with the skeleton's and the water's moduli and the load scaled by a: B and the
      // strains are unchanged, c_v scales with a, the undrained column's period with 1/sqrt(a) (so the
      // load's ramp does too)
      const double a = v.at("stiffness_scale").get<double>();
      auto& js = cfg.scene_json;
      js["materials"]["clay"]["young_modulus"] = js["materials"]["clay"]["young_modulus"].get<double>() * a;
      js["materials"]["water"]["sound_speed"] = js["materials"]["water"]["sound_speed"].get<double>() * std::sqrt(a);
      for (auto& b : js["bodies"])
        if (b.contains("surcharge")) {
          b["surcharge"]["pressure"] = b["surcharge"]["pressure"].get<double>() * a;
          b["surcharge"]["ramp"] = b["surcharge"]["ramp"].get<double>() / std::sqrt(a);
        }
    }
    if (!cfg.use_variant_level(v, ctx.level)) continue;
    std::vector<Record> runs;
    for (double dx : cfg.level_numbers("dx")) {
      runs.push_back(run_at(cfg, ctx, dx));
      runs.back().variant = name;
    }
    annotate_observed_order(runs, cfg.spec.value("expected_order", -1.0));
    out.insert(out.end(), runs.begin(), runs.end());
  }
  return out;
}

GEOSPH_CASE_DRIVER(terzaghi_consolidation, run_terzaghi_consolidation);

}  // namespace geosph::verify
