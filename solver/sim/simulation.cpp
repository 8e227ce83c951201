#include "sim/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "boundary/body_fields.hpp"
#include "boundary/geometry.hpp"
#include "io/json_fields.hpp"
#include "sim/resource_limits.hpp"
#include "sim/stages.hpp"

namespace geosph {

namespace {
// The Verlet list's skin [m]: numerics.pair_list_skin kernel supports, less along a short periodic axis,
// which needs at least five cells of half the list's reach (core/cell_list.cpp).
double pair_list_skin(const Scene& s) {
  double skin = s.pair_list_skin * s.support();
  for (int a = 0; a < s.dim; ++a)
    if (s.domain.periodic[a]) skin = std::min(skin, 0.399 * s.domain.length(a) - s.support());
  return std::max(skin, 0.0);
}
}  // namespace

Simulation::Simulation(Scene scene) : scene_(std::move(scene)) {
  validate_scene(scene_);
  check_resources(scene_);  // before anything is allocated
  std::vector<Particles> placed;
  P_ = build_particles(scene_, &fills_, &placed);
  for (std::size_t b = 0, k = 0; b < scene_.bodies.size(); ++b)
    if (scene_.bodies[b].placed_at > 0) {
      // the placed body's own fields exist from the start, so the particle layout (snapshots,
      // checkpoints) keeps one set of fields through the run
      for (const auto& [name, f] : placed[k].extra_fields()) P_.add_field(name, placed[k].owner(name));
      for (const auto& [name, f] : placed[k].int_fields()) P_.add_int_field(name, placed[k].owner(name));
      placements_.push_back({b, scene_.bodies[b].placed_at, std::move(placed[k++])});
    }
  excavated_.assign(scene_.excavations.size(), 0);
  n_fluid_ = P_.count(Kind::Fluid);
  n_soil_ = P_.count(Kind::Soil);
  n_structure_ = P_.count(Kind::Structure) + P_.count(Kind::RigidStructure);
  if (n_fluid_ + n_soil_ + n_structure_ == 0 && placements_.empty())
    throw InputError(scene_.file + ": field 'bodies': the scene creates no particles (bodies smaller than dx?)");
  const bool dummy = P_.count(Kind::DummyWall) > 0;
  if (scene_.has_fluid()) {
    fluid_ = std::make_unique<FluidForces>(scene_);
    if (dummy) {
      dummy_walls_ = std::make_unique<DummyWalls>(scene_, *fluid_);
      dummy_walls_->allocate(P_);
    }
    for (const auto& m : scene_.materials) bounds_.fluid.rho0.push_back(m.density);
    bounds_.fluid.max_speed = fluid_->max_sound_speed();
  }
  if (scene_.has_soil()) {
    soil_ = std::make_unique<SoilForces>(scene_);
    soil_->allocate(P_);
    if (dummy) {
      soil_walls_ = std::make_unique<SoilWalls>(scene_);
      soil_walls_->allocate(P_);
    }
    for (const auto& m : scene_.soils) bounds_.soil.rho0.push_back(m.density);
    bounds_.soil.max_speed = soil_->max_wave_speed();
  }
  if (TotalLagrangianSolids::wanted(scene_)) {
    total_lagrangian_ = std::make_unique<TotalLagrangianSolids>(scene_);
    total_lagrangian_->allocate(P_);
  }
  if (scene_.walls.type == "mirror") mirror_walls_ = std::make_unique<MirrorWalls>(scene_);
  drained_faces_ = drained_faces(scene_);
  if (P_.count(Kind::RigidStructure) > 0) {
    rigid_ = std::make_unique<RigidMotions>(scene_);
    rigid_->set_velocities(P_, 0.0);
  }
  const bool soil_later = std::any_of(placements_.begin(), placements_.end(), [](const Placement& p) {
    return p.particles.count(Kind::Soil) > 0;
  });
  if ((n_soil_ > 0 || soil_later) && n_structure_ > 0) {
    contact_ = std::make_unique<SoilStructureContact>(scene_);
    contact_->allocate(P_);
  }
  if (scene_.two_phase()) {
    seepage_ = std::make_unique<Seepage>(scene_);
    seepage_->allocate(P_);
  }
  bounds_.max_density_variation = scene_.max_density_variation;
  limits_ = {scene_.cfl, scene_.force_factor, scene_.viscous_factor};
  pair_skin_ = pair_list_skin(scene_);
  const long outside = cells_.build(P_, scene_.domain, scene_.support(), pair_skin_);
  if (outside >= 0)
    throw InputError(scene_.file + ": field 'domain': particle " + std::to_string(P_.id[outside]) + " at (" +
                     std::to_string(P_.x[outside]) + ", " + std::to_string(P_.y[outside]) + ", " +
                     std::to_string(P_.z[outside]) + ") starts outside the domain");
  stages_ = stage_table();
  check_stages(stages_);
  neighbour_search();
  if (seepage_) seepage_->initialise(P_, cells_);
  choose_time_step();  // acoustic limit only (nothing moves yet): the contact needs the step length
  run_hook(Hook::Forces);
  state_ = check_state(P_, scene_.domain, bounds_, step_, t_);
  choose_time_step();
}

std::array<double, 3> Simulation::gravity_at(double t) const {
  const double ramp = loading_now_ ? loading_ramp_ : scene_.gravity_ramp;
  const double from = loading_now_ ? 0.0 : scene_.gravity_ramp_from;
  const double f = ramp > 0 && t < ramp
                       ? from + (1.0 - from) * smooth_start(t, ramp)
                       : 1.0;
  return {f * scene_.gravity[0], f * scene_.gravity[1], f * scene_.gravity[2]};
}

// While the pair list holds every pair (no particle has moved half its skin) and no re-sort is due,
// the cells are not rebuilt: queries read the list, and only the domain check runs.
void Simulation::neighbour_search() {
  const bool reorder = scene_.reorder_every > 0 && step_ % scene_.reorder_every == 0;
  const bool current = !reorder && !rebuild_cells_ && cells_.pairs_current(P_);
  rebuild_cells_ = false;
  const long outside = current ? cells_.find_outside(P_, scene_.domain)
                               : cells_.build(P_, scene_.domain, scene_.support(), pair_skin_);
  if (outside >= 0) {
    Diagnosis d;
    const auto i = static_cast<std::size_t>(outside);
    d.step = step_; d.time = t_; d.particle_id = P_.id[i];
    d.x = P_.x[i]; d.y = P_.y[i]; d.z = P_.z[i];
    d.quantity = "particle left the domain (or its position is not finite)";
    throw InstabilityError(d);
  }
  if (current) return;
  if (reorder && scene_.two_phase()) {
    // by cell within each kind, the kinds one after another (skeleton, pore water, the rest): each pair
    // loop of the coupled step reads only the kinds it needs (CellList::ranges_of), a contiguous part of
    // each particle's ascending list, where the two overlapping phases would interleave in cell order
    const std::vector<std::uint32_t>& by_cell = cells_.sorted();
    const auto group = [&](std::uint32_t i) { return P_.kind[i] == Kind::Soil ? 0 : P_.kind[i] == Kind::Fluid ? 1 : 2; };
    std::array<std::size_t, 4> at{};  // a stable counting sort on the group
    for (const std::uint32_t i : by_cell) ++at[static_cast<std::size_t>(group(i)) + 1];
    for (std::size_t g = 1; g < at.size(); ++g) at[g] += at[g - 1];
    std::vector<std::uint32_t> order(by_cell.size());
    for (const std::uint32_t i : by_cell) order[at[static_cast<std::size_t>(group(i))]++] = i;
    P_.permute(order);
    cells_.build(P_, scene_.domain, scene_.support(), pair_skin_);  // bins the new order (all inside)
  } else if (reorder) {
    P_.permute(cells_.sorted());
    cells_.mark_permuted();
  }
  cells_.rebuild_pairs(P_);
}

// The stages of the step, in order, for the modules this scene has (sim/stages.hpp). Rates: in a
// two-phase scene the soil walls are re-extrapolated at x^{n+1} before the soil's stress update.
// Integrate: the fluid's density is predicted with its last rate, and corrected by its forces stage,
// which computes rate and acceleration in one neighbour pass. Forces: the soil walls before the soil's
// momentum, the fluid walls after the fluid pressure; the seepage coupling after every other force (the
// drag pairs their sums), the contact last (it corrects the accelerations of touching pairs).
std::vector<Stage> Simulation::stage_table() {
  std::vector<Stage> t;
  const auto add = [&](bool present, Stage st) {
    if (present) t.push_back(std::move(st));
  };
  const bool surcharge = P_.has_field(BodyFields::surcharge);
  const auto soil_walls = [this](Hook h) {  // the same stage in two hooks (rates: two-phase only)
    return Stage{"soil_walls", h, {"x", "v", "stress[soil]", "rho[soil]"},
                 {"stress[walls]", "soil_wall_v*", "soil_wall_density", "soil_wall_mass"}, {},
                 [this] { soil_walls_->update(P_, cells_, gravity_at(t_)); }};
  };
  // drift
  add(rigid_ != nullptr, {"rigid_motion", Hook::Drift, {"t"}, {"x[rigid]", "v[rigid]"}, {},
                          [this] { if (!loading_now_) rigid_->advance(P_, t_, dt_); }});
  add(mirror_walls_ != nullptr, {"mirror_wall_crossings", Hook::Drift, {"x[fluid]", "v[fluid]", "x[soil]", "v[soil]"},
                                 {"x[fluid]", "v[fluid]", "x[soil]", "v[soil]"}, {},
                                 [this] { mirror_reflections_ += mirror_walls_->reflect_crossings(P_); }});
  // rates at x^{n+1}, v^{n+1/2}
  add(seepage_ != nullptr, {"seepage_porosity_rate", Hook::Rates, {"x", "v", "porosity"}, {"porosity_rate"}, {},
                            [this] { seepage_->porosity_rate(P_, cells_); }});
  add(seepage_ && soil_walls_, soil_walls(Hook::Rates));
  add(soil_ != nullptr, {"solid_stress", Hook::Rates, {"x", "v", "stress", "soil_wall_*", "model state"},
                         {"drho[solid]", "stress[solid]", "p[solid]", "plastic_strain", "model state", "wave_speed"}, {},
                         [this] { soil_->update_stress(P_, cells_, dt_, step_, t_); }});
  // integrate
  add(true, {"density", Hook::Integrate, {"drho"}, {"rho[moving]"}, {}, [this] { integrate_density(); }});
  add(seepage_ != nullptr, {"seepage_porosity", Hook::Integrate, {"porosity_rate"}, {"porosity[water]"}, {},
                            [this] { seepage_->advance_porosity(P_, dt_); }});
  // forces at the new state
  add(seepage_ != nullptr, {"seepage_skeleton_porosity", Hook::Forces, {"x", "rho", "m", "porosity", "soil_wall_*"},
                            {"porosity[soil]", "hydraulic_conductivity", "kernel sums"}, {},
                            [this] { seepage_->update_porosity(P_, cells_); }});
  add(soil_walls_ != nullptr, soil_walls(Hook::Forces));
  add(soil_ != nullptr, {"solid_momentum", Hook::Forces, {"x", "v", "rho", "m", "stress", "soil_wall_*"},
                         {"a[solid]"}, {}, [this] { soil_->momentum(P_, cells_, gravity_at(t_)); }});
  add(total_lagrangian_ != nullptr, {"structure_total_lagrangian", Hook::Forces, {"x", "v", "m", "reference_*"},
                                     {"a[structure]", "stress[structure]", "rho[structure]", "p[structure]"}, {},
                                     [this] { total_lagrangian_->forces(P_, gravity_at(t_), step_, t_); }});
  add(fluid_ != nullptr, {"fluid_pressure", Hook::Forces, {"rho[fluid]", "porosity"}, {"p[fluid]"}, {},
                          [this] { fluid_->update_pressure(P_); }});
  add(dummy_walls_ != nullptr, {"fluid_walls", Hook::Forces, {"x", "v", "p[fluid]", "rho[fluid]", "porosity"},
                                {"p[walls]", "rho[walls]", "m[walls]", "wall_v*", "porosity[walls]"}, {},
                                [this] { dummy_walls_->update(P_, cells_, gravity_at(t_)); }});
  add(fluid_ != nullptr, {"fluid_rates", Hook::Forces, {"x", "v", "rho", "m", "p", "wall_v*", "porosity"},
                          {"a[fluid]", "drho[fluid]", "rho[fluid]"}, {},
                          [this] { fluid_->rates(P_, cells_, gravity_at(t_), density_dt_); }});
  add(surcharge, {"surcharge", Hook::Forces, {"surcharge", "surcharge_ramp", "t"}, {}, {"a[solid]"},
                  [this] { if (!loading_now_) apply_surcharge(); }});  // the loading stage is gravity only
  add(seepage_ != nullptr, {"seepage_coupling", Hook::Forces, {"p", "porosity", "kernel sums"},
                            {"drag_rate", "drag_partner_*"}, {"a[solid]", "a[fluid]"},
                            [this] { seepage_->apply(P_, cells_); }});
  add(contact_ != nullptr, {"soil_structure_contact", Hook::Forces, {"x", "v", "a", "structure_body"},
                            {"contact_force", "contact_normal", "x[soil]"}, {"a[solid]"},
                            [this] { contact_->apply(P_, cells_, dt_); }});
  // last, on the total force as FLAC damps it: the contact then holds the soil against its undamped
  // weight, and the equilibrium measure sees the contact's reaction (with the damping before the contact,
  // the contact cancelled only the damped acceleration, and soil resting on a structure never settled:
  // 0.81 of its weight stayed unbalanced)
  add(scene_.gravity_loading.active, {"gravity_loading_damping", Hook::Forces, {"a[solid]", "v[solid]"}, {}, {"a[solid]"},
                                      [this] {
                                        if (!loading_now_) return;
                                        unbalanced_ = unbalanced_force_ratio(P_, scene_.gravity);
                                        apply_local_damping(P_, scene_.gravity_loading.damping);
                                      }});
  return t;
}

void Simulation::run_hook(Hook h) {
  for (auto& s : stages_)
    if (s.hook == h) s.run();
}

void Simulation::integrate_density() {
  const std::size_t n = P_.size();
  const double dt = dt_;
  density_dt_ = dt;  // the fluid's rate is last step's here: its forces stage corrects rho (fluid/fluid_forces.hpp)
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i)
    if (is_moving(P_.kind[i])) P_.rho[i] += dt * P_.drho[i];
}

