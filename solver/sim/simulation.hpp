// The time loop. Builds only the modules the scene declares (fluid forces for fluid materials,
// soil stress and forces for soil and structure solids, each phase's wall extrapolation only if the
// scene has dummy walls, the prescribed motion of rigid structures, soil-structure contact when both
// are present, the seepage coupling of saturated soil and its pore water) and advances them with a kick-drift-kick scheme:
//   v^{n+1/2} = v^n + dt/2 a^n,   x^{n+1} = x^n + dt v^{n+1/2},
//   Drho (and, for soil, the strain and spin increments) from (x^{n+1}, v^{n+1/2}):
//   rho^{n+1} = rho^n + dt Drho,  sigma^{n+1} = return_map(sigma^n + Jaumann increment),
//   a^{n+1} from (x^{n+1}, v^{n+1/2}, rho^{n+1}, sigma^{n+1}),   v^{n+1} = v^{n+1/2} + dt/2 a^{n+1}.
#pragma once
#include <functional>
#include <map>
#include <string>
#include <vector>
#include <memory>

#include "boundary/drained_face.hpp"
#include "boundary/dummy_wall.hpp"
#include "boundary/geometry.hpp"
#include "boundary/mirror_wall.hpp"
#include "coupling/seepage.hpp"
#include "coupling/soil_structure_contact.hpp"
#include "boundary/soil_wall.hpp"
#include "core/cell_list.hpp"
#include "core/particles.hpp"
#include "core/time_step.hpp"
#include "fluid/fluid_forces.hpp"
#include "io/scene.hpp"
#include "sim/construction.hpp"
#include "sim/gravity_loading.hpp"
#include "sim/stability.hpp"
#include "sim/stages.hpp"
#include "soil/soil_forces.hpp"
#include "structure/rigid_motion.hpp"
#include "structure/total_lagrangian.hpp"

namespace geosph {

class Simulation {
 public:
  explicit Simulation(Scene scene);
  Simulation(const Simulation&) = delete;  // the stages point at this object
  Simulation& operator=(const Simulation&) = delete;

  // Advances one step; throws InstabilityError with a diagnosis if the state blows up.
  void step();
  // The scene's gravity-loading stage (sim/gravity_loading.hpp), if it has one and it has not run:
  // the solids settle under their weight before t = 0. run() calls it first; a restart skips it.
  // Throws InputError naming gravity_loading.max_time if the solids do not settle.
  const GravityLoadingResult& settle_under_gravity();
  // The same stage for analyses that run many trial stages (analysis/strength_reduction.hpp): `abandon`
  // is asked after every step (true: stop the stage there), and passing max_time is not an error; the
  // result says whether the solids settled. The state is left as the stage ended (velocities kept).
  const GravityLoadingResult& try_settle_under_gravity(const std::function<bool(const Simulation&)>& abandon);
  const GravityLoadingResult& gravity_loading() const { return loading_; }
  // The construction events (sim/construction.hpp) done so far, in order.
  const std::vector<ConstructionEvent>& construction_log() const { return construction_log_; }
  // Runs to scene.time.end (or `until`), calling `observe` after every step.
  void run(const std::function<void(const Simulation&)>& observe = {}, double until = -1);

  const Scene& scene() const { return scene_; }
  const Particles& particles() const { return P_; }
  Particles& particles() { return P_; }
  double time() const { return t_; }
  long steps() const { return step_; }
  double dt() const { return dt_; }
  std::size_t fluid_count() const { return n_fluid_; }
  // mirror walls: fluid particles reflected back across a wall they crossed, over the run so far
  std::size_t mirror_reflections() const { return mirror_reflections_; }
  // Pore water that left through drained container sides (boundary/drained_face.hpp): particles, mass [kg(/m)].
  std::size_t drained_particles() const { return drained_particles_; }
  double drained_mass() const { return drained_mass_; }
  std::size_t soil_count() const { return n_soil_; }
  std::size_t structure_count() const { return n_structure_; }  // deformable and rigid structure particles
  // particles the step integrates or moves: fluid, soil and structures; walls excluded
  std::size_t moving_count() const { return n_fluid_ + n_soil_ + n_structure_; }
  // What each body was filled with (scene order): particles, mass and density x area (volume).
  const std::vector<BodyFill>& fills() const { return fills_; }
  // seepage coupling of a two-phase scene (null otherwise)
  const Seepage* seepage() const { return seepage_.get(); }
  // prescribed motion of the rigid structures (null if the scene has none)
  const RigidMotions* rigid_motions() const { return rigid_.get(); }
  // The time step's stages in order, with what each reads and writes (sim/stages.hpp).
  const std::vector<Stage>& stages() const { return stages_; }
  // Gravity at time t, ramped smoothly from gravity_ramp_from x g over scene.gravity_ramp (Adami et al.
  // 2012, eq. 33, there from zero).
  std::array<double, 3> gravity_at(double t) const;

