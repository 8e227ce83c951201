// Retaining wall against a LIGGGHTS DEM reference (reference/dem/retaining_wall_2d.in): a smooth rigid
// wall standing on a rough (no-slip) floor is translated slowly away from (active) or into (passive) a
// dry granular backfill held by a smooth far wall; the same geometry, wall speed and travel as the DEM
// run. Scored against the DEM: the earth-pressure coefficient at the end of the travel and the angle of
// the failure wedge's slip line, both normalised and detected as reference/dem/postprocess.py does for
// the grains: K = F / (0.5 gamma0 H0^2) (gamma0 H0: the weight per unit floor area, H0: the height
// before the move); the slip line from the horizontal displacements (harness/slip_line.hpp).
// Rankine's K and planes at 45 +/- phi/2 (smooth wall, horizontal surface) are recorded beside them.

#include <algorithm>
#include <cmath>
#include <numbers>

#include "coupling/soil_structure_contact.hpp"
#include "harness/case_record.hpp"
#include "harness/driver_registry.hpp"
#include "harness/metrics.hpp"
#include "harness/run_stats.hpp"
#include "harness/slip_line.hpp"
#include "soil/soil_fields.hpp"

namespace geosph::verify {

namespace {

Record run_at(const CaseConfig& cfg, const CaseContext& ctx, const std::string& variant, double dx) {
  const nlohmann::json& v = cfg.spec.at("variants").at(variant);
  Scene scene = cfg.scene(dx);
  std::size_t wall_body = 0, soil_body = 0;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) (scene.bodies[b].structure ? wall_body : soil_body) = b;
  BodySpec& wall = scene.bodies[wall_body];
  const double speed = v.at("wall_velocity").get<double>(), travel = v.at("wall_travel").get<double>();
  if (speed == 0 || travel <= 0)
    throw InputError((cfg.dir / "case.json").string() + ": field 'variants." + variant +
                     "': wall_velocity must be non-zero and wall_travel > 0");
  wall.motion.velocity[0] = speed;
  // the time to the travel at full speed, plus half the start-up ramp that the wall spends below it
  scene.t_end = travel / std::abs(speed) + 0.5 * wall.motion.ramp;
  const bool active = speed < 0;
  const BodySpec& soil = scene.bodies[soil_body];
  const SoilMaterial& sand = scene.soils.front();
  const double H0 = soil.hi[1] - soil.lo[1], Lb = soil.hi[0] - soil.lo[0];
  const double gamma0 = sand.density * -scene.gravity[1];
  const double phi = sand.as<materials::DruckerPrager>().friction_angle;
  const double sphi = std::sin(phi * std::numbers::pi / 180.0);
  const double K_rankine = active ? (1 - sphi) / (1 + sphi) : (1 + sphi) / (1 - sphi);
  const double angle_rankine = active ? 45 + 0.5 * phi : 45 - 0.5 * phi;

  Simulation sim(scene);
  std::vector<double> x0, y0;  // initial soil positions by particle id
  {
    const Particles& P = sim.particles();
    x0.assign(P.size(), NAN);
    y0.assign(P.size(), NAN);
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.kind[i] == Kind::Soil) { x0[P.id[i]] = P.x[i] - soil.lo[0]; y0[P.id[i]] = P.y[i] - soil.lo[1]; }
  }
  Record rec = start_record(cfg, ctx);
  rec.variant = variant;
  Series curve{"SPH", "simulation", "force", "wall displacement / H", "K = F / (0.5 gamma0 H0^2)", {}, {}};
  double K_sum = 0, next = 0;
  long samples = 0;
  const double t_avg = scene.t_end - 0.1 * travel / std::abs(speed);  // the last 10% of the travel
  const bool ok = run_timed(sim, rec, [&](const Simulation& s) {
    if (s.time() < next && s.time() < t_avg) return;
    // |x-force| of the soil on the wall
    const double K = std::abs(SoilStructureContact::body_force(s.particles(), wall_body)[0]) / (0.5 * gamma0 * H0 * H0);
    if (s.time() >= t_avg) { K_sum += K; ++samples; }  // every step of the last 10% of the travel
    if (s.time() < next) return;
    next += scene.t_end / 200;
    curve.x.push_back(std::abs(s.rigid_motions()->displacement(wall_body)[0]) / H0);
    curve.y.push_back(K);
  }, ctx.progress);
  const double K_sph = samples > 0 ? K_sum / samples : NAN;
  const double moved = sim.rigid_motions()->displacement(wall_body)[0];

