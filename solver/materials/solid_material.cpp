#include "materials/solid_material.hpp"

#include "core/particles.hpp"
#include "io/json_fields.hpp"
#include "io/scene_reference.hpp"
#include "materials/model_list.hpp"
#include "soil/soil_fields.hpp"

namespace geosph {

using Solids = materials::ModelList<materials::SolidModel>;

namespace {
const bool documented = register_section(
    {"materials:solid", "materials.<name> with a solid model", "What every solid (soil or structure) material has.",
     {number_doc("density", Range::positive(), "required", "kg/m^3",
                 "density (saturated soil: the skeleton's dry partial density (1 - n0) rho_s)"),
      number_doc("porosity", Range::open(0, 1), "0 (dry)", "-", "saturated soil: initial porosity n0 (two-phase)"),
      number_doc("hydraulic_conductivity", Range::positive(), "required with porosity (or grain_size)", "m/s",
                 "k at n0 (Kozeny-Carman in n)"),
      number_doc("grain_size", Range::positive(), "instead of hydraulic_conductivity", "m",
                 "d for Kozeny-Carman's k (constant 180)"),
      number_doc("artificial_viscosity", Range::between(0, 1), "0.1", "-", "Monaghan alpha (Bui et al. 2008)"),
      number_doc("artificial_viscosity_beta", Range::between(0, 2), "0", "-", "Monaghan beta"),
      choice_doc("artificial_viscosity_switch", {"none", "balsara"}, "none",
                 "balsara: the viscosity scaled by f = abs(div v) / (abs(div v) + abs(curl v) + 1e-4 c/h) "
                 "(Balsara 1995), on in compression, off in shear flow"),
      {"kernel_gradient_correction", FieldType::Boolean, "true, false", "false", "-",
       "this material's particles use the corrected kernel gradient (Bonet & Lok 1999) in the velocity gradient "
       "and in the stress divergence, whatever numerics says (e.g. a structure a few particles thick)"},
      choice_doc("formulation", {"updated_lagrangian", "total_lagrangian"}, "updated_lagrangian",
                 "total_lagrangian (structures of linear_elastic only): deformation gradient and forces over the "
                 "bonds of the reference configuration, Saint Venant-Kirchhoff stress, the corrected kernel gradient "
                 "(Vignjevic, Reveles & Campbell 2006; Bonet & Lok 1999): no tensile instability, and a member a "
                 "few particles thick carries its section's moment"),
      {"artificial_stress", FieldType::Object, "see materials.artificial_stress", "off", "-",
       "tensile-instability correction (Gray, Monaghan & Swift 2001)"}}});
const bool documented_as = register_section(
    {"materials.artificial_stress", "materials.<name>.artificial_stress", "Artificial stress on tensile principal stresses.",
     {number_doc("epsilon", Range::between(0, 1), "required", "-", "strength epsilon"),
      number_doc("exponent", Range::between(1, 10), "4", "-", "n in f_ij = (W_ij / W(dx))^n")}});
}  // namespace

std::vector<std::string> solid_model_names() { return Solids::names(); }

materials::SolidState SoilMaterial::bind_state(Particles& P) const {
  materials::SolidState st;
  std::visit([&](const auto& m) {
    for (std::size_t f = 0; f < m.state_fields.size(); ++f) st.f[f] = P.add_field(m.state_fields[f], SoilFields::owner).data();
  }, model);
  return st;
}

std::string SoilMaterial::model_name() const {
  return std::visit([](const auto& m) { return std::string(m.name); }, model);
}
double SoilMaterial::poisson_ratio() const {
  return std::visit([](const auto& m) { return m.poisson_ratio(); }, model);
}
bool SoilMaterial::pressure_dependent() const {
  return std::visit([](const auto& m) { return m.pressure_dependent; }, model);
}
double SoilMaterial::wave_speed() const {
  return std::visit([&](const auto& m) { return m.wave_speed(0.0, density); }, model);
}
void SoilMaterial::throw_wrong_model(const std::string& wanted) const {
  throw InputError("material \"" + name + "\" is " + model_name() + ", expected " + wanted);
}

SoilMaterial parse_solid_material(const JsonFields& f, const std::string& name, const std::string& model) {
  SoilMaterial m;
  m.name = name;
  m.density = f.number("density", Range::positive());
  m.model = Solids::parse(model, f);
  if (std::visit([](const auto& s) { return s.saturable; }, m.model)) {  // a two-phase skeleton
    m.porosity = f.number("porosity", Range::open(0, 1), 0.0);
    if (f.has("hydraulic_conductivity") || f.has("grain_size")) {
      if (!m.saturated()) f.fail("porosity", "is required with hydraulic_conductivity or grain_size (saturated soil)");
      if (f.has("hydraulic_conductivity") && f.has("grain_size"))
        f.fail("grain_size", "give either hydraulic_conductivity or grain_size, not both");
      if (f.has("hydraulic_conductivity")) m.hydraulic_conductivity = f.number("hydraulic_conductivity", Range::positive());
      else m.grain_size = f.number("grain_size", Range::positive());
    } else if (m.saturated()) {
      f.fail("hydraulic_conductivity", "is missing: saturated soil (porosity given) needs hydraulic_conductivity [m/s] > 0 "
                                       "or grain_size [m] > 0 (Kozeny-Carman)");
    }
  }
  m.artificial_viscosity = f.number("artificial_viscosity", Range::between(0, 1), 0.1);
  m.artificial_viscosity_beta = f.number("artificial_viscosity_beta", Range::between(0, 2), 0.0);
  m.artificial_viscosity_balsara = f.choice("artificial_viscosity_switch", {"none", "balsara"}, "none") == "balsara";
  m.kernel_gradient_correction = f.boolean("kernel_gradient_correction", false);
  m.total_lagrangian = f.choice("formulation", {"updated_lagrangian", "total_lagrangian"}, "updated_lagrangian") ==
                       "total_lagrangian";
  if (auto a = f.optional_object("artificial_stress")) {
    a->section("materials.artificial_stress");
    m.artificial_stress = a->number("epsilon", Range::between(0, 1));
    m.artificial_stress_exponent = a->number("exponent", Range::between(1, 10), 4.0);
    a->reject_unknown();
  }
  f.reject_unknown();
  return m;
}

}  // namespace geosph
