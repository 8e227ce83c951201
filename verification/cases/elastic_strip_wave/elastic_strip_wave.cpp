// Compression pulse in a free elastic strip (plane strain): the strip starts at rest with a Gaussian
// velocity pulse, which splits into two halves; the right-going half's energy centroid is tracked and
// its speed fitted, against the plate velocity with Love's lateral-inertia correction (case.json).
// Variants: the strip's width, the kernel-gradient correction, and the strip repeated across (periodic:
// a plane P wave, no free sides).

#include <algorithm>
#include <cmath>

#include "harness/case_record.hpp"
#include "harness/driver_registry.hpp"
#include "harness/metrics.hpp"
#include "harness/run_stats.hpp"

namespace geosph::verify {

namespace {

Record run_variant(const CaseConfig& base, const CaseContext& ctx, const std::string& name, double spacing) {
  CaseConfig cfg = base;
  const auto& v = cfg.spec.at("variants").at(name);
  const double W = v.at("width").get<double>();
  cfg.scene_json["bodies"][0]["max"][1] = W;
  cfg.scene_json["domain"]["max"][1] = W + 0.1;
  cfg.scene_json["numerics"]["kernel_gradient_correction"] = v.at("kernel_gradient_correction").get<bool>();
  cfg.scene_json["numerics"]["kernel_gradient_correction_stress"] = v.value("kernel_gradient_correction_stress", false);
  // "laterally_periodic": the strip repeated across (no free sides): a plane wave at the constrained
  // (P-wave) speed, the control that isolates the free sides' effect
  const bool periodic = v.value("laterally_periodic", false);
  if (periodic) {
    cfg.scene_json["domain"]["min"][1] = 0.0;
    cfg.scene_json["domain"]["max"][1] = W;
    cfg.scene_json["domain"]["periodic"] = {"y"};
  }
  const Scene scene = cfg.scene(spacing);
  const SoilMaterial& mat = scene.soils.front();
  const auto& el = mat.as<materials::LinearElastic>().elastic;
  const double nu = el.poisson, cp = std::sqrt(el.young / (mat.density * (1 - nu * nu)));
  const auto& pulse = cfg.spec.at("pulse");
  const double x0 = pulse.at("x0"), w = pulse.at("width"), V0 = pulse.at("velocity_over_cp").get<double>() * cp;
  const double nup = nu / (1 - nu), b = 0.5 * W;
  const double M = el.young * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  const double c_ref = periodic ? std::sqrt(M / mat.density)  // P wave: no dispersion
                                : cp * (1 - nup * nup * b * b / (4 * w * w));  // group velocity over the pulse's spectrum

  Simulation sim(scene);
  Particles& P = sim.particles();
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::Soil) P.vx[i] = V0 * std::exp(-0.5 * (P.x[i] - x0) * (P.x[i] - x0) / (w * w));

  Record rec = start_record(cfg, ctx);
  rec.variant = name;
  rec.scored = v.value("scored", true);  // the uncorrected strips are recorded as studies
  Series X{"SPH: energy centroid of the right pulse", "simulation", "centroid", "t [s]", "x [m]", {}, {}};
  Series Xr{"reference speed", "analytical", "centroid", X.xlabel, X.ylabel, {}, {}};
  const double t_fit = 3 * w / cp;  // the halves have separated (3 standard deviations each way)
  double next = 0;
  const bool ok = run_timed(sim, rec, [&](const Simulation& s) {
    if (s.time() < next) return;
    next += scene.t_end / 200;
    const Particles& Q = s.particles();
    double e = 0, ex = 0;
    for (std::size_t i = 0; i < Q.size(); ++i)
      if (Q.kind[i] == Kind::Soil && Q.x[i] > x0) {
        const double k = Q.m[i] * Q.vx[i] * Q.vx[i];
        e += k;
        ex += k * Q.x[i];
      }
    if (s.time() >= t_fit && e > 0) { X.x.push_back(s.time()); X.y.push_back(ex / e); }
  }, ctx.progress);
  // least-squares slope of the centroid
  double c_sph = NAN;
  if (X.x.size() > 2) {
    double mt = 0, mx = 0;
    for (std::size_t k = 0; k < X.x.size(); ++k) { mt += X.x[k]; mx += X.y[k]; }
    mt /= X.x.size(); mx /= X.x.size();
    double stt = 0, stx = 0;
    for (std::size_t k = 0; k < X.x.size(); ++k) {
      stt += (X.x[k] - mt) * (X.x[k] - mt);
      stx += (X.x[k] - mt) * (X.y[k] - mx);
    }
    c_sph = stx / stt;
    for (double t : {X.x.front(), X.x.back()}) { Xr.x.push_back(t); Xr.y.push_back(mx + c_ref * (t - mt)); }
  }
  // the right pulse's largest velocity at the end, over V0/2
  double vmax = 0;
  for (std::size_t i = 0; i < sim.particles().size(); ++i)
    if (sim.particles().kind[i] == Kind::Soil && sim.particles().x[i] > x0) vmax = std::max(vmax, sim.particles().vx[i]);
  rec.series.push_back(X);
  rec.series.push_back(Xr);
  rec.extra["width_m"] = W;
  rec.extra["particles_across"] = W / scene.dx;
  rec.extra["plate_velocity_m_s"] = cp;
  rec.extra["reference_speed_m_s"] = c_ref;
  rec.extra["sph_speed_m_s"] = c_sph;
  rec.extra["speed_over_plate_velocity"] = c_sph / cp;
  rec.extra["peak_velocity_over_half_pulse"] = vmax / (0.5 * V0);
  add_case_metric(rec, cfg, "wave_speed_rel_error", std::abs(c_sph - c_ref) / c_ref, ok && std::isfinite(c_sph));
  rec.snapshot = field_snapshot(sim, "speed", "m/s");
  return rec;
}

}  // namespace

// Each variant at the level's spacings, or at its own where its "levels" entry names this level (the
// wide strip's finest spacing at the full level only).
std::vector<Record> run_elastic_strip_wave(const CaseContext& ctx, const std::string& case_name) {
  return run_each_variant(ctx, case_name, run_variant);
}

GEOSPH_CASE_DRIVER(elastic_strip_wave, run_elastic_strip_wave);

}  // namespace geosph::verify
