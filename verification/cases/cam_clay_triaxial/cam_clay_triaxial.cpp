// Modified Cam Clay element tests (the solver's point model, soil/modified_cam_clay.*) in drained
// and undrained triaxial compression against the model's closed-form and quadrature solutions
// (reference/analytical/cam_clay_triaxial.*): one record per test and over-consolidation ratio.

#include <chrono>
#include <cmath>
#include <cstdio>

#include "analytical/cam_clay_triaxial.hpp"
#include "harness/case_record.hpp"
#include "harness/driver_registry.hpp"
#include "harness/element_test.hpp"
#include "harness/metrics.hpp"

namespace geosph::verify {

namespace {

struct Setup {
  soil::ModifiedCamClayParams params;
  reference::CamClaySoil soil;
  double p0, eps_end, out_every;
};

Setup setup_of(const CaseConfig& cfg) {
  const auto& m = cfg.spec.at("material");
  Setup s;
  s.params = {m.at("lambda"), m.at("kappa"), m.at("M"), m.at("poisson"), m.at("specific_volume"), m.at("min_pressure")};
  s.soil = {s.params.lambda, s.params.kappa, s.params.M, s.params.poisson, s.params.specific_volume};
  s.p0 = cfg.spec.at("initial_pressure_pa");
  s.eps_end = cfg.spec.at("axial_strain_end");
  s.out_every = cfg.spec.at("output_every");
  return s;
}

Record element_record(const CaseConfig& cfg, const CaseContext& ctx, const std::string& variant, double d,
                      const TriaxialPath& run, double wall_s) {
  Record rec = start_record(cfg, ctx);
  rec.variant = variant;
  rec.dx = d;  // the resolution of an element test is its strain increment
  rec.particles = 1;
  rec.steps = static_cast<long>(std::lround(cfg.spec.at("axial_strain_end").get<double>() / d));
  rec.wall_s = wall_s;
  rec.particle_steps_per_s = wall_s > 0 ? rec.steps / wall_s : 0;
  rec.stable = run.converged;
  if (!run.converged) rec.failure = {{"step", -1}, {"time", 0.0}, {"message", "a Modified Cam Clay return did not converge"}};
  rec.options["soil_model"] = "modified_cam_clay";
  rec.extra["max_return_iterations"] = run.max_iterations;
  return rec;
}

template <class F>
double timed(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

Record drained(const CaseConfig& cfg, const CaseContext& ctx, const Setup& s, double ocr, double d) {
  const soil::ModifiedCamClay model(s.params);
  TriaxialPath run;
  const double wall = timed([&] { run = mcc_drained_triaxial_run(model, s.p0, ocr, d, s.eps_end, s.out_every); });
  char name[48];
  std::snprintf(name, sizeof name, "drained OCR %g", ocr);
  Record rec = element_record(cfg, ctx, name, d, run, wall);
  const reference::CamClayTriaxialSpec spec{s.soil, s.p0, ocr};
  std::vector<double> q_ref, ev_ref;
  for (double ea : run.eps_a) {
    const auto pt = reference::mcc_drained_triaxial_at_axial_strain(spec, ea);
    q_ref.push_back(pt.q);
    ev_ref.push_back(pt.volumetric_strain);
  }
  const double p_cs = reference::mcc_drained_critical_p(spec);
  rec.series.push_back({"point model", "simulation", "drained_q", "axial strain", "q [kPa]", run.eps_a, {}});
  rec.series.push_back({"rate equations (GSL)", "analytical", "drained_q", "axial strain", "q [kPa]", run.eps_a, {}});
  for (std::size_t k = 0; k < q_ref.size(); ++k) { rec.series[0].y.push_back(run.q[k] / 1e3); rec.series[1].y.push_back(q_ref[k] / 1e3); }
  rec.series.push_back({"point model", "simulation", "drained_volumetric_strain", "axial strain", "volumetric strain", run.eps_a, run.eps_v});
  rec.series.push_back({"rate equations (GSL)", "analytical", "drained_volumetric_strain", "axial strain", "volumetric strain", run.eps_a, ev_ref});
  rec.extra["q_over_Mp_at_end"] = run.q.back() / (s.params.M * run.p.back());
  rec.extra["critical_state_p_pa"] = p_cs;
  rec.extra["max_lateral_stress_residual"] = run.max_lateral_residual;
  const bool ok = run.converged;
  for (const auto& [metric, value] :
       std::vector<std::pair<std::string, double>>{{"q_rel_l2", relative_l2(run.q, q_ref)},
                                                   {"volumetric_strain_rel_l2", relative_l2(run.eps_v, ev_ref)},
                                                   {"critical_state_p_rel_error", std::abs(run.p.back() - p_cs) / p_cs}})
    add_case_metric(rec, cfg, metric, value, ok);
  return rec;
}

Record undrained(const CaseConfig& cfg, const CaseContext& ctx, const Setup& s, double ocr, double d) {
  const soil::ModifiedCamClay model(s.params);
  TriaxialPath run;
  const double wall = timed([&] { run = mcc_undrained_triaxial_run(model, s.p0, ocr, d, s.eps_end, d); });
  char name[48];
  std::snprintf(name, sizeof name, "undrained OCR %g", ocr);
  Record rec = element_record(cfg, ctx, name, d, run, wall);
  const reference::CamClayTriaxialSpec spec{s.soil, s.p0, ocr};
  const auto fail = reference::mcc_undrained_failure(spec);
  const double plo = std::min(s.p0, fail.p), phi = std::max(s.p0, fail.p);
  double path_err = 0;
  Series sim{"point model", "simulation", "undrained_path", "p' [kPa]", "q [kPa]", {}, {}};
  const int every = static_cast<int>(std::lround(s.out_every / d));
  for (std::size_t k = 0; k < run.p.size(); ++k) {
    if (run.plastic[k]) {
      const double q_ref = reference::mcc_undrained_q(spec, std::min(phi, std::max(plo, run.p[k])));
      path_err = std::max(path_err, std::abs(run.q[k] - q_ref) / q_ref);
    }
    if ((static_cast<int>(k) + 1) % every == 0) { sim.x.push_back(run.p[k] / 1e3); sim.y.push_back(run.q[k] / 1e3); }
  }
  rec.series.push_back(sim);
  Series ref{"closed form", "analytical", "undrained_path", "p' [kPa]", "q [kPa]", {s.p0 / 1e3, s.p0 / 1e3}, {0.0, reference::mcc_undrained_yield_q(spec) / 1e3}};
  for (int k = 0; k <= 50; ++k) {
    const double p = s.p0 + (fail.p - s.p0) * k / 50.0;
    ref.x.push_back(p / 1e3);
    ref.y.push_back(reference::mcc_undrained_q(spec, std::min(phi, std::max(plo, p))) / 1e3);
  }
  rec.series.push_back(ref);
  rec.series.push_back({"critical state line q = M p'", "analytical", "undrained_path", "p' [kPa]", "q [kPa]",
                        {0.0, 1.2 * phi / 1e3}, {0.0, 1.2 * s.params.M * phi / 1e3}});
  rec.extra["failure_p_pa"] = fail.p;
  rec.extra["failure_q_pa"] = fail.q;
  rec.extra["end_p_pa"] = run.p.back();
  rec.extra["end_q_pa"] = run.q.back();
  const bool ok = run.converged;
  add_case_metric(rec, cfg, "undrained_path_rel_error", path_err, ok);
  add_case_metric(rec, cfg, "undrained_failure_rel_error",
                  std::abs(run.p.back() - fail.p) / fail.p + std::abs(run.q.back() - fail.q) / fail.q, ok);
  return rec;
}

}  // namespace

std::vector<Record> run_cam_clay_triaxial(const CaseContext& ctx, const std::string& case_name) {
  const CaseConfig cfg = load_case(ctx, case_name);
  const Setup s = setup_of(cfg);
  std::vector<Record> out;
  for (double d : cfg.level_numbers("strain_increment")) {
    for (double ocr : cfg.spec.at("drained_ocr").get<std::vector<double>>()) out.push_back(drained(cfg, ctx, s, ocr, d));
    for (double ocr : cfg.spec.at("undrained_ocr").get<std::vector<double>>()) out.push_back(undrained(cfg, ctx, s, ocr, d));
  }
  return out;
}

GEOSPH_CASE_DRIVER(cam_clay_triaxial, run_cam_clay_triaxial);

}  // namespace geosph::verify
