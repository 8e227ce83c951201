// Saturated soil as two particle sets that share space: the soil skeleton (Kind::Soil, effective
// stress from its constitutive model) and the pore water (Kind::Fluid, weakly compressible), after
// Bui & Fukagawa (2013), Int. J. Numer. Anal. Meth. Geomech. 37, 31-50, with the mixture equations of
// Biot/Zienkiewicz for incompressible grains (Zienkiewicz et al. 1999, "Computational Geomechanics",
// eqs. 2.11-2.14, u-w form without the grains' compressibility):
//   water    n rho_w  dv_w/dt = -n grad p + n rho_w g - R
//   skeleton (1-n) rho_s dv_s/dt = div sigma' - (1-n) grad p + (1-n) rho_s g + R
//   drag     R = (n^2 gamma_w / k) (v_w - v_s)   (Darcy: n (v_w - v_s) = -(k/gamma_w)(grad p - rho_w g))
// Particles carry partial densities: water rho = n rho_w (its intrinsic density rho_w = rho / n sets the
// pore pressure through the Tait equation), soil rho = (1-n) rho_s. Porosity:
//   skeleton  n_i = 1 - rho_i / rho_s (its continuity equation: n follows the volumetric strain)
//   water     interpolated from the skeleton at t = 0, then carried by the water particle with its rate
//             D^w n/Dt = (1 - n) div v_s + (v_w - v_s) . grad n (see Seepage::porosity_rate_with)
// Hydraulic conductivity, Kozeny-Carman (Carman 1937; Bear 1972, "Dynamics of Fluids in Porous Media",
// eq. 5.10.18):  k(n) = (gamma_w / mu) d^2/180 n^3/(1-n)^2, or k0 f(n)/f(n0) with f = n^3/(1-n)^2.
// SPH forms (V = m/rho, the particle's share of the mixture volume):
//   drag on soil i from water j  F_ij = beta_i V_i V_j W_ij (v_j - v_i) 2/(S_i + S_j), beta = n^2 gamma_w / k,
//                                equal and opposite on j (Bui & Fukagawa 2013, eq. 27 with pairwise weights);
//                                S = sum V W over the other phase (the lattice sum is not exactly 1: 0.4%
//                                too much drag without it, measured on the Darcy case)
//   pore-pressure force on soil i   the adjoint of the water's porosity rate (energy-consistent; see
//                                Seepage::apply_with), relative to the Shepard-averaged pressure where the
//                                porosity jumps under free water (a constant pressure exerts no force)
// The drag is integrated implicitly for each particle and its partner phase (Seepage::kick), so the
// relaxation time k/(n g) does not limit the time step (as the implicit drag of Monaghan 1997,
// J. Comput. Phys. 138, 801-820, for dusty gas); the stored accelerations exclude the drag.
#pragma once
#include <array>
#include <vector>

#include "core/cell_list.hpp"
#include "coupling/seepage_fields.hpp"
#include "core/particles.hpp"
#include "io/scene.hpp"

namespace geosph {


// Kozeny-Carman porosity function f(n) = n^3 / (1 - n)^2.
inline double kozeny_carman(double n) { return n * n * n / ((1.0 - n) * (1.0 - n)); }

class Seepage {
 public:
  explicit Seepage(const Scene& scene);
  void allocate(Particles& P) const;
  // At t = 0 (after the first neighbour search): porosity of every particle, and the water particles'
  // masses and partial densities n rho_w so that their intrinsic density is the one they were built with.
  void initialise(Particles& P, const CellList& cells) const;
  // Porosity and conductivity of the skeleton (from its density) and the water's kernel sums of the
  // skeleton (the skeleton's sum of the water is taken in apply).
  void update_porosity(Particles& P, const CellList& cells) const;
  // The water particles' porosity rate at (x^{n+1}, v^{n+1/2}) and its update over dt.
  void porosity_rate(Particles& P, const CellList& cells) const;
  void advance_porosity(Particles& P, double dt) const;
  // Adds the skeleton's pore-pressure force to its acceleration and stores each particle's drag rate and
  // partner state for the implicit drag (kick); call after both phases' momentum and all other forces.
  void apply(Particles& P, const CellList& cells) const;
  // Half kick over h, with the implicit drag, of the integrated particles that have a drag partner
  // (drag rate > 0; `fixed` particles excluded); the others take the plain kick.
  void kick(Particles& P, double h, const std::int32_t* fixed) const;
  // Hydraulic conductivity of soil material `mat` at porosity n [m/s].
  double conductivity(std::size_t mat, double n) const;
  // Undrained P-wave speed of the mixture, sqrt((K_w/n + K + 4G/3) / rho_sat), for the time step.
  double undrained_wave_speed(double skeleton_modulus_max) const;
  double unit_weight() const { return gamma_w_; }

 private:
  template <class K>
  void apply_with(const K& kernel, Particles& P, const CellList& cells) const;
  template <class K>
  void porosity_with(const K& kernel, Particles& P, const CellList& cells) const;
  template <class K>
  void interpolate_water_porosity(const K& kernel, Particles& P, const CellList& cells) const;
  template <class K>
  void porosity_rate_with(const K& kernel, Particles& P, const CellList& cells) const;

  const Scene& scene_;
  double rho_w_, gamma_w_, mu_w_;
  const double* volumes(const Particles& P) const;  // m / rho of every particle, into volume_

  mutable std::vector<double> beta_;  // per-particle drag coefficient n^2 gamma_w / k (apply), scratch
  mutable std::vector<double> volume_;  // scratch of volumes()
};

}  // namespace geosph
