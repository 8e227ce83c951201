// Names of the per-particle fields of the seepage coupling (coupling/seepage.hpp), allocated only in
// two-phase scenes; the fluid walls, the soil walls and the state check read the porosity.
#pragma once

namespace geosph {

struct SeepageFields {
  static constexpr const char* porosity = "porosity";                  // soil and water particles, water walls
  static constexpr const char* conductivity = "hydraulic_conductivity"; // soil particles [m/s]
  static constexpr const char* porosity_rate = "porosity_rate";        // water particles: D^w n/Dt [1/s]
  static constexpr const char* other_phase_sum = "other_phase_kernel_sum";  // sum_j V_j W_ij over the other phase (water: Seepage::update_porosity; skeleton: Seepage::apply)
  static constexpr const char* gx = "skeleton_kernel_gradient_x", *gy = "skeleton_kernel_gradient_y",
                               *gz = "skeleton_kernel_gradient_z";  // water particles: G = sum_s V_s grad W
  static constexpr const char* skeleton_sum = "skeleton_kernel_sum";  // water particles: sum_s V_s W (walls included)
  static constexpr const char* nx = "porosity_gradient_x", *ny = "porosity_gradient_y",
                               *nz = "porosity_gradient_z";  // water particles: grad n over the water
  static constexpr const char* drag_c = "drag_rate";                    // C_i [1/s] of the point-implicit drag
  // the other phase around a particle, weighted by the drag: velocity, acceleration (without drag), density
  static constexpr const char* partner_vx = "drag_partner_vx", *partner_vy = "drag_partner_vy",
                               *partner_vz = "drag_partner_vz";
  static constexpr const char* partner_ax = "drag_partner_ax", *partner_ay = "drag_partner_ay",
                               *partner_az = "drag_partner_az";
  static constexpr const char* partner_rho = "drag_partner_density";
};

}  // namespace geosph
