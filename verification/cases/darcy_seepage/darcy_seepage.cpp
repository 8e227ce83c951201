// Darcy seepage through a saturated soil column (two-phase SPH, coupling/seepage): water driven through
// a held (fixed) skeleton by a constant hydraulic gradient i, imposed as a body force i g on the water in
// a column periodic along the flow (the head drop over one period is i L, the pressure itself periodic).
// Variants (case.json "variants"): a uniform soil at several permeabilities, q = k i; two layers in series
// with a permeability contrast, q = i L / (L1/k1 + L2/k2) (the harmonic mean), with the piecewise-linear
// pore pressure between them.

#include <algorithm>
#include <cmath>

#include "coupling/seepage.hpp"
#include "harness/case_record.hpp"
#include "harness/driver_registry.hpp"
#include "harness/metrics.hpp"
#include "harness/run_stats.hpp"

namespace geosph::verify {

namespace {

Record run_variant(const CaseConfig& base, const CaseContext& ctx, const std::string& variant, double spacing) {
  CaseConfig cfg = base;
  const auto& v = cfg.spec.at("variants").at(variant);
  cfg.scene_json["materials"]["lower"]["hydraulic_conductivity"] = v.at("k_lower");
  cfg.scene_json["materials"]["upper"]["hydraulic_conductivity"] = v.at("k_upper");
  cfg.scene_json["time"]["end"] = v.at("t_end");
  const Scene scene = cfg.scene(spacing);
  const double k1 = v.at("k_lower").get<double>(), k2 = v.at("k_upper").get<double>();
  const double L = scene.domain.length(1), L1 = scene.bodies[1].hi[1] - scene.bodies[1].lo[1], L2 = L - L1;
  const double gamma_w = Seepage(scene).unit_weight(), rho_w = scene.materials.front().density;
  const double i = -scene.body_force[1] * rho_w / gamma_w;  // hydraulic gradient, upward flow is negative y
  const double q_ref = -i * L / (L1 / k1 + L2 / k2);         // specific discharge along y
  const bool layered = k1 != k2;

  Simulation sim(scene);
  Record rec = start_record(cfg, ctx);
  rec.variant = variant;
  auto discharge = [&](const Particles& P, double ylo, double yhi) {  // mixture-volume mean of n v_y
    const auto& n = P.extra_fields().at(SeepageFields::porosity);
    double qv = 0, vol = 0;
    for (std::size_t j = 0; j < P.size(); ++j)
      if (P.kind[j] == Kind::Fluid && P.y[j] >= ylo && P.y[j] < yhi) {
        const double V = P.m[j] / P.rho[j];
        qv += V * n[j] * P.vy[j];
        vol += V;
      }
    return vol > 0 ? qv / vol : NAN;
  };
  Series hist{"SPH", "simulation", "discharge_history", "t [s]", "q / q_Darcy", {}, {}};
  double next = 0;
  const double t_end = scene.t_end;
  const bool ok = run_timed(sim, rec, [&](const Simulation& s) {
    if (s.time() < next) return;
    next += t_end / 50;
    hist.x.push_back(s.time());
    hist.y.push_back(discharge(s.particles(), -1e300, 1e300) / q_ref);
  }, ctx.progress);
  rec.series.push_back(hist);
  const Particles& P = sim.particles();
  const double q = discharge(P, -1e300, 1e300);
  // discharge per row: continuity makes it uniform along the column
  const int rows = static_cast<int>(std::lround(L / scene.dx));
  double row_dev = 0;
  Series qrow{"SPH", "simulation", "discharge_profile", "q / q_Darcy", "y [m]", {}, {}};
  for (int r = 0; r < rows; ++r) {
    const double y0 = scene.domain.lo[1] + r * scene.dx, qr = discharge(P, y0, y0 + scene.dx);
    qrow.x.push_back(qr / q_ref); qrow.y.push_back(y0 + 0.5 * scene.dx);
    row_dev = std::max(row_dev, std::abs(qr / q_ref - 1.0));
  }
  rec.series.push_back(qrow);
  if (layered) {
    // pore pressure (mean removed: a periodic column fixes it only up to a constant): in layer m the
    // gradient is dp/dy = rho_w f_y - gamma_w q / k_m (Darcy with the body force)
    Series sp{"SPH", "simulation", "pressure_profile", "p - mean [Pa]", "y [m]", {}, {}};
    Series an{"Darcy, layers in series", "analytical", "pressure_profile", sp.xlabel, sp.ylabel, {}, {}};
    const double y_if = scene.bodies[1].hi[1], f = scene.body_force[1];
    auto p_exact = [&](double y) {  // from y = 0 upward, up to a constant
      const double g1 = rho_w * f - gamma_w * q_ref / k1, g2 = rho_w * f - gamma_w * q_ref / k2;
      return y < y_if ? g1 * y : g1 * y_if + g2 * (y - y_if);
    };
    std::vector<double> ps, pe, ys;
    for (std::size_t j = 0; j < P.size(); ++j)
      if (P.kind[j] == Kind::Fluid) { ps.push_back(P.p[j]); pe.push_back(p_exact(P.y[j])); ys.push_back(P.y[j]); }
    double ms = 0, me = 0;
    for (std::size_t j = 0; j < ps.size(); ++j) { ms += ps[j]; me += pe[j]; }
    ms /= ps.size(); me /= pe.size();
    for (int r = 0; r < rows; ++r) {
      const double yc = scene.domain.lo[1] + (r + 0.5) * scene.dx;
      double s = 0; int c = 0;
      for (std::size_t j = 0; j < ps.size(); ++j)
        if (std::abs(ys[j] - yc) < 0.5 * scene.dx) { s += ps[j] - ms; ++c; }
      sp.x.push_back(c ? s / c : NAN); sp.y.push_back(yc);
      an.x.push_back(p_exact(yc) - me); an.y.push_back(yc);
    }
    rec.series.push_back(sp);
    rec.series.push_back(an);
    for (double& x : ps) x -= ms;
    for (double& x : pe) x -= me;
    rec.extra["pressure_rel_l2"] = relative_l2(ps, pe);
  }
  rec.extra["k_lower_m_s"] = k1;
  rec.extra["k_upper_m_s"] = k2;
  rec.extra["hydraulic_gradient"] = i;
  rec.extra["discharge_m_s"] = q;
  rec.extra["discharge_darcy_m_s"] = q_ref;
  rec.extra["row_discharge_max_deviation"] = row_dev;
  add_case_metric(rec, cfg, layered ? "layered_discharge_rel_error" : "discharge_rel_error",
                  std::abs(q / q_ref - 1.0), ok);
  return rec;
}

}  // namespace

std::vector<Record> run_darcy_seepage(const CaseContext& ctx, const std::string& case_name) { return run_each_variant(ctx, case_name, run_variant); }

GEOSPH_CASE_DRIVER(darcy_seepage, run_darcy_seepage);

}  // namespace geosph::verify
