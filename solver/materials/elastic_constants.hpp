// Isotropic elastic constants shared by the models with linear elasticity, read as
// young_modulus and poisson_ratio; P-wave speed sqrt((K + 4G/3)/rho).
#pragma once
#include <cmath>
#include <vector>

#include "io/scene_reference.hpp"

namespace geosph {

// P-wave speed sqrt((K + 4G/3)/rho).
inline double p_wave_speed(double bulk, double shear, double density) {
  return std::sqrt((bulk + 4.0 * shear / 3.0) / density);
}

namespace materials {
struct ElasticConstants {
  double young = 0, poisson = 0;
  static ElasticConstants parse(const JsonFields& f);  // young_modulus > 0, poisson_ratio in (-1, 0.5)
  static std::vector<FieldDoc> docs();                  // their scene-reference entries
  double wave_speed(double density) const {
    return p_wave_speed(young / (3.0 * (1.0 - 2.0 * poisson)), young / (2.0 * (1.0 + poisson)), density);
  }
};
}  // namespace materials
}  // namespace geosph
