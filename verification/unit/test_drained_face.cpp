// Drained container sides (boundary/drained_face.hpp): which wall particles are drained (a face's own
// particles, not the container's corners), which water particles have crossed a face, free drainage of
// a saturated column through its base at Darcy's rate with the water's mass accounted for, and input
// errors naming the field.
#include <gtest/gtest.h>

#include <cmath>

#include "boundary/drained_face.hpp"
#include "coupling/seepage.hpp"
#include "io/json_fields.hpp"
#include "io/scene.hpp"
#include "sim/simulation.hpp"

using namespace geosph;
using nlohmann::json;

namespace {

// A saturated column of fixed sand (k = 0.1 m/s) in a container drained at its base.
json column_json() {
  return json::parse(R"({
    "name": "drained_column", "dimension": 2, "dx": 0.05,
    "domain": {"min": [0, -0.25], "max": [1.0, 1.45], "periodic": ["x"]},
    "gravity": [0, -9.81], "time": {"end": 0.5},
    "materials": {
      "water": {"model": "tait_fluid", "density": 1000, "sound_speed": 50, "artificial_viscosity": 0.1},
      "sand": {"model": "linear_elastic", "density": 1590, "young_modulus": 1e7, "poisson_ratio": 0.3,
               "porosity": 0.4, "hydraulic_conductivity": 0.1}
    },
    "bodies": [
      {"material": "water", "shape": "box", "min": [0, 0], "max": [1.0, 1.0], "initial": "hydrostatic"},
      {"material": "sand", "shape": "box", "min": [0, 0], "max": [1.0, 1.0], "fixed": true}
    ],
    "walls": {"type": "dummy", "containers": [{"min": [0, 0], "max": [1.0, 1.2], "open": ["top"], "drained": ["bottom"]}]}
  })");
}

double water_mass(const Particles& P) {
  double m = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::Fluid) m += P.m[i];
  return m;
}

}  // namespace

TEST(DrainedFace, FaceParticlesAreDrainedButNotTheCorners) {
  json j = column_json();
  j["domain"].erase("periodic");
  j["domain"]["min"] = {-0.25, -0.25};
  j["domain"]["max"] = {1.25, 1.45};
  const Scene s = parse_scene(j, "drained_column.json");
  const auto faces = drained_faces(s);
  ASSERT_EQ(faces.size(), 1u);
  EXPECT_EQ(faces[0].axis, 1);
  EXPECT_FALSE(faces[0].upper);
  EXPECT_EQ(faces[0].plane, 0.0);
  const double below[3] = {0.475, -0.025, 0}, corner[3] = {-0.025, -0.025, 0}, side[3] = {-0.025, 0.5, 0};
  EXPECT_EQ(drained_face_of(s, faces, 0, below), 1);
  EXPECT_EQ(drained_face_of(s, faces, 0, corner), 0);
  EXPECT_EQ(drained_face_of(s, faces, 0, side), 0);
  // hydrostatic behind the face: depth 0.025 m below it
  EXPECT_NEAR(faces[0].depth(below), 0.025, 1e-15);
  EXPECT_NEAR(faces[0].hydrostatic_pressure(below, 1000.0, {0, -9.81, 0}), 1000.0 * 9.81 * 0.025, 1e-9);

  Particles P;
  P.add(0.5, -0.001, 0, 1, 1000, Kind::Fluid, 0);   // crossed
  P.add(0.5, 0.001, 0, 1, 1000, Kind::Fluid, 0);    // not yet
  P.add(-0.01, -0.001, 0, 1, 1000, Kind::Fluid, 0); // beside the face (outside its extent)
  P.add(0.5, -0.001, 0, 1, 1000, Kind::Soil, 0);    // the skeleton is not drained
  const auto out = crossed_drained_faces(s, faces, P);
  EXPECT_EQ(out, (std::vector<char>{1, 0, 0, 0}));

  Simulation sim(s);
  const Particles& Q = sim.particles();
  const auto& tag = Q.int_field(DrainedFields::face);
  std::size_t drained = 0, under = 0, walls = 0;
  for (std::size_t i = 0; i < Q.size(); ++i) {
    if (Q.kind[i] != Kind::DummyWall) continue;
    ++walls;
    const bool below_face = Q.y[i] < 0 && Q.x[i] > 0 && Q.x[i] < 1.0;
    under += below_face;
    drained += tag[i] > 0;
    EXPECT_EQ(tag[i] > 0, below_face) << "wall particle at " << Q.x[i] << ", " << Q.y[i];
  }
  EXPECT_EQ(drained, under);
  EXPECT_GE(drained, 40u);  // 20 columns, at least two layers
  EXPECT_GT(walls, drained);
}

