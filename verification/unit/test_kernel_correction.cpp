// The kernel-gradient correction of the solids' stress divergence
// (numerics.kernel_gradient_correction_stress, or per material, soil/soil_forces.hpp): the pair force keeps linear momentum
// (antisymmetric) in a stretched free block whose edge particles carry corrections far from the
// identity, and the option is rejected without the velocity-gradient correction. Its accuracy is the
// catalogue's: case elastic_strip_wave.
#include <gtest/gtest.h>

#include <cmath>

#include "io/json_fields.hpp"
#include "io/scene.hpp"
#include "sim/simulation.hpp"
#include "soil/soil_fields.hpp"

using namespace geosph;
using nlohmann::json;

namespace {

json block_json(bool stress_correction) {
  json j = json::parse(R"({
    "name": "block", "dimension": 2, "dx": 0.01,
    "domain": {"min": [-0.1, -0.1], "max": [0.3, 0.2]},
    "gravity": [0, 0], "time": {"end": 0.002},
    "materials": {"solid": {"model": "linear_elastic", "density": 1000, "young_modulus": 2e6, "poisson_ratio": 0.3}},
    "bodies": [{"material": "solid", "shape": "box", "min": [0, 0], "max": [0.2, 0.1]}],
    "numerics": {"kernel_gradient_correction": true}
  })");
  j["numerics"]["kernel_gradient_correction_stress"] = stress_correction;
  return j;
}

// Gives the block a linear velocity field v_x = a x (a uniaxial stretch) and runs a few steps.
void run_stretched(Simulation& sim) {
  Particles& P = sim.particles();
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::Soil) P.vx[i] = 0.05 * (P.x[i] - 0.1) + 0.01 * P.y[i];
  sim.run();
}

}  // namespace

TEST(KernelCorrection, StressDivergenceKeepsLinearMomentum) {
  Simulation sim(parse_scene(block_json(true), "block.json"));
  run_stretched(sim);  // sets the velocities at t = 0, then runs
  const Particles& P = sim.particles();
  double fx = 0, fy = 0, f_abs = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Soil) continue;
    fx += P.m[i] * P.ax[i];
    fy += P.m[i] * P.ay[i];
    f_abs += P.m[i] * std::hypot(P.ax[i], P.ay[i]);
  }
  ASSERT_GT(f_abs, 0.0);
  EXPECT_LT(std::abs(fx), 1e-12 * f_abs);
  EXPECT_LT(std::abs(fy), 1e-12 * f_abs);
  // the correction was applied: the free edge's particles have B^-T far from the identity
  const auto& cxx = P.extra_fields().at(SoilFields::correction[0]);
  double largest = 0;
  for (std::size_t i = 0; i < P.size(); ++i) largest = std::max(largest, std::abs(cxx[i]));
  EXPECT_GT(largest, 0.1);
}

TEST(KernelCorrection, StressCorrectionNeedsTheVelocityGradientCorrection) {
  json j = block_json(true);
  j["numerics"]["kernel_gradient_correction"] = false;
  try {
    parse_scene(j, "block.json");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("kernel_gradient_correction_stress"), std::string::npos) << e.what();
  }
}

// materials.<name>.kernel_gradient_correction corrects that material's particles only (here the left
// half of a block of two materials; numerics asks for no correction): the right half's corrections stay
// zero, the left half's free edges carry them, and the pair force across the two keeps linear momentum.
TEST(KernelCorrection, PerMaterialCorrectsOnlyThatMaterial) {
  json j = block_json(false);
  j["numerics"]["kernel_gradient_correction"] = false;
  j["materials"]["corrected"] = j["materials"]["solid"];
  j["materials"]["corrected"]["kernel_gradient_correction"] = true;
  j["bodies"] = json::parse(R"([
    {"material": "corrected", "shape": "box", "min": [0, 0], "max": [0.1, 0.1]},
    {"material": "solid", "shape": "box", "min": [0.1, 0], "max": [0.2, 0.1]}])");
  const Scene scene = parse_scene(j, "block.json");
  ASSERT_FALSE(scene.kernel_gradient_correction);
  Simulation sim(scene);
  run_stretched(sim);
  const Particles& P = sim.particles();
  const auto& cxx = P.extra_fields().at(SoilFields::correction[0]);
  const auto& cyy = P.extra_fields().at(SoilFields::correction[4]);
  double largest_corrected = 0, largest_other = 0, fx = 0, fy = 0, f_abs = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Soil) continue;
    const double c = std::max(std::abs(cxx[i]), std::abs(cyy[i]));
    if (scene.soils[P.material[i]].kernel_gradient_correction) largest_corrected = std::max(largest_corrected, c);
    else largest_other = std::max(largest_other, c);
    fx += P.m[i] * P.ax[i];
    fy += P.m[i] * P.ay[i];
    f_abs += P.m[i] * std::hypot(P.ax[i], P.ay[i]);
  }
  EXPECT_GT(largest_corrected, 0.1);
  EXPECT_EQ(largest_other, 0.0);
  ASSERT_GT(f_abs, 0.0);
  EXPECT_LT(std::abs(fx), 1e-12 * f_abs);
  EXPECT_LT(std::abs(fy), 1e-12 * f_abs);
}

TEST(KernelCorrection, PerMaterialFlagMustBeABoolean) {
  json j = block_json(false);
  j["materials"]["solid"]["kernel_gradient_correction"] = "yes";
  try {
    parse_scene(j, "block.json");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("kernel_gradient_correction"), std::string::npos) << e.what();
  }
}