// Surcharge pressure q on a soil body's top row: force q dx^(d-1) per particle, downward, ramped.
void Simulation::apply_surcharge() {
  const double* q = P_.field(BodyFields::surcharge).data();
  const double* ramp = P_.field(BodyFields::surcharge_ramp).data();
  const double area = std::pow(scene_.dx, scene_.dim - 1);
  std::vector<double>& a = scene_.dim == 2 ? P_.ay : P_.az;
  for (std::size_t i = 0; i < P_.size(); ++i)
    if (q[i] > 0) a[i] -= smooth_start(t_, ramp[i]) * q[i] * area / P_.m[i];  // 1 after the ramp
}

void Simulation::kick(double half) {
  auto& P = P_;
  const std::size_t n = P.size();
  const std::int32_t* fixed = P.find_int(BodyFields::fixed);
  const double* C = seepage_ ? P.field(SeepageFields::drag_c).data() : nullptr;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_moving(P.kind[i]) || (fixed && fixed[i] > 0) || (C && C[i] > 0)) continue;
    P.vx[i] += half * P.ax[i]; P.vy[i] += half * P.ay[i]; P.vz[i] += half * P.az[i];
  }
  if (seepage_) seepage_->kick(P, half, fixed);
}

void Simulation::choose_time_step() {
  TimeStepInput in;
  in.h = scene_.h();
  in.c_max = std::max(fluid_ ? fluid_->max_sound_speed() : 0.0, soil_ ? soil_->max_wave_speed() : 0.0);
  if (seepage_) in.c_max = std::max(in.c_max, seepage_->undrained_wave_speed(soil_->max_wave_speed()));
  in.v_max = state_.v_max;
  in.a_max = state_.a_max;
  in.nu_max = fluid_ ? fluid_->max_kinematic_viscosity() : 0.0;
  dt_ = stable_time_step(in, limits_);
  if (loading_now_) return;
  const double next = std::min(scene_.t_end, next_construction_time());
  if (t_ + dt_ > next) dt_ = std::max(next - t_, 1e-300);
}

