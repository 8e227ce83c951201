#include "materials/modified_cam_clay.hpp"

#include <algorithm>

#include "io/json_fields.hpp"
#include "io/scene.hpp"
#include "materials/elastic_constants.hpp"

namespace geosph::materials {

namespace {
const bool documented = register_section(
    {"materials:solid:modified_cam_clay", "materials.<name> with \"model\": \"modified_cam_clay\"",
     "Modified Cam Clay (Roscoe & Burland 1968): pressure-dependent elasticity, hardening p_c; needs p' > 0 at start.",
     {number_doc("poisson_ratio", Range::open(-1.0, 0.5), "required", "-", "constant Poisson's ratio nu"),
      number_doc("kappa", Range::positive(), "required", "-", "slope of the unloading-reloading lines in v - ln p'"),
      number_doc("lambda", Range::positive(), "required", "-", "slope of the normal compression line (> kappa)"),
      number_doc("critical_state_slope", Range::open(0, 3), "required", "-", "M of the critical state line q = M p'"),
      number_doc("void_ratio", Range::open(0, 20), "required", "-", "e (specific volume v = 1 + e held constant)"),
      number_doc("min_pressure", Range::positive(), "100", "Pa", "floor on p' in the elastic moduli (free surfaces)")}});
const bool documented_body = register_section(
    {"bodies:modified_cam_clay", "bodies[k] of a modified_cam_clay material", "Body fields the Modified Cam Clay model reads.",
     {number_doc("ocr", Range{1, 1000, false, false}, "1", "-",
                 "overconsolidation ratio: p_c = OCR x p_c of the yield locus through the initial stress")}});
}  // namespace

ModifiedCamClay ModifiedCamClay::parse(const JsonFields& f) {
  ModifiedCamClay m;
  m.poisson = f.number("poisson_ratio", Range::open(-1.0, 0.5));
  m.kappa = f.number("kappa", Range::positive());
  m.lambda = f.number("lambda", Range::positive());
  if (!(m.lambda > m.kappa))
    f.fail("lambda", "must be greater than kappa (" + std::to_string(m.kappa) + "), got " + std::to_string(m.lambda));
  m.critical_state_slope = f.number("critical_state_slope", Range::open(0, 3));
  m.void_ratio = f.number("void_ratio", Range::open(0, 20));
  m.min_pressure = f.number("min_pressure", Range::positive(), 100.0);
  m.point_ = soil::ModifiedCamClay(
      {m.lambda, m.kappa, m.critical_state_slope, m.poisson, 1.0 + m.void_ratio, m.min_pressure});
  return m;
}

double ModifiedCamClay::wave_speed(double p, double density) const {
  return p_wave_speed(point_.bulk_modulus(p), point_.shear_modulus(p), density);
}

void ModifiedCamClay::read_body(const JsonFields& b, BodySpec& body, const std::string& material) const {
  if (body.initial == "rest")
    b.fail("initial", "must be \"geostatic\" or \"isotropic\" for the modified_cam_clay material \"" + material +
                          "\": the model needs an initial mean effective stress p' > 0, and \"rest\" gives p' = 0");
  body.ocr = b.number("ocr", Range{1, 1000, false, false}, 1.0);
}

// p_c is OCR times that of the yield locus through the initial stress (p' floored at min_pressure
// at the free surface).
void ModifiedCamClay::initialise(const Matrix3d& sigma, const BodySpec& b, const SolidState& s, std::size_t i) const {
  using MCC = soil::ModifiedCamClay;
  s.f[0][i] = MCC::preconsolidation_for(std::max(MCC::mean_effective_stress(sigma), min_pressure),
                                        MCC::deviator_stress(sigma), critical_state_slope, b.ocr);
}

std::string ModifiedCamClay::describe_failure(const Matrix3d& sigma, const SolidState& s, std::size_t i) const {
  using MCC = soil::ModifiedCamClay;
  return "the Modified Cam Clay return mapping did not converge (start of step p' = " +
         std::to_string(MCC::mean_effective_stress(sigma)) + " Pa, q = " + std::to_string(MCC::deviator_stress(sigma)) +
         " Pa, p_c = " + std::to_string(s.f[0][i]) + " Pa)";
}

}  // namespace geosph::materials
