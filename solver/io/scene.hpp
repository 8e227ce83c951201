// A scene: everything one simulation needs, read from JSON and validated field by field.
#pragma once
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/cell_list.hpp"
#include "core/kernels.hpp"

namespace geosph {

// Weakly compressible fluid (Tait equation of state, Monaghan 1994).
struct FluidMaterial {
  std::string name;
  double density = 1000;              // reference density rho0 [kg/m^3]
  double sound_speed = 0;             // artificial sound speed c0 [m/s]
  double gamma = 7;                   // Tait exponent
  double background_pressure = 0;     // [Pa]
  double artificial_viscosity = 0;    // Monaghan alpha [-]
  double kinematic_viscosity = 0;     // laminar nu [m^2/s] (Morris et al. 1997)
  double density_diffusion = 0;       // delta-SPH coefficient delta (Molteni & Colagrossi 2009)
  // the diffusion acts on the dynamic density only, less the hydrostatic difference of each pair
  // (Fourtakas et al. 2019, Comput. Fluids 190, 346-361, eq. 17); the plain form flattens the
  // hydrostatic density gradient: a resting water column loses pressure at its base over time
  bool density_diffusion_hydrostatic = false;
};

// An SPH solid material: soil (Drucker-Prager, Bui et al. 2008; Modified Cam Clay, Roscoe & Burland
// 1968) or a structure (linear_elastic; von_mises, elastic-perfectly plastic, integrated as
// Drucker-Prager with phi = 0 and k = yield_stress / sqrt(3)). Angles in degrees as written in the
// scene; the stress is integrated with the Jaumann rate and its pressure comes from the constitutive
// model (no equation of state).
struct SoilMaterial {
  std::string name;
  std::string model = "drucker_prager";  // drucker_prager | modified_cam_clay | linear_elastic (no yield) | von_mises
  double density = 0;                 // [kg/m^3]
  double young = 0;                   // Young's modulus E [Pa]
  double poisson = 0;                 // Poisson ratio nu, in (-1, 0.5)
  double cohesion = 0;                // Mohr-Coulomb c [Pa]
  double friction_angle = 0;          // Mohr-Coulomb phi [deg], in [0, 90)
  double dilatancy_angle = 0;         // psi [deg], in [0, phi]
  double yield_stress = 0;            // von_mises: uniaxial yield stress [Pa] (cohesion = yield_stress / sqrt(3))
  // modified_cam_clay (soil/modified_cam_clay.hpp): pressure-dependent elasticity, no young_modulus
  double lambda = 0;                  // slope of the normal compression line in v - ln p'
  double kappa = 0;                   // slope of the unloading-reloading lines, 0 < kappa < lambda
  double critical_state_slope = 0;    // M, in (0, 3)
  double void_ratio = 0;              // e > 0 (v = 1 + e held constant: small-strain form)
  double min_pressure = 100;          // p'_min [Pa]: floor on p' in the moduli (free surfaces)
  bool is_cam_clay() const { return model == "modified_cam_clay"; }
  // Saturated soil (two-phase, coupling/seepage.hpp): the skeleton's initial porosity n0 in (0, 1);
  // `density` is then the dry (partial) density (1 - n0) rho_s of the skeleton. The hydraulic
  // conductivity follows Kozeny-Carman, from its value at n0 or from the grain size.
  double porosity = 0;                // n0; 0 = dry soil (no pore water)
  double hydraulic_conductivity = 0;  // k at n0 [m/s] (0: from grain_size)
  double grain_size = 0;              // d [m], Kozeny-Carman with the 180 constant (0: from hydraulic_conductivity)
  bool saturated() const { return porosity > 0; }
  double grain_density() const { return density / (1.0 - porosity); }  // rho_s
  double artificial_viscosity = 0.1;  // Monaghan alpha for solids (Bui et al. 2008: 0.1)
  double artificial_viscosity_beta = 0.0;
  double artificial_stress = 0.0;     // epsilon (Gray, Monaghan & Swift 2001); 0 = off
  double artificial_stress_exponent = 4.0;  // n in f_ij = (W_ij / W(dx))^n
  // P-wave speed from young and poisson: the time step's acoustic limit for drucker_prager and
  // linear_elastic (Modified Cam Clay's moduli grow with p': SoilForces takes them from the model).
  double wave_speed() const;
};

// P-wave speed sqrt((K + 4G/3)/rho).
inline double p_wave_speed(double bulk, double shear, double density) {
  return std::sqrt((bulk + 4.0 * shear / 3.0) / density);
}

struct BodySpec {
  std::string material;
  std::array<double, 3> lo{}, hi{};
  std::string initial = "rest";       // rest (uniform rho0) | hydrostatic (fluid: Tait hydrostatic state)
                                      // | geostatic (soil: sigma_v = rho g depth, sigma_h = K0 sigma_v)
                                      // | isotropic (soil: sigma = -pressure I)
  double k0 = -1;                     // geostatic K0; < 0: nu/(1 - nu) (elastic, laterally confined)
  double pressure = 0;                // isotropic: initial mean effective stress p' [Pa]
  double ocr = 1;                     // modified_cam_clay: p_c = OCR x (p_c of the yield locus through the initial stress)
  // Surcharge: a vertical pressure on the body's top particle row (a fill, a footing load; permeable:
  // pore water drains through it), reaching `pressure` over `ramp` seconds with a smooth start.
  struct Surcharge {
    double pressure = 0;               // [Pa], downward
    double ramp = 0;                   // [s]
  } surcharge;
  std::array<double, 3> velocity{};
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

struct ContainerSpec {
  std::array<double, 3> lo{}, hi{};   // the inner (fluid-side) faces of the walls
  std::vector<std::string> open;      // sides without a wall: left right bottom top front back
  std::array<double, 3> velocity{};   // blocks only: prescribed constant velocity (e.g. a footing pushed down)
  double ramp = 0;                    // blocks only: the velocity is reached over `ramp` seconds (smooth start)
};

struct WallSpec {
  std::string type = "dummy";         // dummy (Adami et al. 2012) | repulsive (Monaghan 1994)
  std::string slip = "no_slip";       // no_slip | free_slip
  int layers = 0;                     // 0: enough layers to cover the kernel support
  double repulsive_strength = 0;      // D [m^2/s^2]; 0: 0.05 c0^2 (i.e. ~5 g H for c0 = 10 sqrt(gH))
  std::vector<ContainerSpec> containers;
  std::vector<ContainerSpec> blocks;  // solid boxes of wall particles (e.g. a clamp); `open` unused
};

struct Scene {
  std::string file;                   // where it was read from (for messages)
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
  double output_interval = 0;         // 0: first and last state only
  int reorder_every = 20;             // steps between sorting particles in memory by cell
  double max_density_variation = 0.5; // |rho/rho0 - 1| beyond this is a blow-up
  bool kernel_gradient_correction = false;  // soil velocity gradient corrected (Bonet & Lok 1999)
  std::vector<FluidMaterial> materials;   // fluids (Kind::Fluid particles index this list)
  std::vector<SoilMaterial> soils;       // soils (Kind::Soil particles index this list)
  bool has_fluid() const { return !materials.empty(); }
  bool has_soil() const { return !soils.empty(); }
  std::vector<BodySpec> bodies;
  WallSpec walls;
  bool has_walls() const { return !walls.containers.empty() || !walls.blocks.empty(); }
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
