// Example (unscored): a slope written as one polygon fails and runs out onto the valley floor. The
// record holds the run-out of the toe, the final crest height, the ground surface before and after
// (the highest soil particle of each dx column plus dx/2) and the plastic strain of the final state.

#include <algorithm>
#include <cmath>
#include <map>

#include "harness/case_record.hpp"
#include "harness/driver_registry.hpp"
#include "harness/run_stats.hpp"
#include "soil/soil_fields.hpp"

namespace geosph::verify {

namespace {

Series surface(const Particles& P, double dx, const std::string& name, const std::string& role) {
  std::map<long, double> top;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Soil) continue;
    const long c = std::lround(std::floor(P.x[i] / dx));
    auto [it, fresh] = top.try_emplace(c, P.y[i]);
    if (!fresh) it->second = std::max(it->second, P.y[i]);
  }
  Series s{name, role, "surface", "x [m]", "ground surface y [m]", {}, {}};
  for (const auto& [c, y] : top) {
    s.x.push_back((c + 0.5) * dx);
    s.y.push_back(y + 0.5 * dx);
  }
  return s;
}

Record run_at(const CaseConfig& cfg, const CaseContext& ctx, double spacing) {
  const Scene scene = cfg.scene(spacing);
  Simulation sim(scene);
  Record rec = start_record(cfg, ctx);
  rec.scored = false;
  const Series before = surface(sim.particles(), spacing, "ground at t = 0", "simulation");
  const double toe0 = scene.bodies.front().hi[0];
  run_timed(sim, rec, nullptr, ctx.progress);
  const auto& P = sim.particles();
  double xmax = -1e300, crest = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Soil) continue;
    xmax = std::max(xmax, P.x[i]);
    if (P.x[i] < 0.5 * toe0) crest = std::max(crest, P.y[i] + 0.5 * spacing);
  }
  rec.extra["runout_beyond_toe_m"] = xmax + 0.5 * spacing - toe0;
  rec.extra["final_crest_height_m"] = crest;
  rec.extra["simulated_time_s"] = sim.time();
  rec.series = {before, surface(P, spacing, "ground at t = " + std::to_string(sim.time()).substr(0, 4) + " s", "simulation")};
  rec.snapshot = field_snapshot(sim, SoilFields::plastic_strain, "-");
  return rec;
}

}  // namespace

std::vector<Record> run_landslide_runout_example(const CaseContext& ctx, const std::string& case_name) {
  return run_each_spacing(ctx, case_name, run_at);
}

GEOSPH_CASE_DRIVER(landslide_runout_example, run_landslide_runout_example);

}  // namespace geosph::verify
