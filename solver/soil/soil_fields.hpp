// Names of the per-particle soil fields (allocated only when a scene has soil; written to the
// HDF5 output under these names). Stress is tension positive.
#pragma once

namespace geosph {

struct SoilFields {
  static constexpr const char* owner = "soil";
  static constexpr const char* xx = "stress_xx";
  static constexpr const char* yy = "stress_yy";
  static constexpr const char* zz = "stress_zz";
  static constexpr const char* xy = "stress_xy";
  static constexpr const char* xz = "stress_xz";
  static constexpr const char* yz = "stress_yz";
  static constexpr const char* plastic_strain = "plastic_strain";  // equivalent deviatoric, accumulated
  // Modified Cam Clay only (allocated when a scene declares it):
  static constexpr const char* preconsolidation = "preconsolidation_pressure";   // p_c [Pa]
  static constexpr const char* plastic_volumetric_strain = "plastic_volumetric_strain";  // tr(eps_p), tension positive
  static constexpr const char* wave_speed = "wave_speed";  // local P-wave speed [m/s] (moduli grow with p')
  // materials.artificial_viscosity_switch "balsara": f (soil/viscosity_switch.hpp) per solid particle
  // from the last stress update (1 before the first, and for materials without the switch)
  static constexpr const char* viscosity_switch = "viscosity_switch";
  // numerics.kernel_gradient_correction_stress: B^-T - I per solid particle, row-major (a = 0..2, b = 0..2),
  // from the last stress update (zero: no correction, e.g. where B is singular)
  static constexpr const char* correction[9] = {"kernel_correction_xx", "kernel_correction_xy", "kernel_correction_xz",
                                                "kernel_correction_yx", "kernel_correction_yy", "kernel_correction_yz",
                                                "kernel_correction_zx", "kernel_correction_zy", "kernel_correction_zz"};
};

}  // namespace geosph