void Simulation::step() {
  const std::size_t n = P_.size();
  const double half = 0.5 * dt_, dt = dt_;
  const auto& dom = scene_.domain;
  auto& P = P_;
  const std::int32_t* fixed = P.find_int(BodyFields::fixed);
  const std::int32_t* block = P.find_int(BodyFields::wall_block);
  kick(half);
  const auto& blocks = scene_.walls.blocks;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (block && block[i] > 0) {  // wall blocks move with their prescribed velocity (ramped: at mid-step)
      const auto& b = blocks[static_cast<std::size_t>(block[i]) - 1];
      const double f = loading_now_ ? 0.0 : smooth_start(t_ + half, b.ramp);  // 1 without a ramp; held while loading
      P.vx[i] = f * b.velocity[0]; P.vy[i] = f * b.velocity[1]; P.vz[i] = f * b.velocity[2];
      P.x[i] += dt * P.vx[i]; P.y[i] += dt * P.vy[i]; P.z[i] += dt * P.vz[i];
      continue;
    }
    if (!is_moving(P.kind[i]) || (fixed && fixed[i] > 0)) continue;
    P.x[i] += dt * P.vx[i]; P.y[i] += dt * P.vy[i]; P.z[i] += dt * P.vz[i];
    double* q[3] = {&P.x[i], &P.y[i], &P.z[i]};
    for (int a = 0; a < dom.dim; ++a) {
      if (!dom.periodic[a]) continue;
      if (*q[a] >= dom.hi[a]) *q[a] -= dom.length(a);
      else if (*q[a] < dom.lo[a]) *q[a] += dom.length(a);
    }
  }
  run_hook(Hook::Drift);
  if (!drained_faces_.empty()) drain();
  t_ += dt;
  ++step_;
  neighbour_search();
  run_hook(Hook::Rates);
  run_hook(Hook::Integrate);
  run_hook(Hook::Forces);
  kick(half);
  state_ = check_state(P_, scene_.domain, bounds_, step_, t_);
  if (!loading_now_ && next_construction_time() <= t_ * (1 + 1e-12)) apply_construction();
  choose_time_step();
}

