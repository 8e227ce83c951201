// Elastic cantilever structure (structure body, linear_elastic) clamped at x = 0 (its root, a few
// particle columns at x < 0, is a fixed part of the same body), loaded by its own weight ramped up
// smoothly over two periods of the first mode; the tip deflection averaged over the next two periods
// is the static deflection, compared with Timoshenko beam theory (bending + shear):
//   delta = q L^4 / (8 E' I) + q L^2 / (2 kappa G A),  q = rho g H,  I = H^3/12,  A = H,  kappa = 5/6,
//   E' = E / (1 - nu^2) (plane strain).
// The bending moment at mid-span read from the stress (I times the slope of a least-squares line of
// sigma_xx against y over the particle column) is compared with statics, q (L - x)^2 / 2, at every
// spacing: the readout cantilever_sheet_pile makes of its pile.
// It checks the structure solid alone (no soil). As for oscillating_plate, the single-resolution
// error is first order in dx, so the scored metric is the Richardson-extrapolated deflection, with the
// order observed from three spacings (H/dx = 5, 10, 20 at the quick level).

#include <algorithm>
#include <cmath>
#include <numbers>

#include "harness/case_record.hpp"
#include "harness/driver_registry.hpp"
#include "harness/metrics.hpp"
#include "harness/run_stats.hpp"
#include "soil/soil_fields.hpp"

