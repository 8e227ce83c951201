// What every solid constitutive model (soil or structure) provides, so that the scene reader, the
// particle builder and the stress update handle any model the same way. A model is one type in
// materials/solid_models.hpp's list; it derives from SolidModelDefaults and hides what it changes:
//   static constexpr std::string_view name       the scene's "model" value
//   static M parse(const JsonFields& f)           its parameters, read and range-checked (the one
//                                                 place where its ranges live)
//   double poisson_ratio() const                  for the elastic K0 = nu/(1 - nu) of a geostatic start
//   double wave_speed(double p, double rho) const P-wave speed at mean effective stress p (time step,
//                                                 artificial viscosity)
//   SolidUpdate update(sigma, de, dw, state, i)   Jaumann rotation + constitutive update over one step
// and, where it needs them, state fields (state_fields, read and written through SolidState), an
// initial-state hook (initialise) and body fields of its own (read_body).
// The dispatch is one std::visit per particle; nothing is looked up by name inside the step.
#pragma once
#include <array>
#include <cstddef>
#include <string>
#include <string_view>

#include <Eigen/Core>

namespace geosph {

class JsonFields;
struct BodySpec;

namespace materials {

using Matrix3d = Eigen::Matrix3d;

// The model's state fields of the current particle set, bound once per stress update
// (pointers into Particles; f[k] is the k-th name of the model's state_fields).
struct SolidState {
  std::array<double*, 4> f{};
  double dt = 0;  // the step's length [s], for rate-dependent models
};

struct SolidUpdate {
  Matrix3d stress;          // sigma_{n+1}, tension positive
  double eq_plastic = 0;    // equivalent deviatoric plastic strain increment
  bool converged = true;    // false: an implicit return failed (the step stops with a diagnosis)
};

struct SolidModelDefaults {
  static constexpr bool saturable = true;            // may be the skeleton of a saturated soil
  static constexpr bool structure_allowed = false;   // may form a structure body
  static constexpr bool pressure_dependent = false;  // wave speed changes with p' (per-particle speeds)
  static constexpr bool needs_initial_pressure = false;  // p' > 0 required at start
  static constexpr std::array<const char*, 0> state_fields{};
  // Body fields of the model's own (e.g. an overconsolidation ratio) and body-level checks.
  void read_body(const JsonFields&, BodySpec&, const std::string& /*material*/) const {}
  // Initial values of the state fields for a particle starting at stress sigma.
  void initialise(const Matrix3d&, const BodySpec&, const SolidState&, std::size_t) const {}
  // Why a non-converged update failed, for the diagnosis (start-of-step stress and state).
  std::string describe_failure(const Matrix3d&, const SolidState&, std::size_t) const { return "return mapping failed"; }
};

}  // namespace materials
}  // namespace geosph
