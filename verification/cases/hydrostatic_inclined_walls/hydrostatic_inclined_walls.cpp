// Hydrostatic water in tanks with inclined or curved walls: a trapezoid and a V section (2D) and a
// cylinder (3D, case hydrostatic_cylinder_tank), whose walls are the surface of a solid shape
// (walls.boundaries: a box less the tank's section, a cylinder less the tank's bore). The water starts in its
// hydrostatic state and must hold it: particle pressures averaged over the last quarter of the run
// against the Tait profile with the free surface at the filled height
// (reference/analytical/hydrostatic_tait.hpp), and no particle may end more than dx/2 inside the wall's
// solid: the lattice fill puts water particles up to the inclined surface itself (a 45-degree face passes
// through lattice points), as a box tank's start puts them dx/2 from its faces.

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

// The Tait column whose settled surface is at height H (the hydrostatic start puts it there): its
// uniform-density height H0 found by fixed-point iteration (the compression is of order (gH/c0^2)).
reference::HydrostaticTait column_with_surface(const FluidMaterial& w, double g, double H) {
  double H0 = H;
  for (int k = 0; k < 8; ++k) {
    const reference::HydrostaticTait r(w.density, w.sound_speed, w.gamma, g, H0);
    H0 *= H / r.surface_height();
  }
  return reference::HydrostaticTait(w.density, w.sound_speed, w.gamma, g, H0);
}

Record run_variant(const CaseConfig& base, const CaseContext& ctx, const std::string& variant, double spacing) {
  CaseConfig cfg = base;
  if (!variant.empty()) {  // a 2D section: the water's and the tank's outlines
    const auto& v = cfg.spec.at("variants").at(variant);
    cfg.scene_json["bodies"][0]["shape"]["vertices"] = v.at("water");
    cfg.scene_json["walls"]["boundaries"][0]["shape"]["parts"][1]["vertices"] = v.at("tank");
  }
  const Scene scene = cfg.scene(spacing);
  Simulation sim(scene);
  Record rec = start_record(cfg, ctx);
  rec.variant = variant;

  const auto& water = scene.materials.front();
  const int up = scene.dim - 1;  // gravity along -y (2D) or -z (3D)
  const double g = -scene.gravity[up], H = scene.bodies.front().hi[up];
  const auto ref = column_with_surface(water, g, H);
  const auto& wall = *scene.walls.boundaries.front().shape;

  FluidTimeAverage avg(sim.particles().size(), 0.75 * scene.t_end);  // the last quarter
  const bool ok = run_timed(sim, rec, [&](const Simulation& s) { avg.sample(s.particles(), s.time()); }, ctx.progress);

  if (ok && avg.samples() > 0) {
    HydrostaticProfile profile(ref, scene.dx);
    std::vector<double> near_sim, near_ref;
    const double floor_y = 0.5 * scene.dx;  // the floor row is the box-wall case's business
    avg.for_each([&](double p, double x, double y, double z) {
      const geometry::Point q{x, y, z};
      const double height = q[up];
      profile.add(p, height);
      if (-wall.distance(q) < 2 * scene.dx && height > floor_y) {
        near_sim.push_back(p);
        near_ref.push_back(ref.pressure(height));
      }
    });
    add_case_metric(rec, cfg, "pressure_rel_l2", relative_l2(profile.simulated(), profile.reference()));
    rec.extra["near_wall_pressure_rel_l2"] = relative_l2(near_sim, near_ref);
    rec.extra["near_wall_particles"] = static_cast<double>(near_sim.size());
    long leaked = 0;
    const auto& P = sim.particles();
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.kind[i] == Kind::Fluid && wall.distance({P.x[i], P.y[i], P.z[i]}) < -0.5 * scene.dx) ++leaked;
    add_case_metric(rec, cfg, "leaked_particles", static_cast<double>(leaked));
    rec.series = profile.series();
    rec.extra["surface_height_m"] = H;
    rec.extra["fill_mass_error"] = sim.fills().front().mass / sim.fills().front().shape_mass - 1.0;
  } else {
    add_case_metric(rec, cfg, "pressure_rel_l2", 0.0, false);
  }
  rec.snapshot = pressure_snapshot(sim);
  return rec;
}

}  // namespace

std::vector<Record> run_hydrostatic_inclined_walls(const CaseContext& ctx, const std::string& case_name) {
  if (load_case(ctx, case_name).spec.contains("variants")) return run_each_variant(ctx, case_name, run_variant);
  return run_each_spacing(ctx, case_name, [](const CaseConfig& cfg, const CaseContext& c, double dx) {
    return run_variant(cfg, c, "", dx);
  });
}

GEOSPH_CASE_DRIVER(hydrostatic_inclined_walls, run_hydrostatic_inclined_walls);

}  // namespace geosph::verify
