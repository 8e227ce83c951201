// Two-phase saturated soil (coupling/seepage.hpp): Darcy's law in a periodic column driven by a body
// force on the water (equivalent hydraulic gradient i = f/g), for two permeabilities; a saturated
// column under gravity stays in its geostatic + hydrostatic equilibrium (buoyancy, pore-pressure force
// and walls consistent); both phases keep their mass; Kozeny-Carman scaling; input errors.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/seepage.hpp"
#include "io/json_fields.hpp"
#include "io/scene.hpp"
#include "sim/simulation.hpp"

using namespace geosph;
using nlohmann::json;

namespace {

json darcy_json(double k) {
  json j = json::parse(R"({
    "name": "darcy", "dimension": 2, "dx": 0.01,
    "domain": {"min": [0, 0], "max": [0.1, 0.1], "periodic": ["x", "y"]},
    "gravity": [0, 0], "body_force": [0, -9.81],
    "time": {"end": 0.05},
    "materials": {
      "water": {"model": "tait_fluid", "density": 1000, "sound_speed": 20},
      "sand": {"model": "drucker_prager", "density": 1590, "young_modulus": 1e7, "poisson_ratio": 0.3,
               "friction_angle": 30, "porosity": 0.4, "hydraulic_conductivity": 1e-3}
    },
    "bodies": [
      {"material": "water", "shape": "box", "min": [0, 0], "max": [0.1, 0.1]},
      {"material": "sand", "shape": "box", "min": [0, 0], "max": [0.1, 0.1], "fixed": true}
    ]
  })");
  j["materials"]["sand"]["hydraulic_conductivity"] = k;
  return j;
}

// specific discharge q = sum_w V n v / sum_w V (mixture-volume average)
double discharge(const Simulation& sim) {
  const Particles& P = sim.particles();
  const auto& n = P.extra_fields().at(SeepageFields::porosity);
  double qv = 0, vol = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::Fluid) {
      const double V = P.m[i] / P.rho[i];
      qv += V * n[i] * P.vy[i];
      vol += V;
    }
  return qv / vol;
}

}  // namespace

// Darcy: q = k i with i = f / g (g = 9.80665 m/s^2 defines k when the scene has no gravity). The SPH
// drag is exact for a uniform flow through a uniform skeleton (pair normalisation), so 0.5% bounds the
// residual of the relaxation (time constant k/(n g) = 2.5e-4 s for k = 1e-3 m/s, run 200 of them).
TEST(Seepage, DarcyDischargeMatchesDarcysLaw) {
  for (double k : {1e-3, 1e-4}) {
    Simulation sim(parse_scene(darcy_json(k), "darcy.json"));
    sim.run();
    const double expected = -k * 9.81 / 9.80665;
    EXPECT_NEAR(discharge(sim), expected, 5e-3 * std::abs(expected)) << "k = " << k;
  }
}

// Saturated elastic column (geostatic effective stress from the buoyant weight, hydrostatic water)
// in a container: after 0.5 s (several periods of the column) the mean effective vertical stress
// near the base stays within 2% of gamma' depth and the particles barely move; masses are constant.
// 2%: the soil's dummy-wall extrapolation at the base carries the buoyant weight over ~1.5 dx of
// ghost layer (gamma' 1.5 dx / sigma'_v = 1.5/18 = 8% at the wall row, ~1-2% averaged over the 4 base
// rows); measured drift 0.2% after 2 s. With delta-SPH in the water the drift was 3.3% (the diffusion
// flattens the hydrostatic density gradient; no hydrostatic correction yet), so it is off here.
TEST(Seepage, SaturatedColumnStaysInEquilibrium) {
  json j = json::parse(R"({
    "name": "column", "dimension": 2, "dx": 0.05,
    "domain": {"min": [0, -0.25], "max": [0.5, 1.45], "periodic": ["x"]},
    "gravity": [0, -9.81], "time": {"end": 0.5},
    "materials": {
      "water": {"model": "tait_fluid", "density": 1000, "sound_speed": 50, "artificial_viscosity": 0.1},
      "clay": {"model": "linear_elastic", "density": 1590, "young_modulus": 1.857e5, "poisson_ratio": 0.3,
               "porosity": 0.4, "hydraulic_conductivity": 1e-2}
    },
    "bodies": [
      {"material": "water", "shape": "box", "min": [0, 0], "max": [0.5, 1.0], "initial": "hydrostatic"},
      {"material": "clay", "shape": "box", "min": [0, 0], "max": [0.5, 1.0], "initial": "geostatic"}
    ],
    "walls": {"type": "dummy", "containers": [{"min": [0, 0], "max": [0.5, 1.2], "open": ["top"]}]}
  })");
  Simulation sim(parse_scene(j, "column.json"));
  auto masses = [&] {
    double mw = 0, ms = 0;
    const Particles& P = sim.particles();
    for (std::size_t i = 0; i < P.size(); ++i) (P.kind[i] == Kind::Fluid ? mw : ms) += P.kind[i] == Kind::Fluid || P.kind[i] == Kind::Soil ? P.m[i] : 0.0;
    return std::make_pair(mw, ms);
  };
  const auto m0 = masses();
  sim.run();
  const Particles& P = sim.particles();
  const auto& syy = P.extra_fields().at("stress_yy");
  const double gamma_b = (1590.0 - 0.6 * 1000.0) * 9.81;
  double s = 0, ref = 0, vmax = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::Soil && P.kind[i] != Kind::Fluid) continue;
    vmax = std::max(vmax, std::hypot(P.vx[i], P.vy[i]));
    if (P.kind[i] == Kind::Soil && P.y[i] < 0.2) { s += -syy[i]; ref += gamma_b * (1.0 - P.y[i]); }
  }
  EXPECT_NEAR(s / ref, 1.0, 0.02);
  EXPECT_LT(vmax, 2e-3);  // m/s; the column's gravity wave speed is ~11 m/s
  const auto m1 = masses();
  EXPECT_DOUBLE_EQ(m0.first, m1.first);
  EXPECT_DOUBLE_EQ(m0.second, m1.second);
}