// With the base drained at p = 0 and the free water surface on top, the pore pressure is 0 at both ends
// of the column and the water flows down at the unit hydraulic gradient: Darcy's specific discharge
// q = k (Bear 1972, eq. 4.1.1), the water's velocity q/n. The lattice's rows of water reach the face
// one after another, every dx n / q = 0.2 s: the times at which half of each row has left are checked
// against it within 5% (the Darcy test's drag is exact to 0.5%; the row's spread in arrival adds to it),
// and the discharge of the water in the column within 3%. The water's mass is conserved: what is not in
// the column has been drained.
TEST(DrainedFace, SaturatedColumnDrainsAtDarcysRate) {
  json j = column_json();
  j["time"]["end"] = 0.6;
  Simulation sim(parse_scene(j, "drained_column.json"));
  const double m0 = water_mass(sim.particles()), k = 0.1, n0 = 0.4, dx = 0.05;
  const std::size_t row = 20;  // particles per row
  std::vector<double> half_row_out;
  sim.run([&](const Simulation& s) {
    if (s.drained_particles() >= row / 2 + row * half_row_out.size()) half_row_out.push_back(s.time());
  });
  const Particles& P = sim.particles();
  EXPECT_NEAR(water_mass(P) + sim.drained_mass(), m0, 1e-9 * m0);
  ASSERT_GE(half_row_out.size(), 3u) << "drained " << sim.drained_particles() << " particles";
  const double every = dx * n0 / (k * 9.81 / 9.80665);
  EXPECT_NEAR(half_row_out[1] - half_row_out[0], every, 0.05 * every);
  EXPECT_NEAR(half_row_out[2] - half_row_out[1], every, 0.05 * every);
  // specific discharge n v_w of the water in the column (0.2 < y < 0.6)
  const auto& n = P.extra_fields().at(SeepageFields::porosity);
  double q = 0, vol = 0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::Fluid && P.y[i] > 0.2 && P.y[i] < 0.6) {
      const double V = P.m[i] / P.rho[i];
      q += V * n[i] * P.vy[i];
      vol += V;
    }
  EXPECT_NEAR(q / vol, -k * 9.81 / 9.80665, 0.03 * k);
}

TEST(DrainedFace, BadInputIsRejectedWithTheField) {
  auto message = [](const json& j) {
    try {
      parse_scene(j, "drained.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  json j = column_json();
  j["walls"]["containers"][0]["drained"] = {"top"};
  EXPECT_NE(message(j).find("walls.containers[0].drained"), std::string::npos) << message(j);
  EXPECT_NE(message(j).find("also open"), std::string::npos) << message(j);
  j = column_json();
  j["walls"]["containers"][0]["drained"] = {"front"};
  EXPECT_NE(message(j).find("3D container"), std::string::npos) << message(j);
  j = column_json();
  j["walls"]["containers"][0].erase("drained");
  j["walls"]["containers"][0]["drained_pressure"] = 1000;
  EXPECT_NE(message(j).find("drained_pressure"), std::string::npos) << message(j);
  j = column_json();
  j["walls"]["containers"][0]["drained_pressure"] = -1e6;
  EXPECT_NE(message(j).find("drained_pressure"), std::string::npos) << message(j);
  j = column_json();  // dry soil: nothing to drain
  j["materials"].erase("water");
  j["bodies"].erase(0);
  j["materials"]["sand"].erase("porosity");
  j["materials"]["sand"].erase("hydraulic_conductivity");
  EXPECT_NE(message(j).find("two-phase"), std::string::npos) << message(j);
}
