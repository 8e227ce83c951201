// Dummy soil walls (boundary/soil_wall.hpp) at free-slip container faces, edges and corners: with a
// uniform stress in the soil and no gravity, each wall particle carries R sigma R^T, R = diag(-1 on the
// axes across which it lies beyond the container's inner box), so a face normal to x reverses xy and xz
// and keeps yz, an edge along z keeps xy, and a 2D corner keeps its shear; a no-slip wall keeps every
// shear. (Before, a free-slip dummy wall reversed every shear: the yz shear at an x face pushed the soil
// along the symmetry planes of the 3D collapse.)
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "boundary/body_fields.hpp"
#include "boundary/geometry.hpp"
#include "boundary/soil_wall.hpp"
#include "core/cell_list.hpp"
#include "soil/soil_fields.hpp"
#include "test_scenes.hpp"

using namespace geosph;
using nlohmann::json;

namespace {

json soil_box(int dim, const std::string& slip) {
  json j = json::parse(R"({
    "name": "box", "dx": 0.05,
    "time": {"end": 0.01},
    "materials": {"sand": {"model": "drucker_prager", "density": 2650, "young_modulus": 0.84e6,
                           "poisson_ratio": 0.3, "friction_angle": 30}},
    "walls": {"type": "dummy"}
  })");
  j["dimension"] = dim;
  j["walls"]["slip"] = slip;
  const json lo = dim == 3 ? json{0, 0, 0} : json{0, 0}, hi = dim == 3 ? json{0.3, 0.3, 0.3} : json{0.3, 0.3};
  j["domain"] = {{"min", dim == 3 ? json{-0.3, -0.3, -0.3} : json{-0.3, -0.3}},
                 {"max", dim == 3 ? json{0.6, 0.6, 0.6} : json{0.6, 0.6}}};
  j["gravity"] = dim == 3 ? json{0, 0, 0} : json{0, 0};
  j["bodies"] = json::array({{{"material", "sand"}, {"shape", "box"}, {"min", lo}, {"max", hi}}});
  j["walls"]["containers"] = json::array({{{"min", lo}, {"max", hi}}});
  return j;
}

// Runs the wall update on a uniform stress and checks every wall particle within a support of the soil;
// returns how many particles of each kind (face, edge, corner: the number of mirrored axes) it checked.
std::array<int, 4> check_uniform_shear(int dim, const std::string& slip) {
  const Scene s = parse_scene(soil_box(dim, slip), "ok.json");
  Particles P = build_particles(s);
  // sigma: xx, yy, zz, xy, xz, yz
  const double sig[6] = {-1000, -800, -900, 120, -70, 45};
  const int ncomp = dim == 3 ? 6 : 4;
  // the soil module creates these fields (soil/soil_forces.cpp)
  std::vector<double>* f[6] = {&P.add_field(SoilFields::xx, SoilFields::owner), &P.add_field(SoilFields::yy, SoilFields::owner),
                               &P.add_field(SoilFields::zz, SoilFields::owner), &P.add_field(SoilFields::xy, SoilFields::owner),
                               nullptr, nullptr};
  if (dim == 3) {
    f[4] = &P.add_field(SoilFields::xz, SoilFields::owner);
    f[5] = &P.add_field(SoilFields::yz, SoilFields::owner);
  }
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::Soil)
      for (int c = 0; c < ncomp; ++c) (*f[c])[i] = sig[c];
  CellList cells;
  EXPECT_EQ(cells.build(P, s.domain, s.support()), -1);
  SoilWalls walls(s);
  walls.allocate(P);
  walls.update(P, cells, {0, 0, 0});
  const bool free = slip == "free_slip";
  const int axes_of[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
  std::array<int, 4> count{0, 0, 0, 0};
  for (std::size_t w = 0; w < P.size(); ++w) {
    if (P.kind[w] != Kind::DummyWall) continue;
    const double q[3] = {P.x[w], P.y[w], P.z[w]};
    bool out[3] = {false, false, false};
    double gap2 = 0;  // squared distance to the nearest soil particle's position (dx/2 inside the box)
    int n_out = 0;
    for (int a = 0; a < dim; ++a) {
      const double d = q[a] < 0 ? 0.5 * s.dx - q[a] : q[a] > 0.3 ? q[a] - (0.3 - 0.5 * s.dx) : 0.0;
      out[a] = q[a] < 0 || q[a] > 0.3;
      n_out += out[a];
      gap2 += d * d;
    }
    if (std::sqrt(gap2) >= s.support()) continue;  // in no soil particle's support
    const std::string at = std::to_string(q[0]) + ", " + std::to_string(q[1]) + ", " + std::to_string(q[2]);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR((*f[c])[w], sig[c], 1e-9) << at;
    for (int c = 3; c < ncomp; ++c) {
      const bool reversed = free && out[axes_of[c][0]] != out[axes_of[c][1]];
      EXPECT_NEAR((*f[c])[w], reversed ? -sig[c] : sig[c], 1e-9) << "component " << c << " at " << at;
    }
    ++count[n_out];
  }
  return count;
}

}  // namespace

TEST(SoilWall, FreeSlipMirrorsTheShearAcrossFacesEdgesAndCorners3D) {
  const auto n = check_uniform_shear(3, "free_slip");
  EXPECT_GT(n[1], 0);  // faces
  EXPECT_GT(n[2], 0);  // edges
  EXPECT_GT(n[3], 0);  // corners
}

TEST(SoilWall, FreeSlipKeepsTheShearThroughA2DCorner) {
  const auto n = check_uniform_shear(2, "free_slip");
  EXPECT_GT(n[1], 0);
  EXPECT_GT(n[2], 0);
}

TEST(SoilWall, NoSlipKeepsEveryShear) {
  const auto n = check_uniform_shear(3, "no_slip");
  EXPECT_GT(n[1], 0);
  EXPECT_GT(n[3], 0);
}
