// Material-point (element-test) reference for the Drucker–Prager elastic–perfectly-plastic model:
// the stress path under a prescribed constant strain rate and spin, obtained by integrating the
// CONTINUUM rate equations with GSL's ODE driver (gsl_odeiv2, rk8pd, tight tolerances). It shares
// no code with the solver's return mapping (solver/soil/drucker_prager.*), against which it serves
// as an independent reference.
//
// Rate equations (tension positive; Bui, Fukagawa, Sako & Ohno 2008, Int. J. Numer. Anal. Meth.
// Geomech. 32:1537–1570, eqs. 19 and 25 for the Jaumann terms):
//   d sigma/dt = sigma omega^T + omega sigma + C : d eps/dt,
//   C = D                                             (elastic, or f < 0, or unloading),
//   C = D - (D:dg) (x) (df:D) / (df:D:dg)             (f = 0 and df:D:deps/dt > 0),
//   f = alpha_phi I1 + sqrt(J2) - k_c,  g = alpha_psi I1 + sqrt(J2),
//   df = alpha_phi I + n,  dg = alpha_psi I + n,  n = s / (2 sqrt(J2)),  df:D:dg = G + 9 K alpha_phi alpha_psi,
//   D:a = 2 G dev(a) + K tr(a) I.
// (The Jaumann terms do not change f, so the consistency condition is the one without spin.)
// The first contact with the yield surface is located by bisection of the elastic solution; from
// there on the plastic branch is integrated. The path must load monotonically once plastic (an
// unloading step throws std::runtime_error) and must stay away from the cone's apex (sqrt(J2) > 0).
//
// Optional mixed control: with hold_stress_xx the xx strain rate is not prescribed but solved for
// at every instant so that d sigma_xx/dt = 0 (e.g. a biaxial test at constant lateral stress).
#pragma once

#include <array>
#include <vector>

namespace geosph::reference {

// Symmetric tensor components: xx, yy, zz, xy, yz, xz (tensor, not engineering, shear strains).
using Sym3 = std::array<double, 6>;

struct DruckerPragerPathSpec {
  double bulk = 0, shear = 0;                 // K, G
  double alpha_phi = 0, alpha_psi = 0, k_c = 0;
  Sym3 stress0{};                             // initial stress, f(stress0) <= 0
  Sym3 strain_rate{};                         // constant d eps/dt
  std::array<double, 3> spin_rate{};          // omega_xy, omega_yz, omega_xz (omega antisymmetric)
  bool hold_stress_xx = false;                // solve for d eps_xx/dt so that d sigma_xx/dt = 0
  double duration = 0;
};

struct DruckerPragerPathPoint {
  double t;
  Sym3 stress;
  Sym3 strain;   // accumulated strain (integral of the strain rate, including the solved xx rate)
  bool plastic;  // on the yield surface (plastic branch) at t
};

struct DruckerPragerPath {
  std::vector<DruckerPragerPathPoint> points;  // n_intervals + 1 equally spaced times, 0 .. duration
  double yield_time;                           // first contact with the surface (< 0 if never)
};

// rel_tol: relative tolerance of the ODE driver (errors are measured against the stress scale
// max(|sigma0|, k_c, G |eps_rate| duration) and the strain scale |eps_rate| duration).
DruckerPragerPath drucker_prager_path(const DruckerPragerPathSpec& spec, int n_intervals, double rel_tol = 1e-11);

}  // namespace geosph::reference