namespace geosph::verify {

namespace {

struct Beam {
  double L, H, E_plane, G, q, delta, omega;
};

Beam beam_theory(const Scene& scene) {
  const auto& body = scene.bodies.front();
  const SoilMaterial& m = scene.soils.front();
  const auto& el = m.as<materials::LinearElastic>().elastic;
  Beam b;
  b.L = body.hi[0] - body.lo[0];
  b.H = body.hi[1] - body.lo[1];
  b.E_plane = el.young / (1.0 - el.poisson * el.poisson);
  b.G = el.young / (2.0 * (1.0 + el.poisson));
  b.q = m.density * -scene.gravity[1] * b.H;
  const double I = b.H * b.H * b.H / 12.0, kappa = 5.0 / 6.0;
  b.delta = b.q * std::pow(b.L, 4) / (8.0 * b.E_plane * I) + b.q * b.L * b.L / (2.0 * kappa * b.G * b.H);
  const double k = 1.875 / b.L;  // first cantilever mode
  b.omega = std::sqrt(b.E_plane * I * std::pow(k, 4) / (m.density * b.H));
  return b;
}

Record run_at(const CaseConfig& cfg, const CaseContext& ctx, double spacing) {
  Scene scene = cfg.scene(spacing);
  const Beam b = beam_theory(scene);
  const double T = 2.0 * std::numbers::pi / b.omega;
  scene.gravity_ramp = cfg.spec.at("periods_ramp").get<double>() * T;
  const double t_avg = scene.gravity_ramp;
  scene.t_end = t_avg + cfg.spec.at("periods_average").get<double>() * T;
  Simulation sim(scene);
  const Particles& P0 = sim.particles();
  std::size_t tip = 0;
  double best = 1e300;
  for (std::size_t i = 0; i < P0.size(); ++i) {
    const double d = std::hypot(P0.x[i] - b.L, P0.y[i]);
    if (P0.kind[i] == Kind::Structure && d < best) { best = d; tip = i; }
  }
  const std::int64_t tip_id = P0.id[tip];
  const double y0 = P0.y[tip];
  // the particle column nearest mid-span: its bending moment read from the stress, against statics
  // M = q (L - x)^2 / 2 at the column's x (equilibrium of the span beyond it; no beam theory)
  double x_mid = 0;
  {
    double best_mid = 1e300;
    for (std::size_t i = 0; i < P0.size(); ++i)
      if (P0.kind[i] == Kind::Structure && std::abs(P0.x[i] - 0.5 * b.L) < best_mid) { best_mid = std::abs(P0.x[i] - 0.5 * b.L); x_mid = P0.x[i]; }
  }
  std::vector<std::int64_t> column;
  for (std::size_t i = 0; i < P0.size(); ++i)
    if (P0.kind[i] == Kind::Structure && std::abs(P0.x[i] - x_mid) < 0.25 * scene.dx) column.push_back(P0.id[i]);
  std::sort(column.begin(), column.end());
  // the column's particle indices in index order (the sums' order) and their ids, found again only when
  // the particles were reordered
  std::vector<std::size_t> col_index;
  std::vector<std::int64_t> col_id;
  const auto locate_column = [&](const Particles& P) {
    bool current = col_index.size() == column.size();
    for (std::size_t k = 0; current && k < col_index.size(); ++k) current = P.id[col_index[k]] == col_id[k];
    if (current) return;
    col_index.clear();
    col_id.clear();
    for (std::size_t i = 0; i < P.size(); ++i)
      if (std::binary_search(column.begin(), column.end(), P.id[i])) { col_index.push_back(i); col_id.push_back(P.id[i]); }
  };
  double msum = 0;
  Record rec = start_record(cfg, ctx);
  Series defl{"SPH tip", "simulation", "tip", "t / T", "tip deflection / theory", {}, {}};
  double sum = 0, weight = 0, t_prev = 0;
  const bool ok = run_timed(sim, rec, [&](const Simulation& s) {
    const Particles& P = s.particles();
    if (P.id[tip] != tip_id) tip = static_cast<std::size_t>(std::find(P.id.begin(), P.id.end(), tip_id) - P.id.begin());
    const double w = -(P.y[tip] - y0);
    if (defl.x.empty() || s.time() / T > defl.x.back() + 0.01) { defl.x.push_back(s.time() / T); defl.y.push_back(w / b.delta); }
    if (s.time() > t_avg) {
      const double dt_w = s.time() - std::max(t_prev, t_avg);
      sum += w * dt_w;
      weight += dt_w;
      // M = I * slope of the column's sigma_xx against y (least squares; the clockwise moment that holds
      // the span beyond, positive for a beam hanging under its weight)
      const auto& sxx = P.field(SoilFields::xx);
      locate_column(P);
      double ybar = 0, sbar = 0, n = 0;
      for (const std::size_t i : col_index) { ybar += P.y[i]; sbar += sxx[i]; n += 1; }
      ybar /= n; sbar /= n;
      double sy = 0, yy = 0;
      for (const std::size_t i : col_index) {
        sy += (sxx[i] - sbar) * (P.y[i] - ybar);
        yy += (P.y[i] - ybar) * (P.y[i] - ybar);
      }
      msum += b.H * b.H * b.H / 12.0 * sy / yy * dt_w;
    }
    t_prev = s.time();
  }, ctx.progress);
  const double delta_sph = weight > 0 ? sum / weight : NAN;
  rec.series.push_back(defl);
  rec.series.push_back({"Timoshenko static deflection", "analytical", "tip", defl.xlabel, defl.ylabel,
                        {0.0, defl.x.empty() ? 0.0 : defl.x.back()}, {1.0, 1.0}});
  rec.extra["deflection_sph_m"] = delta_sph;
  rec.extra["deflection_theory_m"] = b.delta;
  rec.extra["shear_part_of_theory"] = (b.q * b.L * b.L / (2.0 * 5.0 / 6.0 * b.G * b.H)) / b.delta;
  rec.extra["H_over_dx"] = b.H / scene.dx;
  const double m_statics = b.q * (b.L - x_mid) * (b.L - x_mid) / 2.0;
  rec.extra["midspan_x_m"] = x_mid;
  rec.extra["midspan_moment_statics_N"] = m_statics;
  rec.extra["midspan_moment_from_stress_N"] = weight > 0 ? msum / weight : NAN;
  rec.extra["midspan_moment_ratio"] = weight > 0 ? msum / weight / m_statics : NAN;
  add_case_metric(rec, cfg, "deflection_rel_error", std::abs(delta_sph - b.delta) / b.delta, ok);
  rec.snapshot = field_snapshot(sim, SoilFields::xx, "Pa");
  return rec;
}

}  // namespace

// Every spacing of the level (coarse to fine); the scored metric, on the finest record, is the
// Richardson-extrapolated deflection; the coarser records are steps of it (unscored).
std::vector<Record> run_cantilever_beam(const CaseContext& ctx, const std::string& case_name) {
  const CaseConfig cfg = load_case(ctx, case_name);
  std::vector<Record> out;
  std::vector<double> spacings, deflections;
  double moment_error = 0;  // the largest over the spacings
  for (double dx : cfg.level_numbers("dx")) {
    out.push_back(run_at(cfg, ctx, dx));
    const double e = std::abs(out.back().extra["midspan_moment_ratio"].get<double>() - 1.0);
    moment_error = std::isfinite(e) ? std::max(moment_error, e) : INFINITY;
    spacings.push_back(dx);
    deflections.push_back(out.back().extra["deflection_sph_m"].get<double>());
  }
  for (std::size_t k = 0; k + 1 < out.size(); ++k) out[k].scored = false;
  Record& fine = out.back();
  const Extrapolation ex = richardson(spacings, deflections, cfg.spec.value("expected_order", 1.0));
  const double theory = fine.extra["deflection_theory_m"];
  fine.extra["deflection_extrapolated_m"] = ex.value;
  fine.extra["extrapolation_order"] = ex.order;
  // for transparency: the same extrapolation with the assumed first order (two finest spacings)
  fine.extra["deflection_extrapolated_first_order_m"] =
      richardson({spacings.end()[-2], spacings.back()}, {deflections.end()[-2], deflections.back()}, 1.0).value;
  const bool all_stable = std::all_of(out.begin(), out.end(), [](const Record& r) { return r.stable; });
  fine.metrics.clear();
  add_case_metric(fine, cfg, "extrapolated_deflection_rel_error", std::abs(ex.value - theory) / theory, all_stable);
  add_case_metric(fine, cfg, "midspan_moment_rel_error", moment_error, all_stable);
  return out;
}

GEOSPH_CASE_DRIVER(cantilever_beam, run_cantilever_beam);

}  // namespace geosph::verify
