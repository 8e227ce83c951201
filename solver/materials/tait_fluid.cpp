#include "materials/tait_fluid.hpp"

#include "io/json_fields.hpp"
#include "io/scene_reference.hpp"

namespace geosph {

namespace {
const bool documented = register_section(
    {"materials:tait_fluid", "materials.<name> with \"model\": \"tait_fluid\"",
     "Weakly compressible fluid: Tait equation of state p = rho0 c0^2/gamma ((rho/rho0)^gamma - 1) + p_bg.",
     {number_doc("density", Range::positive(), "required", "kg/m^3", "reference density rho0"),
      number_doc("sound_speed", Range::positive(), "required", "m/s", "artificial sound speed c0 (>= 10 x the fastest flow)"),
      number_doc("gamma", Range::between(1, 15), "7", "-", "Tait exponent"),
      number_doc("background_pressure", Range::non_negative(), "0", "Pa", "p_bg"),
      number_doc("artificial_viscosity", Range::between(0, 1), "0", "-", "Monaghan alpha"),
      number_doc("kinematic_viscosity", Range::non_negative(), "0", "m^2/s", "laminar viscosity nu (Morris et al. 1997)"),
      number_doc("density_diffusion", Range::between(0, 1), "0", "-", "delta-SPH coefficient (Molteni & Colagrossi 2009)"),
      {"density_diffusion_hydrostatic", FieldType::Boolean, "true, false", "true", "-",
       "diffuse the dynamic density only (Fourtakas et al. 2019, eq. 17): keeps a resting column's pressure; "
       "false: plain delta-SPH, which diffuses the hydrostatic gradient and lets the base pressure fall. "
       "Pore water (two-phase scenes) ignores it: its delta-SPH subtracts the density's linear part (Antuono et al. 2010)"}}});
}  // namespace

std::vector<std::string> fluid_model_names() { return {"tait_fluid"}; }

FluidMaterial parse_fluid_material(const JsonFields& f, const std::string& name) {
  FluidMaterial m;
  m.name = name;
  m.density = f.number("density", Range::positive());
  m.sound_speed = f.number("sound_speed", Range::positive());
  m.gamma = f.number("gamma", Range::between(1, 15), 7.0);
  m.background_pressure = f.number("background_pressure", Range::non_negative(), 0.0);
  m.artificial_viscosity = f.number("artificial_viscosity", Range::between(0, 1), 0.0);
  m.kinematic_viscosity = f.number("kinematic_viscosity", Range::non_negative(), 0.0);
  m.density_diffusion = f.number("density_diffusion", Range::between(0, 1), 0.0);
  m.density_diffusion_hydrostatic = f.boolean("density_diffusion_hydrostatic", true);
  f.reject_unknown();
  return m;
}

}  // namespace geosph
