// Modified Cam Clay soil (Roscoe & Burland 1968): pressure-dependent elasticity, isotropic hardening
// of the preconsolidation pressure p_c; implicit return in soil/modified_cam_clay.hpp. State fields:
// p_c and the accumulated plastic volumetric strain. Needs p' > 0 at start (its stiffness and
// yield locus scale with p'); a body's "ocr" sets p_c above the locus through its initial stress.
#pragma once
#include "materials/solid_model.hpp"
#include "soil/modified_cam_clay.hpp"

namespace geosph::materials {

struct ModifiedCamClay : SolidModelDefaults {
  static constexpr std::string_view name = "modified_cam_clay";
  static constexpr bool pressure_dependent = true;
  static constexpr bool needs_initial_pressure = true;
  static constexpr std::array<const char*, 2> state_fields{"preconsolidation_pressure", "plastic_volumetric_strain"};
  double lambda = 0;                // slope of the normal compression line in v - ln p'
  double kappa = 0;                 // slope of the unloading-reloading lines, 0 < kappa < lambda
  double critical_state_slope = 0;  // M, in (0, 3)
  double poisson = 0;               // nu in (-1, 0.5)
  double void_ratio = 0;            // e > 0 (v = 1 + e held constant: small-strain form)
  double min_pressure = 100;        // p'_min [Pa]: floor on p' in the moduli (free surfaces)

  static ModifiedCamClay parse(const JsonFields& f);
  double poisson_ratio() const { return poisson; }
  double wave_speed(double p, double density) const;
  SolidUpdate update(const Matrix3d& sigma, const Matrix3d& de, const Matrix3d& dw, const SolidState& s,
                     std::size_t i) const {
    const auto r = point_.update(sigma, s.f[0][i], de, dw);
    if (!r.converged) return {r.stress, 0.0, false};
    s.f[0][i] = r.preconsolidation;
    s.f[1][i] += r.volumetric_plastic_strain_increment;
    return {r.stress, r.equivalent_plastic_strain_increment, true};
  }
  void read_body(const JsonFields& b, BodySpec& body, const std::string& material) const;
  void initialise(const Matrix3d& sigma, const BodySpec& b, const SolidState& s, std::size_t i) const;
  std::string describe_failure(const Matrix3d& sigma, const SolidState& s, std::size_t i) const;

 private:
  soil::ModifiedCamClay point_{soil::ModifiedCamClayParams{0.2, 0.02, 1, 0.3, 2, 100}};
};

}  // namespace geosph::materials