// Kozeny-Carman: k(n) = k0 f(n)/f(n0), f = n^3/(1-n)^2 (Carman 1937; Bear 1972, eq. 5.10.18);
// from the grain size, k = gamma_w/mu d^2/180 f(n): d = 0.2 mm, n = 0.4 gives 3.87e-4 m/s.
TEST(Seepage, KozenyCarmanConductivity) {
  json j = darcy_json(1e-3);
  Scene s = parse_scene(j, "darcy.json");
  Seepage sp(s);
  EXPECT_NEAR(sp.conductivity(0, 0.4), 1e-3, 1e-15);
  EXPECT_NEAR(sp.conductivity(0, 0.3), 1e-3 * kozeny_carman(0.3) / kozeny_carman(0.4), 1e-15);
  j["materials"]["sand"].erase("hydraulic_conductivity");
  j["materials"]["sand"]["grain_size"] = 2e-4;
  j["gravity"] = {0, -9.81};
  j["body_force"] = {0, 0};
  j["domain"]["periodic"] = json::array({"x"});
  Scene s2 = parse_scene(j, "darcy.json");
  Seepage sp2(s2);
  const double k = 1000 * 9.81 / 1.002e-3 * 4e-8 / 180 * kozeny_carman(0.4);
  EXPECT_NEAR(sp2.conductivity(0, 0.4), k, 1e-12);
  EXPECT_NEAR(k, 3.87e-4, 0.01e-4);
}

TEST(Seepage, BadInputIsRejectedWithTheField) {
  auto expect_error = [](json j, const std::string& needle) {
    try {
      parse_scene(j, "two_phase.json");
      ADD_FAILURE() << "accepted, expected an error containing: " << needle;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  json j = darcy_json(1e-3);
  for (double n : {0.0, 1.0, -0.2, 1.5}) {
    json b = j;
    b["materials"]["sand"]["porosity"] = n;
    expect_error(b, "materials.sand.porosity");
  }
  for (double k : {0.0, -1e-3}) {
    json b = j;
    b["materials"]["sand"]["hydraulic_conductivity"] = k;
    expect_error(b, "materials.sand.hydraulic_conductivity");
  }
  {
    json b = j;
    b["materials"]["sand"].erase("hydraulic_conductivity");
    b["materials"]["sand"]["grain_size"] = 0;
    expect_error(b, "materials.sand.grain_size");
    b["materials"]["sand"].erase("grain_size");
    expect_error(b, "hydraulic_conductivity");  // missing both
  }
  {
    json b = j;
    b["materials"]["sand"].erase("porosity");
    b["materials"]["sand"].erase("hydraulic_conductivity");
    expect_error(b, "porosity");  // soil with a fluid must be saturated
  }
  {
    json b = j;
    b["bodies"][0]["max"] = {0.1, 0.05};  // water covers only half of the soil
    expect_error(b, "bodies[1]");
  }
  {
    // two water bodies that together hold the soil (the reservoirs either side of a sheet pile, each
    // hydrostatic below its own level) are its pore water; with a gap between them they are not
    json b = j;
    b["bodies"][0]["max"] = {0.1, 0.05};
    json upper = b["bodies"][0];
    upper["min"] = {0.0, 0.05};
    upper["max"] = {0.1, 0.1};
    b["bodies"].push_back(upper);
    EXPECT_NO_THROW(parse_scene(b, "two_phase.json"));
    b["bodies"][2]["min"] = {0.0, 0.07};
    expect_error(b, "bodies[1]");
  }
  {
    json b = j;
    b["materials"].erase("water");
    b["bodies"].erase(0);
    b.erase("body_force");
    expect_error(b, "materials.sand.porosity");  // saturated soil without pore water
  }
}
