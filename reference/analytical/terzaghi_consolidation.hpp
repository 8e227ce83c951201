// One-dimensional consolidation of a saturated elastic layer (Terzaghi 1925, "Erdbaumechanik auf
// bodenphysikalischer Grundlage", Deuticke; Terzaghi 1943, "Theoretical Soil Mechanics", Wiley, the
// chapter on the theory of consolidation), written with the storage of compressible pore water as in
// Biot's theory reduced to one dimension (Biot 1941, J. Appl. Phys. 12, 155-164: incompressible grains,
// fluid compressibility 1/K_w; the same 1D form is in Verruijt, "Theory and Problems of Poroelasticity",
// TU Delft, the chapter on one-dimensional consolidation):
//   storage     S = m_v + n / K_w,  m_v = 1 / E_oed (constrained compressibility)
//   coefficient c_v = k / (gamma_w S)
//   loading     B = m_v / S  (share of a load increment the pore water carries at once)
//   equation    du/dt = c_v d2u/dz2 + B dq/dt,  z depth below the drained top (u = 0 there),
//               du/dz = 0 at the impermeable base z = H, u(z, 0) = 0 before loading.
// Separation of variables with the modes sin(M z / H), M = (2m + 1) pi / 2, gives for a load history
// q(t) (Duhamel's principle):
//   u(z, t) = sum_m (2 / M) sin(M z / H) I_m(t),
//   I_m(t)  = int_0^t B q'(tau) exp(-M^2 c_v (t - tau) / H^2) d tau,
// which for a step load q0 is Terzaghi's series u = sum (2 B q0 / M) sin(M z/H) exp(-M^2 T), T = c_v t/H^2.
// The load is ramped as the solver's surcharge: q(t) = q0 (1 - cos(pi t / t_r)) / 2 for t < t_r, q0 after
// (q0 at once when t_r = 0). The integrals I_m are in closed form (checked against GSL quadrature of
// Duhamel's integral of the step response, verification/unit/test_analytical_references.cpp); the series
// is summed until a bound on its rest falls below 1e-9 B q0 (during a short ramp that takes up to ~1e6 modes). Settlement: s(t) = m_v int_0^H (q - u) dz, so the
// degree of consolidation U(t) = s(t) / s_inf = 1 - u_mean(t) / q(t), u_mean the depth average.
//
// All functions throw std::invalid_argument on invalid input and std::runtime_error if the series does not converge.
#pragma once

namespace geosph::reference {

struct TerzaghiSpec {
  double height = 0;       // H, drainage path: drained top to impermeable base [m]
  double cv = 0;           // consolidation coefficient c_v [m^2/s]
  double B = 1;            // share of the load taken by the pore water at once, in (0, 1]
  double load = 0;         // q0 [Pa]
  double ramp = 0;         // t_r [s], >= 0
};

// c_v and B from the soil's constrained modulus, porosity, conductivity and the water's bulk modulus
// (K_w = 0: incompressible water, B = 1).
TerzaghiSpec terzaghi_spec(double height, double conductivity, double unit_weight_water,
                           double constrained_modulus, double porosity, double water_bulk_modulus,
                           double load, double ramp);
double terzaghi_load(const TerzaghiSpec& s, double t);
// excess pore pressure u at depth z (0 = drained top) and time t
double terzaghi_excess_pressure(const TerzaghiSpec& s, double depth, double t);
// depth average of u
double terzaghi_mean_excess_pressure(const TerzaghiSpec& s, double t);
// degree of consolidation U = 1 - u_mean / q(t)
double terzaghi_degree_of_consolidation(const TerzaghiSpec& s, double t);

}  // namespace geosph::reference
