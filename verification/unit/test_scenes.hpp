// Small scenes shared by the unit tests.
#pragma once
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

#include "io/json_fields.hpp"
#include "io/scene.hpp"

namespace geosph::test {

// parse_scene(j, "bad.json") must throw an InputError whose message names the file and contains
// `field` and `what`.
inline void expect_scene_error(const nlohmann::json& j, const std::string& field, const std::string& what) {
  try {
    parse_scene(j, "bad.json");
    ADD_FAILURE() << "no error for field " << field;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind("bad.json: field '", 0), 0u) << msg;
    EXPECT_NE(msg.find(field), std::string::npos) << msg;
    EXPECT_NE(msg.find(what), std::string::npos) << msg;
  }
}

// A 0.2 m x 0.1 m Drucker-Prager column (geostatic start) in a dummy-wall box.
inline nlohmann::json soil_column_scene(double dx = 0.01) {
  auto j = nlohmann::json::parse(R"({
    "name": "column", "dimension": 2,
    "domain": {"min": [-0.1, -0.1], "max": [0.5, 0.5]},
    "gravity": [0, -9.81],
    "time": {"end": 0.01},
    "materials": {"sand": {"model": "drucker_prager", "density": 2650, "young_modulus": 0.84e6,
                           "poisson_ratio": 0.3, "friction_angle": 19.8}},
    "bodies": [{"material": "sand", "shape": "box", "min": [0, 0], "max": [0.2, 0.1], "initial": "geostatic"}],
    "walls": {"type": "dummy", "containers": [{"min": [0, 0], "max": [0.35, 0.3], "open": ["top"]}]}
  })");
  j["dx"] = dx;
  return j;
}

// Dry soil behind a rigid retaining wall (a structure body with prescribed motion).
inline nlohmann::json soil_structure_scene() {
  return nlohmann::json::parse(R"({
    "name": "wall", "dimension": 2, "dx": 0.05,
    "domain": {"min": [-0.5, -0.3], "max": [2.5, 1.5]},
    "gravity": [0, -9.81],
    "time": {"end": 1.0},
    "materials": {
      "sand": {"model": "drucker_prager", "density": 1700, "young_modulus": 5e6, "poisson_ratio": 0.3,
               "friction_angle": 30},
      "steel": {"model": "linear_elastic", "density": 7800, "young_modulus": 2e8, "poisson_ratio": 0.3}
    },
    "bodies": [
      {"material": "sand", "shape": "box", "min": [0, 0], "max": [2, 1], "initial": "geostatic"},
      {"material": "steel", "shape": "box", "min": [-0.1, 0], "max": [0, 1.2], "structure": true,
       "interface_friction_angle": 20, "motion": {"velocity": [-0.01, 0]}}
    ]
  })");
}

}  // namespace geosph::test
