// Hydrostatic tank: water in a tank with dummy-particle walls, started in its hydrostatic state,
// must hold it: the particle pressures, averaged over the last quarter of a 1 s run (about 12
// acoustic periods 4H/c0), are compared with the hydrostatic profile of the same Tait fluid
// computed independently (reference/analytical/hydrostatic_tait.hpp), and no particle may leave.
// (Started at rest at uniform density instead, the column is still settling after 2 s with this
// artificial viscosity; see the closing note of issue 2.)

#include <algorithm>
#include <cmath>

#include "analytical/hydrostatic_tait.hpp"
#include "harness/case_record.hpp"
#include "harness/driver_registry.hpp"
#include "harness/hydrostatic_profile.hpp"
#include "harness/metrics.hpp"
#include "harness/run_stats.hpp"

namespace geosph::verify {

namespace {
Record run_at(const CaseConfig& cfg, const CaseContext& ctx, double spacing) {
  Scene scene = cfg.scene(spacing);
  Simulation sim(scene);
  Record rec = start_record(cfg, ctx);

  const auto& body = scene.bodies.front();
  const auto& wall = scene.walls.containers.front();
  const double H0 = body.hi[1] - body.lo[1], g = -scene.gravity[1];
  const auto& water = scene.materials.front();
  const reference::HydrostaticTait ref(water.density, water.sound_speed, water.gamma, g, H0);

  // time-average pressure and height of every fluid particle over the last quarter
  FluidTimeAverage avg(sim.particles().size(), 0.75 * scene.t_end);
  const bool ok = run_timed(sim, rec, [&](const Simulation& s) { avg.sample(s.particles(), s.time()); }, ctx.progress);

  if (ok && avg.samples() > 0) {
    HydrostaticProfile profile(ref, scene.dx);
    avg.for_each([&](double p, double, double y, double) { profile.add(p, y); });
    add_case_metric(rec, cfg, "pressure_rel_l2", relative_l2(profile.simulated(), profile.reference()));

    long leaked = 0;
    const auto& P = sim.particles();
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.kind[i] == Kind::Fluid && (P.x[i] < wall.lo[0] || P.x[i] > wall.hi[0] || P.y[i] < wall.lo[1])) ++leaked;
    add_case_metric(rec, cfg, "leaked_particles", static_cast<double>(leaked));
    // spurious currents, recorded for information (no published bound to test against)
    rec.extra["max_speed_over_sqrt_gH"] = avg.max_speed() / std::sqrt(g * H0);
    rec.series = profile.series();
    rec.extra["settled_surface_height_m"] = ref.surface_height();
  } else {
    add_case_metric(rec, cfg, "pressure_rel_l2", 0.0, false);
  }
  rec.snapshot = pressure_snapshot(sim);
  return rec;
}
}  // namespace

std::vector<Record> run_hydrostatic_tank(const CaseContext& ctx, const std::string& case_name) { return run_each_spacing(ctx, case_name, run_at); }

GEOSPH_CASE_DRIVER(hydrostatic_tank, run_hydrostatic_tank);

}  // namespace geosph::verify
