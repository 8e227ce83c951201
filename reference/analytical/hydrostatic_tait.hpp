// Hydrostatic column of a weakly compressible (Tait) fluid, computed independently of the solver:
// dp/d(depth) = rho(p) g with rho(p) = rho0 (p/B + 1)^(1/gamma), B = rho0 c0^2 / gamma
// (Monaghan 1994, eq. 3.3), integrated with GSL's ODE driver; the settled free-surface height H
// follows from mass conservation, int_0^H rho dz = rho0 H0 (GSL quadrature + Brent root finding).
// For an incompressible fluid this reduces to p = rho0 g (H0 - z).
#pragma once

namespace geosph::reference {

class HydrostaticTait {
 public:
  // H0: height of the column when filled at uniform density rho0.
  HydrostaticTait(double rho0, double c0, double gamma, double g, double H0);
  double surface_height() const { return H_; }
  double pressure_at_depth(double depth) const;
  double pressure(double z) const { return pressure_at_depth(H_ - z); }
  double density_at_depth(double depth) const;

 private:
  double rho0_, B_, gamma_, g_, H0_, H_;
};

}  // namespace geosph::reference
