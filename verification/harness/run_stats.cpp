#include "harness/run_stats.hpp"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "harness/metrics.hpp"
#include "sim/progress.hpp"
#include "structure/total_lagrangian.hpp"

namespace geosph::verify {

bool run_timed(Simulation& sim, Record& rec, const std::function<void(const Simulation&)>& observe, bool progress,
               double until) {
  const Scene& s = sim.scene();
  rec.dx = s.dx;
  rec.dimension = s.dim;
  rec.particles = static_cast<long>(sim.moving_count());
  rec.wall_particles = static_cast<long>(sim.particles().size() - sim.moving_count());
  rec.threads = omp_get_max_threads();
  rec.options["kernel"] = kernel_name(s.kernel);
  rec.options["h_over_dx"] = s.h_over_dx;
  rec.options["boundary"] = s.has_walls() ? s.walls.type : "none";
  rec.options["wall_slip"] = s.walls.slip;
  if (s.has_fluid()) {
    const auto& m = s.materials.front();
    rec.options["artificial_viscosity"] = m.artificial_viscosity;
    rec.options["density_diffusion"] = m.density_diffusion;
    rec.options["sound_speed"] = m.sound_speed;
  }
  if (s.has_soil()) {
    const auto& m = s.soils.front();
    rec.options["soil_model"] = m.model_name();
    rec.options["artificial_viscosity"] = m.artificial_viscosity;
    rec.options["artificial_stress"] = m.artificial_stress;
    if (m.artificial_stress > 0) rec.options["artificial_stress_exponent"] = m.artificial_stress_exponent;
    rec.options["kernel_gradient_correction"] = s.corrects_velocity_gradient(0);  // numerics' or the material's
    rec.options["kernel_gradient_correction_stress"] = s.corrects_stress_divergence(0);
    std::visit([&](const auto& model) {  // the friction angles of the models that have them
      if constexpr (requires { model.friction_angle; }) {
        rec.options["friction_angle_deg"] = model.friction_angle;
        rec.options["dilatancy_angle_deg"] = model.dilatancy_angle;
      }
    }, m.model);
    if (TotalLagrangianSolids::wanted(s))
      rec.options["structure_formulation"] = "total_lagrangian";  // structure/total_lagrangian.hpp
  }
  const long steps0 = sim.steps();
  Progress bar(s.t_end, progress);
  const auto t0 = std::chrono::steady_clock::now();
  bool ok = true;
  try {
    sim.run([&](const Simulation& sm) {
      if (observe) observe(sm);
      bar.update(sm.steps(), sm.time());
    }, until);
  } catch (const InstabilityError& e) {
    ok = false;
    rec.stable = false;
    rec.failure = {{"step", e.diagnosis.step}, {"time", e.diagnosis.time}, {"message", e.what()}};
    std::fprintf(stderr, "%s\n", e.what());
  }
  bar.finish(sim.steps(), sim.time());
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  rec.steps += sim.steps() - steps0;
  rec.wall_s += wall;
  // mirror walls: the fluid particles bounced back across a wall (boundary/mirror_wall.hpp)
  if (s.walls.type == "mirror") rec.extra["mirror_wall_reflections"] = sim.mirror_reflections();
  if (!drained_faces(s).empty()) {
    rec.extra["drained_water_particles"] = sim.drained_particles();
    rec.extra["drained_water_mass"] = sim.drained_mass();
  }
  rec.particle_steps_per_s = rec.wall_s > 0 ? rec.particles * static_cast<double>(rec.steps) / rec.wall_s : 0;
  return ok;
}

std::vector<Record> run_each_spacing(const CaseContext& ctx, const std::string& name,
                                     const std::function<Record(const CaseConfig&, const CaseContext&, double)>& run_at) {
  const CaseConfig cfg = load_case(ctx, name);
  std::vector<Record> out;
  for (double dx : cfg.level_numbers("dx")) out.push_back(run_at(cfg, ctx, dx));
  annotate_observed_order(out, cfg.spec.value("expected_order", -1.0));
  return out;
}

std::vector<Record> run_each_variant(
    const CaseContext& ctx, const std::string& name,
    const std::function<Record(const CaseConfig&, const CaseContext&, const std::string&, double)>& run_variant) {
  const CaseConfig base = load_case(ctx, name);
  std::vector<Record> out;
  for (const auto& v : base.spec.at("variants").items()) {
    CaseConfig cfg = base;
    if (!cfg.use_variant_level(v.value(), ctx.level)) continue;
    for (double dx : cfg.level_numbers("dx")) out.push_back(run_variant(cfg, ctx, v.key(), dx));
  }
  return out;
}

nlohmann::json pressure_snapshot(const Simulation& sim, std::size_t max_points) {
  return field_snapshot(sim, "pressure", "Pa", max_points);
}

nlohmann::json field_snapshot(const Simulation& sim, const std::string& field, const std::string& units,
                              std::size_t max_points) {
  return field_snapshot(sim.particles(), field, units, max_points);
}

nlohmann::json field_snapshot(const Particles& P, const std::string& field, const std::string& units,
                              std::size_t max_points) {
  std::size_t moving = 0;
  for (std::size_t i = 0; i < P.size(); ++i) moving += is_moving(P.kind[i]) ? 1 : 0;
  const std::size_t stride = std::max<std::size_t>(1, moving / max_points + 1);
  const std::vector<double>* extra = field == "pressure" || field == "speed" ? nullptr : &P.extra_fields().at(field);
  nlohmann::json x = nlohmann::json::array(), y = nlohmann::json::array(), v = nlohmann::json::array();
  std::size_t k = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (!is_moving(P.kind[i]) || (k++ % stride) != 0) continue;
    x.push_back(P.x[i]); y.push_back(P.y[i]);
    v.push_back(extra ? (*extra)[i]
                      : field == "pressure" ? P.p[i] : std::sqrt(P.vx[i] * P.vx[i] + P.vy[i] * P.vy[i] + P.vz[i] * P.vz[i]));
  }
  return {{"x", x}, {"y", y}, {"values", v}, {"field", field}, {"units", units}};
}

}  // namespace geosph::verify
