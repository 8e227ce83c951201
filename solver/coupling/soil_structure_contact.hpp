// Frictional contact between soil and structure bodies. The soil and each structure are separate SPH
// continua (their particles never enter each other's sums); they interact only through contact forces,
// computed from momentum as an ideal plastic collision with Coulomb friction (Wang & Chan 2014,
// Int. J. Numer. Anal. Meth. Geomech. 38, 747-770, first algorithm; the same velocity-level contact as
// Bardenhagen, Brackbill & Sulsky 2000, Comput. Methods Appl. Mech. Engrg. 187, 529-541, eqs. 9-13):
//   contact surface: node (soil particle i) to surface (structure particle j nearest to i), the
//                    structure's outward normal n_j = -grad C / |grad C|, C = sum_k V_k W_jk over the
//                    particles k of j's own body;
//   gap              g = (x_i - x_j) . n_j - dx   (particle centres sit dx/2 off the interface);
//   trial velocities v* = v + dt a (a: every other force), rigid structures: their prescribed velocity;
//   normal           the relative normal velocity u_n = (v*_i - v*_j) . n may at most close the gap in the
//                    step, u_n >= -g/dt, and a penetration g < 0 may not deepen, u_n >= 0:
//                    F_n = m* (u_target - u_n)/dt >= 0, m* = m_i m_j/(m_i + m_j) (m_i if j is rigid or fixed);
//   penetration      the soil particle is moved out along n by beta |g| each step (beta = 0.2), a position
//                    correction that adds no momentum (a velocity bias -beta g/dt, Baumgarte 1972, Comput.
//                    Methods Appl. Mech. Engng 1, 1-16, kept the recovery speed after the penetration was
//                    gone, at a speed set by the time step: a light pile, whose stiffness makes dt 3 times
//                    shorter, threw its head particle out of the domain);
//   tangential       sticking needs F_t = m* |u_t|/dt; Coulomb limits it, |F_t| <= tan(delta) F_n, opposite u_t.
//   a penetration is counted at most as the centres' overlap, g >= min(0, |x_i - x_j| - dx): at a convex
//                    structure corner the corner particle's normal is diagonal, and a soil particle one
//                    spacing below or beside it would otherwise see g = -0.29 dx and be pushed off the
//                    corner (a sheet pile's toe threw its soil off at 19 m/s in the first 0.01 s).
// The force acts on i and, reversed, on j; it is stored on the structure particles (fields contact_f*)
// so the wall load and its distribution can be read.
#pragma once
#include <array>
#include <vector>

#include "core/cell_list.hpp"
#include "core/particles.hpp"
#include "io/scene.hpp"

namespace geosph {

struct ContactFields {
  static constexpr const char* fx = "contact_fx";  // force of the soil on a structure particle [N (per m in 2D)]
  static constexpr const char* fy = "contact_fy";
  static constexpr const char* fz = "contact_fz";
  static constexpr const char* nx = "surface_nx";  // structure outward normal (zero inside the body)
  static constexpr const char* ny = "surface_ny";
  static constexpr const char* nz = "surface_nz";
};

class SoilStructureContact {
 public:
  explicit SoilStructureContact(const Scene& scene);
  void allocate(Particles& P) const;
  // Adds the contact accelerations for a step of length dt to soil and deformable structure particles
  // (P.a must already hold all other accelerations) and stores the forces on the structure particles.
  void apply(Particles& P, const CellList& cells, double dt) const;
  // Resultant force of the soil on structure body `body` (scene body index).
  static std::array<double, 3> body_force(const Particles& P, std::size_t body);

  static constexpr double kPenetrationRecovery = 0.2;  // beta: fraction of a penetration removed per step

 private:
  template <class K>
  void normals_with(const K& kernel, Particles& P, const CellList& cells) const;
  const Scene& scene_;
  std::vector<double> tan_delta_;  // per scene body
  mutable std::vector<std::int64_t> partner_;  // per particle: structure partner of a soil particle in contact
  mutable std::vector<std::array<double, 3>> force_;
  mutable std::vector<std::array<double, 3>> shift_;  // per particle: the penetration's position correction
};

}  // namespace geosph
