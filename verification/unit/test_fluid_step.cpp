// The fluid's one-pass step (fluid/fluid_forces.hpp): the density stage predicts rho with the last
// rate, the fused pair loop computes the new rate and corrects rho, so after every step
// rho^{n+1} = rho^n + dt drho^n with the rate of that step, as with a separate continuity pass.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "io/json_fields.hpp"
#include "io/scene.hpp"
#include "sim/simulation.hpp"

using namespace geosph;
using nlohmann::json;

namespace {
Scene small_dam_break() {
  return parse_scene(json::parse(R"({
    "name": "dam", "dimension": 2, "dx": 0.02,
    "kernel": {"type": "wendland_c2"},
    "domain": {"min": [-0.1, -0.1], "max": [1.1, 0.8]},
    "gravity": [0, -9.81], "time": {"end": 1.0},
    "materials": {"water": {"model": "tait_fluid", "density": 1000, "sound_speed": 20,
                            "artificial_viscosity": 0.05, "density_diffusion": 0.1}},
    "bodies": [{"material": "water", "shape": "box", "min": [0, 0], "max": [0.3, 0.5], "initial": "hydrostatic"}],
    "walls": {"type": "dummy", "containers": [{"min": [0, 0], "max": [1.0, 0.7], "open": ["top"]}]}
  })"), "dam.json");
}

std::map<std::int64_t, double> fluid_density(const Particles& P) {
  std::map<std::int64_t, double> rho;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::Fluid) rho[P.id[i]] = P.rho[i];
  return rho;
}
}  // namespace

TEST(FluidStep, DensityIsTheUpdateWithTheStepsOwnRate) {
  Simulation sim(small_dam_break());
  double max_rate = 0;
  for (int k = 0; k < 60; ++k) {  // through a reorder (every 20 steps): particles are matched by id
    const auto before = fluid_density(sim.particles());
    const double dt = sim.dt();
    sim.step();
    const Particles& P = sim.particles();
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (P.kind[i] != Kind::Fluid) continue;
      // rounding only: rho~ + dt (new - old) against rho^n + dt new, |rho| ~ 1e3
      ASSERT_NEAR(P.rho[i], before.at(P.id[i]) + dt * P.drho[i], 1e-9) << "step " << k << ", particle " << P.id[i];
      max_rate = std::max(max_rate, std::abs(P.drho[i]));
    }
  }
  EXPECT_GT(max_rate, 1.0);  // the column is collapsing: the rates are not trivially zero
}

// At t = 0 nothing has been predicted: building the simulation leaves the initial density as it is.
TEST(FluidStep, FirstForceEvaluationKeepsTheInitialDensity) {
  const Scene scene = small_dam_break();
  Simulation sim(scene);
  const Particles& P = sim.particles();
  double rate = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Fluid) continue;
    const double depth = 0.5 - P.y[i];
    const TaitEos eos(scene.materials[0]);
    EXPECT_NEAR(P.rho[i], eos.density(eos.hydrostatic_pressure(9.81, depth)), 1e-9);
    rate = std::max(rate, std::abs(P.drho[i]));
  }
  EXPECT_GT(rate, 0.0);  // the rate was computed
}