  // The state a restart needs besides the particle fields (io/checkpoint.hpp): time, step count, step
  // length, the last state summary and the modules' running state, as named numbers.
  using RunState = std::map<std::string, std::vector<double>>;
  RunState run_state() const;
  void restore_run_state(const RunState& s);  // throws std::invalid_argument naming a missing entry
  // Makes run() return after the current step (an interruption; the state stays consistent).
  void request_stop() { stop_ = true; }
  bool stop_requested() const { return stop_; }

 private:
  void neighbour_search();  // cell list (and, every reorder_every steps, particles sorted by cell)
  std::vector<Stage> stage_table();  // the step's stages in order, for this scene's modules
  void run_hook(Hook h);
  void integrate_density();  // rho += dt drho of the integrated particles
  void choose_time_step();
  // Half kick v += dt/2 a of the integrated particles; with pore water the drag is implicit
  // (Seepage::kick).
  void kick(double half);
  void apply_surcharge();
  // The excavations and placed bodies due at the current time; then the neighbours, the forces and,
  // with gravity_loading.after_construction, a damped settling at the held time.
  void apply_construction();
  // The next construction event's time after t (1e300 if none): the step is shortened to meet it.
  double next_construction_time() const;
  // Damped steps until the solids' kinetic energy falls to the stage's ratio of its peak and their
  // unbalanced force to the stage's ratio of their weight, or to `max_time`; returns whether they settled.
  bool settle(double max_time, long& steps, double& peak, double& ke,
              const std::function<bool(const Simulation&)>& abandon = {});
  bool begin_loading();  // false: the scene has no stage, or it ran
  void hold_rigid_structures();  // zero velocity on rigid structures (their motion waits for a stage)
  void stop_solids();            // zero velocity on soil and deformable structures (a stage ends at rest)

  Scene scene_;
  Particles P_;
  CellList cells_;
  double pair_skin_ = 0;  // the pair list's skin beyond the kernel support [m] (core/cell_list.hpp)
  std::unique_ptr<FluidForces> fluid_;
  std::unique_ptr<DummyWalls> dummy_walls_;
  std::unique_ptr<MirrorWalls> mirror_walls_;  // walls.type "mirror": their crossings (boundary/mirror_wall.hpp)
  std::size_t mirror_reflections_ = 0;
  std::vector<DrainedFace> drained_faces_;  // containers' drained sides
  std::size_t drained_particles_ = 0;
  double drained_mass_ = 0;
  bool rebuild_cells_ = false;  // the particle set changed since the last neighbour search
  // Removes the water particles that crossed a drained side (after the drift).
  void drain();  std::unique_ptr<SoilForces> soil_;
  std::unique_ptr<SoilWalls> soil_walls_;
  std::unique_ptr<RigidMotions> rigid_;
  std::unique_ptr<SoilStructureContact> contact_;
  std::unique_ptr<TotalLagrangianSolids> total_lagrangian_;  // materials' formulation "total_lagrangian"
  std::unique_ptr<Seepage> seepage_;
  std::vector<Stage> stages_;
  StateBounds bounds_;
  TimeStepLimits limits_;
  StateSummary state_;
  std::size_t n_fluid_ = 0, n_soil_ = 0, n_structure_ = 0;
  std::vector<BodyFill> fills_;
  double t_ = 0, dt_ = 0;
  double density_dt_ = 0;  // the step the density stage last predicted the fluid density with (0 before the first)
  long step_ = 0;
  bool stop_ = false;
  bool loading_now_ = false;  // inside the gravity-loading stage (or a settling after construction)
  double loading_ramp_ = 0;   // gravity's ramp within the stage (the first only)
  double unbalanced_ = 0;     // the solids' unbalanced-force ratio at the last damped step (gravity_loading.hpp)
  GravityLoadingResult loading_;
  struct Placement {          // a body placed during the run, built at start
    std::size_t body;
    double time;
    Particles particles;
    bool done = false;
  };
  std::vector<Placement> placements_;
  std::vector<char> excavated_;  // per scene excavation: done
  std::vector<ConstructionEvent> construction_log_;
};

}  // namespace geosph
