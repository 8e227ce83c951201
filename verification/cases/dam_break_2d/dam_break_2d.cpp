// 2D dam break: a water column of width a and height 2a collapses in a tank of length 4a. The
// surge-front position Z = x/a against T = t sqrt(2g/a) is compared with the experiments of
// Martin & Moyce (1952) and Koshizuka & Oka (1996) up to the impact on the far wall.
#include "cases/dam_break_2d/dam_break_2d.hpp"

#include <algorithm>
#include <cmath>

#include "harness/catalogue.hpp"
#include "harness/metrics.hpp"
#include "harness/run_stats.hpp"

namespace geosph::verify {

namespace {
// Front = largest x of the fluid particles within 2 dx of the floor (ignores isolated spray).
double front_position(const Particles& P, double floor_y, double dx) {
  double xmax = -1e300;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::Fluid && P.y[i] < floor_y + 2 * dx) xmax = std::max(xmax, P.x[i]);
  return xmax;
}
}  // namespace

std::vector<Record> run_dam_break_2d(const CaseContext& ctx) {
  const CaseConfig cfg = load_case(ctx, "dam_break_2d");
  Scene scene = cfg.scene(cfg.level_number("dx"));
  Simulation sim(scene);
  Record rec = start_record(cfg, ctx);
  const auto& col = scene.bodies.front();
  const double a = col.hi[0] - col.lo[0], g = -scene.gravity[1];
  const double t_scale = std::sqrt(2 * g / a);

  Series front{"SPH", "simulation", "front", "T = t sqrt(2g/a)", "Z = x/a", {0.0}, {1.0}};
  double next_sample = 0.0;
  const double sample_dt = 0.002;
  const bool ok = run_timed(sim, rec, [&](const Simulation& s) {
    if (s.time() < next_sample) return;
    next_sample += sample_dt;
    front.x.push_back(s.time() * t_scale);
    front.y.push_back((front_position(s.particles(), col.lo[1], scene.dx) - col.lo[0]) / a);
  }, ctx.progress);
  rec.series.push_back(front);

  const double T_end = scene.t_end * t_scale;
  for (const auto& [metric, file, label] :
       {std::tuple{"front_rel_l2_koshizuka_oka", "experimental/dam_break_koshizuka_oka_1996.csv", "Koshizuka & Oka 1996"},
        std::tuple{"front_rel_l2_martin_moyce", "experimental/dam_break_martin_moyce_1952.csv", "Martin & Moyce 1952"}}) {
    const Csv data = read_csv(cfg.reference_file(ctx, file).string());
    const auto &T = data.column("T"), &Z = data.column("Z");
    Series exp{label, "experiment", "front", front.xlabel, front.ylabel, {}, {}};
    std::vector<double> zs, ze;
    for (std::size_t k = 0; k < T.size(); ++k) {
      exp.x.push_back(T[k]); exp.y.push_back(Z[k]);
      // compare before the front reaches the far wall (Z < 4) and within the simulated time
      if (T[k] <= 0 || T[k] > T_end || Z[k] >= 4.0) continue;
      ze.push_back(Z[k]);
      zs.push_back(interpolate(front.x, front.y, T[k]));
    }
    rec.series.push_back(exp);
    const auto& tol = cfg.tolerance(metric);
    rec.add_metric(metric, ok && !zs.empty() ? relative_l2(zs, ze) : NAN, tol.value, tol.why);
  }
  rec.snapshot = pressure_snapshot(sim);
  return {rec};
}

}  // namespace geosph::verify
