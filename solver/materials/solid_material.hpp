// An SPH solid material: soil or a structure, one constitutive model from materials/solid_models.hpp
// plus what every solid has: density, the saturated-soil data of a two-phase skeleton and the
// stabilisation (artificial viscosity and stress). Angles in degrees as written in the scene; the
// stress is integrated with the Jaumann rate and its pressure comes from the constitutive model (no
// equation of state).
#pragma once
#include <string>
#include <vector>

#include "materials/solid_models.hpp"

namespace geosph {

class JsonFields;
struct Particles;

struct SoilMaterial {
  std::string name;
  materials::SolidModel model;
  double density = 0;                 // [kg/m^3]
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
  // Balsara's (1995) switch: Pi_ij scaled by (f_i + f_j)/2 with f from balsara_switch
  // (soil/viscosity_switch.hpp), so that the viscosity acts in compression and not in shear flow
  bool artificial_viscosity_balsara = false;
  double artificial_stress = 0.0;     // epsilon (Gray, Monaghan & Swift 2001); 0 = off
  double artificial_stress_exponent = 4.0;  // n in f_ij = (W_ij / W(dx))^n
  // This material's particles use the corrected kernel gradient (Bonet & Lok 1999) in the velocity
  // gradient and in their side of the stress divergence, as numerics.kernel_gradient_correction and
  // kernel_gradient_correction_stress do for every solid: a structure a few particles thick transmits
  // its section's moment with it (without it its free surfaces' truncated sums make it too compliant)
  bool kernel_gradient_correction = false;
  // formulation "total_lagrangian": a structure's linear elastic particles are summed over the bonds of
  // their reference configuration (structure/total_lagrangian.hpp) instead of the Jaumann-rate update
  bool total_lagrangian = false;

  std::string model_name() const;
  // The model's state fields in P (created, owned by the soil module, if not there yet).
  materials::SolidState bind_state(Particles& P) const;
  double poisson_ratio() const;
  bool pressure_dependent() const;  // wave speed changes with p' (per-particle speeds)
  // P-wave speed at zero mean stress for pressure-dependent models; the constant one otherwise.
  double wave_speed() const;
  template <class M> bool is() const { return std::holds_alternative<M>(model); }
  // The model as M; throws InputError naming the material if it is another model.
  template <class M> const M& as() const {
    if (const M* m = std::get_if<M>(&model)) return *m;
    throw_wrong_model(std::string(M::name));
  }

  [[noreturn]] void throw_wrong_model(const std::string& wanted) const;
};

// Reads materials.<name> of a solid model (the "model" field already checked against solid_model_names()).
SoilMaterial parse_solid_material(const JsonFields& f, const std::string& name, const std::string& model);
std::vector<std::string> solid_model_names();

}  // namespace geosph
