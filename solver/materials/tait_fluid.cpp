#include "materials/tait_fluid.hpp"

#include "io/json_fields.hpp"

namespace geosph {

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
  m.density_diffusion_hydrostatic = f.boolean("density_diffusion_hydrostatic", false);
  f.reject_unknown();
  return m;
}

}  // namespace geosph
