// Elastic structures in the total Lagrangian formulation (materials.<name>.formulation
// "total_lagrangian"): every sum runs over the bonds of the reference configuration X (the positions at
// the start), so a structure has no tensile instability and its neighbourhoods do not change as it bends.
//   F_i = sum_j (x_j - x_i) (x) c_ij, with weights from a least-squares fit of the motion over the bonds
//   with a quadratic basis p = (X_ij, X_ij X_ij), weights V0_j W_ij: c_ij = V0_j W_ij [M_i^-1 p(X_ij)]_grad,
//   M_i = sum_j V0_j W_ij p p^T. F is exact for motions quadratic in X, also at free surfaces (the MSPH
//   idea, Zhang & Batra 2004, Comput. Mech. 34, 137-146), so the outer rows of a member read the bending
//   strain at their own position, where a first-order gradient, all of whose bonds lie inward, reads it
//   inside the section. Where the bonds cannot fix a quadratic: Bonet & Lok's first-order correction
//   (1999, CMAME 180, eq. 22), c_ij = V0_j A_i^-T grad0 W_ij, A_i = sum_j V0_j (X_j - X_i) (x) grad0 W_ij.
//   E = (F^T F - I)/2, S = lambda tr(E) I + 2 mu E      (Saint Venant-Kirchhoff; plane strain in 2D)
//   f_i = -dU/dx_i = sum_j (V0_i P_i c_ij - V0_j P_j c_ji),  P = F S,  U = sum_i V0_i psi(F_i)
//                                                         (Vignjevic, Reveles & Campbell 2006, CMES 14:
//                                                         the forces as the gradient of the discrete
//                                                         strain energy; they conserve linear and angular
//                                                         momentum)
//   artificial viscosity -m_j Pi_ij fw(|X_ij|) x_ij with the material's alpha, beta (Monaghan 1992,
//   eq. 4.2): along the current x_ij with the bond's reference kernel gradient, so that it is central
//   Cauchy stress sigma = P F^T / J into the stress fields, rho = rho0 / J, p = -tr(sigma)/3.
// Only structures of the linear_elastic model; bonds join the total Lagrangian structure particles
// within the kernel's support at the start (a clamp and its beam, a pile and its head), whatever body.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "core/particles.hpp"
#include "io/scene.hpp"

namespace geosph {

struct TotalLagrangianFields {
  static constexpr const char* owner = "structure_total_lagrangian";
  static constexpr const char* reference[3] = {"reference_x", "reference_y", "reference_z"};  // X [m]
  static constexpr const char* has_reference = "has_reference";  // 1 once X is set (placed bodies later)
};

class TotalLagrangianSolids {
 public:
  // Throws InputError naming the material or body where a total Lagrangian material is not a
  // structure's linear_elastic one, or asks for what the formulation replaces.
  explicit TotalLagrangianSolids(const Scene& scene);
  static bool wanted(const Scene& scene);
  bool is_total_lagrangian(std::size_t material) const { return tl_[material] != 0; }
  void allocate(Particles& P) const;
  // F, the stress fields, rho and p of the structure's particles, then their accelerations (gravity
  // and body force included). The bonds are rebuilt when the particle set or its order has changed.
  void forces(Particles& P, const std::array<double, 3>& g, long step, double time) const;

 private:
  void build_bonds(Particles& P) const;
  template <int Dim> void forces_with(Particles& P, const std::array<double, 3>& g, long step, double time) const;

  const Scene& scene_;
  std::vector<std::uint8_t> tl_;           // per solid material
  std::vector<double> lambda_, mu_, c_;    // per solid material: Lame constants, P-wave speed
  mutable std::vector<std::int64_t> ids_;  // P.id at the last build
  mutable std::vector<std::uint32_t> list_;  // the structure's particles (indices into P)
  mutable std::vector<std::uint32_t> start_;  // bonds of list_[k]: start_[k] .. start_[k+1]
  mutable std::vector<std::uint32_t> bond_j_;  // the partner's position in list_
  mutable std::vector<std::array<double, 3>> bond_c_;  // c_ij: F_i = sum_j (x_j - x_i) (x) c_ij
  mutable std::vector<std::uint32_t> bond_rev_;  // the bond j -> i of bond i -> j
  mutable std::vector<double> bond_fw_;  // grad0 W_ij / |X_ij| (the viscosity's magnitude)
  mutable std::vector<std::array<double, 9>> P_;  // V0_i P_i per structure particle, row-major 3x3
  mutable std::vector<double> V0_;
};

}  // namespace geosph
