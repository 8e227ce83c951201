// Strip footing on weightless undrained clay, phi = 0: Drucker-Prager (von Mises matched to Tresca in
// plane strain, sqrt(J2) = c) or Mohr-Coulomb (Tresca itself; case strip_footing_mohr_coulomb): a rigid block of width B is pushed into the soil at a
// constant slow speed; the bearing pressure q (mean -sigma_yy of the soil rows within 2 dx below
// the base, |x - x_c| < B/2) rises to a limit that Prandtl's mechanism gives as (2 + pi) c.

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

Record run_at(const CaseConfig& cfg, const CaseContext& ctx, double spacing) {
  Scene scene = cfg.scene(spacing);
  const double dx = scene.dx, B = cfg.spec.at("footing_width");
  const auto& footing = scene.walls.blocks.front();
  const double xc = 0.5 * (footing.lo[0] + footing.hi[0]), y_base0 = footing.lo[1], v = -footing.velocity[1];
  const double c = std::visit([&](const auto& model) -> double {  // Drucker-Prager or Mohr-Coulomb with phi = 0
    if constexpr (requires { model.cohesion; }) return model.cohesion;
    else scene.soils.front().throw_wrong_model("drucker_prager or mohr_coulomb");
  }, scene.soils.front().model);
  const double q_prandtl = (2.0 + std::numbers::pi) * c;
  Simulation sim(scene);
  Record rec = start_record(cfg, ctx);

  Series curve{"SPH", "simulation", "load", "settlement / B", "q / c", {0.0}, {0.0}};
  double q_max = 0, s_at_max = 0, next = 0;
  const bool ok = run_timed(sim, rec, [&](const Simulation& s) {
    if (s.time() < next) return;
    next += 0.002;
    const Particles& P = s.particles();
    const auto& syy = P.extra_fields().at(SoilFields::yy);
    const double y_base = y_base0 - v * s.time();
    double sum = 0;
    int count = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.kind[i] == Kind::Soil && std::abs(P.x[i] - xc) < 0.5 * B && P.y[i] < y_base && P.y[i] > y_base - 2 * dx) {
        sum += -syy[i];
        ++count;
      }
    const double q = count > 0 ? sum / count : 0.0;
    const double settlement = v * s.time();
    curve.x.push_back(settlement / B);
    curve.y.push_back(q / c);
    if (q > q_max) { q_max = q; s_at_max = settlement; }
  }, ctx.progress);
  rec.series.push_back(curve);
  rec.series.push_back({"Prandtl (2 + pi) c", "analytical", "load", curve.xlabel, curve.ylabel,
                        {0.0, curve.x.back()}, {2.0 + std::numbers::pi, 2.0 + std::numbers::pi}});
  rec.extra["q_max_over_c"] = q_max / c;
  rec.extra["settlement_at_q_max_over_B"] = s_at_max / B;
  rec.extra["footing_width_over_dx"] = B / dx;
  add_case_metric(rec, cfg, "bearing_capacity_rel_error", std::abs(q_max - q_prandtl) / q_prandtl, ok);
  rec.snapshot = field_snapshot(sim, SoilFields::plastic_strain, "-");
  return rec;
}

}  // namespace

std::vector<Record> run_strip_footing(const CaseContext& ctx, const std::string& case_name) { return run_each_spacing(ctx, case_name, run_at); }

GEOSPH_CASE_DRIVER(strip_footing, run_strip_footing);

}  // namespace geosph::verify
