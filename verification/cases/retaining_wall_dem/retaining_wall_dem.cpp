// Retaining wall against a LIGGGHTS DEM reference (reference/dem/retaining_wall_2d.in): a smooth rigid
// wall translated slowly away from (active) or into (passive) a dry granular backfill on a smooth floor,
// against a smooth far wall; the same geometry, wall speed and travel as the DEM run. Scored against
// the DEM: the earth-pressure coefficient at the end of the travel and the angle of the failure wedge's
// slip line. Both are normalised and detected as reference/dem/postprocess.py does for the grains:
//   K = F / (0.5 gamma0 H0^2)  (gamma0 H0: the weight per unit floor area, H0: height before the move),
//   slip line: per 0.1 H0 strip of the initial soil, the x where the median horizontal displacement
//   (bins one spacing wide, running median of three) falls below half the wall's travel; the wedge
//   angle is the least-squares slope over 0.15-0.85 H0.
// Rankine's K and planes at 45 +/- phi/2 (smooth wall, horizontal surface) are recorded beside them.

#include <gsl/gsl_fit.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "coupling/soil_structure_contact.hpp"
#include "harness/case_record.hpp"
#include "harness/driver_registry.hpp"
#include "harness/metrics.hpp"
#include "harness/run_stats.hpp"
#include "soil/soil_fields.hpp"

namespace geosph::verify {

namespace {

constexpr int kStrips = 10;

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Least-squares wedge angle [deg] of slip points (x/H, y/H) over 0.15 < y/H < 0.85; NaN under 3 points.
double wedge_angle(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<double> xs, ys;
  for (std::size_t k = 0; k < x.size(); ++k)
    if (y[k] > 0.15 && y[k] < 0.85) { xs.push_back(x[k]); ys.push_back(y[k]); }
  if (xs.size() < 3) return NAN;
  double c0, c1, c00, c01, c11, ss;
  gsl_fit_linear(xs.data(), 1, ys.data(), 1, xs.size(), &c0, &c1, &c00, &c01, &c11, &ss);
  return std::atan(std::abs(c1)) * 180.0 / std::numbers::pi;
}

// Slip points (x, y) of the wedge and the wedge angle [deg from the horizontal]; `travel` is signed
// (negative: active). Inputs: the initial positions and horizontal displacements of the soil.
double slip_line(const std::vector<double>& x0, const std::vector<double>& y0, const std::vector<double>& ux,
                 double H, double Lb, double bin, double travel, Series& line) {
  const double half = 0.5 * std::abs(travel), sign = travel < 0 ? -1.0 : 1.0;
  const int nb = static_cast<int>(std::ceil(Lb / bin));
  for (int k = 0; k < kStrips; ++k) {
    const double ylo = k * H / kStrips, yhi = (k + 1) * H / kStrips;
    std::vector<std::vector<double>> in_bin(nb);
    std::size_t count = 0;
    for (std::size_t i = 0; i < x0.size(); ++i) {
      if (y0[i] < ylo || y0[i] >= yhi || x0[i] < 0) continue;
      const int b = static_cast<int>(x0[i] / bin);
      if (b < nb) { in_bin[b].push_back(sign * ux[i]); ++count; }
    }
    if (count < 10) continue;
    std::vector<double> med(nb), sm(nb);
    for (int b = 0; b < nb; ++b) med[b] = median(in_bin[b]);
    for (int b = 0; b < nb; ++b) {
      std::vector<double> around;
      for (int c = std::max(0, b - 1); c <= std::min(nb - 1, b + 1); ++c)
        if (!std::isnan(med[c])) around.push_back(med[c]);
      sm[b] = median(around);
    }
    for (int b = 0; b < nb; ++b) {
      if (std::isnan(sm[b]) || sm[b] >= half) continue;
      double xs = 0.0;
      if (b > 0) {  // linear interpolation between the bin centres
        const double x1 = (b - 0.5) * bin, x2 = (b + 0.5) * bin;
        xs = sm[b - 1] != sm[b] ? x1 + (sm[b - 1] - half) / (sm[b - 1] - sm[b]) * (x2 - x1) : x2;
      }
      line.x.push_back(xs / H);
      line.y.push_back(0.5 * (ylo + yhi) / H);
      break;
    }
  }
  return wedge_angle(line.x, line.y);
}

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
  Series sph_slip{"SPH slip points", "simulation", "slip_line", "x / H", "y / H", {}, {}};
  const double angle_sph = ok ? slip_line(xi, yi, ux, H0, Lb, dx, moved, sph_slip) : NAN;

  const Csv dem = read_csv(cfg.reference_file(ctx, v.at("reference").get<std::string>()).string());
  const Csv dem_slip = read_csv(cfg.reference_file(ctx, v.at("reference_slip").get<std::string>()).string());
  const double K_dem = dem.comment_number("K_final");
  const double angle_dem = wedge_angle(dem_slip.column("x_over_H"), dem_slip.column("y_over_H"));
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