// The pore water that crossed a drained side has left the layer: its particles are removed, and the
// neighbours are searched again (the pair list refers to particle indices).
void Simulation::drain() {
  const std::vector<char> out = crossed_drained_faces(scene_, drained_faces_, P_);
  double mass = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < out.size(); ++i)
    if (out[i]) { mass += P_.m[i]; ++count; }
  if (count == 0) return;
  P_.remove(out);
  drained_particles_ += count;
  drained_mass_ += mass;
  n_fluid_ = P_.count(Kind::Fluid);
  rebuild_cells_ = true;
}

double Simulation::next_construction_time() const {
  double next = 1e300;
  for (std::size_t k = 0; k < excavated_.size(); ++k)
    if (!excavated_[k]) next = std::min(next, scene_.excavations[k].time);
  for (const auto& p : placements_)
    if (!p.done) next = std::min(next, p.time);
  return next;
}

void Simulation::apply_construction() {
  const double due = t_ * (1 + 1e-12);
  std::vector<ConstructionEvent> events;
  for (std::size_t k = 0; k < excavated_.size(); ++k) {
    if (excavated_[k] || scene_.excavations[k].time > due) continue;
    excavated_[k] = 1;
    ConstructionEvent e{"excavations[" + std::to_string(k) + "]", t_};
    e.removed = P_.remove(inside_excavation(P_, *scene_.excavations[k].shape, scene_.dx));
    events.push_back(e);
  }
  for (auto& p : placements_) {
    if (p.done || p.time > due) continue;
    p.done = true;
    const std::string field = "bodies[" + std::to_string(p.body) + "]";
    const long o = first_overlap(P_, p.particles, scene_.dx);
    if (o >= 0)
      throw InputError(scene_.file + ": field '" + field + ".placed_at': at t = " + std::to_string(t_) +
                       " s the body would sit on particle " + std::to_string(P_.id[o]) + " at (" + std::to_string(P_.x[o]) +
                       ", " + std::to_string(P_.y[o]) + ", " + std::to_string(P_.z[o]) +
                       ") (closer than dx/2); place it where nothing is then (excavate first, or leave a gap)");
    P_.append(p.particles);
    ConstructionEvent e{field, t_};
    e.added = p.particles.size();
    events.push_back(e);
  }
  if (events.empty()) return;
  n_fluid_ = P_.count(Kind::Fluid);
  n_soil_ = P_.count(Kind::Soil);
  n_structure_ = P_.count(Kind::Structure) + P_.count(Kind::RigidStructure);
  if (soil_) soil_->allocate(P_);  // the wave speeds of the new particles
  const long outside = cells_.build(P_, scene_.domain, scene_.support(), pair_skin_);
  if (outside >= 0)
    throw InputError(scene_.file + ": field '" + events.back().what + "': particle " + std::to_string(P_.id[outside]) +
                     " lies outside the domain");
  cells_.rebuild_pairs(P_);
  density_dt_ = 0;  // the fluid density of this state is already corrected
  run_hook(Hook::Forces);
  state_ = check_state(P_, scene_.domain, bounds_, step_, t_);
  if (scene_.gravity_loading.after_construction) {
    const double t_held = t_;
    const long step_held = step_;
    loading_now_ = true;
    loading_ramp_ = 0;
    t_ = 0;
    hold_rigid_structures();  // prescribed motions pause while the stage settles
    choose_time_step();
    long steps = 0;
    double peak = 0, ke = 0;
    events.back().settled = settle(scene_.gravity_loading.max_time, steps, peak, ke);
    events.back().settle_steps = steps;
    loading_now_ = false;
    stop_solids();
    t_ = t_held;
    step_ = step_held;
    if (rigid_) rigid_->set_velocities(P_, t_);
    density_dt_ = 0;
    run_hook(Hook::Forces);
    state_ = check_state(P_, scene_.domain, bounds_, step_, t_);
  }
  construction_log_.insert(construction_log_.end(), events.begin(), events.end());
}

