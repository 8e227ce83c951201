#include "sim/stability.hpp"

#include <cmath>
#include <sstream>

#include "coupling/seepage_fields.hpp"

namespace geosph {

std::string Diagnosis::message() const {
  std::ostringstream s;
  s.precision(6);
  s << "simulation unstable at step " << step << " (t = " << time << " s): particle id " << particle_id
    << " at (" << x << ", " << y << ", " << z << "): " << quantity;
  return s.str();
}

StateSummary check_state(const Particles& P, const Box& domain, const StateBounds& bounds, long step, double time) {
  const std::size_t n = P.size();
  double v2max = 0, a2max = 0;
  long bad = -1;
  // pore water (two-phase): rho is the partial density n rho_w, judged by its intrinsic density
  const double* por = P.find(SeepageFields::porosity);  // two-phase scenes
  auto density_ratio = [&](std::size_t i, const PhaseBounds& b) {
    const double r = P.rho[i] / b.rho0[P.material[i]];
    return por && P.kind[i] == Kind::Fluid ? r / por[i] : r;
  };
#pragma omp parallel for reduction(max : v2max, a2max) schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_moving(P.kind[i])) continue;
    const PhaseBounds& b = P.kind[i] == Kind::Fluid ? bounds.fluid : bounds.soil;
    const double v2 = P.vx[i] * P.vx[i] + P.vy[i] * P.vy[i] + P.vz[i] * P.vz[i];
    const double a2 = P.ax[i] * P.ax[i] + P.ay[i] * P.ay[i] + P.az[i] * P.az[i];
    const double ratio = density_ratio(i, b);
    const bool ok = std::isfinite(v2) && std::isfinite(a2) && std::isfinite(P.x[i] + P.y[i] + P.z[i]) &&
                    std::isfinite(ratio) && v2 <= b.max_speed * b.max_speed &&
                    std::abs(ratio - 1.0) <= bounds.max_density_variation && domain.contains(P.x[i], P.y[i], P.z[i]);
    if (!ok) {
#pragma omp critical
      if (bad < 0 || static_cast<long>(i) < bad) bad = static_cast<long>(i);
    }
    v2max = std::max(v2max, v2);
    a2max = std::max(a2max, a2);
  }
  if (bad >= 0) {
    const std::size_t i = static_cast<std::size_t>(bad);
    Diagnosis d;
    d.step = step; d.time = time; d.particle_id = P.id[i];
    d.x = P.x[i]; d.y = P.y[i]; d.z = P.z[i];
    std::ostringstream q;
    q.precision(6);
    const double v = std::sqrt(P.vx[i] * P.vx[i] + P.vy[i] * P.vy[i] + P.vz[i] * P.vz[i]);
    const double a = std::sqrt(P.ax[i] * P.ax[i] + P.ay[i] * P.ay[i] + P.az[i] * P.az[i]);
    const PhaseBounds& b = P.kind[i] == Kind::Fluid ? bounds.fluid : bounds.soil;
    const double ratio = density_ratio(i, b);
    if (!std::isfinite(P.x[i] + P.y[i] + P.z[i])) q << "position is not finite";
    else if (!std::isfinite(v)) q << "velocity is not finite";
    else if (!std::isfinite(a)) q << "acceleration is not finite";
    else if (!std::isfinite(ratio)) q << "density is not finite";
    else if (v > b.max_speed)
      q << "speed " << v << " m/s exceeds the " << (P.kind[i] == Kind::Fluid ? "sound" : "elastic wave") << " speed "
        << b.max_speed << " m/s (weak compressibility lost)";
    else if (std::abs(ratio - 1.0) > bounds.max_density_variation)
      q << "density ratio rho/rho0 = " << ratio << " is outside 1 +/- " << bounds.max_density_variation;
    else q << "particle left the domain";
    d.quantity = q.str();
    throw InstabilityError(d);
  }
  return {std::sqrt(v2max), std::sqrt(a2max)};
}

}  // namespace geosph
