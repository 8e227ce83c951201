#include "harness/deposit.hpp"

#include "sim/gravity_loading.hpp"  // solid_kinetic_energy

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace geosph::verify {

Profile surface_profile(const Particles& P, double x0, double floor_y, double dx) {
  double xmax = x0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::Soil) xmax = std::max(xmax, P.x[i]);
  const auto nb = static_cast<std::size_t>(std::ceil((xmax - x0) / dx)) + 1;
  Profile pr;
  pr.h.assign(nb, 0.0);
  for (std::size_t b = 0; b < nb; ++b) pr.x.push_back(x0 + (b + 0.5) * dx);
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Soil) continue;
    const auto b = std::min(nb - 1, static_cast<std::size_t>(std::max(0.0, (P.x[i] - x0) / dx)));
    pr.h[b] = std::max(pr.h[b], P.y[i] + 0.5 * dx - floor_y);
  }
  return pr;
}

double runout_front(const Particles& P, double floor_y, double dx) {
  double xmax = -1e300;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::Soil && P.y[i] < floor_y + 2 * dx) xmax = std::max(xmax, P.x[i]);
  return xmax + 0.5 * dx;
}

double scaling_law(const nlohmann::json& entries, double a) {
  for (const auto& e : entries) {
    const double lo = e.at("a_min").get<double>();
    const double hi = e.at("a_max").is_null() ? std::numeric_limits<double>::infinity() : e.at("a_max").get<double>();
    if (a >= lo && a < hi) return e.at("coefficient").get<double>() * std::pow(a, e.at("exponent").get<double>());
  }
  return std::numeric_limits<double>::quiet_NaN();
}

double max_soil_speed(const Particles& P) {
  double v2 = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::Soil) v2 = std::max(v2, P.vx[i] * P.vx[i] + P.vy[i] * P.vy[i] + P.vz[i] * P.vz[i]);
  return std::sqrt(v2);
}

double rms_solid_speed(const Particles& P) {
  double m = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::Soil || P.kind[i] == Kind::Structure) m += P.m[i];
  return m > 0 ? std::sqrt(2.0 * solid_kinetic_energy(P) / m) : 0.0;
}

std::size_t soil_particles_faster_than(const Particles& P, double v) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::Soil && P.vx[i] * P.vx[i] + P.vy[i] * P.vy[i] + P.vz[i] * P.vz[i] > v * v) ++n;
  return n;
}

std::vector<SandModel> sand_models(const CaseConfig& cfg) {
  const nlohmann::json& all = cfg.spec.at("sand_models");
  std::vector<std::string> names;
  if (cfg.level.contains("sand_models"))
    names = cfg.level.at("sand_models").get<std::vector<std::string>>();
  else
    for (const auto& m : all.items()) names.push_back(m.key());
  std::vector<SandModel> out;
  for (const auto& n : names) {
    if (!all.contains(n))
      throw std::invalid_argument(cfg.name + "/case.json: the level names sand model '" + n +
                                  "', which is not in \"sand_models\"");
    const auto& m = all.at(n);
    out.push_back({n, m.at("material"), m.value("scored", true), m.value("why", std::string())});
  }
  return out;
}

}  // namespace geosph::verify