void Simulation::hold_rigid_structures() {
  for (std::size_t i = 0; i < P_.size(); ++i)
    if (P_.kind[i] == Kind::RigidStructure) P_.vx[i] = P_.vy[i] = P_.vz[i] = 0;
}

void Simulation::stop_solids() {
  for (std::size_t i = 0; i < P_.size(); ++i)
    if (P_.kind[i] == Kind::Soil || P_.kind[i] == Kind::Structure) P_.vx[i] = P_.vy[i] = P_.vz[i] = 0;
}

bool Simulation::settle(double max_time, long& steps, double& peak, double& ke,
                        const std::function<bool(const Simulation&)>& abandon) {
  const GravityLoadingSpec& g = scene_.gravity_loading;
  steps = 0;
  peak = ke = 0;
  while (true) {
    step();
    ++steps;
    ke = solid_kinetic_energy(P_);
    peak = std::max(peak, ke);
    if (t_ >= loading_ramp_ && steps >= 20 && ke <= g.kinetic_energy_ratio * peak && unbalanced_ <= g.force_ratio)
      return true;
    if (t_ > max_time || (abandon && abandon(*this))) return false;
  }
}

Simulation::RunState Simulation::run_state() const {
  RunState s{{"time", {t_}}, {"dt", {dt_}}, {"step", {static_cast<double>(step_)}},
             {"state_summary", {state_.v_max, state_.a_max}}};
  if (soil_) s["soil_max_wave_speed"] = {soil_->max_wave_speed()};
  if (rigid_) s["rigid_motion"] = rigid_->state();
  if (!drained_faces_.empty()) s["drained_water"] = {static_cast<double>(drained_particles_), drained_mass_};
  return s;
}

