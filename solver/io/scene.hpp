// A scene: everything one simulation needs, read from JSON and validated field by field.
#pragma once
#include <array>
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
};

struct BodySpec {
  std::string material;
  std::array<double, 3> lo{}, hi{};
  std::string initial = "rest";       // rest (uniform rho0) | hydrostatic (Tait hydrostatic state)
  std::array<double, 3> velocity{};
};

struct ContainerSpec {
  std::array<double, 3> lo{}, hi{};   // the inner (fluid-side) faces of the walls
  std::vector<std::string> open;      // sides without a wall: left right bottom top front back
};

struct WallSpec {
  std::string type = "dummy";         // dummy (Adami et al. 2012) | repulsive (Monaghan 1994)
  std::string slip = "no_slip";       // no_slip | free_slip
  int layers = 0;                     // 0: enough layers to cover the kernel support
  double repulsive_strength = 0;      // D [m^2/s^2]; 0: 0.05 c0^2 (i.e. ~5 g H for c0 = 10 sqrt(gH))
  std::vector<ContainerSpec> containers;
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
  std::array<double, 3> body_force{}; // extra acceleration on fluid [m/s^2]
  double t_end = 0;
  double cfl = 0.2, force_factor = 0.25, viscous_factor = 0.125;
  long max_steps = 100000000;
  double output_interval = 0;         // 0: first and last state only
  int reorder_every = 20;             // steps between sorting particles in memory by cell
  double max_density_variation = 0.5; // |rho/rho0 - 1| beyond this is a blow-up
  std::vector<FluidMaterial> materials;
  std::vector<BodySpec> bodies;
  WallSpec walls;
  bool has_walls() const { return !walls.containers.empty(); }

  double h() const { return h_over_dx * dx; }
  double support() const { return kernel_support_factor(kernel) * h(); }
};

// Parse and validate; throws InputError naming the file and field.
Scene parse_scene(const nlohmann::json& j, const std::string& file);
Scene load_scene(const std::filesystem::path& path);
// Cross-field checks (particles inside the domain, periodic lengths...), also for scenes built in code.
void validate_scene(const Scene& s);

}  // namespace geosph
