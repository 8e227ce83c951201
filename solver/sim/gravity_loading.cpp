#include "sim/gravity_loading.hpp"

#include <cmath>

#include "boundary/body_fields.hpp"
#include "io/scene_reference.hpp"

namespace geosph {

namespace {

const bool documented = register_section(
    {"gravity_loading", "gravity_loading",
     "A gravity-loading stage before t = 0: the solids settle under their weight with local damping (Cundall "
     "1987) until their kinetic energy falls below a fraction of its peak; then velocities are zeroed and the "
     "run starts from the settled state.",
     {choice_doc("model", {"elastic", "material"}, "elastic",
                 "the solids during the stage: linear elastic with their own E and nu, or their own model"),
      number_doc("damping", Range{0, 1, false, true}, "0.8", "-", "local damping coefficient alpha"),
      number_doc("kinetic_energy_ratio", Range::open(0, 1), "1e-4", "-",
                 "the stage ends when the solids' kinetic energy is at most this fraction of its peak"),
      number_doc("force_ratio", Range::open(0, 1), "1e-3", "-",
                 "and when the solids' mean unbalanced force is at most this fraction of their mean weight "
                 "(FLAC's equilibrium ratio; the kinetic energy alone also vanishes at an oscillation's turning point)"),
      number_doc("ramp", Range::non_negative(), "0", "s", "gravity grows smoothly over this time within the stage"),
      number_doc("max_time", Range::positive(), "20", "s", "not settled by then stops the run with an error"),
      {"after_construction", FieldType::Boolean, "true, false", "false", "-",
       "after every excavation or placed body the solids settle again (their own model, time held); not "
       "settled in max_time is logged and the run goes on (the stage is failing)"}}});

}  // namespace

GravityLoadingSpec parse_gravity_loading(const JsonFields& f) {
  f.section("gravity_loading");
  GravityLoadingSpec g;
  g.active = true;
  g.model = f.choice("model", {"elastic", "material"}, "elastic");
  g.damping = f.number("damping", Range{0, 1, false, true}, 0.8);
  g.kinetic_energy_ratio = f.number("kinetic_energy_ratio", Range::open(0, 1), 1e-4);
  g.force_ratio = f.number("force_ratio", Range::open(0, 1), 1e-3);
  g.ramp = f.number("ramp", Range::non_negative(), 0.0);
  g.max_time = f.number("max_time", Range::positive(), 20.0);
  g.after_construction = f.boolean("after_construction", false);
  if (g.ramp >= g.max_time) f.fail("ramp", "must be shorter than max_time");
  f.reject_unknown();
  return g;
}

void apply_local_damping(Particles& P, double alpha) {
  const std::size_t n = P.size();
  auto damp = [alpha](double& a, double v) {
    if (v != 0) a -= alpha * std::abs(a) * (v > 0 ? 1.0 : -1.0);
  };
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (P.kind[i] != Kind::Soil && P.kind[i] != Kind::Structure) continue;
    damp(P.ax[i], P.vx[i]);
    damp(P.ay[i], P.vy[i]);
    damp(P.az[i], P.vz[i]);
  }
}

double unbalanced_force_ratio(const Particles& P, const std::array<double, 3>& g) {
  const std::int32_t* fixed = P.find_int(BodyFields::fixed);
  const double g_norm = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  double unbalanced = 0, weight = 0;
  const std::size_t n = P.size();
#pragma omp parallel for reduction(+ : unbalanced, weight) schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if ((P.kind[i] != Kind::Soil && P.kind[i] != Kind::Structure) || (fixed && fixed[i] > 0)) continue;
    unbalanced += P.m[i] * std::sqrt(P.ax[i] * P.ax[i] + P.ay[i] * P.ay[i] + P.az[i] * P.az[i]);
    weight += P.m[i] * g_norm;
  }
  return weight > 0 ? unbalanced / weight : 0.0;
}

double solid_kinetic_energy(const Particles& P) {
  double e = 0;
  const std::size_t n = P.size();
#pragma omp parallel for reduction(+ : e) schedule(static)
  for (std::size_t i = 0; i < n; ++i)
    if (P.kind[i] == Kind::Soil || P.kind[i] == Kind::Structure)
      e += 0.5 * P.m[i] * (P.vx[i] * P.vx[i] + P.vy[i] * P.vy[i] + P.vz[i] * P.vz[i]);
  return e;
}

}  // namespace geosph
