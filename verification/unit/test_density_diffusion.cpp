// delta-SPH density diffusion in a resting water column under gravity: the plain form (Molteni &
// Colagrossi 2009) diffuses the hydrostatic density gradient away, so the pressure at the base drifts
// low; the hydrostatic form (Fourtakas et al. 2019, Comput. Fluids 190, 346-361, eq. 17) diffuses only
// the dynamic part and keeps it.
#include <gtest/gtest.h>

#include <cmath>

#include "io/json_fields.hpp"
#include "io/scene.hpp"
#include "sim/simulation.hpp"

using namespace geosph;
using nlohmann::json;

namespace {

// mean of p / (rho0 g depth) over the two water rows next to the base, after 2 s
double base_pressure_ratio(bool hydrostatic) {
  json j = json::parse(R"({
    "name": "column", "dimension": 2, "dx": 0.05,
    "domain": {"min": [0, -0.25], "max": [0.5, 1.45], "periodic": ["x"]},
    "gravity": [0, -9.81], "time": {"end": 2.0},
    "materials": {"water": {"model": "tait_fluid", "density": 1000, "sound_speed": 50,
                            "artificial_viscosity": 0.1, "density_diffusion": 0.1}},
    "bodies": [{"material": "water", "shape": "box", "min": [0, 0], "max": [0.5, 1.0], "initial": "hydrostatic"}],
    "walls": {"type": "dummy", "containers": [{"min": [0, 0], "max": [0.5, 1.2], "open": ["top"]}]}
  })");
  j["materials"]["water"]["density_diffusion_hydrostatic"] = hydrostatic;
  Simulation sim(parse_scene(j, "column.json"));
  sim.run();
  const Particles& P = sim.particles();
  double s = 0;
  int n = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::Fluid && P.y[i] < 0.1) { s += P.p[i] / (1000 * 9.81 * (1.0 - P.y[i])); ++n; }
  return s / n;
}

}  // namespace

// 1 m column, c0 = 50 m/s, delta = 0.1, 2 s (~100 acoustic periods of the column). Measured over the
// two base rows: plain form -4.6%, hydrostatic form +0.66% (the Tait compressibility alone puts the
// exact hydrostatic pressure 0.2% above rho0 g depth there; the dummy-wall rows carry the rest). 1% bounds
// the hydrostatic form; the plain form's drift (> 2%) is asserted too, so the test shows what the option
// is for.
TEST(DensityDiffusion, HydrostaticFormKeepsTheBasePressure) {
  EXPECT_NEAR(base_pressure_ratio(true), 1.0, 0.01);
  EXPECT_LT(base_pressure_ratio(false), 0.98);
}