void Simulation::restore_run_state(const RunState& s) {
  const auto get = [&](const std::string& k, std::size_t n) -> const std::vector<double>& {
    const auto it = s.find(k);
    if (it == s.end() || (n > 0 && it->second.size() != n)) throw std::invalid_argument("run state '" + k + "' missing");
    return it->second;
  };
  t_ = get("time", 1)[0];
  dt_ = get("dt", 1)[0];
  step_ = static_cast<long>(get("step", 1)[0]);
  state_ = {get("state_summary", 2)[0], get("state_summary", 2)[1]};
  if (soil_) soil_->restore_max_wave_speed(get("soil_max_wave_speed", 1)[0]);
  if (rigid_) rigid_->restore_state(get("rigid_motion", 0));
  if (!drained_faces_.empty()) {
    drained_particles_ = static_cast<std::size_t>(get("drained_water", 2)[0]);
    drained_mass_ = get("drained_water", 2)[1];
  }
  loading_.ran = scene_.gravity_loading.active;  // the checkpoint holds the settled state
  const double done = t_ * (1 + 1e-12);  // and the construction events up to its time
  for (std::size_t k = 0; k < excavated_.size(); ++k) excavated_[k] = scene_.excavations[k].time <= done;
  for (auto& p : placements_) p.done = p.time <= done;
}

