// Weakly compressible SPH fluid: continuity and momentum equations for the fluid particles.
//   continuity   d rho_i/dt = sum_j m_j v_ij . grad_i W_ij                     (Monaghan 1992, eq. 4.7)
//                + delta-SPH diffusion  delta h c0 sum_j 2 (rho_i - rho_j) r_ij.grad_i W_ij / (r^2 + eta^2) V_j
//                                                              (Molteni & Colagrossi 2009, eq. 14)
//   momentum     dv_i/dt = -sum_j m_j (p_i/rho_i^2 + p_j/rho_j^2 + Pi_ij) grad_i W_ij + g
//                artificial viscosity Pi_ij = -alpha c0 mu_ij / rho_ij, mu_ij = h v_ij.r_ij/(r^2 + eta^2)
//                                                              (Monaghan 1992, eq. 4.2)
//                laminar viscosity  sum_j m_j (mu_i + mu_j) r_ij.grad_i W_ij / (rho_i rho_j (r^2 + eta^2)) v_ij
//                                                              (Morris, Fox & Zhu 1997, eq. 10)
//   repulsive walls  f = D [(r0/r)^12 - (r0/r)^4] r_ij / r^2 for r < r0      (Monaghan 1994, eq. 6.1)
// Pore water (two-phase scenes, coupling/seepage.hpp): rho is the partial density n rho_w, p follows
// rho/n, and the pressure term is multiplied by n_i (-n grad p / (n rho_w)).
// with eta^2 = 0.01 h^2 (1e-4 h^2 in the laminar term, see fluid_forces.cpp). Dummy wall particles enter with the pressure, density and (no-slip)
// velocity extrapolated by DummyWalls (Adami, Hu & Adams 2012); Morris walls with the dummy pressure and
// the relative velocity beta (v_i - v_wall) in the viscous terms (Morris, Fox & Zhu 1997, boundary/morris_wall.hpp).
// Mirror walls add the same pair terms with the images of the neighbours (boundary/mirror_wall.hpp).
#pragma once
#include <memory>
#include <vector>

#include "boundary/mirror_wall.hpp"
#include "core/cell_list.hpp"
#include "core/kernels.hpp"
#include "core/particles.hpp"
#include "fluid/equation_of_state.hpp"
#include "io/scene.hpp"

namespace geosph {

class FluidForces {
 public:
  explicit FluidForces(const Scene& scene);
  // Pressure of fluid particles from their density.
  void update_pressure(Particles& P) const;
  // Density rates (continuity + delta-SPH) and accelerations of the fluid particles in one neighbour
  // pass, at the state the step predicted: rho~ = rho^n + dt drho^{n-1} (Simulation's density stage,
  // `dt_predicted` its step; 0 when nothing was predicted, as at t = 0). Then corrects the density to
  // rho^n + dt drho^n with the new rate, so rho stays the second-order update it was with a separate
  // continuity pass; only the pressure the accelerations see is the predicted one, O(dt^2) off.
  // `g` is the current gravity (and the hydrostatic part of the density diffusion).
  void rates(Particles& P, const CellList& cells, const std::array<double, 3>& g, double dt_predicted) const;

  const std::vector<TaitEos>& eos() const { return eos_; }
  double max_sound_speed() const;
  double max_kinematic_viscosity() const;

 private:
  // Morris: Morris no-slip walls (boundary/morris_wall.hpp), never mixed slip or porous
  template <int Dim, bool MixedSlip, bool Porous, bool Morris, class K>
  void rates_with(const K& kernel, Particles& P, const CellList& cells, const std::array<double, 3>& g) const;
  void correct_density(Particles& P, double dt_predicted) const;
  // Mirror walls (boundary/mirror_wall.hpp): adds the images' share to the rates and accelerations
  // rates_with wrote (fluid/fluid_mirror_images.cpp).
  void add_mirror_images(Particles& P, const CellList& cells, const std::array<double, 3>& g) const;
  template <int Dim, class K>
  void mirror_images_with(const K& kernel, Particles& P, const CellList& cells, const std::array<double, 3>& g) const;

  // porosity of the pore water (two-phase scenes, coupling/seepage.hpp), else null
  const double* porosity(const Particles& P) const;
  template <int Dim, class K>
  // vol: m / rho of every particle
  void density_gradients(const K& kernel, const Particles& P, const CellList& cells, const double* por,
                         const double* vol) const;
  mutable std::array<std::vector<double>, 3> grad_rho_;

  const Scene& scene_;
  std::vector<TaitEos> eos_;
  std::vector<FluidMaterial> mats_;
  bool free_slip_walls_, morris_walls_;
  std::shared_ptr<const MirrorWalls> mirror_;  // walls.type "mirror" only
  double repulsive_D_, repulsive_r0_;
  mutable std::vector<double> pressure_over_rho2_, volume_, drho_new_;  // scratch, per particle
};

}  // namespace geosph
