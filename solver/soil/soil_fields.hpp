// Names of the per-particle soil fields (allocated only when a scene has soil; written to the
// HDF5 output under these names). Stress is tension positive.
#pragma once

namespace geosph {

struct SoilFields {
  static constexpr const char* xx = "stress_xx";
  static constexpr const char* yy = "stress_yy";
  static constexpr const char* zz = "stress_zz";
  static constexpr const char* xy = "stress_xy";
  static constexpr const char* xz = "stress_xz";
  static constexpr const char* yz = "stress_yz";
  static constexpr const char* plastic_strain = "plastic_strain";
};

}  // namespace geosph