bool Simulation::begin_loading() {
  const GravityLoadingSpec& g = scene_.gravity_loading;
  if (!g.active || loading_.ran) return false;
  loading_now_ = true;
  if (soil_) soil_->set_elastic_only(g.model == "elastic");
  hold_rigid_structures();  // prescribed motions wait for the run proper
  loading_ramp_ = g.ramp;
  run_hook(Hook::Forces);  // at the loading stage's gravity of t = 0
  choose_time_step();
  return true;
}

const GravityLoadingResult& Simulation::try_settle_under_gravity(const std::function<bool(const Simulation&)>& abandon) {
  if (!begin_loading()) return loading_;
  double peak = 0, ke = 0;
  long steps = 0;
  const bool settled = settle(scene_.gravity_loading.max_time, steps, peak, ke, abandon);
  loading_ = {true, settled, steps, t_, peak, ke, unbalanced_};
  loading_now_ = false;
  if (soil_) soil_->set_elastic_only(false);
  return loading_;
}

const GravityLoadingResult& Simulation::settle_under_gravity() {
  const GravityLoadingSpec& g = scene_.gravity_loading;
  if (!begin_loading()) return loading_;
  double peak = 0, ke = 0;
  long steps = 0;
  if (!settle(g.max_time, steps, peak, ke)) {
    loading_now_ = false;
    throw InputError(scene_.file + ": field 'gravity_loading.max_time': the solids have not settled in " +
                     std::to_string(g.max_time) + " s (" + std::to_string(steps) + " steps): kinetic energy " +
                     std::to_string(ke) + " J" + (scene_.dim == 2 ? "/m" : "") + " is " +
                     std::to_string(peak > 0 ? ke / peak : 0.0) + " of its peak (kinetic_energy_ratio " +
                     std::to_string(g.kinetic_energy_ratio) + ") and the unbalanced force " + std::to_string(unbalanced_) +
                     " of the weight (force_ratio " + std::to_string(g.force_ratio) + "); raise max_time or damping, or the slope is failing");
  }
  loading_ = {true, true, steps, t_, peak, ke, unbalanced_};
  loading_now_ = false;
  if (soil_) soil_->set_elastic_only(false);
  stop_solids();
  t_ = 0;
  step_ = 0;
  if (rigid_) rigid_->set_velocities(P_, 0.0);
  run_hook(Hook::Forces);
  state_ = check_state(P_, scene_.domain, bounds_, step_, t_);
  choose_time_step();
  return loading_;
}

void Simulation::run(const std::function<void(const Simulation&)>& observe, double until) {
  settle_under_gravity();
  const double t_stop = until > 0 ? std::min(until, scene_.t_end) : scene_.t_end;
  while (t_ < t_stop * (1 - 1e-12) && step_ < scene_.max_steps && !stop_) {
    if (t_ + dt_ > t_stop) dt_ = t_stop - t_;
    step();
    if (observe) observe(*this);
  }
}

}  // namespace geosph
