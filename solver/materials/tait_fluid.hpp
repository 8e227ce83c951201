// Weakly compressible fluid (Tait equation of state, Monaghan 1994; fluid/equation_of_state.hpp):
// the scene's fluid model "tait_fluid", with its viscosity and density diffusion.
#pragma once
#include <string>
#include <vector>

namespace geosph {

class JsonFields;

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
  // hydrostatic density gradient: a resting water column loses pressure at its base over time.
  // Pore water (two-phase) ignores it: its diffusion subtracts the density's linear part instead
  // (fluid/fluid_forces.cpp, Antuono et al. 2010)
  bool density_diffusion_hydrostatic = true;
};

// The fluid models (one today); materials.<name> of a fluid model.
std::vector<std::string> fluid_model_names();
FluidMaterial parse_fluid_material(const JsonFields& f, const std::string& name);

}  // namespace geosph
