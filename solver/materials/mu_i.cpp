#include "materials/mu_i.hpp"

#include "io/json_fields.hpp"
#include "io/scene_reference.hpp"

namespace geosph::materials {

namespace {
std::vector<FieldDoc> docs() {
  auto d = ElasticConstants::docs();
  d.push_back(number_doc("mu_s", Range::non_negative(), "required", "-",
                         "static friction coefficient: sqrt(J2) = mu_s p' at the onset of flow (tan of the repose angle)"));
  d.push_back(number_doc("mu_2", Range::non_negative(), "required", "-", "limiting friction coefficient at large I, >= mu_s"));
  d.push_back(number_doc("i0", Range::positive(), "0.279", "-", "inertial number I_0 (Jop et al. 2006's glass beads)"));
  d.push_back(number_doc("grain_diameter", Range::positive(), "required", "m", "grain diameter d in I = gamma_dot d / sqrt(p'/rho_s)"));
  d.push_back(number_doc("grain_density", Range::positive(), "density", "kg/m^3", "grain density rho_s in I"));
  return d;
}
const bool documented = register_section(
    {"materials:solid:mu_i", "materials.<name> with \"model\": \"mu_i\"",
     "mu(I) granular rheology, elasto-viscoplastic: elastic below sqrt(J2) = mu_s p', flow at sqrt(J2) = mu(I) p' with "
     "mu(I) = mu_s + (mu_2 - mu_s)/(I_0/I + 1) (Jop, Forterre & Pouliquen 2006; the return of Dunatunga & Kamrin 2015); "
     "stress-free at p' <= 0; no plastic volume change.",
     docs()});
}  // namespace

MuI MuI::parse(const JsonFields& f) {
  MuI m;
  m.elastic = ElasticConstants::parse(f);
  const double mu_s = f.number("mu_s", Range::non_negative());
  const double mu_2 = f.number("mu_2", Range::non_negative());
  if (mu_2 < mu_s) f.fail("mu_2", "must be >= mu_s (" + std::to_string(mu_s) + "), got " + std::to_string(mu_2));
  const double i0 = f.number("i0", Range::positive(), 0.279);
  const double d = f.number("grain_diameter", Range::positive());
  const double rho_s = f.number("grain_density", Range::positive(), f.number("density", Range::positive()));
  m.point_ = soil::MuIRheology({m.elastic.young, m.elastic.poisson, mu_s, mu_2, i0, d, rho_s});
  return m;
}

}  // namespace geosph::materials
