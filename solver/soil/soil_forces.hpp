// Elasto-plastic soil as an SPH continuum (Bui, Fukagawa, Sako & Ohno 2008, Int. J. Numer. Anal.
// Meth. Geomech. 32, 1537-1570), tension positive:
//   velocity gradient  L_i = sum_j V_j (v_j - v_i) (x) grad_i W_ij                 (Bui 2008, eq. 30)
//                      optionally corrected, L_i <- L_i B_i^-1, B_i = sum_j V_j (x_j - x_i) (x) grad_i W_ij,
//                      exact for linear velocity fields also at free surfaces (Bonet & Lok 1999,
//                      Comput. Methods Appl. Mech. Engrg. 180, eq. 22; numerics.kernel_gradient_correction)
//   continuity         d rho_i/dt = sum_j m_j (v_i - v_j) . grad_i W_ij
//   stress             Jaumann rate + Drucker-Prager (soil/drucker_prager.hpp) or Modified Cam Clay
//                      (soil/modified_cam_clay.hpp) return mapping
//   momentum           dv_i/dt = sum_j m_j (S_i + S_j + (R_i + R_j) f_ij^n - Pi_ij I) . grad_i W_ij + g,
//                      S = sigma / rho^2                                           (Bui 2008, eq. 29)
//                      optionally with S_i B_i^-T grad W + S_j B_j^-T grad W for the stresses, the
//                      corrected gradient on each side (numerics.kernel_gradient_correction_stress;
//                      per material, with the corrected L: materials.<name>.kernel_gradient_correction)
//   artificial viscosity Pi_ij = (-alpha c_ij mu_ij + beta mu_ij^2) / rho_ij for v_ij.r_ij < 0
//                                                                                  (Monaghan 1992, eq. 4.2)
//                      optionally scaled by (f_i + f_j)/2, f = |div v| / (|div v| + |curl v| + 1e-4 c/h)
//                      from the velocity gradient L (Balsara 1995, J. Comput. Phys. 121, 357-372, eq. 4.1;
//                      materials.artificial_viscosity_switch): on in compression, off in shear flow
//                      c_ij = (c_i + c_j)/2, the local P-wave speeds (constant for Drucker-Prager;
//                      growing with p' for Modified Cam Clay)
//   artificial stress  R = -epsilon sigma'_aa / rho^2 on tensile principal stresses, rotated back;
//                      f_ij = W(r_ij) / W(dx)            (Gray, Monaghan & Swift 2001, eqs. 3.1-3.6)
// Pressure p = -tr(sigma)/3 is an output of the constitutive model, not an equation of state.
#pragma once
#include <array>
#include <memory>
#include <vector>

#include "boundary/mirror_wall.hpp"
#include "core/cell_list.hpp"
#include "core/particles.hpp"
#include "io/scene.hpp"
#include <optional>
#include <set>
#include <string>

#include "materials/linear_elastic.hpp"
#include "materials/solid_model.hpp"
#include "soil/soil_fields.hpp"

namespace geosph {

class SoilForces {
 public:
  explicit SoilForces(const Scene& scene);
  void allocate(Particles& P) const;
  // Largest P-wave speed of the soil now (Modified Cam Clay: from the current stresses, updated with
  // every stress update); the time step's acoustic limit.
  double max_wave_speed() const;
  void restore_max_wave_speed(double c) const { max_wave_speed_ = c; }  // a restart (io/checkpoint.hpp)
  double density(std::size_t material) const { return scene_.soils[material].density; }

  // At x^{n+1} with v^{n+1/2}: density rate and the stress update over dt (velocity gradient,
  // Jaumann rotation, return mapping). Throws InstabilityError if a stress becomes non-finite or a
  // Modified Cam Clay return does not converge.
  void update_stress(Particles& P, const CellList& cells, double dt, long step, double time) const;
  // The gravity-loading stage's "elastic" mode (sim/gravity_loading.hpp): models with constant moduli
  // update the stress elastically (Jaumann rotation + Hooke), without their plastic return.
  void set_elastic_only(bool on) const { elastic_only_ = on; }
  // Accelerations of soil particles (after the wall particles carry their extrapolated stress).
  void momentum(Particles& P, const CellList& cells, const std::array<double, 3>& g) const;

 private:
  template <int Dim, class K>
  void update_stress_with(const K& kernel, Particles& P, const CellList& cells, double dt, long step,
                          double time) const;
  template <int Dim, class K>
  void momentum_with(const K& kernel, Particles& P, const CellList& cells, const std::array<double, 3>& g) const;
  // Mass, density and velocity as the soil's sums see them: the soil walls' ghost values at dummy
  // particles (boundary/soil_wall.hpp), the particles' own elsewhere; one pass instead of a choice per pair.
  void gather_soil_view(const Particles& P) const;
  // S = sigma/rho^2 and artificial stress R per particle
  void prepare_pair_terms(Particles& P) const;

  // The models' state fields per material.
  std::vector<materials::SolidState> bind_states(Particles& P) const;
  // Local wave speeds of the pressure-dependent (Modified Cam Clay) particles (field SoilFields::wave_speed) and their maximum.
  void update_wave_speeds(Particles& P) const;

  const Scene& scene_;
  std::set<std::string> state_fields_;  // the models' state fields (materials/solid_model.hpp)
  // per material: its structure particles are stepped by structure/total_lagrangian.hpp, not here
  std::vector<std::uint8_t> total_lagrangian_;
  std::vector<double> wave_speed_;  // per material (the constant one where the model has one)
  bool has_pressure_dependent_ = false;  // per-particle wave speeds (field SoilFields::wave_speed)
  bool has_viscosity_switch_ = false;  // a material with Balsara's switch (field SoilFields::viscosity_switch)
  // numerics.kernel_gradient_correction_stress or a material's kernel_gradient_correction: the field
  // SoilFields::correction (B^-T - I, zero for the particles that are not corrected)
  bool stress_correction_ = false;
  mutable double max_wave_speed_ = 0;
  mutable bool elastic_only_ = false;
  // per material: Hooke's law with its own constants, for the elastic mode (models with constant moduli)
  std::vector<std::optional<materials::LinearElastic>> hooke_;
  mutable std::vector<std::array<double, 6>> S_, R_;  // xx yy zz xy xz yz
  mutable std::vector<std::uint8_t> tension_;  // R_[i] is not zero
  std::shared_ptr<const MirrorWalls> mirror_;  // walls.type "mirror" (soil/soil_mirror_images.hpp)
  mutable std::vector<double> mass_, rho_, volume_, ghost_vx_, ghost_vy_, ghost_vz_;  // volume_ = mass_ / rho_
};

}  // namespace geosph
