#include "analytical/hydrostatic_tait.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_roots.h>

#include <cmath>
#include <stdexcept>

namespace geosph::reference {

namespace {
struct Params { double rho0, B, gamma, g; };

double rho_of_p(const Params& q, double p) { return q.rho0 * std::pow(p / q.B + 1.0, 1.0 / q.gamma); }

int rhs(double, const double y[], double dydt[], void* params) {
  const auto* q = static_cast<const Params*>(params);
  dydt[0] = rho_of_p(*q, y[0]) * q->g;
  return GSL_SUCCESS;
}

double integrate_pressure(const Params& q, double depth) {
  if (depth <= 0) return 0.0;
  gsl_odeiv2_system sys{rhs, nullptr, 1, const_cast<Params*>(&q)};
  gsl_odeiv2_driver* d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, depth * 1e-3, 1e-13, 1e-13);
  double t = 0, y[1] = {0.0};
  const int status = gsl_odeiv2_driver_apply(d, &t, depth, y);
  gsl_odeiv2_driver_free(d);
  if (status != GSL_SUCCESS) throw std::runtime_error("HydrostaticTait: ODE integration failed");
  return y[0];
}

struct MassParams { const Params* q; };
double density_integrand(double depth, void* mp) {
  const Params& q = *static_cast<MassParams*>(mp)->q;
  return rho_of_p(q, integrate_pressure(q, depth));
}

struct RootParams { const Params* q; double target; gsl_integration_workspace* w; };
double mass_residual(double H, void* rp) {
  auto* r = static_cast<RootParams*>(rp);
  MassParams mp{r->q};
  gsl_function f{density_integrand, &mp};
  double result = 0, err = 0;
  gsl_integration_qag(&f, 0.0, H, 0.0, 1e-12, 1000, GSL_INTEG_GAUSS21, r->w, &result, &err);
  return result - r->target;
}
}  // namespace

HydrostaticTait::HydrostaticTait(double rho0, double c0, double gamma, double g, double H0)
    : rho0_(rho0), B_(rho0 * c0 * c0 / gamma), gamma_(gamma), g_(g), H0_(H0), H_(H0) {
  const Params q{rho0_, B_, gamma_, g_};
  gsl_integration_workspace* w = gsl_integration_workspace_alloc(1000);
  RootParams rp{&q, rho0_ * H0_, w};
  gsl_function f{mass_residual, &rp};
  gsl_root_fsolver* s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  gsl_root_fsolver_set(s, &f, 0.5 * H0_, H0_);
  int status = GSL_CONTINUE;
  for (int it = 0; it < 200 && status == GSL_CONTINUE; ++it) {
    gsl_root_fsolver_iterate(s);
    status = gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s), 0.0, 1e-13 * H0_);
  }
  H_ = gsl_root_fsolver_root(s);
  gsl_root_fsolver_free(s);
  gsl_integration_workspace_free(w);
  if (status != GSL_SUCCESS) throw std::runtime_error("HydrostaticTait: surface height did not converge");
}

double HydrostaticTait::pressure_at_depth(double depth) const {
  return integrate_pressure(Params{rho0_, B_, gamma_, g_}, depth);
}

double HydrostaticTait::density_at_depth(double depth) const {
  return rho_of_p(Params{rho0_, B_, gamma_, g_}, pressure_at_depth(depth));
}

}  // namespace geosph::reference