  std::vector<double> xi, yi, ux;
  const Particles& P = sim.particles();
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Soil || std::isnan(x0[P.id[i]])) continue;
    xi.push_back(x0[P.id[i]]);
    yi.push_back(y0[P.id[i]]);
    ux.push_back(P.x[i] - soil.lo[0] - x0[P.id[i]]);
  }
  // an unstable run's displacements need not be finite (the medians would sort NaNs): no slip line then
  const SlipLine sph = ok ? slip_line(xi, yi, ux, H0, Lb, dx, moved) : SlipLine{{}, {}, NAN};
  const double angle_sph = sph.angle_deg;
  Series sph_slip{"SPH slip points", "simulation", "slip_line", "x / H", "y / H", sph.x, sph.y};

  const Csv dem = read_csv(cfg.reference_file(ctx, v.at("reference").get<std::string>()).string());
  const Csv dem_slip = read_csv(cfg.reference_file(ctx, v.at("reference_slip").get<std::string>()).string());
  const double K_dem = dem.comment_number("K_final");
  const double angle_dem = wedge_angle_deg(dem_slip.column("x_over_H"), dem_slip.column("y_over_H"));
  const double x_end = std::max(curve.x.empty() ? 0.0 : curve.x.back(), dem.column("displacement_over_H").back());
  rec.series.push_back(curve);
  rec.series.push_back({"LIGGGHTS DEM", "dem", "force", curve.xlabel, curve.ylabel, dem.column("displacement_over_H"),
                        dem.column("K")});
  rec.series.push_back({std::string("Rankine ") + (active ? "K_a" : "K_p"), "analytical", "force", curve.xlabel,
                        curve.ylabel, {0.0, x_end}, {K_rankine, K_rankine}});
  rec.series.push_back(sph_slip);
  rec.series.push_back({"LIGGGHTS DEM slip points", "dem", "slip_line", "x / H", "y / H", dem_slip.column("x_over_H"),
                        dem_slip.column("y_over_H")});
  const double t = std::tan(angle_rankine * std::numbers::pi / 180.0);
  rec.series.push_back({"Rankine plane " + std::to_string(static_cast<int>(std::lround(angle_rankine))) + " deg",
                        "analytical", "slip_line", "x / H", "y / H", {0.0, 1.0 / t}, {0.0, 1.0}});

  rec.extra["K_simulated"] = K_sph;
  rec.extra["K_dem"] = K_dem;
  rec.extra["K_dem_initial"] = dem.comment_number("K_initial");
  rec.extra["K_rankine"] = K_rankine;
  rec.extra["K_at_rest"] = sand.poisson_ratio() / (1 - sand.poisson_ratio());
  rec.extra["K_rel_diff_vs_rankine"] = (K_sph - K_rankine) / K_rankine;
  rec.extra["wedge_angle_deg"] = angle_sph;
  rec.extra["wedge_angle_deg_dem"] = angle_dem;
  rec.extra["wedge_angle_deg_rankine"] = angle_rankine;
  rec.extra["wall_displacement_over_H"] = std::abs(moved) / H0;
  rec.extra["H_over_dx"] = H0 / dx;
  rec.options["interface_friction_angle"] = wall.interface_friction_angle;
  rec.options["walls"] = scene.walls.slip;
  add_case_metric(rec, cfg, "earth_pressure_coefficient_rel_diff_vs_dem", std::abs(K_sph - K_dem) / K_dem, ok);
  add_case_metric(rec, cfg, "wedge_angle_diff_deg_vs_dem", std::abs(angle_sph - angle_dem), ok);
  rec.snapshot = field_snapshot(sim, SoilFields::plastic_strain, "-");
  return rec;
}

}  // namespace

// Variants "active" and "passive" of case.json, each against its own DEM run.
std::vector<Record> run_retaining_wall_dem(const CaseContext& ctx, const std::string& case_name) {
  return run_each_variant(ctx, case_name, run_at);
}

GEOSPH_CASE_DRIVER(retaining_wall_dem, run_retaining_wall_dem);

}  // namespace geosph::verify
