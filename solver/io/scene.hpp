// A scene: everything one simulation needs, read from JSON and validated field by field.
#pragma once
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "boundary/morris_wall.hpp"
#include "core/cell_list.hpp"
#include "core/kernels.hpp"
#include "geometry/shape.hpp"
#include "materials/solid_material.hpp"
#include "materials/tait_fluid.hpp"

namespace geosph {

struct BodySpec {
  std::string material;
  std::array<double, 3> lo{}, hi{};   // the box, or the bounding box of `shape`
  // The body's shape when it is not the box lo..hi (geometry/shape.hpp); its particles fill the points
  // (i + 1/2) dx inside it (geometry/lattice_fill.hpp).
  geometry::ShapePtr shape;
  std::string initial = "rest";       // rest (uniform rho0) | hydrostatic (fluid: Tait hydrostatic state)
                                      // | geostatic (soil: sigma_v = rho g depth, sigma_h = K0 sigma_v)
                                      // | isotropic (soil: sigma = -pressure I)
  double k0 = -1;                     // geostatic K0; < 0: nu/(1 - nu) (elastic, laterally confined)
  double pressure = 0;                // isotropic: initial mean effective stress p' [Pa]
  double ocr = 1;                     // modified_cam_clay: p_c = OCR x (p_c of the yield locus through the initial stress)
                                      // (read by the model: materials/modified_cam_clay.cpp)
  // Surcharge: a vertical pressure on the body's top particle row (a fill, a footing load; permeable:
  // pore water drains through it), reaching `pressure` over `ramp` seconds with a smooth start.
  struct Surcharge {
    double pressure = 0;               // [Pa], downward
    double ramp = 0;                   // [s]
  } surcharge;
  std::array<double, 3> velocity{};
  // Construction (sim/construction.hpp): > 0, the body appears at this time, e.g. a fill layer or an
  // embankment lift; 0, it is there from the start.
  double placed_at = 0;
  bool fixed = false;                 // held in place (velocity zero) but otherwise part of the material,
                                      // e.g. the clamped root of a plate (Gray, Monaghan & Swift 2001)
  // Structure bodies (structure/, coupling/soil_structure_contact.hpp): an SPH solid of their own
  // material that meets soil only through frictional contact.
  bool structure = false;
  double interface_friction_angle = -1;  // delta [deg] of the soil-structure interface (Coulomb), in [0, 90)
  // Prescribed rigid motion (makes the structure rigid): velocity of its reference point and angular
  // velocity about it (2D: about z), both scaled by a smooth start over `ramp` seconds.
  struct Motion {
    bool active = false;
    std::array<double, 3> velocity{};  // [m/s]
    double angular_velocity = 0;       // [rad/s], counter-clockwise
    std::array<double, 3> centre{};    // reference point (rotation centre) at t = 0 [m]
    double ramp = 0;                   // [s]
  } motion;
  bool is_rigid_structure() const { return structure && motion.active; }
};

// The name of a container's side (ContainerSpec::open): left/right along x; in 2D bottom/top along y;
// in 3D front/back along y (min/max) and bottom/top along z, so that "top" is always the side gravity
// points away from in the catalogue's convention (-y in 2D, -z in 3D).
inline const char* container_side(int dim, int axis, bool upper) {
  static const char* lo2[2] = {"left", "bottom"};
  static const char* hi2[2] = {"right", "top"};
  static const char* lo3[3] = {"left", "front", "bottom"};
  static const char* hi3[3] = {"right", "back", "top"};
  return dim == 2 ? (upper ? hi2[axis] : lo2[axis]) : (upper ? hi3[axis] : lo3[axis]);
}

struct ContainerSpec {
  std::array<double, 3> lo{}, hi{};   // the inner (fluid-side) faces of the walls
  std::vector<std::string> open;      // sides without a wall: left right bottom top front back
  std::string slip;                   // containers: no_slip | free_slip (default: walls.slip)
  std::vector<std::string> drained;   // containers: sides the pore water drains through (boundary/drained_face.hpp)
  double drained_pressure = 0;        // containers: pore pressure at the drained sides [Pa]
  std::array<double, 3> velocity{};   // blocks only: prescribed constant velocity (e.g. a footing pushed down)
  double ramp = 0;                    // blocks only: the velocity is reached over `ramp` seconds (smooth start)
};

// A wall of any shape: the solid `shape`, whose surface is the wall; its particles fill the lattice
// points inside it within the wall layers of the surface, and carry the surface's outward normal.
struct BoundarySpec {
  geometry::ShapePtr shape;
  std::array<double, 3> lo{}, hi{};   // the shape's bounding box
  std::string slip;                   // no_slip | free_slip (default: walls.slip)
};

struct WallSpec {
  std::string type = "dummy";         // dummy (Adami et al. 2012) | repulsive (Monaghan 1994) | morris (1997) | ghost (2011)
  std::string slip = "no_slip";       // no_slip | free_slip
  int layers = 0;                     // 0: enough layers to cover the kernel support
  double repulsive_strength = 0;      // D [m^2/s^2]; 0: 0.05 c0^2 (i.e. ~5 g H for c0 = 10 sqrt(gH))
  double morris_beta_max = kMorrisBetaMax;  // Morris walls: cap of beta = 1 + d_wall/d_fluid
  std::vector<ContainerSpec> containers;
  std::vector<ContainerSpec> blocks;  // solid boxes of wall particles (e.g. a clamp); `open` unused
  std::vector<BoundarySpec> boundaries;
};

// An excavation (sim/construction.hpp): at `time` the soil and fluid particles inside `shape` are removed.
struct ExcavationSpec {
  double time = 0;                    // [s], > 0
  geometry::ShapePtr shape;
  std::array<double, 3> lo{}, hi{};   // the shape's bounding box
};

// The gravity-loading stage before t = 0 (sim/gravity_loading.hpp).
struct GravityLoadingSpec {
  bool active = false;
  std::string model = "elastic";        // elastic | material
  double damping = 0.8;                 // alpha in [0, 1): Cundall's local damping coefficient
  double kinetic_energy_ratio = 1e-4;   // the stage ends when KE <= ratio x its peak KE
  double force_ratio = 1e-3;            // and the mean unbalanced force <= ratio x the mean weight
  double ramp = 0;                      // s: gravity grows smoothly over this time within the stage
  double max_time = 20;                 // s: not settled by then is an error naming the field
  // After every construction event (an excavation, a placed body) the solids settle again under the
  // same damping, with the scene's time held, as a staged geotechnical analysis solves each stage to
  // equilibrium; their own model throughout.
  bool after_construction = false;
};

// Resource limits of a run (not scene fields: the command line sets them, sim/resource_limits.hpp).
struct RunLimits {
  double max_particles = 2e7;  // --max-particles; ~8 GB of a soil scene
  double max_cells = 2e8;      // --max-cells; the cell list's 4 bytes per cell (0.8 GB)
};

struct Scene {
  std::string file;                   // where it was read from (for messages)
  std::string source;                 // the scene's JSON, canonical (keys sorted, no comments)
  std::string hash;                   // content_hash(source) (core/provenance.hpp)
  std::string name;
  int dim = 2;
  double dx = 0;
  KernelType kernel = KernelType::WendlandC2;
  double h_over_dx = 0;
  Box domain;
  std::array<double, 3> gravity{};
  double gravity_ramp = 0;            // s; gravity grows smoothly over this time (Adami et al. 2012, eq. 33)
  double gravity_ramp_from = 0;       // fraction of the gravity at t = 0 when ramped (in [0, 1))
  // Gravity factor at t = 0: the initial hydrostatic/geostatic states are computed with it.
  double initial_gravity_factor() const { return gravity_ramp > 0 ? gravity_ramp_from : 1.0; }
  std::array<double, 3> body_force{}; // extra acceleration on fluid [m/s^2]
  double t_end = 0;
  double cfl = 0.2, force_factor = 0.25, viscous_factor = 0.125;
  long max_steps = 100000000;
  RunLimits limits;
  double output_interval = 0;         // 0: first and last state only
  int reorder_every = 20;             // steps between sorting particles in memory by cell
  double max_density_variation = 0.5; // |rho/rho0 - 1| beyond this is a blow-up
  double pair_list_skin = 0.1;        // Verlet list reach beyond the support, in supports (0: no list)
  bool kernel_gradient_correction = false;  // soil velocity gradient corrected (Bonet & Lok 1999)
  bool kernel_gradient_correction_stress = false;  // and the solids' stress divergence (both sides of each pair)
  std::vector<FluidMaterial> materials;   // fluids (Kind::Fluid particles index this list)
  std::vector<SoilMaterial> soils;       // soils (Kind::Soil particles index this list)
  bool has_fluid() const { return !materials.empty(); }
  bool has_soil() const { return !soils.empty(); }
  // The corrections a solid particle of soils[k] gets: numerics' for every solid, or its material's own
  // (materials.<name>.kernel_gradient_correction corrects both)
  bool corrects_velocity_gradient(std::size_t k) const {
    return kernel_gradient_correction || soils[k].kernel_gradient_correction;
  }
  bool corrects_stress_divergence(std::size_t k) const {
    return kernel_gradient_correction_stress || soils[k].kernel_gradient_correction;
  }
  std::vector<BodySpec> bodies;
  WallSpec walls;
  GravityLoadingSpec gravity_loading;
  std::vector<ExcavationSpec> excavations;  // in time order
  bool has_construction() const {
    if (!excavations.empty()) return true;
    for (const auto& b : bodies)
      if (b.placed_at > 0) return true;
    return false;
  }
  bool has_walls() const { return !walls.containers.empty() || !walls.blocks.empty() || !walls.boundaries.empty(); }
  // Some container's or boundary's slip differs from walls.slip: the wall particles carry
  // BodyFields::wall_free_slip.
  bool mixed_wall_slip() const {
    for (const auto& c : walls.containers)
      if (c.slip != walls.slip) return true;
    for (const auto& b : walls.boundaries)
      if (b.slip != walls.slip) return true;
    return false;
  }
  // Any wall is no-slip (walls.slip, blocks, or a container's or boundary's own).
  bool any_no_slip_wall() const {
    if (walls.slip == "no_slip") return true;
    for (const auto& c : walls.containers)
      if (c.slip == "no_slip") return true;
    for (const auto& b : walls.boundaries)
      if (b.slip == "no_slip") return true;
    return false;
  }
  // The soil (or structure) material called `name`, null if there is none.
  const SoilMaterial* find_soil(const std::string& name) const {
    for (const auto& m : soils)
      if (m.name == name) return &m;
    return nullptr;
  }
  // Saturated soil and its pore water (the scene's fluid) as two particle sets (coupling/seepage.hpp).
  bool two_phase() const {
    if (!has_fluid()) return false;
    for (const auto& m : soils)
      if (m.saturated()) return true;
    return false;
  }

  double h() const { return h_over_dx * dx; }
  double support() const { return kernel_support_factor(kernel) * h(); }
};

// Parse and validate; throws InputError naming the file and field.
Scene parse_scene(const nlohmann::json& j, const std::string& file);
Scene load_scene(const std::filesystem::path& path);
// Cross-field checks (particles inside the domain, periodic lengths...), also for scenes built in code.
void validate_scene(const Scene& s);

}  // namespace geosph
